// Regions of drawings: faces of the strokes' arrangement, gap closing (threshold, direction,
// fingers kept apart), self-crossings, nesting, slivers, the object's shape, bad input.
#include "geometry_test_support.h"

#include <finbook/geometry/object_shape.h>
#include <finbook/geometry/regions.h>
#include <finbook/geometry/simplicity.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace finbook::geometry;

namespace {

Eigen::MatrixX2d arc(int n, double r, Eigen::RowVector2d c, double from, double to)
{
    Eigen::MatrixX2d points(n, 2);
    for (int i = 0; i < n; ++i) {
        const double t = from + (to - from) * i / (n - 1);
        points.row(i) = c + r * Eigen::RowVector2d(std::cos(t), std::sin(t));
    }
    return points;
}

Eigen::MatrixX2d polyline(std::initializer_list<std::pair<double, double>> points)
{
    return finbook::test::rows(points);
}

// A circle of radius r open by a chord of length `gap` around angle 0.
StrokeInput cShape(double r, double gap)
{
    const double half = std::asin(0.5 * gap / r);
    return {arc(181, r, {0, 0}, half, 2 * M_PI - half), 3.0};
}

// What every result promises: positive faces with finite seeds inside them, sorted strokes.
void checkRegions(const Regions &regions, int strokeCount)
{
    QVERIFY(std::isfinite(regions.closeGap));
    for (std::size_t i = 0; i < regions.faces.size(); ++i) {
        const Face &f = regions.faces[i];
        QVERIFY(f.area > 0.0 && std::isfinite(f.area));
        QVERIFY(f.polygon.outer.allFinite());
        QVERIFY(regionArea(Region{f.polygon}) > 0.0);
        QVERIFY(f.seed.allFinite());
        QCOMPARE(faceAt(regions, f.seed.x(), f.seed.y()), int(i));
        QVERIFY(std::is_sorted(f.strokes.begin(), f.strokes.end()));
        QVERIFY(std::adjacent_find(f.strokes.begin(), f.strokes.end()) == f.strokes.end());
        for (int s : f.strokes)
            QVERIFY(s >= 0 && s < strokeCount);
    }
    // A gap closure is at most the gap long; one that joins a mouth's two sides, twice that.
    const bool mouths = std::any_of(regions.closures.begin(), regions.closures.end(),
                                    [](const GapClosure &g) { return g.mouth; });
    for (const GapClosure &g : regions.closures) {
        QVERIFY(g.from.allFinite() && g.to.allFinite());
        QVERIFY(g.mouth ||
                (g.to - g.from).norm() <= (mouths ? 2.0 : 1.0) * regions.closeGap + 1e-9);
        QVERIFY(g.fromStroke >= 0 && g.fromStroke < strokeCount);
        QVERIFY(g.toStroke >= 0 && g.toStroke < strokeCount);
    }
}

Regions regionsOf(const std::vector<StrokeInput> &strokes, double closeGap = -1.0,
                  bool mouths = true)
{
    RegionsOptions options{closeGap};
    options.closeMouths = mouths;
    auto r = computeRegions(strokes, options);
    if (!r)
        qWarning("%s", r.error().message.c_str());
    return r ? *r : Regions{};
}

QString dataDir()
{
    const QByteArray env = qgetenv("FINBOOK_DATA_DIR");
    return env.isEmpty() ? QStringLiteral(FINBOOK_DATA_DIR) : QString::fromLocal8Bit(env);
}

} // namespace

class TestRegions : public QObject {
    Q_OBJECT
private slots:
    void closedCircleIsOneFace();
    void gapJustUnderThresholdCloses();
    void gapJustOverThresholdStaysOpen();
    void outlineOfSeveralShortStrokesCloses();
    void automaticGapClosesSmallOpening();
    void fingersSideBySideStayApart();
    void fingersInOneOutlineStayApart();
    void tubeRubbedAcrossStaysOneFace();
    void spiralMakesNoFaceWhenTurnsAreFar();
    void tightSpiralStaysFinite();
    void figureEightMakesTwoFaces();
    void strokeCrossingItselfMakesALoop();
    void crossingStrokesMakeFaces();
    void nestedFacesAreHoles();
    void overshootSliverIsMerged();
    void whiskerInsideClosedFaceIsNotJoined();
    void barEndIsNotSpentOnItsOwnStem();
    void closedGapsEndIsNotClosedAgain();
    void degenerateInput();
    void scribbleIsRefusedQuickly();
    void mittenOpenAtTheWristIsClosed();
    void treeOpenAtTheFootIsClosedWithItsCrown();
    void legsUnderABodyStayLines();
    void linesSpreadingFromABodyStayLines();
    void objectShapeOfTidyOutlineIsItsSilhouette();
    void objectShapeFillsGapWristedOutline();
    void objectShapeKeepsTheSlitBetweenFingers();
    void realSketches();
};

void TestRegions::closedCircleIsOneFace()
{
    Eigen::MatrixX2d ring = arc(91, 50, {0, 0}, 0, 2 * M_PI);
    const Regions r = regionsOf({{ring, 3.0}});
    checkRegions(r, 1);
    QCOMPARE(int(r.faces.size()), 1);
    QCOMPARE(r.freeEnds, 0);
    QVERIFY(r.closures.empty());
    QVERIFY(std::abs(r.faces[0].area - M_PI * 2500) < 0.02 * M_PI * 2500); // simplified
    QCOMPARE(r.faces[0].strokes, std::vector<int>{0});
    QVERIFY(r.faces[0].seed.norm() < 10.0); // far from the boundary: near the middle
}

void TestRegions::gapJustUnderThresholdCloses()
{
    const Regions r = regionsOf({cShape(50, 9.5)}, 10.0);
    checkRegions(r, 1);
    QCOMPARE(r.freeEnds, 2);
    QCOMPARE(int(r.closures.size()), 1);
    QCOMPARE(int(r.faces.size()), 1);
    QVERIFY(r.faces[0].area > 0.95 * M_PI * 2500);
    QCOMPARE(faceAt(r, 0, 0), 0);
}

void TestRegions::gapJustOverThresholdStaysOpen()
{
    const Regions r = regionsOf({cShape(50, 10.5)}, 10.0);
    checkRegions(r, 1);
    QCOMPARE(r.freeEnds, 2);
    QVERIFY(r.closures.empty());
    QVERIFY(r.faces.empty());
    QCOMPARE(faceAt(r, 0, 0), -1);
}

void TestRegions::outlineOfSeveralShortStrokesCloses()
{
    // A head drawn as four arcs that each stop 6 px short of the next (the cat in
    // ../shared/data/sketches): no one closure closes anything, the four together do.
    std::vector<StrokeInput> strokes;
    const double r = 50, gapAngle = 6.0 / r;
    for (int k = 0; k < 4; ++k) {
        const double from = k * M_PI / 2 + gapAngle / 2;
        strokes.push_back({arc(20, r, {0, 0}, from, from + M_PI / 2 - gapAngle), 3.0});
    }
    const Regions r4 = regionsOf(strokes, 10.0);
    checkRegions(r4, 4);
    QCOMPARE(r4.freeEnds, 8);
    QCOMPARE(int(r4.closures.size()), 4);
    QCOMPARE(int(r4.faces.size()), 1);
    QVERIFY(r4.faces[0].area > 0.95 * M_PI * r * r);
    QCOMPARE(faceAt(r4, 0, 0), 0);
    // One of the four gaps wider than the threshold: the ring stays open.
    strokes[0] = {arc(20, r, {0, 0}, 0.4, M_PI / 2 - gapAngle / 2), 3.0};
    const Regions open = regionsOf(strokes, 10.0);
    checkRegions(open, 4);
    QVERIFY(open.faces.empty());
}

void TestRegions::automaticGapClosesSmallOpening()
{
    // 6 % of a 100 px drawing's diagonal (141 px) is 8.5 px, at least 4 pen widths: 12 px.
    const std::vector<StrokeInput> strokes{cShape(50, 11.0)};
    QVERIFY(std::abs(autoCloseGap(strokes) - 12.0) < 1e-9);
    const Regions r = regionsOf(strokes);
    checkRegions(r, 1);
    QCOMPARE(int(r.faces.size()), 1);
    QVERIFY(regionsOf({cShape(50, 13.0)}).faces.empty());
}

void TestRegions::fingersSideBySideStayApart()
{
    // Two fingers drawn as separate upside-down U strokes, 4 px apart, open at the base.
    const auto finger = [](double x) {
        Eigen::MatrixX2d points(0, 2);
        Eigen::MatrixX2d tip = arc(31, 10, {x + 10, 10}, M_PI, 2 * M_PI);
        points.resize(tip.rows() + 2, 2);
        points.row(0) << x, 80;
        points.middleRows(1, tip.rows()) = tip.colwise().reverse();
        points.row(tip.rows() + 1) << x + 20, 80;
        return StrokeInput{points, 3.0};
    };
    const std::vector<StrokeInput> strokes{finger(0), finger(24)};
    const Regions r = regionsOf(strokes, 10.0);
    checkRegions(r, 2);
    QCOMPARE(r.freeEnds, 4);
    QCOMPARE(faceAt(r, 22, 40), -1); // between the fingers
    const int first = faceAt(r, 10, 40), second = faceAt(r, 34, 40);
    QVERIFY(first == -1 || first != second);
    for (const GapClosure &g : r.closures)
        QCOMPARE(g.fromStroke, g.toStroke); // never from one finger to the other
}

void TestRegions::fingersInOneOutlineStayApart()
{
    // One outline: palm, two fingers 3 px apart, open at the wrist by 8 px (under the gap).
    const Eigen::MatrixX2d outline = polyline({{46, 120},
                                               {0, 120},
                                               {0, 40},
                                               {0, 0},
                                               {20, 0},
                                               {20, 60},
                                               {23, 60},
                                               {23, 0},
                                               {43, 0},
                                               {43, 40},
                                               {43, 70},
                                               {54, 70},
                                               {54, 120}});
    const Regions r = regionsOf({{outline, 3.0}}, 10.0);
    checkRegions(r, 1);
    QCOMPARE(int(r.closures.size()), 1);
    QCOMPARE(int(r.faces.size()), 1);
    const int hand = faceAt(r, 10, 100);
    QVERIFY(hand >= 0);
    QCOMPARE(faceAt(r, 10, 20), hand); // the fingers belong to the hand
    QCOMPARE(faceAt(r, 33, 20), hand);
    QCOMPARE(faceAt(r, 21.5, 20), -1); // the slit between them stays open
}

void TestRegions::tubeRubbedAcrossStaysOneFace()
{
    // An arm drawn as one closed outline, 28 px wide, that the eraser rubbed across: two
    // U-shaped pieces whose ends face each other head-on over 12 px gaps. Each piece's mouth
    // (28 px, under the 30 px gap, but a turn of 90°) must not be closed before the two
    // head-on closures, which lie 28 px apart: closer than a gap, yet not two fingers.
    const Eigen::MatrixX2d upper = polyline({{94, 0}, {0, 0}, {0, 28}, {94, 28}});
    const Eigen::MatrixX2d lower = polyline({{106, 0}, {200, 0}, {200, 28}, {106, 28}});
    const Regions r = regionsOf({{upper, 3.0}, {lower, 3.0}}, 30.0);
    checkRegions(r, 2);
    QCOMPARE(int(r.faces.size()), 1);
    QCOMPARE(int(r.closures.size()), 2);
    const int arm = faceAt(r, 50, 14);
    QVERIFY(arm >= 0);
    QCOMPARE(faceAt(r, 100, 14), arm); // across the rub
    QCOMPARE(faceAt(r, 150, 14), arm);
    for (const GapClosure &g : r.closures)
        QVERIFY(g.fromStroke != g.toStroke); // from piece to piece, not across a mouth
}

void TestRegions::spiralMakesNoFaceWhenTurnsAreFar()
{
    Eigen::MatrixX2d spiral(600, 2);
    for (int i = 0; i < 600; ++i) {
        const double t = 6 * M_PI * i / 599.0, r = 5 + 20 * t / (2 * M_PI);
        spiral.row(i) << r * std::cos(t), r * std::sin(t);
    }
    const Regions r = regionsOf({{spiral, 3.0}}, 10.0);
    checkRegions(r, 1);
    QCOMPARE(r.freeEnds, 2);
    QVERIFY(r.faces.empty());
}

void TestRegions::tightSpiralStaysFinite()
{
    Eigen::MatrixX2d spiral(600, 2);
    for (int i = 0; i < 600; ++i) {
        const double t = 6 * M_PI * i / 599.0, r = 5 + 6 * t / (2 * M_PI);
        spiral.row(i) << r * std::cos(t), r * std::sin(t);
    }
    const Regions r = regionsOf({{spiral, 3.0}}, 10.0);
    checkRegions(r, 1);
    QVERIFY(r.faces.size() <= 2); // at most each end's loop closes
}

void TestRegions::figureEightMakesTwoFaces()
{
    Eigen::MatrixX2d eight(201, 2);
    for (int i = 0; i <= 200; ++i) {
        const double t = 2 * M_PI * i / 200.0;
        eight.row(i) << 60 * std::sin(t), 30 * std::sin(2 * t);
    }
    const Regions r = regionsOf({{eight, 3.0}});
    checkRegions(r, 1);
    QCOMPARE(r.freeEnds, 0);
    QCOMPARE(int(r.faces.size()), 2);
    QVERIFY(faceAt(r, 30, 0) >= 0);
    QVERIFY(faceAt(r, -30, 0) >= 0);
    QVERIFY(faceAt(r, 30, 0) != faceAt(r, -30, 0));
    QVERIFY(std::abs(r.faces[0].area - r.faces[1].area) < 0.02 * r.faces[0].area);
}

void TestRegions::strokeCrossingItselfMakesALoop()
{
    // An α: a tail, a loop through its own crossing, another tail far away.
    Eigen::MatrixX2d alpha(0, 2);
    const Eigen::MatrixX2d loop = arc(120, 30, {0, 0}, -0.75 * M_PI, 0.75 * M_PI);
    alpha.resize(loop.rows() + 2, 2);
    alpha.row(0) << -80, 60;
    alpha.middleRows(1, loop.rows()) = loop;
    alpha.row(loop.rows() + 1) << -80, -60;
    const Regions r = regionsOf({{alpha, 3.0}}, 10.0);
    checkRegions(r, 1);
    QCOMPARE(r.freeEnds, 2);
    QCOMPARE(int(r.faces.size()), 1);
    QCOMPARE(faceAt(r, 0, 0), 0);
}

void TestRegions::crossingStrokesMakeFaces()
{
    // A # of four strokes: one face in the middle (the outer cells are open).
    const std::vector<StrokeInput> hash{{polyline({{0, 30}, {100, 30}}), 3.0},
                                        {polyline({{0, 70}, {100, 70}}), 3.0},
                                        {polyline({{30, 0}, {30, 100}}), 3.0},
                                        {polyline({{70, 0}, {70, 100}}), 3.0}};
    const Regions r = regionsOf(hash, 10.0);
    checkRegions(r, 4);
    QCOMPARE(int(r.faces.size()), 1);
    QCOMPARE(r.faces[0].strokes, (std::vector<int>{0, 1, 2, 3}));
    QVERIFY(std::abs(r.faces[0].area - 1600.0) < 1e-6);
    QVERIFY(r.closures.empty());
}

void TestRegions::nestedFacesAreHoles()
{
    const std::vector<StrokeInput> rings{{arc(121, 60, {0, 0}, 0, 2 * M_PI), 3.0},
                                         {arc(61, 20, {0, 0}, 0, 2 * M_PI), 3.0}};
    const Regions r = regionsOf(rings);
    checkRegions(r, 2);
    QCOMPARE(int(r.faces.size()), 2);
    const int inner = faceAt(r, 0, 0), outer = faceAt(r, 40, 0);
    QVERIFY(inner >= 0 && outer >= 0 && inner != outer);
    QCOMPARE(int(r.faces[std::size_t(outer)].polygon.holes.size()), 1);
    QCOMPARE(r.faces[std::size_t(outer)].strokes, (std::vector<int>{0, 1}));
    QCOMPARE(r.faces[std::size_t(inner)].strokes, std::vector<int>{1});
    const double total = r.faces[0].area + r.faces[1].area;
    QVERIFY(std::abs(total - M_PI * 3600) < 0.01 * M_PI * 3600);
    QCOMPARE(faceAt(r, 100, 0), -1);
}

void TestRegions::overshootSliverIsMerged()
{
    // A closed outline whose end runs 20 px past its start, crossing it at a shallow angle.
    Eigen::MatrixX2d ring = arc(200, 50, {0, 0}, 0, 2 * M_PI + 0.4);
    for (Eigen::Index i = 0; i < ring.rows(); ++i)
        ring(i, 1) += 1.5 * double(i) / double(ring.rows()); // drift outward: a real crossing
    const Regions r = regionsOf({{ring, 3.0}});
    checkRegions(r, 1);
    QCOMPARE(int(r.faces.size()), 1);
    QVERIFY(r.faces[0].area > 0.95 * M_PI * 2500);
}

void TestRegions::whiskerInsideClosedFaceIsNotJoined()
{
    // A closed head with a short stroke inside it, 5 px from the outline: no closure.
    const std::vector<StrokeInput> strokes{{arc(121, 60, {0, 0}, 0, 2 * M_PI), 3.0},
                                           {polyline({{20, 0}, {55, 0}}), 3.0}};
    const Regions r = regionsOf(strokes, 10.0);
    checkRegions(r, 2);
    QVERIFY(r.closures.empty());
    QCOMPARE(int(r.faces.size()), 1);
}

void TestRegions::barEndIsNotSpentOnItsOwnStem()
{
    // A body drawn as an arch open at the bottom, and a leg drawn as a T whose bar nearly
    // spans the opening (a cat's belly in a real sketch): 40 px open on the left, 50 px on the
    // right. The bar's right end must close to the arch, not back along the bar onto the stem
    // it crosses (that encloses nothing and would leave the belly open).
    const std::vector<StrokeInput> strokes{
        {polyline({{0, 200}, {0, 100}, {300, 100}, {300, 200}}), 3.0},
        {polyline({{40, 200}, {145, 198}, {250, 203}}), 3.0},
        {polyline({{215, 190}, {215, 260}}), 3.0}};
    const Regions r = regionsOf(strokes, 60.0);
    checkRegions(r, 3);
    const int belly = faceAt(r, 150, 150);
    QVERIFY(belly >= 0);
    QVERIFY(std::abs(r.faces[std::size_t(belly)].area - 300.0 * 100.0) < 0.05 * 300.0 * 100.0);
    const auto onBar = [](const Eigen::Vector2d &p) {
        return std::abs(p.y() - 200.0) < 5.0 && p.x() > 35.0 && p.x() < 255.0;
    };
    for (const GapClosure &g : r.closures)
        QVERIFY2(!(onBar(g.from) && onBar(g.to)), "a closure lies along the bar");
}

// Issue 45: a 4 px gap in a body's outline closed, then a second closure ran from the gap's
// other end to the arm nearby, and Fill All filled the armpit wedge it made.
void TestRegions::closedGapsEndIsNotClosedAgain()
{
    StrokeInput body = cShape(50, 4.0);
    // The arm leaves the body above the gap and runs out to the right, 22 px from the gap.
    const StrokeInput arm{
        polyline({{50 * std::cos(0.5), -50 * std::sin(0.5)}, {140, -50 * std::sin(0.5)}}), 3.0};
    for (bool armFirst : {false, true}) {
        const std::vector<StrokeInput> strokes =
            armFirst ? std::vector<StrokeInput>{arm, body} : std::vector<StrokeInput>{body, arm};
        const Regions r = regionsOf(strokes, 30.0);
        checkRegions(r, 2);
        QCOMPARE(int(r.closures.size()), 1);
        QVERIFY((r.closures[0].to - r.closures[0].from).norm() < 5.0);
        QCOMPARE(int(r.faces.size()), 1); // the body, no wedge
        QVERIFY(r.faces[0].area > 0.95 * M_PI * 2500);
    }
}

void TestRegions::degenerateInput()
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto dot = computeRegions({{polyline({{5, 5}}), 3.0}});
    QVERIFY(dot);
    QVERIFY(dot->faces.empty());
    QCOMPARE(dot->freeEnds, 0);
    QCOMPARE(faceAt(*dot, 5, 5), -1);

    Eigen::MatrixX2d withNan = arc(91, 50, {0, 0}, 0, 2 * M_PI);
    withNan(10, 0) = nan;
    const auto survived = computeRegions({{withNan, 3.0}});
    QVERIFY(survived);
    checkRegions(*survived, 1);
    QCOMPARE(int(survived->faces.size()), 1);

    const auto allNan = computeRegions({{polyline({{nan, 1}, {2, nan}}), 3.0}});
    QVERIFY(!allNan);
    QCOMPARE(allNan.error().code, GeometryErrorCode::EmptyInput);
    QCOMPARE(computeRegions({}).error().code, GeometryErrorCode::EmptyInput);
    QCOMPARE(computeRegions({{polyline({{0, 0}, {2e6, 0}}), 3.0}}).error().code,
             GeometryErrorCode::CoordinateOutOfRange);
    QCOMPARE(computeRegions({{polyline({{0, 0}, {2, 0}}), nan}}).error().code,
             GeometryErrorCode::InvalidWidth);
    QCOMPARE(computeRegions({cShape(50, 5)}, RegionsOptions{nan}).error().code,
             GeometryErrorCode::InvalidOptions);

    // Huge but allowed coordinates, repeated points, zero width: defined results.
    Eigen::MatrixX2d far = arc(91, 5e5, {0, 0}, 0, 2 * M_PI) * 1.9;
    const auto huge = computeRegions({{far, 0.0}, {polyline({{1, 1}, {1, 1}, {1, 1}}), 0.0}});
    QVERIFY(huge);
    checkRegions(*huge, 2);
    QCOMPARE(int(huge->faces.size()), 1);
    const auto line = computeRegions({{polyline({{0, 0}, {10, 0}, {0, 0}, {10, 0}}), 3.0}});
    QVERIFY(line);
    QVERIFY(line->faces.empty());
}

void TestRegions::scribbleIsRefusedQuickly()
{
    // Hundreds of long random strokes cross each other hundreds of thousands of times.
    std::vector<StrokeInput> strokes;
    unsigned state = 7;
    const auto next = [&] { return double((state = state * 1103515245u + 12345u) >> 8 & 1023); };
    for (int s = 0; s < 300; ++s) {
        Eigen::MatrixX2d points(12, 2);
        for (Eigen::Index i = 0; i < points.rows(); ++i)
            points.row(i) << next(), next();
        strokes.push_back({points, 2.0});
    }
    const auto r = computeRegions(strokes);
    QVERIFY(!r);
    QCOMPARE(r.error().code, GeometryErrorCode::TooManyPoints);
    const auto shape = objectShape(strokes);
    const auto bands = silhouette(strokes);
    QVERIFY(shape && bands);
    QCOMPARE(regionArea(*shape), regionArea(*bands)); // the ink alone, as before regions
}

int mouthCount(const Regions &r)
{
    return int(std::count_if(r.closures.begin(), r.closures.end(),
                             [](const GapClosure &g) { return g.mouth; }));
}

void TestRegions::mittenOpenAtTheWristIsClosed()
{
    // A mitten drawn as one line, open at the wrist by 50 px, five times the gap.
    const Eigen::MatrixX2d outline = polyline(
        {{0, 150}, {0, 20}, {10, 0}, {40, 0}, {50, 20}, {50, 90}, {70, 70}, {80, 80}, {50, 150}});
    const Regions r = regionsOf({{outline, 3.0}}, 10.0);
    checkRegions(r, 1);
    QCOMPARE(int(r.faces.size()), 1);
    QCOMPARE(mouthCount(r), 1);
    QVERIFY((r.closures[0].from - Eigen::Vector2d(0, 150)).norm() < 1e-6 ||
            (r.closures[0].to - Eigen::Vector2d(0, 150)).norm() < 1e-6);
    QVERIFY(faceAt(r, 25, 140) >= 0); // just inside the wrist
    QVERIFY(faceAt(r, 60, 85) >= 0);  // the thumb
    QVERIFY(r.faces[0].area > 0.95 * (50 * 150 - 2 * 100 + 400));
    const auto shape = objectShape({{outline, 3.0}}, {}, RegionsOptions{10.0});
    QVERIFY(shape && regionContains(*shape, 25, 75));
    // The setting turns it off, as "don't close gaps" turns every closure off.
    QVERIFY(regionsOf({{outline, 3.0}}, 10.0, false).faces.empty());
    QVERIFY(regionsOf({{outline, 3.0}}, 0.0).faces.empty());
    // Drawn in one line flaring out at the wrist (each end leans 135° away from the other
    // across the mouth), the hand is still closed.
    const Eigen::MatrixX2d flared = polyline(
        {{-20, 170}, {0, 150}, {0, 20}, {10, 0}, {70, 0}, {80, 20}, {80, 150}, {100, 170}});
    const Regions r2 = regionsOf({{flared, 3.0}}, 10.0);
    checkRegions(r2, 1);
    QCOMPARE(mouthCount(r2), 1);
    QVERIFY(faceAt(r2, 40, 160) >= 0);
}

void TestRegions::treeOpenAtTheFootIsClosedWithItsCrown()
{
    // A crown drawn as one arc whose ends meet the tops of the trunk's two lines, the trunk
    // open at the foot and flaring a little (each side leans ~8° out): the whole tree is
    // one body. The crown's right end stops 14 px short of its trunk line, more than the gap
    // (10 px): alone it would close nothing; with the mouth it closes the tree.
    const double r = std::hypot(15.0, 55.0), top = std::atan2(-55.0, 15.0);
    const Eigen::MatrixX2d crown =
        arc(60, r, {0, -60}, M_PI + top, 2 * M_PI - top - 14.0 / r); // (−15, −5) over the top
    const std::vector<StrokeInput> tree{{crown, 3.0},
                                        {polyline({{-15, -5}, {-30, 100}}), 3.0},
                                        {polyline({{15, -5}, {30, 100}}), 3.0}};
    const Regions closed = regionsOf(tree, 10.0);
    checkRegions(closed, 3);
    QCOMPARE(int(closed.faces.size()), 1);
    QCOMPARE(mouthCount(closed), 1);
    const int body = faceAt(closed, 0, 60);
    QVERIFY(body >= 0);
    QCOMPARE(faceAt(closed, 0, -60), body);
    QVERIFY(regionsOf(tree, 10.0, false).faces.empty());
}

void TestRegions::legsUnderABodyStayLines()
{
    // A closed body with two legs drawn as lines from its underside, 40 px apart: the space
    // between them is no shape, whatever the gap.
    const std::vector<StrokeInput> animal{
        {arc(90, 40, {0, 0}, 0, 2 * M_PI) * Eigen::DiagonalMatrix<double, 2>(2.0, 1.0), 3.0},
        {polyline({{-20, 38.7}, {-20, 110}}), 3.0},
        {polyline({{20, 38.7}, {20, 110}}), 3.0}};
    const Regions r = regionsOf(animal, 10.0);
    checkRegions(r, 3);
    QCOMPARE(mouthCount(r), 0);
    QCOMPARE(faceAt(r, 0, 80), -1);
    QVERIFY(faceAt(r, 0, 0) >= 0);
}

void TestRegions::linesSpreadingFromABodyStayLines()
{
    // Two legs drawn as separate lines from one hip point, spreading ~17° each way (a stick
    // figure's legs under a big round body): chained end to end, but they spread apart and
    // hold little of the drawing's ink. Drawn as one line turned back on itself (a fish's
    // tail), the same wedge closes.
    const StrokeInput body{arc(120, 80, {0, -80}, 0, 2 * M_PI), 3.0};
    const Regions legs = regionsOf(
        {body, {polyline({{0, 0}, {-25, 80}}), 3.0}, {polyline({{0, 0}, {25, 80}}), 3.0}}, 10.0);
    checkRegions(legs, 3);
    QCOMPARE(mouthCount(legs), 0);
    QCOMPARE(faceAt(legs, 0, 60), -1);
    const Regions tail = regionsOf({body, {polyline({{-25, 80}, {0, 0}, {25, 80}}), 3.0}}, 10.0);
    checkRegions(tail, 2);
    QCOMPARE(mouthCount(tail), 1);
    QVERIFY(faceAt(tail, 0, 60) >= 0);
}

void TestRegions::objectShapeOfTidyOutlineIsItsSilhouette()
{
    const std::vector<StrokeInput> strokes{{arc(91, 50, {0, 0}, 0, 2 * M_PI), 3.0}};
    const auto shape = objectShape(strokes);
    const auto bands = silhouette(strokes);
    QVERIFY(shape && bands);
    QCOMPARE(int(shape->size()), int(bands->size()));
    QCOMPARE(shape->front().outer, bands->front().outer);
}

void TestRegions::objectShapeFillsGapWristedOutline()
{
    // Open by 11 px: today's 8 px closing leaves a ring, the automatic 12 px gap closes it.
    const std::vector<StrokeInput> strokes{cShape(50, 11.0)};
    const auto shape = objectShape(strokes);
    const auto ink = silhouette(strokes, {0.0, 0.0, HoleMode::KeepHoles, 0.4});
    QVERIFY(shape && ink);
    QVERIFY(isSimple(*shape, Touching::AllowedAtPoints));
    QVERIFY(regionArea(*shape) > 3.0 * regionArea(*ink));
    QVERIFY(regionContains(*shape, 0, 0));
    for (Eigen::Index i = 0; i < strokes[0].points.rows(); i += 10)
        QVERIFY(regionContains(*shape, strokes[0].points(i, 0), strokes[0].points(i, 1)));
}

void TestRegions::objectShapeKeepsTheSlitBetweenFingers()
{
    // One closed outline: a palm and two long fingers whose sides are 12 px apart, so the
    // silhouette's 8 px closing fills the slit between them (5 px between the bands). The
    // object's shape keeps it open, as the fill does: fingers, tentacles and coils turn apart.
    const Eigen::MatrixX2d outline = polyline(
        {{0, 260}, {0, 0}, {30, 0}, {30, 160}, {42, 160}, {42, 0}, {72, 0}, {72, 260}, {0, 260}});
    const std::vector<StrokeInput> hand{{outline, 3.0}};
    const auto shape = objectShape(hand);
    const auto closed = silhouette(hand);
    QVERIFY(shape && closed);
    QVERIFY(regionContains(*closed, 36, 80)); // the closing filled the slit...
    QVERIFY(!regionContains(*shape, 36, 80)); // ...the shape does not
    QVERIFY(!regionContains(*shape, 36, 10));
    QVERIFY(regionContains(*shape, 15, 80) && regionContains(*shape, 57, 80));
    QVERIFY(regionContains(*shape, 36, 200)); // the palm
    QVERIFY(isSimple(*shape, Touching::AllowedAtPoints));
    QCOMPARE(int(shape->size()), 1);
    for (Eigen::Index i = 0; i < outline.rows(); ++i)
        QVERIFY(regionContains(*shape, outline(i, 0), outline(i, 1)));
    // Two separate strokes as far apart are still bridged: the closing joins two parts.
    const std::vector<StrokeInput> pair{{polyline({{30, 0}, {30, 160}}), 3.0},
                                        {polyline({{42, 0}, {42, 160}}), 3.0}};
    const auto bridged = objectShape(pair);
    QVERIFY(bridged);
    QVERIFY(regionContains(*bridged, 36, 80));
    QCOMPARE(int(bridged->size()), 1);
    // A slit a stroke's free end reaches into stays filled (a sketchy line drawn over the
    // palm and stopping in the slit: the sliver beside an overshoot).
    std::vector<StrokeInput> sketchy = hand;
    sketchy.push_back({polyline({{36, 240}, {36, 150}}), 3.0});
    const auto kept = objectShape(sketchy);
    QVERIFY(kept);
    QVERIFY(regionContains(*kept, 36, 80));
}

void TestRegions::realSketches()
{
    const QDir dir(dataDir() + QStringLiteral("/sketches"));
    const QStringList files = dir.entryList({QStringLiteral("*.json")}, QDir::Files);
    if (files.isEmpty())
        QSKIP("shared/data/sketches is not available (set FINBOOK_DATA_DIR)");
    for (const QString &name : files) {
        QFile file(dir.filePath(name));
        QVERIFY(file.open(QIODevice::ReadOnly));
        std::vector<StrokeInput> strokes;
        const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
        for (const QJsonValue &stroke : json.value(QStringLiteral("strokes")).toArray())
            strokes.push_back({finbook::test::toMatrix(stroke.toArray()), 3.0});
        const auto r = computeRegions(strokes);
        QVERIFY2(r, qPrintable(name));
        checkRegions(*r, int(strokes.size()));
        const auto shape = objectShape(strokes);
        QVERIFY2(shape, qPrintable(name));
        QVERIFY(isSimple(*shape, Touching::AllowedAtPoints));
    }
}

QTEST_APPLESS_MAIN(TestRegions)
#include "tst_regions.moc"
