// finbook-bench cage [--vertices N] [--corners N] [FILE...]: harmonic cage coordinates.
// For each shape — a sketch (strokes) or silhouette (contours) JSON of shared/data, or a 2D
// .off mesh (its boundary is the shape, its vertices the bound points) — fit a cage, build the
// coordinates, bind the points and pose the cage; one JSON object per line. Without files:
// a synthetic 32-corner horseshoe meshed at about 1.4k, 5.4k and 21k vertices, with 10k
// stroke points. Times are medians over several runs: wall clock, its minimum, and CPU time
// (all threads, and the calling thread alone: on a machine busy with other work the wall clock
// grows, while the calling thread's CPU time stays close to the idle machine's wall clock).
#include "../geometry/cage_test_shapes.h"
#include "../geometry/geometry_test_support.h"
#include "bench.h"

#include <finbook/deform/cage/harmonic_cage.h>
#include <finbook/geometry/cage/cage_mesh.h>
#include <finbook/geometry/cage/cage_polygon.h>
#include <finbook/geometry/cage/fit_cage.h>
#include <finbook/geometry/import/off_mesh.h>
#include <finbook/geometry/mesh_quality.h>
#include <finbook/geometry/polyline.h>
#include <finbook/geometry/silhouette.h>

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <time.h>

namespace {

using namespace finbook;
using Clock = std::chrono::steady_clock;

constexpr double kPenWidth = 3.0; // Quick, Draw! strokes carry no width
constexpr int kDragEvents = 200;

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double cpuMs(clockid_t clock)
{
    timespec t{};
    clock_gettime(clock, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

struct Shape {
    QString name;
    geometry::Region region;
    Eigen::MatrixX2d points;              // the bound points: stroke, contour or mesh vertices
    std::optional<Eigen::MatrixX2d> cage; // given (synthetic) instead of fitted
};

Eigen::MatrixX2d stacked(const std::vector<Eigen::MatrixX2d> &parts)
{
    Eigen::Index total = 0;
    for (const auto &p : parts)
        total += p.rows();
    Eigen::MatrixX2d all(total, 2);
    total = 0;
    for (const auto &p : parts) {
        all.middleRows(total, p.rows()) = p;
        total += p.rows();
    }
    return all;
}

std::optional<Shape> readJsonShape(const QString &path, QString &why)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        why = QStringLiteral("unreadable");
        return std::nullopt;
    }
    const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
    Shape shape{QFileInfo(path).fileName(), {}, {}, {}};
    std::vector<Eigen::MatrixX2d> lines;
    if (json.contains(QStringLiteral("strokes"))) {
        std::vector<geometry::StrokeInput> strokes;
        for (const QJsonValue &stroke : json.value(QStringLiteral("strokes")).toArray()) {
            strokes.push_back({finbook::test::toMatrix(stroke.toArray()), kPenWidth});
            lines.push_back(strokes.back().points);
        }
        auto region = geometry::silhouette(strokes);
        if (!region) {
            why = QString::fromStdString(region.error().message);
            return std::nullopt;
        }
        shape.region = std::move(*region);
    } else if (json.contains(QStringLiteral("contours"))) {
        const QJsonArray contours = json.value(QStringLiteral("contours")).toArray();
        geometry::Polygon polygon;
        for (qsizetype i = 0; i < contours.size(); ++i) {
            lines.push_back(finbook::test::toMatrix(contours[i].toArray()));
            (i == 0 ? polygon.outer : polygon.holes.emplace_back()) = lines.back();
        }
        shape.region = {polygon};
    } else {
        why = QStringLiteral("neither strokes nor contours");
        return std::nullopt;
    }
    shape.points = stacked(lines);
    return shape;
}

std::optional<Shape> readOffShape(const QString &path, QString &why)
{
    const auto mesh = geometry::readOff(path.toStdString());
    if (!mesh) {
        why = QString::fromStdString(mesh.error().message);
        return std::nullopt;
    }
    Shape shape{QFileInfo(path).fileName(), {}, mesh->V, {}};
    for (const Eigen::MatrixX2d &ring : geometry::boundaryRings(*mesh))
        if (geometry::signedArea(ring) > 0.0) // outer boundaries; holes do not matter to a cage
            shape.region.push_back({ring, {}});
    return shape;
}

// 32 corners around a 270° band, and `count` points spread inside it.
Shape syntheticShape(int count)
{
    Shape shape;
    shape.cage = finbook::test::horseshoeCage(16, 400.0);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    shape.points.resize(count, 2);
    for (int k = 0; k < count;) {
        const Eigen::RowVector2d p(400.0 * unit(random), 400.0 * unit(random));
        if (geometry::cageOutsidePoints(*shape.cage, p, 1.0).size() == 0)
            shape.points.row(k++) = p;
    }
    return shape;
}

struct Settings {
    long vertices = 3000;
    int corners = 16;
};

QJsonObject measure(const Shape &shape, const Settings &settings, int runs)
{
    QJsonObject row{{QStringLiteral("file"), shape.name}};
    const auto fail = [&](const std::string &message) {
        row.insert(QStringLiteral("error"), QString::fromStdString(message));
        return row;
    };
    Eigen::MatrixX2d cage;
    if (shape.cage) {
        cage = *shape.cage;
    } else {
        geometry::FitCageOptions fit;
        fit.corners = settings.corners;
        const auto start = Clock::now();
        auto fitted = geometry::fitCage(shape.region, shape.points, fit);
        row.insert(QStringLiteral("fit_ms"), msSince(start));
        if (!fitted)
            return fail(fitted.error().message);
        cage = std::move(*fitted);
    }
    deform::CageOptions options;
    options.maxEdge = geometry::cageEdgeLength(cage, settings.vertices);
    std::vector<double> meshMs, totalMs, bindMs, cpuTotalMs, cpuThreadMs;
    std::shared_ptr<const deform::CagePrecompute> d;
    std::optional<deform::CageBinding> binding;
    for (int run = 0; run < runs; ++run) {
        auto start = Clock::now();
        const auto mesh = geometry::meshCage(cage, options.maxEdge);
        meshMs.push_back(msSince(start));
        const double process0 = cpuMs(CLOCK_PROCESS_CPUTIME_ID);
        const double thread0 = cpuMs(CLOCK_THREAD_CPUTIME_ID);
        start = Clock::now();
        auto pre = deform::cagePrecompute(cage, options);
        const double precomputeMs = msSince(start);
        if (!pre)
            return fail(pre.error().message);
        start = Clock::now();
        auto bound = deform::cageBind(**pre, shape.points);
        bindMs.push_back(msSince(start));
        if (!bound)
            return fail(bound.error().message);
        totalMs.push_back(precomputeMs + bindMs.back());
        cpuTotalMs.push_back(cpuMs(CLOCK_PROCESS_CPUTIME_ID) - process0);
        cpuThreadMs.push_back(cpuMs(CLOCK_THREAD_CPUTIME_ID) - thread0);
        d = *pre;
        binding = std::move(*bound);
    }
    Eigen::MatrixX2d out;
    deform::cageDeform(*binding, cage, out);
    const double reproduction = (out - shape.points).cwiseAbs().maxCoeff();
    const double partition = (binding->weights.rowwise().sum().array() - 1.0).abs().maxCoeff();
    // A drag: corner 0 circles, the others stay; each event is one cageDeform.
    std::vector<double> dragMs;
    for (int event = 0; event < kDragEvents; ++event) {
        Eigen::MatrixX2d posed = cage;
        posed.row(0) +=
            0.1 * d->extent * Eigen::RowVector2d(std::cos(0.1 * event), std::sin(0.1 * event));
        const auto start = Clock::now();
        deform::cageDeform(*binding, posed, out);
        dragMs.push_back(msSince(start));
    }
    using bench::median;
    const auto minimum = [](const std::vector<double> &v) {
        return *std::min_element(v.begin(), v.end());
    };
    row.insert(QStringLiteral("cage_vertices"), qint64(cage.rows()));
    row.insert(QStringLiteral("mesh_vertices"), qint64(d->mesh.V.rows()));
    row.insert(QStringLiteral("mesh_triangles"), qint64(d->mesh.F.rows()));
    row.insert(QStringLiteral("lattice_vertices"), d->mesh.latticeVertices);
    row.insert(QStringLiteral("min_angle_deg"), geometry::minAngleDegrees(d->mesh.V, d->mesh.F));
    row.insert(QStringLiteral("precompute_ms"), median(totalMs));
    row.insert(QStringLiteral("precompute_min_ms"), minimum(totalMs));
    row.insert(QStringLiteral("precompute_cpu_ms"), median(cpuTotalMs));
    row.insert(QStringLiteral("precompute_thread_cpu_ms"), median(cpuThreadMs));
    row.insert(QStringLiteral("mesh_ms"), median(meshMs));
    row.insert(QStringLiteral("solve_ms"), median(totalMs) - median(meshMs) - median(bindMs));
    row.insert(QStringLiteral("bind_ms"), median(bindMs));
    row.insert(QStringLiteral("min_coordinate"),
               std::min(d->minCoordinate, binding->weights.minCoeff()));
    row.insert(QStringLiteral("negative_edge_weights"), d->negativeEdgeWeights);
    row.insert(QStringLiteral("reproduction_error"), reproduction);
    row.insert(QStringLiteral("partition_error"), partition);
    row.insert(QStringLiteral("relative_residual"), d->relativeResidual);
    row.insert(QStringLiteral("drag_ms"), median(dragMs));
    row.insert(QStringLiteral("drag_p95_ms"), bench::percentile(dragMs, 0.95));
    row.insert(QStringLiteral("stroke_points"), qint64(shape.points.rows()));
    return row;
}

void print(const QJsonObject &row)
{
    std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
    std::fflush(stdout);
}

int benchCage(const QStringList &arguments)
{
    Settings settings;
    QStringList files;
    for (qsizetype i = 0; i < arguments.size(); ++i) {
        const QString &a = arguments[i];
        if ((a == QLatin1String("--vertices") || a == QLatin1String("--corners")) &&
            i + 1 < arguments.size()) {
            const long value = arguments[++i].toLong();
            if (a == QLatin1String("--vertices"))
                settings.vertices = std::max(3L, value);
            else
                settings.corners = int(std::clamp(value, 3L, 1000L));
        } else {
            files << a;
        }
    }
    int failures = 0;
    if (files.isEmpty()) {
        for (const long target : {1400L, 5400L, 21000L}) {
            Shape shape = syntheticShape(10000);
            shape.name = QStringLiteral("synthetic-horseshoe-%1").arg(target);
            Settings synthetic = settings;
            synthetic.vertices = target;
            const QJsonObject row = measure(shape, synthetic, target > 10000 ? 7 : 11);
            failures += row.contains(QStringLiteral("error")) ? 1 : 0;
            print(row);
        }
        return failures == 0 ? 0 : 1;
    }
    for (const QString &path : files) {
        QString why;
        const std::optional<Shape> shape = path.endsWith(QLatin1String(".off"), Qt::CaseInsensitive)
                                               ? readOffShape(path, why)
                                               : readJsonShape(path, why);
        const QJsonObject row =
            shape ? measure(*shape, settings, 5)
                  : QJsonObject{{QStringLiteral("file"), QFileInfo(path).fileName()},
                                {QStringLiteral("error"), why}};
        failures += row.contains(QStringLiteral("error")) ? 1 : 0;
        print(row);
    }
    return failures == 0 ? 0 : 1;
}

} // namespace

FINBOOK_BENCH("cage",
              "[--vertices N] [--corners N] [FILE...] (sketch/silhouette JSON or 2D .off; "
              "none: synthetic 1.4k/5.4k/21k-vertex cages)",
              benchCage);
