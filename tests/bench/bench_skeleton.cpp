// finbook-bench skeleton [--png DIR] FILE...: the automatic skeleton of each drawing (Quick,
// Draw! "strokes", through the object's shape: closed regions and ink) or shape ("contours", as
// given), in the formats of shared/data/README.md. One JSON object per file per line: the time of
// the whole pipeline from the silhouette (raw straight skeleton + default refinement; median of 9
// runs, wall clock as skeleton_ms and this thread's CPU time as skeleton_cpu_ms), its size, and how
// much of the bones' length lies inside the shape (sampled every 0.25 px). --png writes a picture
// of each result to DIR: shape grey, simplified outline blue, raw skeleton orange, bones
// black, joints as circles of their radius, the root red, and DIR/sheet.png: every picture on
// one contact sheet. Per file also the rig an animator sees (issue 21): terminals, junctions,
// bones, the shortest bone relative to the shape's diagonal, whether the root is a tip, and the
// limb bases (where limbs leave the body: IK turns a limb there; blue dots in the pictures).
// --before: without the animator rig (RefineOptions::animatorRig off), for comparison.
// --as-strokes: shape contours as the app sees them after `finbook-bench import`: each contour
// a closed stroke of the pen width, scaled into the 1280 × 720 canvas as the import scales it,
// through the object's shape like a sketch (the contours as given skip the silhouette's
// closing, which filled the slits between an octopus's arms until objectShape reopened them).
// "Wires": a skeleton that lies within one pen width of the strokes along most (> half) of its
// length traces the pen line instead of the body. Each row says whether the skeleton is one
// now (wire_after) and whether the one from the silhouette alone, before regions, was
// (wire_before); the last line counts both.
// Thin parts (issue 21): thin_tips counts the ends of protrusions at most 6 % of the diagonal
// wide (thin_tips.h), thin_tips_reached those a bone comes within that width of (drawn as
// magenta rings, filled when reached); outside_px is the bones' length outside the shape. The
// last line totals them: outside_share = outside_px / bone_px over all files.
// Issue 48's measures of what the eye sees: air_px (the bones' length outside the shape, as
// outside_px) and air_over_1pct (more than 1 % of the bone length in the air); spurs, the
// branches from a junction to a tip shorter than 1.5 times the junction's radius (they poke
// into a corner, a tick mark or a hem instead of running down a limb; orange rings in the
// pictures); root_radius_ratio, the root's inscribed radius over the largest in the shape
// (the root belongs in the thickest part of the body). The last line counts the files with
// spurs, with air over 1 %, and with the root's ratio at least 0.7.
#include "../geometry/geometry_test_support.h"
#include "bench.h"
#include "thin_tips.h"

#include <finbook/geometry/object_shape.h>
#include <finbook/geometry/silhouette.h>
#include <finbook/geometry/skeleton/raw_skeleton.h>
#include <finbook/geometry/skeleton/skeleton.h>
#include <finbook/geometry/skeleton/skeleton_refine.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <optional>
#include <time.h>
#include <utility>

namespace {

using finbook::bench::threadCpuMs;

using namespace finbook::geometry;
using finbook::test::contoursAsStrokes;
using finbook::test::insideRing;
using finbook::test::toMatrix;
using Clock = std::chrono::steady_clock;

constexpr int kRuns = 9;
constexpr double kPenWidth = 3.0;       // Quick, Draw! strokes carry no width
constexpr double kSampleSpacing = 0.25; // px along bones for the inside fraction

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct Input {
    Region before, after;                // silhouette alone, object shape (equal for contours)
    std::vector<Eigen::MatrixX2d> lines; // the pen lines (strokes, or the contours)
};

// The shape of pen strokes: the object's shape (and the silhouette alone, for wires).
std::optional<Input> shapeOfStrokes(const std::vector<StrokeInput> &strokes, QString &problem)
{
    Input input;
    for (const StrokeInput &stroke : strokes)
        input.lines.push_back(stroke.points);
    const auto before = silhouette(strokes);
    const auto after = objectShape(strokes);
    if (!before || !after) {
        problem = QString::fromStdString(!before ? before.error().message : after.error().message);
        return std::nullopt;
    }
    input.before = *before;
    input.after = *after;
    return input;
}

// The shape of a file: the object shape of its strokes, or its contours as one polygon (or,
// asStrokes, as closed strokes).
std::optional<Input> readShape(const QString &path, bool asStrokes, QString &problem)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        problem = QStringLiteral("unreadable");
        return std::nullopt;
    }
    const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
    if (json.contains(QStringLiteral("strokes"))) {
        std::vector<StrokeInput> strokes;
        for (const QJsonValue &stroke : json.value(QStringLiteral("strokes")).toArray())
            strokes.push_back({toMatrix(stroke.toArray()), kPenWidth});
        return shapeOfStrokes(strokes, problem);
    }
    if (json.contains(QStringLiteral("contours")) && asStrokes) {
        std::vector<StrokeInput> strokes;
        for (Eigen::MatrixX2d &points :
             contoursAsStrokes(json.value(QStringLiteral("contours")).toArray()))
            strokes.push_back({std::move(points), kPenWidth});
        return shapeOfStrokes(strokes, problem);
    }
    if (json.contains(QStringLiteral("contours"))) {
        const QJsonArray contours = json.value(QStringLiteral("contours")).toArray();
        Input input;
        Polygon polygon;
        for (qsizetype i = 0; i < contours.size(); ++i) {
            (i == 0 ? polygon.outer : polygon.holes.emplace_back()) =
                toMatrix(contours[i].toArray());
            Eigen::MatrixX2d closed = toMatrix(contours[i].toArray());
            if (closed.rows() > 0) {
                closed.conservativeResize(closed.rows() + 1, 2);
                closed.row(closed.rows() - 1) = closed.row(0);
            }
            input.lines.push_back(closed);
        }
        input.before = input.after = Region{polygon};
        return input;
    }
    problem = QStringLiteral("neither strokes nor contours");
    return std::nullopt;
}

bool insideRegion(const Region &region, const Eigen::RowVector2d &p)
{
    bool in = false;
    for (const Eigen::MatrixX2d &ring : regionRings(region))
        in ^= insideRing(ring, p);
    return in;
}

// Fraction of the bones' total length inside the region (even-odd), sampled every
// kSampleSpacing px; 1 for a skeleton without bones.
double bonesInside(const Skeleton &s, const Region &region, double *boneLength = nullptr)
{
    double inside = 0.0, total = 0.0;
    for (int j = 0; j < s.jointCount(); ++j) {
        if (s.parent(j) < 0)
            continue;
        const Eigen::RowVector2d a = s.joints.row(s.parent(j)), b = s.joints.row(j);
        const double length = (b - a).norm();
        const int samples = std::max(1, int(std::ceil(length / kSampleSpacing)));
        for (int k = 0; k < samples; ++k) {
            const double t = (k + 0.5) / samples;
            total += length / samples;
            inside += insideRegion(region, a + t * (b - a)) ? length / samples : 0.0;
        }
    }
    if (boneLength)
        *boneLength = total;
    return total > 0.0 ? inside / total : 1.0;
}

struct Totals {
    int wiresBefore = 0, wiresAfter = 0, tips = 0, reached = 0;
    int spurs = 0, filesWithSpurs = 0, airOver1Pct = 0, rootThick = 0, rooted = 0;
    double bonePx = 0.0, outsidePx = 0.0;
    std::vector<double> cpuMs;
};

double distanceToLines(const std::vector<Eigen::MatrixX2d> &lines, const Eigen::RowVector2d &p)
{
    double best = std::numeric_limits<double>::max();
    for (const Eigen::MatrixX2d &line : lines)
        for (Eigen::Index i = 0; i < line.rows(); ++i) {
            const Eigen::RowVector2d a = line.row(i);
            const Eigen::RowVector2d ab = i + 1 < line.rows()
                                              ? Eigen::RowVector2d(line.row(i + 1) - a)
                                              : Eigen::RowVector2d::Zero();
            const double len2 = ab.squaredNorm();
            const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
            best = std::min(best, (p - (a + t * ab)).norm());
        }
    return best;
}

// Fraction of the bones' length within one pen width of the pen lines (sampled every px).
double boneLengthOnLines(const Skeleton &s, const std::vector<Eigen::MatrixX2d> &lines)
{
    double near = 0.0, total = 0.0;
    for (int j = 0; j < s.jointCount(); ++j) {
        if (s.parent(j) < 0)
            continue;
        const Eigen::RowVector2d a = s.joints.row(s.parent(j)), b = s.joints.row(j);
        const double length = (b - a).norm();
        const int samples = std::max(1, int(std::ceil(length)));
        for (int k = 0; k < samples; ++k) {
            total += length / samples;
            if (distanceToLines(lines, a + (k + 0.5) / samples * (b - a)) <= kPenWidth)
                near += length / samples;
        }
    }
    return total > 0.0 ? near / total : 0.0;
}

// Whether the default skeleton of `shape` is a wire along `lines`; nullopt if none is built.
std::optional<bool> isWire(const Region &shape, const std::vector<Eigen::MatrixX2d> &lines)
{
    auto raw = rawSkeleton(shape);
    if (!raw)
        return std::nullopt;
    auto s = refineSkeleton(*raw);
    if (!s)
        return std::nullopt;
    return boneLengthOnLines(*s, lines) > 0.5;
}

constexpr double kSpurFactor = 1.5; // a branch shorter than this × its junction's radius

// The tips of the branches that end within kSpurFactor of their junction's radius: from each
// tip along joints of two bones to the first junction.
std::vector<int> spurTips(const Skeleton &s)
{
    std::vector<std::vector<int>> next(std::size_t(s.jointCount()));
    for (int j = 0; j < s.jointCount(); ++j)
        if (s.parent(j) >= 0) {
            next[std::size_t(j)].push_back(s.parent(j));
            next[std::size_t(s.parent(j))].push_back(j);
        }
    std::vector<int> out;
    for (int tip = 0; tip < s.jointCount(); ++tip) {
        if (next[std::size_t(tip)].size() != 1)
            continue;
        int previous = tip, at = next[std::size_t(tip)][0];
        double length = (s.joints.row(at) - s.joints.row(tip)).norm();
        while (next[std::size_t(at)].size() == 2) {
            const int step = next[std::size_t(at)][0] == previous ? next[std::size_t(at)][1]
                                                                  : next[std::size_t(at)][0];
            length += (s.joints.row(step) - s.joints.row(at)).norm();
            previous = std::exchange(at, step);
        }
        if (next[std::size_t(at)].size() >= 3 && length < kSpurFactor * s.radius(at))
            out.push_back(tip);
    }
    return out;
}

void writePicture(const QString &dir, const QString &name, const Region &shape,
                  const RawSkeleton &raw, const Skeleton &s,
                  const std::vector<std::pair<Eigen::RowVector2d, bool>> &tips)
{
    Eigen::RowVector2d lo = Eigen::RowVector2d::Constant(1e300), hi = -lo;
    for (const Eigen::MatrixX2d &ring : regionRings(shape)) {
        lo = lo.cwiseMin(ring.colwise().minCoeff());
        hi = hi.cwiseMax(ring.colwise().maxCoeff());
    }
    const double scale = 800.0 / std::max(1.0, (hi - lo).maxCoeff());
    QImage image(int((hi - lo).x() * scale) + 40, int((hi - lo).y() * scale) + 40,
                 QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.translate(20, 20);
    painter.scale(scale, scale);
    painter.translate(-lo.x(), -lo.y());
    auto path = [](const Region &region) {
        QPainterPath p;
        p.setFillRule(Qt::OddEvenFill);
        for (const Eigen::MatrixX2d &ring : regionRings(region)) {
            for (Eigen::Index i = 0; i < ring.rows(); ++i)
                i == 0 ? p.moveTo(ring(i, 0), ring(i, 1)) : p.lineTo(ring(i, 0), ring(i, 1));
            p.closeSubpath();
        }
        return p;
    };
    painter.fillPath(path(shape), QColor(220, 220, 220));
    painter.setPen(QPen(QColor(120, 160, 255), 1.0 / scale));
    painter.drawPath(path(raw.contour));
    painter.setPen(QPen(QColor(255, 180, 120), 1.0 / scale));
    for (Eigen::Index e = 0; e < raw.edges.rows(); ++e)
        painter.drawLine(QPointF(raw.nodes(raw.edges(e, 0), 0), raw.nodes(raw.edges(e, 0), 1)),
                         QPointF(raw.nodes(raw.edges(e, 1), 0), raw.nodes(raw.edges(e, 1), 1)));
    painter.setPen(QPen(Qt::black, 2.0 / scale));
    for (int j = 0; j < s.jointCount(); ++j) {
        if (s.parent(j) >= 0)
            painter.drawLine(QPointF(s.joints(j, 0), s.joints(j, 1)),
                             QPointF(s.joints(s.parent(j), 0), s.joints(s.parent(j), 1)));
    }
    for (int j = 0; j < s.jointCount(); ++j) {
        painter.setPen(QPen(j == s.root ? Qt::red : QColor(0, 120, 0), 1.0 / scale));
        painter.drawEllipse(QPointF(s.joints(j, 0), s.joints(j, 1)), s.radius(j), s.radius(j));
    }
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 150, 255));
    for (int j = 0; j < int(s.limbBase.size()); ++j)
        if (s.limbBase[std::size_t(j)])
            painter.drawEllipse(QPointF(s.joints(j, 0), s.joints(j, 1)), 4.0 / scale, 4.0 / scale);
    painter.setBrush(QBrush());
    painter.setPen(QPen(QColor(255, 140, 0), 3.0 / scale));
    for (int tip : spurTips(s))
        painter.drawEllipse(QPointF(s.joints(tip, 0), s.joints(tip, 1)), 9.0 / scale, 9.0 / scale);
    painter.setPen(QPen(Qt::magenta, 2.0 / scale));
    for (const auto &[tip, reached] : tips) {
        painter.setBrush(reached ? QBrush(Qt::magenta) : QBrush());
        painter.drawEllipse(QPointF(tip.x(), tip.y()), 5.0 / scale, 5.0 / scale);
    }
    painter.end();
    image.save(QDir(dir).filePath(name + QStringLiteral(".png")));
}

// Every picture in `files` scaled into one grid, with its name: what an animator looks over.
void writeContactSheet(const QString &dir, const QStringList &names)
{
    constexpr int kTile = 260, kColumns = 8;
    const int rows = (int(names.size()) + kColumns - 1) / kColumns;
    QImage sheet(kColumns * kTile, std::max(1, rows) * kTile, QImage::Format_RGB32);
    sheet.fill(Qt::white);
    QPainter painter(&sheet);
    painter.setRenderHint(QPainter::SmoothPixmapTransform);
    for (qsizetype i = 0; i < names.size(); ++i) {
        const QImage image(QDir(dir).filePath(names[i] + QStringLiteral(".png")));
        const QRect cell(int(i % kColumns) * kTile, int(i / kColumns) * kTile, kTile, kTile);
        if (!image.isNull()) {
            const QImage scaled =
                image.scaled(kTile - 8, kTile - 22, Qt::KeepAspectRatio, Qt::SmoothTransformation);
            painter.drawImage(cell.left() + 4, cell.top() + 18, scaled);
        }
        painter.setPen(Qt::black);
        painter.drawText(cell.adjusted(4, 2, -4, 0), Qt::AlignTop | Qt::AlignLeft, names[i]);
        painter.setPen(QColor(200, 200, 200));
        painter.drawRect(cell.adjusted(0, 0, -1, -1));
    }
    painter.end();
    sheet.save(QDir(dir).filePath(QStringLiteral("sheet.png")));
}

double shortestBone(const Skeleton &s)
{
    double shortest = 0.0;
    const Eigen::VectorXd lengths = boneLengths(s);
    for (int j = 0; j < s.jointCount(); ++j) {
        if (s.parent(j) >= 0 && (shortest == 0.0 || lengths(j) < shortest))
            shortest = lengths(j);
    }
    return shortest;
}

QJsonObject measure(const QString &path, const Input &input, const QString &pngDir, bool before,
                    Totals &totals)
{
    const Region &shape = input.after;
    QJsonObject row{{QStringLiteral("file"), QFileInfo(path).fileName()}};
    std::vector<double> totalMs, rawMs, cpuMs;
    std::optional<RawSkeleton> raw;
    std::optional<Skeleton> skeleton;
    for (int run = 0; run < kRuns; ++run) {
        const auto start = Clock::now();
        const double cpuStart = threadCpuMs();
        auto r = rawSkeleton(shape);
        rawMs.push_back(msSince(start));
        if (!r) {
            row.insert(QStringLiteral("error"), QString::fromStdString(r.error().message));
            return row;
        }
        RefineOptions refine;
        refine.animatorRig = !before;
        auto s = refineSkeleton(*r, refine);
        totalMs.push_back(msSince(start));
        cpuMs.push_back(threadCpuMs() - cpuStart);
        if (!s) {
            row.insert(QStringLiteral("error"), QString::fromStdString(s.error().message));
            return row;
        }
        raw = std::move(*r);
        skeleton = std::move(*s);
    }
    const std::vector<JointKind> kinds = jointKinds(*skeleton);
    using finbook::bench::median;
    row.insert(QStringLiteral("parts"), qint64(raw->contour.size()));
    row.insert(QStringLiteral("input_vertices"), qint64(regionVertexCount(shape)));
    row.insert(QStringLiteral("polygon_vertices"), qint64(raw->polygonVertices));
    row.insert(QStringLiteral("tolerance_px"), raw->tolerance);
    row.insert(QStringLiteral("raw_nodes"), qint64(raw->nodes.rows()));
    row.insert(QStringLiteral("skeleton_ms"), median(totalMs));
    row.insert(QStringLiteral("skeleton_cpu_ms"), median(cpuMs));
    row.insert(QStringLiteral("raw_ms"), median(rawMs));
    row.insert(QStringLiteral("joints"), skeleton->jointCount());
    row.insert(QStringLiteral("bones"), boneCount(*skeleton));
    row.insert(QStringLiteral("junctions"),
               qint64(std::count(kinds.begin(), kinds.end(), JointKind::Junction)));
    row.insert(QStringLiteral("terminals"),
               qint64(std::count(kinds.begin(), kinds.end(), JointKind::Terminal)));
    row.insert(QStringLiteral("limb_bases"),
               qint64(std::count(skeleton->limbBase.begin(), skeleton->limbBase.end(), true)));
    double bonePx = 0.0;
    const double inside = bonesInside(*skeleton, shape, &bonePx);
    row.insert(QStringLiteral("bones_inside"), inside);
    row.insert(QStringLiteral("bone_px"), bonePx);
    row.insert(QStringLiteral("outside_px"), (1.0 - inside) * bonePx);
    totals.bonePx += bonePx;
    totals.outsidePx += (1.0 - inside) * bonePx;
    row.insert(QStringLiteral("air_px"), (1.0 - inside) * bonePx);
    totals.airOver1Pct += 1.0 - inside > 0.01 ? 1 : 0;
    const int spurs = int(spurTips(*skeleton).size());
    row.insert(QStringLiteral("spurs"), spurs);
    totals.spurs += spurs;
    totals.filesWithSpurs += spurs > 0 ? 1 : 0;
    if (skeleton->root >= 0 && raw->radius.size() > 0 && raw->radius.maxCoeff() > 0.0) {
        const double ratio = skeleton->radius(skeleton->root) / raw->radius.maxCoeff();
        row.insert(QStringLiteral("root_radius_ratio"), ratio);
        totals.rooted += 1;
        totals.rootThick += ratio >= 0.7 ? 1 : 0;
    }
    totals.cpuMs.push_back(median(cpuMs));
    Eigen::RowVector2d lo = Eigen::RowVector2d::Constant(1e300), hi = -lo;
    for (const Eigen::MatrixX2d &ring : regionRings(shape)) {
        lo = lo.cwiseMin(ring.colwise().minCoeff());
        hi = hi.cwiseMax(ring.colwise().maxCoeff());
    }
    Eigen::MatrixX2d from(skeleton->jointCount(), 2), to(skeleton->jointCount(), 2);
    Eigen::Index bones = 0;
    for (int j = 0; j < skeleton->jointCount(); ++j) {
        if (skeleton->parent(j) < 0)
            continue;
        from.row(bones) = skeleton->joints.row(skeleton->parent(j));
        to.row(bones++) = skeleton->joints.row(j);
    }
    from.conservativeResize(bones, 2);
    to.conservativeResize(bones, 2);
    std::vector<std::pair<Eigen::RowVector2d, bool>> tips;
    for (const Eigen::RowVector2d &tip : finbook::bench::thinTips(shape))
        tips.emplace_back(tip, finbook::bench::tipReached(
                                   tip, from, to, finbook::bench::kTipWidth * (hi - lo).norm()));
    const auto reached = std::count_if(tips.begin(), tips.end(), [](auto &t) { return t.second; });
    row.insert(QStringLiteral("thin_tips"), qint64(tips.size()));
    row.insert(QStringLiteral("thin_tips_reached"), qint64(reached));
    totals.tips += int(tips.size());
    totals.reached += int(reached);
    row.insert(QStringLiteral("shortest_bone_rel"), shortestBone(*skeleton) / (hi - lo).norm());
    row.insert(QStringLiteral("root_is_terminal"),
               skeleton->root >= 0 && jointDegrees(*skeleton)(skeleton->root) == 1);
    row.insert(QStringLiteral("trees"), qint64((skeleton->parent.array() < 0).count()));
    row.insert(QStringLiteral("finite"), skeleton->joints.allFinite() &&
                                             skeleton->radius.allFinite() &&
                                             isValidSkeleton(*skeleton));
    const std::optional<bool> wireBefore = isWire(input.before, input.lines);
    const std::optional<bool> wireAfter = isWire(input.after, input.lines);
    row.insert(QStringLiteral("wire_before"), wireBefore.value_or(false));
    row.insert(QStringLiteral("wire_after"), wireAfter.value_or(false));
    totals.wiresBefore += wireBefore.value_or(false) ? 1 : 0;
    totals.wiresAfter += wireAfter.value_or(false) ? 1 : 0;
    if (!pngDir.isEmpty())
        writePicture(pngDir, QFileInfo(path).baseName(), shape, *raw, *skeleton, tips);
    return row;
}

int benchSkeleton(const QStringList &arguments)
{
    QStringList args = arguments;
    QString pngDir;
    bool before = false, asStrokes = false;
    while (!args.isEmpty()) {
        if (args.size() >= 2 && args.front() == QStringLiteral("--png")) {
            pngDir = args[1];
            args = args.mid(2);
            QDir().mkpath(pngDir);
        } else if (args.front() == QStringLiteral("--before")) {
            before = true;
            args.removeFirst();
        } else if (args.front() == QStringLiteral("--as-strokes")) {
            asStrokes = true;
            args.removeFirst();
        } else {
            break;
        }
    }
    if (args.isEmpty()) {
        std::fprintf(
            stderr,
            "usage: finbook-bench skeleton [--before] [--as-strokes] [--png DIR] FILE...\n");
        return 2;
    }
    int failures = 0;
    Totals totals;
    QStringList names;
    for (const QString &path : args) {
        QString problem;
        const std::optional<Input> input = readShape(path, asStrokes, problem);
        const QJsonObject row =
            input ? measure(path, *input, pngDir, before, totals)
                  : QJsonObject{{QStringLiteral("file"), QFileInfo(path).fileName()},
                                {QStringLiteral("error"), problem}};
        failures += row.contains(QStringLiteral("error")) ? 1 : 0;
        std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
        std::fflush(stdout);
        names << QFileInfo(path).baseName();
    }
    if (!pngDir.isEmpty())
        writeContactSheet(pngDir, names);
    const QJsonObject summary{{QStringLiteral("summary"), true},
                              {QStringLiteral("files"), qint64(args.size())},
                              {QStringLiteral("failures"), failures},
                              {QStringLiteral("wires_before"), totals.wiresBefore},
                              {QStringLiteral("wires_after"), totals.wiresAfter},
                              {QStringLiteral("bone_px"), totals.bonePx},
                              {QStringLiteral("outside_px"), totals.outsidePx},
                              {QStringLiteral("outside_share"),
                               totals.bonePx > 0.0 ? totals.outsidePx / totals.bonePx : 0.0},
                              {QStringLiteral("air_over_1pct_files"), totals.airOver1Pct},
                              {QStringLiteral("spurs"), totals.spurs},
                              {QStringLiteral("files_with_spurs"), totals.filesWithSpurs},
                              {QStringLiteral("root_radius_ratio_at_least_0_7"),
                               totals.rooted > 0 ? double(totals.rootThick) / totals.rooted : 0.0},
                              {QStringLiteral("thin_tips"), totals.tips},
                              {QStringLiteral("thin_tips_reached"), totals.reached},
                              {QStringLiteral("median_skeleton_cpu_ms"),
                               totals.cpuMs.empty() ? 0.0 : finbook::bench::median(totals.cpuMs)}};
    std::printf("%s\n", QJsonDocument(summary).toJson(QJsonDocument::Compact).constData());
    return failures == 0 ? 0 : 1;
}

} // namespace

FINBOOK_BENCH(
    "skeleton",
    "[--before] [--as-strokes] [--png DIR] FILE... (Quick, Draw! strokes or shape contours "
    "as JSON)",
    benchSkeleton);
