// finbook-bench mesh FILE...: silhouette and meshing time, mesh size and quality, and the
// cost of embedding points, for drawings (Quick, Draw! "strokes") and shapes ("contours") in
// the formats of shared/data/README.md. One JSON object per file per line.
#include "../geometry/geometry_test_support.h"
#include "bench.h"

#include <finbook/geometry/embedding.h>
#include <finbook/geometry/mesh_quality.h>
#include <finbook/geometry/object_mesh.h>
#include <finbook/geometry/polygon_repair.h>
#include <finbook/geometry/silhouette.h>
#include <finbook/geometry/triangle_locator.h>

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <chrono>
#include <cstdio>
#include <optional>

namespace {

using namespace finbook::test;

using namespace finbook::geometry;
using Clock = std::chrono::steady_clock;

constexpr int kRuns = 9;
constexpr double kPenWidth = 3.0; // Quick, Draw! strokes carry no width

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A file is either strokes (meshed via silhouette) or contours (outer + holes, via repair).
struct Input {
    std::vector<StrokeInput> strokes;
    std::optional<Region> region;
    Eigen::MatrixX2d points; // what gets embedded: all stroke or contour points
};

std::optional<Input> readInput(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return std::nullopt;
    const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
    Input input;
    std::vector<Eigen::MatrixX2d> lines;
    if (json.contains(QStringLiteral("strokes"))) {
        for (const QJsonValue &stroke : json.value(QStringLiteral("strokes")).toArray()) {
            input.strokes.push_back({toMatrix(stroke.toArray()), kPenWidth});
            lines.push_back(input.strokes.back().points);
        }
    } else if (json.contains(QStringLiteral("contours"))) {
        const QJsonArray contours = json.value(QStringLiteral("contours")).toArray();
        Polygon polygon;
        for (qsizetype i = 0; i < contours.size(); ++i) {
            lines.push_back(toMatrix(contours[i].toArray()));
            (i == 0 ? polygon.outer : polygon.holes.emplace_back()) = lines.back();
        }
        input.region = Region{polygon};
    } else {
        return std::nullopt;
    }
    Eigen::Index total = 0;
    for (const Eigen::MatrixX2d &line : lines)
        total += line.rows();
    input.points.resize(total, 2);
    total = 0;
    for (const Eigen::MatrixX2d &line : lines) {
        input.points.middleRows(total, line.rows()) = line;
        total += line.rows();
    }
    return input;
}

finbook::Expected<Region, GeometryError> outline(const Input &input)
{
    return input.region ? repairRegion(*input.region) : silhouette(input.strokes);
}

QJsonObject measure(const QString &path, const Input &input)
{
    QJsonObject row{{QStringLiteral("file"), QFileInfo(path).fileName()}};
    std::vector<double> silhouetteMs, meshMs, embedUs;
    std::optional<ObjectMesh> mesh;
    for (int run = 0; run < kRuns; ++run) {
        auto start = Clock::now();
        const auto region = outline(input);
        silhouetteMs.push_back(msSince(start));
        if (!region) {
            row.insert(QStringLiteral("error"), QString::fromStdString(region.error().message));
            return row;
        }
        start = Clock::now();
        auto meshed = meshRegion(*region);
        meshMs.push_back(msSince(start));
        if (!meshed) {
            row.insert(QStringLiteral("error"), QString::fromStdString(meshed.error().message));
            return row;
        }
        start = Clock::now();
        const Embedding embedding = embed(*meshed, input.points);
        embedUs.push_back(1000.0 * msSince(start) /
                          double(std::max<Eigen::Index>(1, input.points.rows())));
        mesh = std::move(*meshed);
    }
    const Embedding embedding = embed(*mesh, input.points);
    // The same split as precompute + solve: building the grid once, then per-point queries.
    std::vector<double> buildUs, locateUs;
    for (int run = 0; run < kRuns; ++run) {
        auto start = Clock::now();
        const TriangleLocator locator(mesh->V, mesh->F);
        buildUs.push_back(1000.0 * msSince(start));
        start = Clock::now();
        int found = 0;
        for (Eigen::Index i = 0; i < input.points.rows(); ++i)
            found += locator.locate(input.points.row(i).transpose()).triangle >= 0 ? 1 : 0;
        locateUs.push_back(1000.0 * msSince(start) / double(std::max(1, found)));
    }
    using finbook::bench::median;
    row.insert(QStringLiteral("vertices"), qint64(mesh->V.rows()));
    row.insert(QStringLiteral("triangles"), qint64(mesh->F.rows()));
    row.insert(QStringLiteral("components"), connectedComponents(mesh->F, mesh->V.rows()));
    row.insert(QStringLiteral("min_angle_deg"), minAngleDegrees(mesh->V, mesh->F));
    row.insert(QStringLiteral("silhouette_ms"), median(silhouetteMs));
    row.insert(QStringLiteral("mesh_ms"), median(meshMs));
    row.insert(QStringLiteral("embed_us_per_point"), median(embedUs));
    row.insert(QStringLiteral("embed_points"), qint64(input.points.rows()));
    row.insert(QStringLiteral("locator_build_us"), median(buildUs));
    row.insert(QStringLiteral("locate_us_per_point"), median(locateUs));
    row.insert(QStringLiteral("snapped_points"), embedding.snapped);
    return row;
}

int benchMesh(const QStringList &args)
{
    if (args.isEmpty()) {
        std::fprintf(stderr, "usage: finbook-bench mesh FILE...\n");
        return 2;
    }
    int failures = 0;
    for (const QString &path : args) {
        const std::optional<Input> input = readInput(path);
        QJsonObject row;
        if (!input) {
            row = {{QStringLiteral("file"), QFileInfo(path).fileName()},
                   {QStringLiteral("error"),
                    QStringLiteral("unreadable, or neither strokes nor contours")}};
        } else {
            row = measure(path, *input);
        }
        failures += row.contains(QStringLiteral("error")) ? 1 : 0;
        std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
        std::fflush(stdout);
    }
    return failures == 0 ? 0 : 1;
}

} // namespace

FINBOOK_BENCH("mesh", "FILE... (Quick, Draw! strokes or shape contours as JSON)", benchMesh);
