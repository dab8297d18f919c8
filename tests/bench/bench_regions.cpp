// finbook-bench regions [--png DIR] [--gap PX] FILE...: the regions of each drawing (Quick, Draw!
// "strokes") or shape ("contours", each drawn as one closed stroke), in the formats of
// shared/data/README.md, pen width 3 px. One JSON object per file per line: strokes, free
// ends, gaps closed, regions, the area of the object's shape (objectShape) against the ink
// band (the strokes' bands alone, nothing filled) and today's silhouette, and the times
// (median of 7 runs, wall clock, shared machine). A last line sums up (median and max time,
// how many shapes are at least 3× their ink, how many mouths were closed). --png draws each:
// faces in colour, strokes black, gap closures red, mouths' chords orange, free ends as red
// circles, the shape's outline blue. --no-mouths: without closing open mouths (regions.h),
// for comparison.
#include "../geometry/geometry_test_support.h"
#include "bench.h"

#include <finbook/geometry/object_shape.h>
#include <finbook/geometry/regions.h>
#include <finbook/geometry/silhouette.h>

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
#include <optional>

namespace {

using namespace finbook::geometry;
using finbook::test::toMatrix;
using Clock = std::chrono::steady_clock;

constexpr int kRuns = 7;
constexpr double kPenWidth = 3.0;
constexpr double kFilledFactor = 3.0; // "a body, not a wire": shape ≥ 3× its ink

std::optional<std::vector<StrokeInput>> readStrokes(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return std::nullopt;
    const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
    std::vector<StrokeInput> strokes;
    if (json.contains(QStringLiteral("strokes"))) {
        for (const QJsonValue &stroke : json.value(QStringLiteral("strokes")).toArray())
            strokes.push_back({toMatrix(stroke.toArray()), kPenWidth});
    } else if (json.contains(QStringLiteral("contours"))) {
        for (const QJsonValue &contour : json.value(QStringLiteral("contours")).toArray()) {
            Eigen::MatrixX2d ring = toMatrix(contour.toArray());
            if (ring.rows() == 0)
                continue;
            ring.conservativeResize(ring.rows() + 1, 2);
            ring.row(ring.rows() - 1) = ring.row(0);
            strokes.push_back({ring, kPenWidth});
        }
    } else {
        return std::nullopt;
    }
    return strokes;
}

QPainterPath pathOf(const std::vector<Eigen::MatrixX2d> &rings)
{
    QPainterPath p;
    p.setFillRule(Qt::OddEvenFill);
    for (const Eigen::MatrixX2d &ring : rings) {
        for (Eigen::Index i = 0; i < ring.rows(); ++i)
            i == 0 ? p.moveTo(ring(i, 0), ring(i, 1)) : p.lineTo(ring(i, 0), ring(i, 1));
        p.closeSubpath();
    }
    return p;
}

void writePicture(const QString &file, const QString &title,
                  const std::vector<StrokeInput> &strokes, const Regions &regions,
                  const Region &shape)
{
    Eigen::RowVector2d lo = Eigen::RowVector2d::Constant(1e300), hi = -lo;
    for (const Eigen::MatrixX2d &ring : regionRings(shape)) {
        lo = lo.cwiseMin(ring.colwise().minCoeff());
        hi = hi.cwiseMax(ring.colwise().maxCoeff());
    }
    const double scale = 560.0 / std::max(1.0, (hi - lo).maxCoeff());
    QImage image(600, 630, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.drawText(QRectF(5, 605, 590, 25), title);
    painter.translate(20, 20);
    painter.scale(scale, scale);
    painter.translate(-lo.x(), -lo.y());
    painter.fillPath(pathOf(regionRings(shape)), QColor(235, 235, 235));
    for (std::size_t i = 0; i < regions.faces.size(); ++i) {
        const Face &f = regions.faces[i];
        std::vector<Eigen::MatrixX2d> rings{f.polygon.outer};
        rings.insert(rings.end(), f.polygon.holes.begin(), f.polygon.holes.end());
        painter.fillPath(pathOf(rings), QColor::fromHsv(int(i * 67 % 360), 90, 245));
        painter.setPen(QPen(Qt::darkGreen, 1.0 / scale));
        painter.drawEllipse(QPointF(f.seed.x(), f.seed.y()), 3 / scale, 3 / scale);
    }
    painter.setPen(QPen(QColor(60, 90, 255), 1.5 / scale));
    painter.drawPath(pathOf(regionRings(shape)));
    painter.setPen(QPen(Qt::black, 1.5 / scale, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    for (const StrokeInput &s : strokes) {
        QPainterPath p;
        for (Eigen::Index i = 0; i < s.points.rows(); ++i)
            i == 0 ? p.moveTo(s.points(i, 0), s.points(i, 1))
                   : p.lineTo(s.points(i, 0), s.points(i, 1));
        painter.drawPath(p);
    }
    for (const GapClosure &g : regions.closures) {
        painter.setPen(
            QPen(g.mouth ? QColor(255, 140, 0) : QColor(Qt::red), 2.5 / scale, Qt::DashLine));
        painter.drawLine(QPointF(g.from.x(), g.from.y()), QPointF(g.to.x(), g.to.y()));
    }
    painter.setPen(QPen(Qt::red, 1.0 / scale));
    for (const StrokeInput &s : strokes)
        for (Eigen::Index i : {Eigen::Index(0), s.points.rows() - 1})
            if (i >= 0)
                painter.drawEllipse(QPointF(s.points(i, 0), s.points(i, 1)), 4 / scale, 4 / scale);
    painter.end();
    image.save(file);
}

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct Tally {
    std::vector<double> times;
    int filled = 0, mouths = 0;
};

QJsonObject measure(const QString &path, const std::vector<StrokeInput> &strokes,
                    const QString &pngDir, const RegionsOptions &options, Tally &tally)
{
    QJsonObject row{{QStringLiteral("file"), QFileInfo(path).fileName()}};
    std::vector<double> regionMs, shapeMs;
    std::optional<Regions> regions;
    std::optional<Region> shape;
    for (int run = 0; run < kRuns; ++run) {
        auto start = Clock::now();
        auto r = computeRegions(strokes, options);
        regionMs.push_back(msSince(start));
        start = Clock::now();
        RegionsOptions forShape;
        forShape.closeMouths = options.closeMouths;
        auto s = objectShape(strokes, {}, forShape);
        shapeMs.push_back(msSince(start));
        if (!r || !s) {
            row.insert(QStringLiteral("error"),
                       QString::fromStdString(!r ? r.error().message : s.error().message));
            return row;
        }
        regions = std::move(*r);
        shape = std::move(*s);
    }
    const auto ink = silhouette(strokes, {0.0, 0.0, HoleMode::KeepHoles, 0.4});
    const auto today = silhouette(strokes);
    const double inkArea = ink ? regionArea(*ink) : 0.0;
    const double shapeArea = regionArea(*shape);
    long points = 0;
    for (const StrokeInput &s : strokes)
        points += long(s.points.rows());
    using finbook::bench::median;
    row.insert(QStringLiteral("strokes"), qint64(strokes.size()));
    row.insert(QStringLiteral("points"), qint64(points));
    row.insert(QStringLiteral("free_ends"), regions->freeEnds);
    const int mouths = int(std::count_if(regions->closures.begin(), regions->closures.end(),
                                         [](const GapClosure &g) { return g.mouth; }));
    row.insert(QStringLiteral("gaps_closed"), qint64(regions->closures.size()) - mouths);
    row.insert(QStringLiteral("mouths_closed"), mouths);
    row.insert(QStringLiteral("regions"), qint64(regions->faces.size()));
    row.insert(QStringLiteral("close_gap_px"), regions->closeGap);
    row.insert(QStringLiteral("ink_area"), inkArea);
    row.insert(QStringLiteral("silhouette_area"), today ? regionArea(*today) : 0.0);
    row.insert(QStringLiteral("shape_area"), shapeArea);
    row.insert(QStringLiteral("shape_over_ink"), inkArea > 0.0 ? shapeArea / inkArea : 0.0);
    row.insert(QStringLiteral("regions_ms"), median(regionMs));
    row.insert(QStringLiteral("shape_ms"), median(shapeMs));
    tally.times.push_back(median(regionMs));
    tally.filled += shapeArea >= kFilledFactor * inkArea ? 1 : 0;
    tally.mouths += mouths;
    if (!pngDir.isEmpty()) {
        const QString title = QStringLiteral("%1  ends %2 closed %3+%6 faces %4  x%5")
                                  .arg(QFileInfo(path).baseName())
                                  .arg(regions->freeEnds)
                                  .arg(regions->closures.size() - std::size_t(mouths))
                                  .arg(regions->faces.size())
                                  .arg(inkArea > 0.0 ? shapeArea / inkArea : 0.0, 0, 'f', 1)
                                  .arg(mouths);
        writePicture(QDir(pngDir).filePath(QFileInfo(path).baseName() + QStringLiteral(".png")),
                     title, strokes, *regions, *shape);
    }
    return row;
}

int benchRegions(const QStringList &arguments)
{
    QStringList args = arguments;
    QString pngDir;
    RegionsOptions options; // automatic gap, mouths closed: as the app's default
    while (!args.isEmpty() && args.front().startsWith(QStringLiteral("--"))) {
        if (args.front() == QStringLiteral("--no-mouths")) {
            options.closeMouths = false;
            args = args.mid(1);
            continue;
        }
        if (args.size() < 2)
            break;
        if (args.front() == QStringLiteral("--png")) {
            pngDir = args[1];
            QDir().mkpath(pngDir);
        } else if (args.front() == QStringLiteral("--gap")) {
            options.closeGap = args[1].toDouble();
        } else {
            break;
        }
        args = args.mid(2);
    }
    if (args.isEmpty()) {
        std::fprintf(stderr,
                     "usage: finbook-bench regions [--png DIR] [--gap PX] [--no-mouths] FILE...\n");
        return 2;
    }
    int failures = 0;
    Tally tally;
    for (const QString &path : args) {
        const auto strokes = readStrokes(path);
        const QJsonObject row =
            strokes ? measure(path, *strokes, pngDir, options, tally)
                    : QJsonObject{{QStringLiteral("file"), QFileInfo(path).fileName()},
                                  {QStringLiteral("error"), QStringLiteral("unreadable")}};
        failures += row.contains(QStringLiteral("error")) ? 1 : 0;
        std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
        std::fflush(stdout);
    }
    const QJsonObject summary{
        {QStringLiteral("summary"), true},
        {QStringLiteral("files"), qint64(args.size())},
        {QStringLiteral("failures"), failures},
        {QStringLiteral("regions_ms_median"), finbook::bench::median(tally.times)},
        {QStringLiteral("regions_ms_max"),
         tally.times.empty() ? 0.0 : *std::max_element(tally.times.begin(), tally.times.end())},
        {QStringLiteral("shape_at_least_3x_ink"), tally.filled},
        {QStringLiteral("mouths_closed"), tally.mouths}};
    std::printf("%s\n", QJsonDocument(summary).toJson(QJsonDocument::Compact).constData());
    return failures == 0 ? 0 : 1;
}

} // namespace

FINBOOK_BENCH(
    "regions",
    "[--png DIR] [--gap PX] [--no-mouths] FILE... (Quick, Draw! strokes or shape contours as JSON)",
    benchRegions);
