// finbook-bench bake [--png DIR [--faces]] [--rig NAME] FILE...: what you see is what you
// keep. For each drawing (Quick, Draw! "strokes" or a shape's "contours", shared/data/README.md;
// pen 3 px): Fill All, each fill then recoloured apart (so a fill that moves to another region
// shows), then for each rig kind and skinning (pins: the arap --quality bend, the right end turned
// 60° round the held left end; cage: Fit Cage with two opposite corners moved out; skeleton: the
// automatic one, every limb turned ±60° at its base, in each skinning) pose it, render the posed
// object as the app draws it, Apply Pose to Drawing, render again. One JSON object per drawing and
// rig: agree_pct (the share of the drawing's pixels whose colour agrees, each channel within 8/255;
// a pixel on a colour edge in both pictures, the anti-aliased rim, is left out), filled_px before
// and after (fills alone), fills before and after, how many fills own a face of the regions
// (fills_shown: a fill may own only faces that show nothing, a zero-area face or one under another
// fill), and how many show on the picture (fills_visible: each fill has a colour of its own; more
// than 12 px of it; fills_appeared_or_vanished: fills on more than 12 px in one picture and not in
// the other, the two more than 6 px apart), and the filled area as the picture shows it
// (shown_filled_px before and after, shown_filled_change_pct: the fills' colours, so no fill under
// ink).
// A last line per rig kind sums up: bake_agree_pct_min and bake_agree_pct_median, the worst
// drawing, the largest filled-area change (fills alone, and as shown), how many drawings changed
// their fill count (faces owned: shown_fill_count_changed; on the picture, a fill appeared or
// vanished: visible_fill_count_changed), how many meet all three targets (meets_all_targets:
// agreement ≥ 99.5 %, filled area within 0.5 %, the same fills on the picture), and Apply Pose's
// own time (apply_ms per drawing; median and max, on the UI thread in the app).
// --png writes, per drawing and rig, the posed picture, the baked one and the differences;
// --rig pins|cage|skeleton_rigid|skeleton_blend|skeleton_cut_out measures that one alone;
// --faces outlines the baked drawing's faces (green) and gap closures (magenta) on the
// differences, and adds a fourth picture: the fills alone, under the lines too, before and
// after (grey kept, red lost, blue gained: what filled_change_pct counts).
#include "../model/bake_support.h"
#include "bench.h"

#include <finbook/model/cage/cage_setup.h>
#include <finbook/model/commands.h>
#include <finbook/model/deform_setup.h>
#include <finbook/model/document.h>
#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/fill/fill_regions.h>
#include <finbook/model/fill/fill_render.h>
#include <finbook/model/fill/fill_resolve.h>
#include <finbook/model/render.h>
#include <finbook/model/rig/rig_commands.h>
#include <finbook/model/skeleton/skeleton_commands.h>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

using namespace finbook::model;
using finbook::testing::drawingDocument;
using finbook::testing::readDrawing;
using finbook::testing::skeletonBend;

namespace {

constexpr int kPicture = 640;    // the longer side of the compared pictures, px
constexpr double kTurn = 60.0;   // degrees: the pins' bend and each limb's turn
constexpr double kCageOut = 0.2; // the two cage corners move out by this share of the size

QPointF turned(QPointF p, QPointF about, double degrees)
{
    const double a = degrees * std::numbers::pi / 180.0;
    const QPointF d = p - about;
    return about + QPointF(std::cos(a) * d.x() - std::sin(a) * d.y(),
                           std::sin(a) * d.x() + std::cos(a) * d.y());
}

// Pins on the stroke points of the left and right 6 % of the drawing (at most 8 each, spread
// along it); the right ones turned round the left ones' centroid.
Rig pinBend(const StrokeGroup &group)
{
    const QRectF box = finbook::testing::shownBounds(group);
    std::vector<QPointF> left, right;
    for (const Stroke &s : group.strokes)
        for (const StrokePoint &p : s.data->points) {
            if (p.x <= box.left() + 0.06 * box.width())
                left.emplace_back(p.x, p.y);
            else if (p.x >= box.right() - 0.06 * box.width())
                right.emplace_back(p.x, p.y);
        }
    const auto spread = [](const std::vector<QPointF> &all) {
        std::vector<QPointF> out;
        const std::size_t step = std::max<std::size_t>(1, all.size() / 8);
        for (std::size_t i = 0; i < all.size() && out.size() < 8; i += step)
            out.push_back(all[i]);
        return out;
    };
    left = spread(left);
    right = spread(right);
    Rig rig;
    if (left.empty() || right.empty())
        return rig;
    QPointF centre;
    for (const QPointF &p : left)
        centre += p / double(left.size());
    Id id = 1;
    for (const QPointF &p : left)
        rig.pins.push_back({id++, p, p});
    for (const QPointF &p : right)
        rig.pins.push_back({id++, p, turned(p, centre, kTurn)});
    return rig;
}

Rig cageBend(const StrokeGroup &group, double closeGap)
{
    Rig rig;
    const auto corners = fitCage(group, kDefaultFitCageCorners, closeGap);
    if (!corners || corners->size() < 4)
        return rig;
    rig.cage.rest = *corners;
    rig.cage.posed = *corners;
    QPointF centre;
    for (const QPointF &p : *corners)
        centre += p / double(corners->size());
    const QRectF box = finbook::testing::shownBounds(group);
    const double out = kCageOut * std::max(box.width(), box.height());
    for (std::size_t k : {std::size_t(0), corners->size() / 2}) {
        QPointF &p = rig.cage.posed[k];
        const QPointF d = p - centre;
        const double length = std::hypot(d.x(), d.y());
        if (length > 0)
            p += d * (out / length);
    }
    return rig;
}

int shownFills(const StrokeGroup &group, double closeGap)
{
    const auto regions = objectRegions(group, closeGap);
    const std::vector<int> owners = faceFills(*regions, group.fills);
    std::vector<bool> seen(group.fills.size(), false);
    for (int f : owners)
        if (f >= 0)
            seen[std::size_t(f)] = true;
    return int(std::count(seen.begin(), seen.end(), true));
}

// A fill shown on fewer pixels of the compared pictures is a speck (as tst_pose_bake's).
constexpr long long kSpeck = 12;

// The fills as `picture` shows them (each fill has a colour of its own): how many show on more
// than a speck, the pixels of their colours (the filled area the eye sees: none under ink), and
// the pixels of each of `colours`.
struct VisibleFills {
    int count = 0;
    long long pixels = 0;
    std::vector<long long> perColour;
};

std::vector<QRgb> fillColours(const std::vector<Fill> &fills)
{
    std::vector<QRgb> colours;
    for (const Fill &fill : fills)
        if (std::find(colours.begin(), colours.end(), fill.color) == colours.end())
            colours.push_back(fill.color);
    return colours;
}

// Fills that one picture shows and the other does not: more than a speck on one, a speck or
// nothing on the other, and more than half a speck apart (a fill on 12 px before and 13 after is
// the same speck, not a fill that appeared).
int fillsAppearedOrVanished(const VisibleFills &before, const VisibleFills &after)
{
    int changed = 0;
    for (std::size_t c = 0; c < before.perColour.size() && c < after.perColour.size(); ++c) {
        const long long a = before.perColour[c], b = after.perColour[c];
        changed += (a > kSpeck) != (b > kSpeck) && std::abs(a - b) > kSpeck / 2;
    }
    return changed;
}

VisibleFills visibleFills(const std::vector<QRgb> &colours, const QImage &picture)
{
    std::vector<long long> pixels(colours.size(), 0);
    for (int y = 0; y < picture.height(); ++y) {
        const auto *row = reinterpret_cast<const QRgb *>(picture.constScanLine(y));
        for (int x = 0; x < picture.width(); ++x)
            for (std::size_t c = 0; c < colours.size(); ++c)
                if (finbook::testing::sameColour(row[x], colours[c])) {
                    ++pixels[c];
                    break;
                }
    }
    VisibleFills out;
    out.count =
        int(std::count_if(pixels.begin(), pixels.end(), [](long long n) { return n > kSpeck; }));
    for (long long n : pixels)
        out.pixels += n;
    out.perColour = std::move(pixels);
    return out;
}

// Two pictures of the fills alone (black on white) compared, a pixel filled as darkPixels counts
// it: grey where both are filled, red where only `before` is, blue where only `after` is.
QImage fillsDifference(const QImage &before, const QImage &after)
{
    QImage out(before.size(), QImage::Format_RGB32);
    out.fill(Qt::white);
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x) {
            const bool a = qRed(before.pixel(x, y)) < 128, b = qRed(after.pixel(x, y)) < 128;
            if (a && b)
                out.setPixel(x, y, qRgb(200, 200, 200));
            else if (a)
                out.setPixel(x, y, qRgb(230, 0, 0));
            else if (b)
                out.setPixel(x, y, qRgb(0, 60, 255));
        }
    return out;
}

struct Case {
    const char *name;
    RigKind kind;
    SkinningMode mode;
};
constexpr Case kCases[] = {
    {"pins", RigKind::Pins, SkinningMode::Rigid},
    {"cage", RigKind::Cage, SkinningMode::Rigid},
    {"skeleton_rigid", RigKind::Skeleton, SkinningMode::Rigid},
    {"skeleton_blend", RigKind::Skeleton, SkinningMode::LinearBlend},
    {"skeleton_cut_out", RigKind::Skeleton, SkinningMode::CutOut},
};

void print(const QJsonObject &row)
{
    std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
    std::fflush(stdout);
}

struct Summary {
    std::vector<double> agree;
    QString worst;
    double worstPct = 101.0;
    double maxAreaChangePct = 0.0;
    double maxShownAreaChangePct = 0.0;
    int meetsAll = 0;
    std::vector<double> applyMs; // Apply Pose's own time per drawing
    int fillCountChanged = 0;
    int visibleCountChanged = 0;
    int failed = 0;
};

QJsonObject bakeOne(const QString &file, const std::vector<std::vector<QPointF>> &lines,
                    const Case &c, const QString &pngDir, bool showFaces, Summary &summary)
{
    QJsonObject row{{QStringLiteral("bench"), QStringLiteral("bake")},
                    {QStringLiteral("file"), QFileInfo(file).fileName()},
                    {QStringLiteral("rig"), QLatin1String(c.name)}};
    Document doc;
    const Id g = drawingDocument(doc, lines);
    const double closeGap = doc.settings().closeGap;
    const StrokeGroup &group = *doc.group(g);
    row.insert(QStringLiteral("fills_made"), int(group.fills.size()));
    if (group.fills.empty()) {
        row.insert(QStringLiteral("skipped"), QStringLiteral("no region to fill"));
        return row;
    }
    const Rig rig = c.kind == RigKind::Pins   ? pinBend(group)
                    : c.kind == RigKind::Cage ? cageBend(group, closeGap)
                                              : skeletonBend(group, closeGap, c.mode, kTurn);
    const QString error = rig.empty() ? QString() : finbook::testing::poseObject(doc, g, rig);
    if (rig.empty() || !error.isEmpty()) {
        row.insert(QStringLiteral("error"), rig.empty() ? QStringLiteral("no rig") : error);
        ++summary.failed;
        return row;
    }
    using finbook::testing::framePicture;
    const QTransform t = finbook::testing::pictureView(
        finbook::testing::shownBounds(*doc.group(g)).adjusted(-5, -5, 5, 5), kPicture);
    const QImage posed = framePicture(doc, 0, t, kPicture);
    const QImage fillsPosed = framePicture(doc, 0, t, kPicture, true);
    const long long filledBefore = finbook::testing::darkPixels(fillsPosed);
    const int fillsBefore = int(doc.group(g)->fills.size());
    const int shownBefore = shownFills(*doc.group(g), closeGap);
    const std::vector<QRgb> colours = fillColours(doc.group(g)->fills);
    const VisibleFills visibleBefore = visibleFills(colours, posed);
    QElapsedTimer clock;
    clock.start();
    doc.undoStack()->push(new ApplyPoseCommand(&doc, g));
    const double applyMs = double(clock.nsecsElapsed()) / 1e6;
    const QImage baked = framePicture(doc, 0, t, kPicture);
    const QImage fillsBaked = framePicture(doc, 0, t, kPicture, true);
    const long long filledAfter = finbook::testing::darkPixels(fillsBaked);
    const finbook::testing::PictureAgreement cmp = finbook::testing::comparePictures(posed, baked);
    const int fillsAfter = int(doc.group(g)->fills.size());
    const int shownAfter = shownFills(*doc.group(g), closeGap);
    const VisibleFills visibleAfter = visibleFills(colours, baked);
    const int fillsChanged = fillsAppearedOrVanished(visibleBefore, visibleAfter);
    const double areaChange =
        filledBefore > 0 ? 100.0 * double(filledAfter - filledBefore) / double(filledBefore) : 0.0;
    row.insert(QStringLiteral("agree_pct"), cmp.agreePct);
    row.insert(QStringLiteral("filled_px_before"), double(filledBefore));
    row.insert(QStringLiteral("filled_px_after"), double(filledAfter));
    row.insert(QStringLiteral("filled_change_pct"), areaChange);
    row.insert(QStringLiteral("fills_before"), fillsBefore);
    row.insert(QStringLiteral("fills_after"), fillsAfter);
    row.insert(QStringLiteral("fills_shown_before"), shownBefore);
    row.insert(QStringLiteral("fills_shown_after"), shownAfter);
    row.insert(QStringLiteral("fills_visible_before"), visibleBefore.count);
    row.insert(QStringLiteral("fills_visible_after"), visibleAfter.count);
    row.insert(QStringLiteral("fills_appeared_or_vanished"), fillsChanged);
    const double shownAreaChange =
        visibleBefore.pixels > 0 ? 100.0 * double(visibleAfter.pixels - visibleBefore.pixels) /
                                       double(visibleBefore.pixels)
                                 : 0.0;
    row.insert(QStringLiteral("shown_filled_px_before"), double(visibleBefore.pixels));
    row.insert(QStringLiteral("shown_filled_px_after"), double(visibleAfter.pixels));
    row.insert(QStringLiteral("shown_filled_change_pct"), shownAreaChange);
    row.insert(QStringLiteral("apply_ms"), applyMs);
    summary.applyMs.push_back(applyMs);
    summary.agree.push_back(cmp.agreePct);
    if (cmp.agreePct < summary.worstPct) {
        summary.worstPct = cmp.agreePct;
        summary.worst = QFileInfo(file).fileName();
    }
    summary.maxAreaChangePct = std::max(summary.maxAreaChangePct, std::abs(areaChange));
    summary.fillCountChanged += shownBefore != shownAfter;
    summary.visibleCountChanged += fillsChanged > 0;
    summary.maxShownAreaChangePct =
        std::max(summary.maxShownAreaChangePct, std::abs(shownAreaChange));
    // The three targets: agreement, filled area (under ink too) and the same fills.
    summary.meetsAll += cmp.agreePct >= 99.5 && std::abs(areaChange) <= 0.5 && fillsChanged == 0;
    if (!pngDir.isEmpty()) {
        const int panels = showFaces ? 4 : 3;
        QImage sheet(panels * kPicture, kPicture, QImage::Format_RGB32);
        sheet.fill(Qt::white);
        QPainter painter(&sheet);
        painter.drawImage(0, 0, posed);
        painter.drawImage(kPicture, 0, baked);
        painter.drawImage(2 * kPicture, 0, cmp.difference);
        // The lines of no ink Apply Pose added (gap and cut closers), in blue over the
        // differences: where the baked regions end without a drawn line.
        painter.save();
        painter.setClipRect(2 * kPicture, 0, kPicture, kPicture);
        painter.translate(2 * kPicture, 0);
        painter.setTransform(t, true);
        painter.setPen(QPen(QColor(0, 90, 255), 0.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter.setRenderHint(QPainter::Antialiasing);
        for (const Stroke &s : doc.group(g)->strokes) {
            if (!s.data || qAlpha(s.data->color) != 0 || s.data->points.size() < 2)
                continue;
            QPolygonF line;
            for (const auto &p : s.data->points)
                line << QPointF(p.x, p.y);
            painter.drawPolyline(line);
        }
        if (showFaces) { // the baked drawing's faces, outlined in green, with their seeds
            const auto regions = objectRegions(*doc.group(g), closeGap);
            painter.setPen(QPen(QColor(0, 160, 0), 0.0));
            for (const auto &face : regions->regions().faces) {
                const auto ring = [&](const Eigen::MatrixX2d &m) {
                    QPolygonF poly;
                    for (Eigen::Index r = 0; r < m.rows(); ++r)
                        poly << QPointF(m(r, 0), m(r, 1));
                    painter.drawPolygon(poly);
                };
                ring(face.polygon.outer);
                for (const auto &hole : face.polygon.holes)
                    ring(hole);
                painter.drawEllipse(QPointF(face.seed.x(), face.seed.y()), 2.0, 2.0);
            }
            painter.setPen(QPen(QColor(220, 0, 220), 0.0)); // its gap closures, magenta
            for (const auto &closure : regions->regions().closures)
                painter.drawLine(QPointF(closure.from.x(), closure.from.y()),
                                 QPointF(closure.to.x(), closure.to.y()));
        }
        painter.restore();
        if (showFaces) // the fills alone (under the lines too): grey kept, red lost, blue gained
            painter.drawImage(3 * kPicture, 0, fillsDifference(fillsPosed, fillsBaked));
        painter.setPen(Qt::black);
        painter.drawText(
            QRectF(5, 2, panels * kPicture, 20),
            QStringLiteral("%1 %2: posed | applied | differences (%3 %)%4")
                .arg(QFileInfo(file).completeBaseName(), QLatin1String(c.name))
                .arg(cmp.agreePct, 0, 'f', 2)
                .arg(showFaces ? QStringLiteral(" | fills alone (%1 %)").arg(areaChange, 0, 'f', 2)
                               : QString()));
        painter.end();
        sheet.save(QDir(pngDir).filePath(QFileInfo(file).completeBaseName() + QLatin1Char('_') +
                                         QLatin1String(c.name) + QStringLiteral(".png")));
    }
    return row;
}

int benchBake(const QStringList &argsIn)
{
    QStringList args = argsIn;
    QString pngDir, onlyRig;
    bool showFaces = false;
    while (args.size() >= 2 && args[0].startsWith(QLatin1String("--"))) {
        if (args[0] == QLatin1String("--faces")) {
            showFaces = true;
            args = args.mid(1);
            continue;
        }
        if (args[0] == QLatin1String("--png")) {
            pngDir = args[1];
            QDir().mkpath(pngDir);
        } else if (args[0] == QLatin1String("--rig")) {
            onlyRig = args[1];
            if (std::none_of(std::begin(kCases), std::end(kCases),
                             [&](const Case &c) { return onlyRig == QLatin1String(c.name); })) {
                std::fprintf(stderr, "bake: no rig called %s\n", qPrintable(onlyRig));
                return 2;
            }
        } else {
            break;
        }
        args = args.mid(2);
    }
    const auto wanted = [&](const Case &c) {
        return onlyRig.isEmpty() || onlyRig == QLatin1String(c.name);
    };
    if (args.isEmpty()) {
        std::fprintf(stderr, "bake: no drawing given\n");
        return 2;
    }
    std::map<std::string, Summary> summaries;
    int unreadable = 0;
    for (const QString &file : args) {
        QString error;
        const auto lines = readDrawing(file, &error);
        if (!error.isEmpty()) {
            print({{QStringLiteral("bench"), QStringLiteral("bake")},
                   {QStringLiteral("file"), file},
                   {QStringLiteral("error"), error}});
            ++unreadable;
            continue;
        }
        for (const Case &c : kCases)
            if (wanted(c))
                print(bakeOne(file, lines, c, pngDir, showFaces, summaries[c.name]));
    }
    for (const Case &c : kCases) {
        if (!wanted(c))
            continue;
        const Summary &s = summaries[c.name];
        QJsonObject row{{QStringLiteral("bench"), QStringLiteral("bake_summary")},
                        {QStringLiteral("rig"), QLatin1String(c.name)},
                        {QStringLiteral("drawings"), int(s.agree.size())},
                        {QStringLiteral("failed"), s.failed}};
        if (!s.agree.empty()) {
            row.insert(QStringLiteral("bake_agree_pct_min"),
                       *std::min_element(s.agree.begin(), s.agree.end()));
            row.insert(QStringLiteral("bake_agree_pct_median"), finbook::bench::median(s.agree));
            row.insert(QStringLiteral("worst"), s.worst);
            row.insert(QStringLiteral("below_99_5"),
                       int(std::count_if(s.agree.begin(), s.agree.end(),
                                         [](double p) { return p < 99.5; })));
            row.insert(QStringLiteral("filled_change_pct_max"), s.maxAreaChangePct);
            row.insert(QStringLiteral("shown_filled_change_pct_max"), s.maxShownAreaChangePct);
            row.insert(QStringLiteral("meets_all_targets"), s.meetsAll);
            row.insert(QStringLiteral("shown_fill_count_changed"), s.fillCountChanged);
            row.insert(QStringLiteral("visible_fill_count_changed"), s.visibleCountChanged);
            row.insert(QStringLiteral("apply_ms_median"), finbook::bench::median(s.applyMs));
            row.insert(QStringLiteral("apply_ms_max"),
                       *std::max_element(s.applyMs.begin(), s.applyMs.end()));
        }
        print(row);
    }
    return unreadable > 0 ? 1 : 0;
}

} // namespace

FINBOOK_BENCH("bake",
              "[--png DIR [--faces]] [--rig NAME] FILE...  (Apply Pose keeps what was shown)",
              benchBake);
