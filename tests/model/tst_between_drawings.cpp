// Between Drawings (issue 50): in-betweens of two different drawings of one object. A figure
// (a body with an arm) drawn as key A, and key B drawn again from it — moved, or with the arm
// turned — resampled, its lines split, reversed and shuffled. The fit finds where A went; the
// in-betweens start on A's lines, land on B's, keep the arm's length, and go in as one undo step.
#include "bake_support.h"
#include "redrawn_key.h"
#include "stroke_support.h"

#include <finbook/deform/between/arap_interpolation.h>
#include <finbook/geometry/embedding.h>
#include <finbook/model/commands.h>
#include <finbook/model/document.h>
#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/fill/fill_regions.h>
#include <finbook/model/fill/fill_resolve.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/inbetween/between_drawings.h>
#include <finbook/model/inbetween/inbetween_commands.h>

#include <QRegularExpression>
#include <QTest>
#include <QtMath>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <set>

using namespace finbook;
using namespace finbook::model;

namespace {

constexpr float kPen = 3.0f;
const QPointF kShoulder(200.0, 135.0);

// The figure's outline: a body 100 × 160 and an arm 180 long, 30 wide, to the right.
std::vector<QPointF> figureCorners()
{
    return {{100, 100}, {200, 100}, {200, 120}, {380, 120},
            {380, 150}, {200, 150}, {200, 260}, {100, 260}};
}

// Points every `spacing` round the closed polygon, the first repeated at the end.
std::vector<QPointF> around(const std::vector<QPointF> &corners, double spacing)
{
    std::vector<QPointF> out;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const QPointF a = corners[i], b = corners[(i + 1) % corners.size()];
        const int steps = std::max(1, int(std::ceil(QLineF(a, b).length() / spacing)));
        for (int k = 0; k < steps; ++k)
            out.push_back(a + (b - a) * (double(k) / steps));
    }
    out.push_back(out.front());
    return out;
}

StrokeDataPtr strokeThrough(const std::vector<QPointF> &points)
{
    auto data = std::make_shared<StrokeData>();
    data->width = kPen;
    for (const QPointF &p : points)
        data->points.push_back({float(p.x()), float(p.y()), 1.0f});
    return data;
}

// The arm turned by `degrees` about the shoulder, blended over 30 px (as a pose bends it).
QPointF armTurned(QPointF p, double degrees)
{
    const double x = std::clamp((p.x() - kShoulder.x()) / 30.0 + 0.5, 0.0, 1.0);
    const double a = qDegreesToRadians(degrees * x * x * (3.0 - 2.0 * x));
    const QPointF d = p - kShoulder;
    return kShoulder + QPointF(std::cos(a) * d.x() - std::sin(a) * d.y(),
                               std::sin(a) * d.x() + std::cos(a) * d.y());
}

// Key A: the outline (4 px spacing) and an eye, ids from 1.
StrokeGroup keyA()
{
    StrokeGroup g;
    g.id = 1;
    g.name = QStringLiteral("Figure");
    g.strokes.push_back(Stroke{2, strokeThrough(around(figureCorners(), 4.0))});
    g.strokes.push_back(Stroke{3, testing::lineStroke({140, 130}, {160, 130}, 6, kPen)});
    return g;
}

// Key B: A's lines moved by `move`, resampled at 5.5 px, the outline split in two pieces, every
// other line reversed, the lines shuffled unless `inOrder`, ids from 100.
StrokeGroup keyB(const std::function<QPointF(QPointF)> &move, bool inOrder = false)
{
    std::vector<QPointF> outline;
    for (const QPointF &p : around(figureCorners(), 5.5))
        outline.push_back(move(p));
    std::vector<std::vector<QPointF>> lines;
    const std::size_t half = outline.size() / 2;
    lines.emplace_back(outline.begin(), outline.begin() + std::ptrdiff_t(half) + 1);
    lines.emplace_back(outline.begin() + std::ptrdiff_t(half), outline.end());
    lines.push_back({move({140, 130}), move({150, 130}), move({160, 130})});
    if (!inOrder) {
        std::reverse(lines[1].begin(), lines[1].end());
        std::mt19937 random(7);
        std::shuffle(lines.begin(), lines.end(), random);
    }
    StrokeGroup g;
    g.id = 100;
    g.name = QStringLiteral("Figure");
    Id next = 101;
    for (const auto &line : lines)
        g.strokes.push_back(Stroke{next++, strokeThrough(line)});
    return g;
}

// Where the fit puts A's stroke point k of stroke s.
QPointF fitted(const DrawingFit &fit, std::size_t s, std::size_t k)
{
    const auto &e = fit.meshed->embedding;
    const Eigen::Index r = Eigen::Index(fit.meshed->strokeOffsets[s] + k);
    const Eigen::MatrixX3i &F = fit.meshed->mesh.F;
    Eigen::Vector2d p = Eigen::Vector2d::Zero();
    for (int j = 0; j < 3; ++j)
        p += e.B(r, j) * fit.fit.U.row(F(e.I(r), j)).transpose();
    return {p.x(), p.y()};
}

// Largest distance of A's outline points, fitted, from where `move` puts them.
double worstError(const DrawingFit &fit, const StrokeGroup &a,
                  const std::function<QPointF(QPointF)> &move)
{
    double worst = 0.0;
    const auto &points = a.strokes[0].data->points;
    for (std::size_t k = 0; k < points.size(); ++k)
        worst =
            std::max(worst, QLineF(fitted(fit, 0, k), move({points[k].x, points[k].y})).length());
    return worst;
}

QPointF pointOf(const StrokePoint &p)
{
    return {p.x, p.y};
}

// A character as drawn in the app: a body, a head and two arms, each a closed line of its own,
// the arms' tops drawn over the body's outline; the right arm from its shoulder to
// `rightHand`. `spacing` is the pen's point spacing, `phase` where round each loop it starts.
std::vector<QPointF> ellipseLine(QPointF c, double rx, double ry, double spacing, double phase)
{
    const int n = std::max(12, int(std::ceil(2.0 * std::numbers::pi * std::max(rx, ry) / spacing)));
    std::vector<QPointF> out;
    for (int i = 0; i <= n; ++i) {
        const double a = phase + 2.0 * std::numbers::pi * i / n;
        out.emplace_back(c.x() + rx * std::cos(a), c.y() + ry * std::sin(a));
    }
    return out;
}

std::vector<QPointF> capsuleLine(QPointF a, QPointF b, double halfWidth, double spacing)
{
    const QPointF d = b - a;
    const QPointF u = d / std::hypot(d.x(), d.y()), n(-u.y(), u.x());
    std::vector<QPointF> corners = {a + n * halfWidth};
    for (int i = 0; i <= 8; ++i) {
        const double t = std::numbers::pi * i / 8;
        corners.push_back(b + n * (halfWidth * std::cos(t)) + u * (halfWidth * std::sin(t)));
    }
    corners.push_back(a - n * halfWidth);
    return around(corners, spacing);
}

const QPointF kRightShoulder(772, 400);

StrokeGroup character(QPointF rightHand, double spacing, double phase, Id firstId)
{
    StrokeGroup g;
    g.id = firstId;
    g.name = QStringLiteral("Character");
    const std::vector<std::vector<QPointF>> lines = {
        ellipseLine({720, 470}, 60, 100, spacing, phase),
        ellipseLine({720, 318}, 46, 48, spacing, phase + 1.0),
        capsuleLine({668, 400}, {610, 560}, 14, spacing),
        capsuleLine(kRightShoulder, rightHand, 14, spacing)};
    Id next = firstId + 1;
    for (const auto &line : lines)
        g.strokes.push_back(Stroke{next++, strokeThrough(line)});
    return g;
}

// The face of `g` at `inside`, if its area is within 15 % of `area` and it shows `colour`
// (an in-between at t); else -1, with the reason as a test warning.
int keepsItsRegion(const StrokeGroup &g, const ObjectRegions &regions, QPointF inside, double area,
                   QRgb colour, double t)
{
    const int face = regions.faceAt(inside);
    if (face < 0) {
        qWarning("t %.2f: no region at (%.0f, %.0f)", t, inside.x(), inside.y());
        return -1;
    }
    const double now = regions.regions().faces[std::size_t(face)].area;
    if (!(std::abs(now / area - 1.0) < 0.15)) {
        qWarning("t %.2f: the region %.0f px² of %.0f", t, now, area);
        return -1;
    }
    const int shows = faceFills(regions, g.fills)[std::size_t(face)];
    if (shows < 0 || g.fills[std::size_t(shows)].color != colour) {
        qWarning("t %.2f: the region shows %08x, not %08x", t,
                 shows < 0 ? 0u : g.fills[std::size_t(shows)].color, colour);
        return -1;
    }
    return face;
}

// The seed of a region of `g` that shows another fill (or none) than the region of `a` holding
// it, if any.
std::optional<QPointF> regionShowingOtherwise(const StrokeGroup &g, const StrokeGroup &a,
                                              double closeGap)
{
    const ObjectRegionsPtr now = objectRegions(g, closeGap), then = objectRegions(a, closeGap);
    const std::vector<int> nowShows = faceFills(*now, g.fills),
                           thenShows = faceFills(*then, a.fills);
    for (int face = 0; face < now->faceCount(); ++face) {
        const Eigen::Vector2d seed = now->regions().faces[std::size_t(face)].seed;
        const int inA = then->faceAt(QPointF(seed.x(), seed.y()));
        const int x = nowShows[std::size_t(face)], y = inA >= 0 ? thenShows[std::size_t(inA)] : -1;
        if (inA < 0 || (x < 0) != (y < 0) ||
            (x >= 0 && g.fills[std::size_t(x)].color != a.fills[std::size_t(y)].color))
            return QPointF(seed.x(), seed.y());
    }
    return std::nullopt;
}

} // namespace

class TestBetweenDrawings : public QObject {
    Q_OBJECT

private slots:
    void aRigidMotionIsRecovered();
    void aTurnedArmIsFittedWithItsElbowInPlace();
    void reversedAndShuffledLinesGiveTheSameFit();
    void correspondencePinsMoveTheFit();
    void drawingsThatDoNotFitAreRefusedWithAReason();
    void anArmTheFitCannotSwingIsRefusedWhereBShowsIt_data();
    void anArmTheFitCannotSwingIsRefusedWhereBShowsIt();
    void anArmSwungOutInTheAppIsFound();
    void anArmDrawnOverTheBodyTurnsAsAPiece_data();
    void anArmDrawnOverTheBodyTurnsAsAPiece();
    void aBodyDrawnOpenUnderAnArmStaysClosed();
    void aBodyClosedByAPartStaysClosedAsThePartTurns();
    void aKeyTheAxesTurnOverIsFoundUpright();
    void inbetweensStartOnAAndLandOnB();
    void generatedInbetweensAreOneUndoStep();
};

void TestBetweenDrawings::aRigidMotionIsRecovered()
{
    const auto move = [](QPointF p) {
        const double a = qDegreesToRadians(12.0);
        const QPointF c(240, 180);
        const QPointF d = p - c;
        return c +
               QPointF(std::cos(a) * d.x() - std::sin(a) * d.y(),
                       std::sin(a) * d.x() + std::cos(a) * d.y()) +
               QPointF(35, -20);
    };
    const StrokeGroup a = keyA();
    const auto fit = fitDrawings(a, keyB(move), -1.0);
    QVERIFY2(fit, fit ? "" : qPrintable(fit.error()));
    // Every outline point within 2 px of its place (B's points are 5.5 px apart).
    const double worst = worstError(**fit, a, move);
    qInfo("rigid motion: worst %.2f px", worst);
    QVERIFY2(worst < 2.0, qPrintable(QString::number(worst)));
    QVERIFY((*fit)->fit.distortion < 0.02);
}

void TestBetweenDrawings::aTurnedArmIsFittedWithItsElbowInPlace()
{
    const auto move = [](QPointF p) { return armTurned(p, 40.0); };
    const StrokeGroup a = keyA();
    const auto fit = fitDrawings(a, keyB(move), -1.0);
    QVERIFY2(fit, fit ? "" : qPrintable(fit.error()));
    const DrawingFit &f = **fit;
    // The hand (the arm's far end) and the shoulder land where B has them.
    const auto &points = a.strokes[0].data->points;
    double hand = 0.0, shoulder = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const QPointF p = pointOf(points[k]);
        const double off = QLineF(fitted(f, 0, k), move(p)).length();
        if (p.x() >= 370.0)
            hand = std::max(hand, off);
        if (std::abs(p.x() - 200.0) < 1.0 && p.y() < 160.0)
            shoulder = std::max(shoulder, off);
    }
    qInfo("turned arm: hand %.2f px, shoulder %.2f px", hand, shoulder);
    QVERIFY2(hand < 6.0, qPrintable(QString::number(hand)));
    QVERIFY2(shoulder < 6.0, qPrintable(QString::number(shoulder)));
    // The mid in-between turns the arm half way, keeping its length (a straight-line morph
    // would shorten it by 1 − cos 20° ≈ 6 %).
    const StrokeGroup mid = betweenDrawing(f, 0.5);
    const auto &midPoints = mid.strokes[0].data->points;
    QPointF tip;
    for (std::size_t k = 0; k < points.size(); ++k)
        if (points[k].x == 380.0f && points[k].y == 135.0f)
            tip = pointOf(midPoints[k]);
    if (tip.isNull()) { // the outline has no point at the arm's end middle: take the corners'
        QPointF sum;
        int n = 0;
        for (std::size_t k = 0; k < points.size(); ++k)
            if (points[k].x == 380.0f) {
                sum += pointOf(midPoints[k]);
                ++n;
            }
        tip = sum / n;
    }
    const double length = QLineF(kShoulder, tip).length();
    qInfo("mid in-between: arm %.2f px long (180 at rest)", length);
    QVERIFY2(std::abs(length - 180.0) / 180.0 < 0.03, qPrintable(QString::number(length)));
    const double turned = QLineF(kShoulder, tip).angleTo(QLineF(kShoulder, {380, 135}));
    const double degrees = turned > 180.0 ? 360.0 - turned : turned;
    qInfo("mid in-between: arm turned %.2f° (20 half way)", degrees);
    QVERIFY2(std::abs(degrees - 20.0) < 4.0, qPrintable(QString::number(degrees)));
}

void TestBetweenDrawings::reversedAndShuffledLinesGiveTheSameFit()
{
    const auto move = [](QPointF p) { return armTurned(p, 30.0) + QPointF(10, 5); };
    const StrokeGroup a = keyA();
    const auto inOrder = fitDrawings(a, keyB(move, true), -1.0);
    const auto shuffled = fitDrawings(a, keyB(move, false), -1.0);
    QVERIFY(inOrder && shuffled);
    const auto &points = a.strokes[0].data->points;
    double worst = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k)
        worst = std::max(worst, QLineF(fitted(**inOrder, 0, k), fitted(**shuffled, 0, k)).length());
    qInfo("in order against shuffled: %.3f px apart at most", worst);
    // B's points are thinned square by square, not along each line, so the fit sees the same
    // points however B was drawn: the same fit, not a close one.
    QVERIFY2(worst < 1e-9, qPrintable(QString::number(worst)));
}

void TestBetweenDrawings::correspondencePinsMoveTheFit()
{
    const auto move = [](QPointF p) { return armTurned(p, 30.0); };
    const StrokeGroup a = keyA();
    const auto free = fitDrawings(a, keyB(move), -1.0);
    QVERIFY(free);
    // The animator says the hand's top corner belongs 25 px further along B's arm.
    const QPointF corner(380, 120);
    const QPointF wanted = armTurned(QPointF(355, 120), 30.0);
    const auto pinned = fitDrawings(a, keyB(move), -1.0, {BetweenPin{corner, wanted}});
    QVERIFY2(pinned, pinned ? "" : qPrintable(pinned.error()));
    const auto &points = a.strokes[0].data->points;
    std::size_t at = 0;
    for (std::size_t k = 0; k < points.size(); ++k)
        if (QLineF(pointOf(points[k]), corner).length() <
            QLineF(pointOf(points[at]), corner).length())
            at = k;
    const double before = QLineF(fitted(**free, 0, at), wanted).length();
    const double after = QLineF(fitted(**pinned, 0, at), wanted).length();
    qInfo("pinned corner: %.2f px from its pin's place, %.2f px without the pin", after, before);
    QVERIFY2(after < 0.5 * before && after < 8.0,
             qPrintable(QStringLiteral("%1 → %2").arg(before).arg(after)));
    // Dragged live: the fit refitted from where it settled takes the pin as well, and taking the
    // pin away again gives back a fit like the free one.
    const auto live = refitDrawings(**free, {BetweenPin{corner, wanted}});
    QVERIFY2(live, live ? "" : qPrintable(live.error()));
    const double refitted = QLineF(fitted(**live, 0, at), wanted).length();
    qInfo("refitted with the pin: %.2f px from its place", refitted);
    QVERIFY(refitted < 0.5 * before && refitted < 8.0);
    QCOMPARE((*live)->pins.size(), std::size_t(1));
    const auto unpinned = refitDrawings(**live, {});
    QVERIFY(unpinned);
    QVERIFY(QLineF(fitted(**unpinned, 0, at), fitted(**free, 0, at)).length() < 0.5 * before);
}

void TestBetweenDrawings::drawingsThatDoNotFitAreRefusedWithAReason()
{
    const StrokeGroup a = keyA();
    // B: a long zigzag, nothing like the figure.
    std::vector<QPointF> zigzag;
    for (int i = 0; i <= 40; ++i)
        zigzag.emplace_back(50.0 + 25.0 * i, i % 2 ? 100.0 : 400.0);
    StrokeGroup b;
    b.id = 100;
    b.strokes.push_back(Stroke{101, strokeThrough(zigzag)});
    const auto fit = fitDrawings(a, b, -1.0);
    QVERIFY(!fit);
    QVERIFY2(fit.error().contains(QLatin1String("too different")), qPrintable(fit.error()));
    // An empty key is refused too, and nothing ever throws or returns NaN.
    QVERIFY(!fitDrawings(a, StrokeGroup{}, -1.0));
    QVERIFY(!fitDrawings(StrokeGroup{}, a, -1.0));

    // In the document: such keys switch over half way, as before, and say why.
    Document doc;
    doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
    doc.undoStack()->push(new InsertFrameCommand(&doc, 1));
    const Id ga = doc.frameAt(0).groups.at(0).id, gb = doc.frameAt(1).groups.at(0).id;
    doc.undoStack()->push(new AddStrokeCommand(&doc, ga, a.strokes[0].data));
    doc.undoStack()->push(new AddStrokeCommand(&doc, gb, b.strokes[0].data));
    const KeyFits fits = fitKeyDrawings(doc.frameAt(0), doc.frameAt(1), -1.0);
    QCOMPARE(fits.failures.size(), std::size_t(1));
    QCOMPARE(fits.failures.front().first, 0);
    QVERIFY(std::none_of(fits.fits.begin(), fits.fits.end(), [](const auto &f) { return f; }));
    const InbetweenPlan plan =
        planInbetweens(doc.frameAt(0), doc.frameAt(1), {0.5}, TargetPath::Arc, fits.fits);
    QVERIFY(std::none_of(plan.objects.begin(), plan.objects.end(),
                         [](const auto &o) { return o.fate == ObjectFate::Fitted; }));
}

void TestBetweenDrawings::anArmTheFitCannotSwingIsRefusedWhereBShowsIt_data()
{
    QTest::addColumn<QPointF>("hand");
    QTest::newRow("raised (120°)") << QPointF(880, 270);
    QTest::newRow("drawn in the app") << QPointF(); // tests/data/between_arm_out.finbook
}

void TestBetweenDrawings::anArmTheFitCannotSwingIsRefusedWhereBShowsIt()
{
    // Found in the app: a character drawn with both arms down, their tops over the body, and
    // drawn again with the right arm raised, or (drawn in the app) out to the side. With A meshed
    // as one (BetweenOptions::layeredParts off), the mesh is the union of what was drawn, so the
    // arm is joined to the body along its top and no fit as rigid as possible swings it free: the
    // fit lays A's arm along the body, and its in-betweens crumpled the arm. Such a fit is refused,
    // and the message names where B's arm is.
    QFETCH(QPointF, hand);
    StrokeGroup a, b;
    double closeGap = -1.0;
    if (hand.isNull()) { // the same drawn with the pen, filled, on frames 1 and 2
        const auto loaded =
            loadFinbook(QStringLiteral(FINBOOK_SOURCE_DIR "/tests/data/between_arm_out.finbook"));
        QVERIFY(loaded && loaded->frames.size() == 2);
        a = loaded->frames[0].groups.at(0);
        b = loaded->frames[1].groups.at(0);
        closeGap = loaded->settings.closeGap;
        QCOMPARE(b.strokes.size(), std::size_t(4));
    } else {
        a = character({830, 560}, 3.0, 0.0, 1);
        b = character(hand, 4.1, 2.0, 100);
    }
    BetweenOptions whole; // A meshed as one (anArmDrawnOverTheBodyTurnsAsAPiece: as parts)
    whole.layeredParts = false;
    const auto made = fitDrawings(a, b, closeGap, {}, whole);
    QVERIFY(!made);
    qInfo("%s", qPrintable(made.error()));
    const QRegularExpressionMatch at =
        QRegularExpression(QStringLiteral("around \\((\\d+), (\\d+)\\)")).match(made.error());
    QVERIFY2(at.hasMatch(), qPrintable(made.error()));
    const QPointF centre(at.captured(1).toDouble(), at.captured(2).toDouble());
    QRectF arm;
    for (const StrokePoint &p : b.strokes[3].data->points)
        arm = arm.united(QRectF(p.x, p.y, 0.01, 0.01));
    QVERIFY2(arm.adjusted(-10, -10, 10, 10).contains(centre),
             qPrintable(QStringLiteral("(%1, %2)").arg(centre.x()).arg(centre.y())));
}

void TestBetweenDrawings::anArmSwungOutInTheAppIsFound()
{
    // tests/data/between_arm_swing.finbook, drawn with the pen in the real window: the same
    // character with its right arm swung out by about 30° in the second key. The start that
    // leaves the arm hanging lies closer on the medians (the arm is a small part of the
    // drawing), but leaves B's arm with nothing on it; the fit keeps the start that swings it.
    const auto loaded =
        loadFinbook(QStringLiteral(FINBOOK_SOURCE_DIR "/tests/data/between_arm_swing.finbook"));
    QVERIFY(loaded && loaded->frames.size() == 2);
    const StrokeGroup &a = loaded->frames[0].groups.at(0), &b = loaded->frames[1].groups.at(0);
    QCOMPARE(a.strokes.size(), std::size_t(4));
    QCOMPARE(b.strokes.size(), std::size_t(4));
    const auto made = fitDrawings(a, b, loaded->settings.closeGap);
    QVERIFY2(made, made ? "" : qPrintable(made.error()));
    // The right arm's hand end (its line's point farthest from the body's centre) in each key.
    QRectF body;
    for (const StrokePoint &p : a.strokes[0].data->points)
        body = body.united(QRectF(p.x, p.y, 0.01, 0.01));
    const auto handOf = [&](const StrokeGroup &g) {
        std::size_t best = 0;
        const auto &points = g.strokes[3].data->points;
        for (std::size_t k = 0; k < points.size(); ++k)
            if (QLineF(body.center(), pointOf(points[k])).length() >
                QLineF(body.center(), pointOf(points[best])).length())
                best = k;
        return best;
    };
    const std::size_t hand = handOf(a);
    const QPointF handA = pointOf(a.strokes[3].data->points[hand]);
    const QPointF handB = pointOf(b.strokes[3].data->points[handOf(b)]);
    const double off = QLineF(fitted(**made, 3, hand), handB).length();
    const double swing = QLineF(handA, handB).length();
    qInfo("hand fitted %.1f px from B's (it swung %.1f px)", off, swing);
    QVERIFY2(off < 0.2 * swing, qPrintable(QString::number(off)));
    QVERIFY((*made)->fit.uncoveredShare < 0.05);
}

void TestBetweenDrawings::anArmDrawnOverTheBodyTurnsAsAPiece_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("raised (120°)") << QString();
    QTest::newRow("out to the side, drawn in the app") << QStringLiteral("between_arm_out.finbook");
    QTest::newRow("swung out, drawn in the app") << QStringLiteral("between_arm_swing.finbook");
    QTest::newRow("across the chest, drawn in the app")
        << QStringLiteral("between_arm_across.finbook");
}

void TestBetweenDrawings::anArmDrawnOverTheBodyTurnsAsAPiece()
{
    // The same keys, A meshed as parts (the default): each arm, a closed line drawn over the
    // body, is meshed on its own and hinged where it overlaps the body. The in-betweens turn the
    // arm about the shoulder as a piece (its length kept, half the turn half way), and their
    // fills are what the parts show: the body's own colour where the arm's top covered it, and
    // nothing in the space the arm swung out of.
    QFETCH(QString, file);
    StrokeGroup a, b;
    double closeGap = -1.0;
    if (file.isEmpty()) {
        a = character({830, 560}, 3.0, 0.0, 1);
        b = character({880, 270}, 4.1, 2.0, 100);
    } else {
        const auto loaded = loadFinbook(QStringLiteral(FINBOOK_SOURCE_DIR "/tests/data/") + file);
        QVERIFY(loaded && loaded->frames.size() == 2);
        a = loaded->frames[0].groups.at(0);
        b = loaded->frames[1].groups.at(0);
        closeGap = loaded->settings.closeGap;
        QVERIFY(!a.fills.empty());
    }
    const auto made = fitDrawings(a, b, closeGap);
    QVERIFY2(made, made ? "" : qPrintable(made.error()));
    const DrawingFit &fit = **made;
    QCOMPARE(fit.hinges.size(), std::size_t(2)); // both arms, the head only touches the body
    QCOMPARE(fit.parts.size(), std::size_t(2));
    BetweenOptions noFade;
    noFade.crossFade = 0.0;
    const StrokeGroup mid = betweenDrawing(fit, 0.5, noFade);
    const auto line = [](const StrokeGroup &g, std::size_t s) {
        QPolygonF out;
        for (const StrokePoint &p : g.strokes[s].data->points)
            out << pointOf(p);
        return out;
    };
    // The arm (stroke 3) as a piece: its farthest two points as far apart, its hand (A's point
    // farthest from the body's centre) carried onto B's arm, and half way turned about the
    // body's centre by half as much as at the end.
    const QPointF centre = line(a, 0).boundingRect().center();
    const auto span = [](const QPolygonF &arm) {
        double most = 0.0;
        for (const QPointF &p : arm)
            for (const QPointF &q : arm)
                most = std::max(most, QLineF(p, q).length());
        return most;
    };
    const QPolygonF armA = line(a, 3), armMid = line(mid, 3), armB = line(b, 3);
    QVERIFY2(std::abs(span(armMid) / span(armA) - 1.0) < 0.03,
             qPrintable(QString::number(span(armMid) / span(armA))));
    int hand = 0;
    for (int k = 0; k < int(armA.size()); ++k)
        if (QLineF(centre, armA[k]).length() > QLineF(centre, armA[hand]).length())
            hand = k;
    const QPointF landed = line(betweenDrawing(fit, 1.0, noFade), 3)[hand];
    double offB = std::numeric_limits<double>::infinity();
    for (const QPointF &p : armB)
        offB = std::min(offB, QLineF(p, landed).length());
    QVERIFY2(offB < 0.1 * span(armA), qPrintable(QString::number(offB)));
    const auto turnTo = [&](QPointF p) {
        return std::remainder(QLineF(centre, p).angle() - QLineF(centre, armA[hand]).angle(),
                              360.0);
    };
    const double whole = turnTo(landed), half = turnTo(armMid[hand]);
    qInfo("arm turned %.1f° of %.1f° half way; its hand lands %.1f px from B's arm", half, whole,
          offB);
    QVERIFY2(std::abs(half - 0.5 * whole) < 0.15 * std::abs(whole) + 2.0,
             qPrintable(QStringLiteral("%1 of %2").arg(half).arg(whole)));
    if (a.fills.empty())
        return;
    // Fills: every fill of the in-between lies on a part as carried (body, head or an arm), and
    // where A's arm top lay over the body the body's colour shows once the arm has left it.
    const ObjectRegionsPtr regions = objectRegions(mid, closeGap);
    const std::vector<int> shows = faceFills(*regions, mid.fills);
    const auto colourAt = [&](QPointF p) -> std::optional<QRgb> {
        const int face = regions->faceAt(p);
        if (face < 0 || shows[std::size_t(face)] < 0)
            return std::nullopt;
        return mid.fills[std::size_t(shows[std::size_t(face)])].color;
    };
    for (const Fill &f : mid.fills)
        QVERIFY2(
            std::any_of(mid.strokes.begin(), mid.strokes.end(),
                        [&](const Stroke &s) {
                            QPolygonF ring;
                            for (const StrokePoint &p : s.data->points)
                                ring << pointOf(p);
                            return ring.size() > 8 && ring.containsPoint(f.seed, Qt::OddEvenFill);
                        }),
            qPrintable(
                QStringLiteral("a fill at (%1, %2) on no part").arg(f.seed.x()).arg(f.seed.y())));
    const std::optional<QRgb> body = colourAt(centre);
    QVERIFY(body);
    // At t = 0 every region shows what it shows in A.
    const std::optional<QPointF> differs =
        regionShowingOtherwise(betweenDrawing(fit, 0.0, noFade), a, closeGap);
    QVERIFY2(!differs,
             differs
                 ? qPrintable(
                       QStringLiteral("the region at (%1, %2)").arg(differs->x()).arg(differs->y()))
                 : "");
    QPointF top; // the middle of A's arm's points inside the body
    int inside = 0;
    const QPolygonF bodyLine = line(a, 0);
    for (const QPointF &p : armA)
        if (bodyLine.containsPoint(p, Qt::OddEvenFill)) {
            top += p;
            ++inside;
        }
    QVERIFY(inside > 0);
    top /= inside;
    if (!armMid.containsPoint(top, Qt::OddEvenFill)) // the arm has left it
        QCOMPARE(colourAt(top), body);
    else // swung across the chest: the arm, drawn on top, still covers it
        QVERIFY(colourAt(top) && colourAt(top) != body);
    // A correspondence pin on the arm's top, where it lies over the body, is on the arm (the
    // part drawn on top): pulled 20 px outwards, it moves the arm's line, not the body's.
    std::size_t nearest = 0;
    for (std::size_t k = 0; k < std::size_t(armA.size()); ++k)
        if (QLineF(armA[int(k)], top).length() < QLineF(armA[int(nearest)], top).length())
            nearest = k;
    const QPointF from = fitted(fit, 3, nearest);
    const QLineF outwards(centre, from);
    const QPointF to = from + QPointF(outwards.dx(), outwards.dy()) * (20.0 / outwards.length());
    const auto pinned = refitDrawings(fit, {BetweenPin{top, to}});
    QVERIFY(pinned);
    const auto moved = [&](std::size_t s) {
        double sum = 0.0;
        const std::size_t n = a.strokes[s].data->points.size();
        for (std::size_t k = 0; k < n; ++k)
            sum += QLineF(fitted(fit, s, k), fitted(**pinned, s, k)).length();
        return sum / double(n);
    };
    qInfo("pinned: the arm's line moved %.1f px, the body's %.1f px", moved(3), moved(0));
    QVERIFY2(moved(3) > 2.0 * moved(0),
             qPrintable(QStringLiteral("arm %1, body %2").arg(moved(3)).arg(moved(0))));
}

void TestBetweenDrawings::aBodyDrawnOpenUnderAnArmStaysClosed()
{
    // The body's outline drawn with a gap where the right arm's top covers it (the pen lifted
    // under the arm): at rest the arm's lines close the body. As the arm swings out, the body
    // keeps a region of its own in its colour. Meshed with the automatic gap of the body and
    // head alone (smaller than A's, which the arms' reach widens), the body's mesh was its ink
    // ring only, so no in-between found its inside and the body lost its fill.
    StrokeGroup a = character({830, 560}, 3.0, 0.0, 1);
    {
        const std::vector<StrokePoint> &ring = a.strokes[0].data->points;
        const QPointF under(768, 408); // on the body's outline, under the arm's top
        std::vector<bool> gone(ring.size());
        for (std::size_t k = 0; k < ring.size(); ++k)
            gone[k] = QLineF(pointOf(ring[k]), under).length() < 10.0;
        std::size_t last = 0;
        for (std::size_t k = 0; k < ring.size(); ++k)
            if (gone[k])
                last = k;
        auto open = std::make_shared<StrokeData>(*a.strokes[0].data);
        open->points.clear();
        for (std::size_t i = 1; i < ring.size(); ++i) { // from after the gap round to before it
            const std::size_t k = (last + i) % (ring.size() - 1); // the ring's last = its first
            if (!gone[k])
                open->points.push_back(ring[k]);
        }
        QVERIFY(open->points.size() + 4 < ring.size());
        a.strokes[0].data = std::move(open);
    }
    const ObjectRegionsPtr rest = objectRegions(a, -1.0);
    const auto fillAt = [&](QPointF p, QRgb colour) {
        const int face = rest->faceAt(p);
        QVERIFY(face >= 0);
        a.fills.push_back(fillOfFace(*rest, face, colour));
    };
    const QRgb blue = 0xff3060c0, orange = 0xfff09020;
    fillAt({720, 500}, blue);
    fillAt({815, 520}, orange); // the right arm (its top over the body is the body's face)
    fillAt({625, 520}, orange); // the left arm
    const double bodyArea = rest->regions().faces[std::size_t(rest->faceAt({720, 500}))].area;
    const StrokeGroup b = character({900, 420}, 4.1, 2.0, 100);
    const auto made = fitDrawings(a, b, -1.0);
    QVERIFY2(made, made ? "" : qPrintable(made.error()));
    QCOMPARE((*made)->parts.size(), std::size_t(2));
    BetweenOptions noFade;
    noFade.crossFade = 0.0;
    for (const double t : {0.25, 0.5, 0.75}) {
        const StrokeGroup g = betweenDrawing(**made, t, noFade);
        const ObjectRegionsPtr regions = objectRegions(g, -1.0);
        QVERIFY(keepsItsRegion(g, *regions, {720, 500}, bodyArea, blue, t) >= 0);
    }
}

void TestBetweenDrawings::aBodyClosedByAPartStaysClosedAsThePartTurns()
{
    // tests/data/quickdraw_fish_5549221702795264.json: the tail, a closed line, drawn over the
    // body's end, and the body's outline left open where the tail's lines cross it. Turned, the
    // tail no longer closes the body: without the gap the regions close under the parts (A's
    // lines without the tail's), the body's region ran into the tail's and took its colour
    // (the tail went red at t = 0.25 in finbook-bench between's sheet).
    QString error;
    const auto lines = testing::readDrawing(
        QStringLiteral(FINBOOK_SOURCE_DIR "/tests/data/quickdraw_fish_5549221702795264.json"),
        &error);
    QVERIFY2(lines.size() == 4, qPrintable(error));
    Document doc;
    const Id g = testing::drawingDocument(doc, lines);
    const StrokeGroup a = *doc.group(g);
    const double closeGap = doc.settings().closeGap;
    QCOMPARE(a.fills.size(), std::size_t(2));
    StrokeGroup b = a;
    b.fills.clear();
    {
        auto tail = std::make_shared<StrokeData>(*b.strokes[0].data);
        const QPointF pivot(193, 234);
        QTransform turn;
        turn.translate(pivot.x(), pivot.y()).rotate(30.0).translate(-pivot.x(), -pivot.y());
        for (StrokePoint &p : tail->points) {
            const QPointF q = turn.map(pointOf(p));
            p.x = float(q.x());
            p.y = float(q.y());
        }
        b.strokes[0].data = std::move(tail);
    }
    const auto made = fitDrawings(a, b, closeGap);
    QVERIFY2(made, made ? "" : qPrintable(made.error()));
    QCOMPARE((*made)->parts.size(), std::size_t(1));
    const ObjectRegionsPtr rest = objectRegions(a, closeGap);
    const QPointF inBody(132, 221);
    const int bodyFace = rest->faceAt(inBody);
    QVERIFY(bodyFace >= 0);
    const double bodyArea = rest->regions().faces[std::size_t(bodyFace)].area;
    const QRgb bodyColour =
        a.fills[std::size_t(faceFills(*rest, a.fills)[std::size_t(bodyFace)])].color;
    BetweenOptions noFade;
    noFade.crossFade = 0.0;
    for (const double t : {0.25, 0.5, 0.75}) {
        const StrokeGroup mid = betweenDrawing(**made, t, noFade);
        const ObjectRegionsPtr regions = objectRegions(mid, closeGap);
        const int body = keepsItsRegion(mid, *regions, inBody, bodyArea, bodyColour, t);
        QVERIFY(body >= 0);
        const std::vector<int> shows = faceFills(*regions, mid.fills);
        // The tail's own region, in another colour.
        QPolygonF tail;
        for (const StrokePoint &p : mid.strokes[0].data->points)
            tail << pointOf(p);
        const int tailFace = regions->faceAt(tail.boundingRect().center());
        QVERIFY(tailFace >= 0 && tailFace != body && shows[std::size_t(tailFace)] >= 0);
        QVERIFY(mid.fills[std::size_t(shows[std::size_t(tailFace)])].color != bodyColour);
    }
}

void TestBetweenDrawings::aKeyTheAxesTurnOverIsFoundUpright()
{
    // tests/data/quickdraw_octopus_5005193466871808.json, posed by its automatic skeleton (each
    // limb turned 40° where it leaves the body, as finbook-bench between makes key B): one arm
    // swung down beside a leg, the other up. B's principal axes turn A half round, and the fit
    // from there (rigid ICP, the skeleton's starts) stayed upside down and was refused ("its
    // lines ... have nothing of the first key on them"). A sweep of turns finds it upright.
    QString error;
    const auto lines = testing::readDrawing(
        QStringLiteral(FINBOOK_SOURCE_DIR "/tests/data/quickdraw_octopus_5005193466871808.json"),
        &error);
    QVERIFY2(!lines.empty(), qPrintable(error));
    Document doc;
    const Id g = testing::drawingDocument(doc, lines);
    const StrokeGroup a = *doc.group(g);
    const double closeGap = doc.settings().closeGap;
    const Rig rig = testing::skeletonBend(a, closeGap, SkinningMode::Rigid, 40.0);
    QVERIFY(!rig.empty());
    QCOMPARE(testing::poseObject(doc, g, rig), QString());
    const StrokeGroup posed = *doc.group(g);
    QVERIFY(posed.isDeformed());
    // Key B: the posed lines redrawn, as the bench makes it (resampled, jittered, reversed,
    // shuffled, split), with the bench's seed for this drawing.
    const StrokeGroup b = testing::redrawnKey(
        posed, std::uint32_t(qHash(QStringLiteral("quickdraw_octopus_5005193466871808"))));
    const auto made = fitDrawings(a, b, closeGap);
    QVERIFY2(made, made ? "" : qPrintable(made.error()));
    const DrawingFit &fit = **made;
    // Each of A's points lands where the pose took it: median within 2 % of A's diagonal.
    const Eigen::MatrixX2d fitted =
        geometry::applyEmbedding(fit.meshed->embedding, fit.fit.U, fit.meshed->mesh.F);
    const QRectF box = testing::shownBounds(a);
    const double diagonal = std::hypot(box.width(), box.height());
    std::vector<double> errors;
    for (std::size_t s = 0; s < a.strokes.size(); ++s)
        for (std::size_t k = 0; k < posed.deformed->strokes[s].size(); ++k) {
            const StrokePoint &truth = posed.deformed->strokes[s][k];
            const Eigen::Index r = Eigen::Index(fit.meshed->strokeOffsets[s] + k);
            errors.push_back(std::hypot(fitted(r, 0) - truth.x, fitted(r, 1) - truth.y));
        }
    QVERIFY(!errors.empty());
    std::nth_element(errors.begin(), errors.begin() + std::ptrdiff_t(errors.size() / 2),
                     errors.end());
    const double median = errors[errors.size() / 2];
    QVERIFY2(median <= 0.02 * diagonal,
             qPrintable(QStringLiteral("%1 of %2").arg(median).arg(diagonal)));
}

void TestBetweenDrawings::inbetweensStartOnAAndLandOnB()
{
    const auto move = [](QPointF p) { return armTurned(p, 40.0) + QPointF(20, 0); };
    StrokeGroup a = keyA();
    Fill fill;
    fill.color = 0xff3060c0;
    fill.seed = QPointF(150, 200); // in the body
    fill.strokes = {2};
    a.fills.push_back(fill);
    const StrokeGroup b = keyB(move);
    const auto fitted = fitDrawings(a, b, -1.0);
    QVERIFY(fitted);
    const DrawingFit &fit = **fitted;
    // t = 0: A exactly, nothing of B.
    const StrokeGroup start = betweenDrawing(fit, 0.0);
    QCOMPARE(start.strokes.size(), a.strokes.size());
    for (std::size_t s = 0; s < a.strokes.size(); ++s) {
        QCOMPARE(start.strokes[s].id, a.strokes[s].id);
        QCOMPARE(start.strokes[s].data->color, a.strokes[s].data->color);
        for (std::size_t k = 0; k < a.strokes[s].data->points.size(); ++k)
            QVERIFY(QLineF(pointOf(start.strokes[s].data->points[k]),
                           pointOf(a.strokes[s].data->points[k]))
                        .length() < 1e-3);
    }
    // The fill is the body's, as Apply Pose ties it (its seed in the body, its outline's id).
    QCOMPARE(start.fills.size(), std::size_t(1));
    QCOMPARE(start.fills[0].color, fill.color);
    QVERIFY(
        std::binary_search(start.fills[0].strokes.begin(), start.fills[0].strokes.end(), Id(2)));
    // Before the cross-fade only A's drawing; in it A's lines fade out while B's drawing comes
    // in over it, and at the end B's lines are where B drew them.
    QVERIFY(!fadingInDrawing(fit, 0.6));
    const StrokeGroup fading = betweenDrawing(fit, 0.85);
    QCOMPARE(fading.strokes.size(), a.strokes.size());
    QVERIFY(qAlpha(fading.strokes[0].data->color) < 255 &&
            qAlpha(fading.strokes[0].data->color) > 0);
    QCOMPARE(fading.fills[0].color, fill.color); // under B's, as a dissolve
    const std::optional<StrokeGroup> in = fadingInDrawing(fit, 0.85);
    QVERIFY(in);
    QCOMPARE(in->strokes.size(), b.strokes.size());
    QVERIFY(qAlpha(in->strokes[0].data->color) < 255 && qAlpha(in->strokes[0].data->color) > 0);
    const std::optional<StrokeGroup> end = fadingInDrawing(fit, 1.0);
    QVERIFY(end);
    for (std::size_t s = 0; s < b.strokes.size(); ++s) {
        const Stroke &drawn = end->strokes[s];
        QCOMPARE(drawn.id, b.strokes[s].id);
        QCOMPARE(qAlpha(drawn.data->color), 255);
        for (std::size_t k = 0; k < drawn.data->points.size(); ++k)
            QVERIFY2(QLineF(pointOf(drawn.data->points[k]), pointOf(b.strokes[s].data->points[k]))
                             .length() < 0.05,
                     qPrintable(QStringLiteral("stroke %1 point %2").arg(s).arg(k)));
    }
    // The fill's seed rides in the body; every point of every in-between is finite.
    for (double t : {0.1, 0.3, 0.5, 0.7, 0.9, 0.99}) {
        const StrokeGroup g = betweenDrawing(fit, t);
        QVERIFY(std::isfinite(g.fills[0].seed.x()) && std::isfinite(g.fills[0].seed.y()));
        QVERIFY(g.fills[0].seed.x() > 90 && g.fills[0].seed.x() < 230);
        for (const Stroke &s : g.strokes)
            for (const StrokePoint &p : s.data->points)
                QVERIFY(std::isfinite(p.x) && std::isfinite(p.y));
    }
}

void TestBetweenDrawings::generatedInbetweensAreOneUndoStep()
{
    Document doc;
    doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
    doc.undoStack()->push(new InsertFrameCommand(&doc, 1));
    const Id ga = doc.frameAt(0).groups.at(0).id, gb = doc.frameAt(1).groups.at(0).id;
    for (const Stroke &s : keyA().strokes)
        doc.undoStack()->push(new AddStrokeCommand(&doc, ga, s.data));
    for (const Stroke &s : keyB([](QPointF p) { return armTurned(p, 40.0); }).strokes)
        doc.undoStack()->push(new AddStrokeCommand(&doc, gb, s.data));
    if (auto all = fillAllRegionsCommand(&doc, ga, 0xff3060c0))
        doc.undoStack()->push(all.release());
    QCOMPARE(doc.group(ga)->fills.size(), std::size_t(1));
    const QByteArray before = serializeFinbook(doc);
    const KeyFits fits = fitKeyDrawings(doc.frameAt(0), doc.frameAt(1), doc.settings().closeGap);
    QVERIFY2(fits.failures.empty(),
             qPrintable(fits.failures.empty() ? QString() : fits.failures[0].second));
    auto *command =
        new InsertInbetweensCommand(&doc, doc.frameAt(0).id, doc.frameAt(1).id, 3, {}, fits.fits);
    QCOMPARE(command->plan().objects.size(), std::size_t(1));
    QCOMPARE(command->plan().objects[0].fate, ObjectFate::Fitted);
    doc.undoStack()->push(command);
    QCOMPARE(doc.frameCount(), 5);
    // Editable strokes under fresh ids, the fill carried, the arm turning frame by frame.
    std::set<Id> ids;
    for (const Frame &f : doc.frames())
        for (const StrokeGroup &g : f.groups)
            for (const Stroke &s : g.strokes)
                QVERIFY(ids.insert(s.id).second);
    double previous = 0.0;
    for (int i = 1; i <= 3; ++i) {
        const StrokeGroup &g = doc.frameAt(i).groups.at(0);
        QVERIFY(g.rig.empty() && !g.deformed);
        QCOMPARE(g.fills.size(), std::size_t(1));
        QVERIFY(std::binary_search(g.fills[0].strokes.begin(), g.fills[0].strokes.end(),
                                   g.strokes[0].id));
        // The hand's lowest point, turned further down frame by frame.
        double lowest = 0.0;
        for (const StrokePoint &p : g.strokes[0].data->points)
            if (p.x > 300.0f)
                lowest = std::max(lowest, double(p.y));
        QVERIFY2(lowest > previous, qPrintable(QString::number(lowest)));
        previous = lowest;
    }
    // The last in-between (t = 0.75, in the cross-fade) shows the second key's drawing
    // fading in as an object of its own; the others only the first's.
    QCOMPARE(doc.frameAt(1).groups.size(), std::size_t(1));
    QCOMPARE(doc.frameAt(3).groups.size(), std::size_t(2));
    QVERIFY(qAlpha(doc.frameAt(3).groups[1].strokes[0].data->color) < 255);
    // The frames save and open again.
    const auto reopened = readFinbook(serializeFinbook(doc));
    QVERIFY2(reopened, reopened ? "" : qPrintable(reopened.error().message));
    doc.undoStack()->undo();
    QCOMPARE(doc.frameCount(), 2);
    QCOMPARE(serializeFinbook(doc), before);
    doc.undoStack()->redo();
    QCOMPARE(doc.frameCount(), 5);
}

QTEST_MAIN(TestBetweenDrawings)
#include "tst_between_drawings.moc"
