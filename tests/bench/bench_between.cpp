// finbook-bench between [--png DIR] FILE...: Between Drawings (issue 50) on real drawings
// (Quick, Draw! "strokes" or a shape's "contours", shared/data/README.md; pen 3 px).
//
// For each drawing, key A is the drawing as drawn (filled, as finbook-bench bake fills it) and
// key B is A posed by its automatic skeleton, every limb turned ±40° where it leaves the body
// (so the true place of each of A's points in B is known), then "redrawn": each line resampled
// at 1.37× its point spacing, every point jittered by up to 1 px, every other line reversed, the
// lines' order shuffled, and the longest line split in two. A is fitted onto B without pins
// (model/inbetween/between_drawings.h, as the app does it). One JSON line per drawing:
//   error_median_pct, error_p95_pct: A's stroke points, fitted, against their true places in B,
//     % of the drawing's diagonal;
//   limb_change_pct: the mid in-between (t = 0.5, as-rigid-as-possible interpolation) — each
//     limb's chord from its base to each tip (A's joints carried by the motion) against the
//     true one (the rig posed with half of each turn), % change, max over limbs longer than
//     4 px whose joints lie in A's shape; fit_limb_change_pct the same for the fit against
//     B's pose; naive_limb_change_pct for a point-to-point morph (each vertex halfway along a
//     straight line to its fitted place);
//   fit_ms: the whole fit (mesh, skeleton, precompute, fit from its starts, interpolation's
//     precompute); inbetween_ms: one in-between's drawing (t = 0.5: strokes carried, fills tied
//     as Apply Pose ties them); fills_kept: it has as many fills as A; vertices;
//   uncovered_pct: B's points farther than 5 % of B's diagonal from every fitted point of A (a
//     part of B the fit did not reach; above 7.5 % the fit is refused, and the row says why);
//   pin_ms: a correspondence pin put on A's worst-fitted point at its true place and dragged
//     2 px at a time, the live refit's time (median of 5); worst_point_pct and
//     worst_point_pinned_pct: that point's error before and with the pin.
// The last line sums up: medians and worst cases, and how many drawings meet the issue's
// targets (median ≤ 2 % and p95 ≤ 6 %; mid in-between limbs within 3 %).
// --png DIR: per drawing DIR/between_NAME.png: A, B, A's fitted lines (red) over B (grey),
// and the in-betweens at t = 0.25, 0.5 and 0.85 (in the cross-fade), drawn as the app draws.
#include "../model/bake_support.h"
#include "../model/redrawn_key.h"
#include "bench.h"

#include <finbook/deform/between/arap_interpolation.h>
#include <finbook/geometry/embedding.h>
#include <finbook/geometry/triangle_locator.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/inbetween/between_drawings.h>

#include <QDir>
#include <QFileInfo>
#include <QPainter>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

using namespace finbook;
using namespace finbook::model;

namespace {

constexpr double kTurn = 40.0;     // degrees: each limb's turn at its base
constexpr double kShortLimb = 4.0; // px: limbs shorter than this are not compared
constexpr int kCell = 300;

QImage cell(const Frame &frame, const QTransform &t, const DocumentSettings &settings,
            const StrokeGroup *under = nullptr)
{
    QImage image(kCell, kCell, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setTransform(t);
    painter.setRenderHint(QPainter::Antialiasing);
    if (!under) {
        paintFrame(painter, frame, settings);
        return image;
    }
    // B's lines, wide and grey, under A's fitted ones, thin and red.
    const auto lines = [&](const StrokeGroup &g, const QPen &pen) {
        painter.setPen(pen);
        for (const Stroke &s : g.strokes) {
            QPolygonF line;
            for (const StrokePoint &p : s.data->points)
                line << QPointF(p.x, p.y);
            painter.drawPolyline(line);
        }
    };
    lines(*under, QPen(QColor(150, 150, 150), 9.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    for (const StrokeGroup &g : frame.groups)
        lines(g, QPen(QColor(224, 32, 32), 1.5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    return image;
}

// A result row of `file`, and its printing (one JSON line, flushed).
QJsonObject rowOf(const QString &file)
{
    return {{QStringLiteral("bench"), QStringLiteral("between")},
            {QStringLiteral("file"), QFileInfo(file).fileName()}};
}

void printRow(const QJsonObject &row)
{
    std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
    std::fflush(stdout);
}

// The cells side by side, a grey line between each two.
void saveSheet(const std::vector<QImage> &cells, const QString &path)
{
    QImage sheet(kCell * int(cells.size()), kCell, QImage::Format_RGB32);
    QPainter painter(&sheet);
    for (std::size_t i = 0; i < cells.size(); ++i) {
        painter.drawImage(int(i) * kCell, 0, cells[i]);
        painter.setPen(QColor(200, 200, 200));
        painter.drawLine(int(i) * kCell, 0, int(i) * kCell, kCell);
    }
    painter.end();
    sheet.save(path);
}

struct Summary {
    std::vector<double> median, p95, limb, naive, ms, drawingMs, pinMs;
    int meets = 0, limbsMeet = 0, failed = 0, drawings = 0, fillsKept = 0;
    QString worstFile;
    double worstP95 = -1.0;
};

void runOne(const QString &file, const std::vector<std::vector<QPointF>> &lines,
            const BetweenOptions &options, const QString &pngDir, Summary &summary)
{
    const QString name = QFileInfo(file).completeBaseName();
    QJsonObject row = rowOf(file);
    const auto print = [&row] { printRow(row); };
    Document doc;
    const Id g = testing::drawingDocument(doc, lines);
    const double closeGap = doc.settings().closeGap;
    StrokeGroup a = *doc.group(g);
    const Rig rig = testing::skeletonBend(a, closeGap, SkinningMode::Rigid, kTurn);
    if (rig.empty()) {
        row.insert(QStringLiteral("skipped"), QStringLiteral("no skeleton with a limb"));
        return print();
    }
    if (const QString error = testing::poseObject(doc, g, rig); !error.isEmpty()) {
        row.insert(QStringLiteral("skipped"), error);
        return print();
    }
    const StrokeGroup &posed = *doc.group(g);
    const StrokeGroup b = testing::redrawnKey(posed, std::uint32_t(qHash(name)));
    ++summary.drawings;
    const auto fitted = fitDrawings(a, b, closeGap, {}, options);
    if (!fitted) {
        ++summary.failed;
        row.insert(QStringLiteral("error"), fitted.error());
        print();
        // The sheet of a refused fit shows the two keys: what could not be laid on what.
        if (!pngDir.isEmpty()) {
            const QRectF view =
                testing::shownBounds(a).united(testing::shownBounds(b)).adjusted(-8, -8, 8, 8);
            const QTransform t = testing::pictureView(view, kCell);
            std::vector<QImage> cells;
            for (const StrokeGroup *key : {static_cast<const StrokeGroup *>(&a), &b}) {
                Frame f;
                f.groups.push_back(*key);
                cells.push_back(cell(f, t, doc.settings()));
            }
            saveSheet(cells, QDir(pngDir).filePath(QStringLiteral("between_%1.png").arg(name)));
        }
        return;
    }
    const DrawingFit &fit = **fitted;
    const Eigen::MatrixX2d &V = fit.meshed->mesh.V;
    const Eigen::MatrixX3i &F = fit.meshed->mesh.F;
    const geometry::Embedding &all = fit.meshed->embedding;
    // Correspondence error over A's stroke points (and the worst one, pinned below).
    const QRectF box = testing::shownBounds(a);
    const double diagonal = std::hypot(box.width(), box.height());
    std::vector<double> error;
    std::size_t worstStroke = 0, worstPoint = 0;
    double worstError = -1.0;
    const Eigen::MatrixX2d fittedA = geometry::applyEmbedding(all, fit.fit.U, F);
    for (std::size_t s = 0; s < a.strokes.size(); ++s) {
        const std::vector<StrokePoint> &truth = posed.deformed->strokes[s];
        for (std::size_t k = 0; k < truth.size(); ++k) {
            const Eigen::Index r = Eigen::Index(fit.meshed->strokeOffsets[s] + k);
            if (all.I(r) < 0)
                continue;
            const Eigen::Vector2d p = fittedA.row(r).transpose();
            const double e = std::hypot(p.x() - truth[k].x, p.y() - truth[k].y);
            error.push_back(100.0 * e / diagonal);
            if (e > worstError) {
                worstError = e;
                worstStroke = s;
                worstPoint = k;
            }
        }
    }
    // Limb lengths. A limb runs from a turned joint's parent (its base) to each tip below it.
    // B's pose pins the mesh at its posed bones (an ARAP solve), so the true chord base–tip is
    // that of the rig's joints posed: with all of B's turns for the fit, with half of each for
    // the mid in-between (a limb with a turned limb of its own changes its chord). The fitted
    // motion, its mid in-between and the straight-line morph carry A's rest joints through A's
    // mesh. Only joints inside A's shape count: one the skeleton hung between two pieces drawn
    // apart has no place in the mesh to be carried by.
    const SkeletonRig &skeleton = rig.skeleton;
    const int n = skeleton.jointCount();
    Eigen::MatrixX2d joints(n, 2);
    for (int j = 0; j < n; ++j)
        joints.row(j) << skeleton.joints[std::size_t(j)].x(), skeleton.joints[std::size_t(j)].y();
    const SkeletonRig &truePose = doc.group(g)->rig.skeleton;
    SkeletonRig halfPose = truePose;
    for (double &angle : halfPose.angles)
        angle *= 0.5;
    const std::vector<QPointF> jointsTrue = truePose.posedJoints(),
                               jointsHalf = halfPose.posedJoints();
    const geometry::Embedding inA = geometry::embed(V, F, joints);
    const auto mid = deform::between::arapInterpolate(*fit.motion, 0.5);
    const Eigen::MatrixX2d naiveMid = 0.5 * (V + fit.fit.U);
    std::vector<bool> hasChild(std::size_t(n), false);
    for (int j = 0; j < n; ++j)
        if (skeleton.parent[std::size_t(j)] >= 0)
            hasChild[std::size_t(skeleton.parent[std::size_t(j)])] = true;
    const auto below = [&](int tip, int joint) {
        for (int k = tip; k >= 0; k = skeleton.parent[std::size_t(k)])
            if (k == joint)
                return true;
        return false;
    };
    // Whether a joint lies in A's shape (embed puts a joint outside, such as one the skeleton
    // hung between two pieces drawn apart, on the nearest triangle, which the pose does not move
    // with the joint's bone).
    const geometry::TriangleLocator locator(V, F);
    const auto inShape = [&](int joint) {
        return locator.locate(joints.row(joint).transpose()).inside;
    };
    // The joints carried by the mid in-between, the fit and the straight-line morph.
    const Eigen::MatrixX2d jointsMid = mid ? geometry::applyEmbedding(inA, *mid, F) : joints;
    const Eigen::MatrixX2d jointsFit = geometry::applyEmbedding(inA, fit.fit.U, F);
    const Eigen::MatrixX2d jointsNaive = geometry::applyEmbedding(inA, naiveMid, F);
    double limb = 0.0, naive = 0.0, fitLimb = 0.0;
    int limbs = 0;
    for (int j = 0; j < n; ++j) {
        const int base = skeleton.parent[std::size_t(j)];
        if (base < 0 || skeleton.angles[std::size_t(j)] == 0.0 || !inShape(base) ||
            std::size_t(base) >= jointsTrue.size())
            continue;
        for (int tip = 0; tip < n; ++tip) {
            if (hasChild[std::size_t(tip)] || !below(tip, j) || inA.I(tip) < 0 ||
                std::size_t(tip) >= jointsTrue.size() || !inShape(tip))
                continue;
            const auto chordOf = [&](const std::vector<QPointF> &at) {
                const QPointF d = at[std::size_t(tip)] - at[std::size_t(base)];
                return std::hypot(d.x(), d.y());
            };
            const double half = chordOf(jointsHalf), whole = chordOf(jointsTrue);
            if (half < kShortLimb || whole < kShortLimb)
                continue;
            const auto chord = [&](const Eigen::MatrixX2d &at) {
                return (at.row(tip) - at.row(base)).norm();
            };
            ++limbs;
            if (mid)
                limb = std::max(limb, 100.0 * std::abs(chord(jointsMid) - half) / half);
            fitLimb = std::max(fitLimb, 100.0 * std::abs(chord(jointsFit) - whole) / whole);
            naive = std::max(naive, 100.0 * std::abs(chord(jointsNaive) - half) / half);
        }
    }
    // A correspondence pin on A's worst point at its true place, then dragged 2 px at a time:
    // the time of each live refit (refitDrawings), and how far that point is then.
    std::vector<double> pinMs;
    double pinnedError = -1.0;
    {
        const StrokePoint &rest = a.strokes[worstStroke].data->points[worstPoint];
        const StrokePoint &goal = posed.deformed->strokes[worstStroke][worstPoint];
        std::shared_ptr<const DrawingFit> live = *fitted;
        for (int move = 0; move < 5 && live; ++move) {
            const BetweenPin pin{QPointF(rest.x, rest.y), QPointF(goal.x, goal.y + 2.0 * move)};
            const auto pinStart = std::chrono::steady_clock::now();
            const auto refitted = refitDrawings(*live, {pin}, options);
            pinMs.push_back(std::chrono::duration<double, std::milli>(
                                std::chrono::steady_clock::now() - pinStart)
                                .count());
            if (!refitted)
                break;
            live = *refitted;
            if (move == 0) {
                const Eigen::Index r =
                    Eigen::Index(live->meshed->strokeOffsets[worstStroke] + worstPoint);
                const Eigen::Vector2d p =
                    geometry::applyEmbedding(all, live->fit.U, F).row(r).transpose();
                pinnedError = 100.0 * std::hypot(p.x() - goal.x, p.y() - goal.y) / diagonal;
            }
        }
        row.insert(QStringLiteral("worst_point_pct"), 100.0 * worstError / diagonal);
        row.insert(QStringLiteral("worst_point_pinned_pct"), pinnedError);
    }
    // One in-between's drawing (carried strokes, fills as Apply Pose ties them): what each
    // generated frame costs.
    const auto drawingStart = std::chrono::steady_clock::now();
    const StrokeGroup midDrawing = betweenDrawing(fit, 0.5, options);
    const double drawingMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - drawingStart)
            .count();
    const double median = bench::percentile(error, 0.5), p95 = bench::percentile(error, 0.95);
    const double ms = 1000.0 * fit.seconds;
    row.insert(QStringLiteral("vertices"), int(V.rows()));
    row.insert(QStringLiteral("limbs"), limbs);
    row.insert(QStringLiteral("error_median_pct"), median);
    row.insert(QStringLiteral("error_p95_pct"), p95);
    row.insert(QStringLiteral("limb_change_pct"), limb);
    row.insert(QStringLiteral("naive_limb_change_pct"), naive);
    row.insert(QStringLiteral("fit_limb_change_pct"), fitLimb);
    row.insert(QStringLiteral("fit_ms"), ms);
    row.insert(QStringLiteral("inbetween_ms"), drawingMs);
    row.insert(QStringLiteral("pin_ms"), pinMs.empty() ? -1.0 : bench::percentile(pinMs, 0.5));
    row.insert(QStringLiteral("fills_kept"), int(midDrawing.fills.size()) == int(a.fills.size()));
    row.insert(QStringLiteral("distortion"), fit.fit.distortion);
    row.insert(QStringLiteral("uncovered_pct"), 100.0 * fit.fit.uncoveredShare);
    print();
    summary.median.push_back(median);
    summary.p95.push_back(p95);
    summary.limb.push_back(limb);
    summary.naive.push_back(naive);
    summary.ms.push_back(ms);
    summary.drawingMs.push_back(drawingMs);
    summary.pinMs.insert(summary.pinMs.end(), pinMs.begin(), pinMs.end());
    summary.fillsKept += midDrawing.fills.size() == a.fills.size();
    summary.meets += median <= 2.0 && p95 <= 6.0;
    summary.limbsMeet += limb <= 3.0;
    if (p95 > summary.worstP95) {
        summary.worstP95 = p95;
        summary.worstFile = QFileInfo(file).fileName();
    }
    if (pngDir.isEmpty())
        return;
    const QRectF view = box.united(testing::shownBounds(b)).adjusted(-8, -8, 8, 8);
    const QTransform t = testing::pictureView(view, kCell);
    const auto alone = [](const StrokeGroup &group) {
        Frame f;
        f.groups.push_back(group);
        return f;
    };
    std::vector<QImage> cells{cell(alone(a), t, doc.settings()), cell(alone(b), t, doc.settings())};
    BetweenOptions noFade = options;
    noFade.crossFade = 0.0;
    StrokeGroup carried = betweenDrawing(fit, 1.0, noFade);
    cells.push_back(cell(alone(carried), t, doc.settings(), &b));
    for (double u : {0.25, 0.5, 0.85}) {
        Frame f;
        f.groups.push_back(betweenDrawing(fit, u, options));
        if (auto in = fadingInDrawing(fit, u, options))
            f.groups.push_back(std::move(*in));
        cells.push_back(cell(f, t, doc.settings()));
    }
    saveSheet(cells, QDir(pngDir).filePath(QStringLiteral("between_%1.png").arg(name)));
}

// Two keys drawn in the app (a .finbook file: its first and last frames, each object the two
// draw differently): no true pose to measure against, so the row gives the fit's own figures,
// and the sheet (--png) what the animator would see: A, B, the fit over B, and the in-betweens
// at 0.25, 0.5 and 0.85.
void runKeys(const QString &file, const BetweenOptions &options, const QString &pngDir)
{
    const QString name = QFileInfo(file).completeBaseName();
    QJsonObject row = rowOf(file);
    const auto print = [&row] { printRow(row); };
    const auto loaded = loadFinbook(file);
    if (!loaded || loaded->frames.size() < 2) {
        row.insert(QStringLiteral("error"),
                   loaded ? QStringLiteral("fewer than two frames") : loaded.error().message);
        return print();
    }
    const Frame &first = loaded->frames.front(), &last = loaded->frames.back();
    const double closeGap = loaded->settings.closeGap;
    const KeyFits fits = fitKeyDrawings(first, last, closeGap, options);
    for (const auto &[object, why] : fits.failures)
        row.insert(QStringLiteral("refused_%1").arg(object), why);
    Frame fitted, mid[3];
    const double times[3] = {0.25, 0.5, 0.85};
    QRectF box;
    for (std::size_t i = 0; i < fits.fits.size(); ++i) {
        const std::shared_ptr<const DrawingFit> &fit = fits.fits[i];
        if (!fit)
            continue;
        row.insert(QStringLiteral("fit_ms_%1").arg(i), 1000.0 * fit->seconds);
        row.insert(QStringLiteral("error_median_pct_%1").arg(i), 100.0 * fit->fit.relativeMedian);
        row.insert(QStringLiteral("uncovered_pct_%1").arg(i), 100.0 * fit->fit.uncoveredShare);
        row.insert(QStringLiteral("distortion_%1").arg(i), fit->fit.distortion);
        row.insert(QStringLiteral("hinges_%1").arg(i), int(fit->hinges.size()));
        row.insert(QStringLiteral("vertices_%1").arg(i), int(fit->meshed->mesh.V.rows()));
        BetweenOptions noFade = options;
        noFade.crossFade = 0.0;
        fitted.groups.push_back(betweenDrawing(*fit, 1.0, noFade));
        for (int k = 0; k < 3; ++k) {
            mid[k].groups.push_back(betweenDrawing(*fit, times[k], options));
            if (auto in = fadingInDrawing(*fit, times[k], options))
                mid[k].groups.push_back(std::move(*in));
        }
    }
    print();
    if (pngDir.isEmpty())
        return;
    for (const Frame *f : {&first, &last})
        for (const StrokeGroup &g : f->groups)
            box = box.united(testing::shownBounds(g));
    const QTransform t = testing::pictureView(box.adjusted(-8, -8, 8, 8), kCell);
    Frame under;
    for (const StrokeGroup &g : last.groups)
        under.groups.push_back(g);
    std::vector<QImage> cells{cell(first, t, loaded->settings), cell(last, t, loaded->settings)};
    cells.push_back(
        cell(fitted, t, loaded->settings, under.groups.empty() ? nullptr : &under.groups[0]));
    for (const Frame &f : mid)
        cells.push_back(cell(f, t, loaded->settings));
    saveSheet(cells, QDir(pngDir).filePath(QStringLiteral("between_%1.png").arg(name)));
}

int benchBetween(const QStringList &args)
{
    QString pngDir;
    QStringList files;
    BetweenOptions options;
    for (int i = 0; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--png") && i + 1 < args.size()) {
            pngDir = args[++i];
        } else if (args[i] == QLatin1String("--stiffness") && i + 1 < args.size()) {
            options.fit.stiffness.clear();
            for (const QString &v : args[++i].split(QLatin1Char(',')))
                options.fit.stiffness.push_back(v.toDouble());
        } else if (args[i] == QLatin1String("--no-articulated")) {
            options.articulated = false;
        } else if (args[i] == QLatin1String("--whole-mesh")) {
            options.layeredParts = false;
        } else if (args[i] == QLatin1String("--hinge-weight") && i + 1 < args.size()) {
            options.fit.hingeWeight = args[++i].toDouble();
        } else if (args[i] == QLatin1String("--fail-distortion") && i + 1 < args.size()) {
            options.fit.failDistortion = args[++i].toDouble();
        } else {
            files << args[i];
        }
    }
    if (files.isEmpty()) {
        std::fprintf(stderr, "usage: finbook-bench between [--png DIR] FILE...\n");
        return 2;
    }
    if (!pngDir.isEmpty())
        QDir().mkpath(pngDir);
    Summary summary;
    for (const QString &file : files) {
        if (file.endsWith(QLatin1String(".finbook"))) {
            runKeys(file, options, pngDir);
            continue;
        }
        QString error;
        const auto lines = testing::readDrawing(file, &error);
        if (lines.empty()) {
            std::printf("{\"bench\":\"between\",\"file\":\"%s\",\"error\":\"%s\"}\n",
                        qPrintable(QFileInfo(file).fileName()), qPrintable(error));
            continue;
        }
        runOne(file, lines, options, pngDir, summary);
    }
    const auto pct = [](const std::vector<double> &v, double p) {
        return v.empty() ? 0.0 : bench::percentile(v, p);
    };
    const auto worst = [](const std::vector<double> &v) {
        return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
    };
    const int fitted = int(summary.median.size());
    std::printf("{\"bench\":\"between\",\"summary\":true,\"drawings\":%d,\"fitted\":%d,"
                "\"failed\":%d,\"error_median_pct_median\":%.3f,\"error_p95_pct_median\":%.3f,"
                "\"error_p95_pct_max\":%.3f,\"worst\":\"%s\",\"meet_error_targets\":%d,"
                "\"meet_error_targets_pct\":%.1f,\"limb_change_pct_median\":%.3f,"
                "\"limb_change_pct_max\":%.3f,\"limbs_within_3pct\":%d,"
                "\"naive_limb_change_pct_median\":%.3f,\"naive_limb_change_pct_max\":%.3f,"
                "\"fit_ms_median\":%.1f,\"fit_ms_max\":%.1f,\"inbetween_ms_median\":%.1f,"
                "\"inbetween_ms_max\":%.1f,\"fills_kept\":%d,\"pin_ms_median\":%.1f,"
                "\"pin_ms_p95\":%.1f}\n",
                summary.drawings, fitted, summary.failed, pct(summary.median, 0.5),
                pct(summary.p95, 0.5), worst(summary.p95), qPrintable(summary.worstFile),
                summary.meets,
                summary.drawings > 0 ? 100.0 * summary.meets / summary.drawings : 0.0,
                pct(summary.limb, 0.5), worst(summary.limb), summary.limbsMeet,
                pct(summary.naive, 0.5), worst(summary.naive), pct(summary.ms, 0.5),
                worst(summary.ms), pct(summary.drawingMs, 0.5), worst(summary.drawingMs),
                summary.fillsKept, pct(summary.pinMs, 0.5), pct(summary.pinMs, 0.95));
    return 0;
}

} // namespace

FINBOOK_BENCH("between",
              "[--png DIR] FILE...  (Between Drawings on real drawings: fit A onto a "
              "posed, redrawn B)",
              benchBetween);
