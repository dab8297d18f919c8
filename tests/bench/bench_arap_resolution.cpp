// finbook-bench arap-resolution: how fine must the ARAP mesh be for the drawing to stop changing?
// Each drawing (a file of ../shared/data, placed as `finbook-bench import` places it: fitted into
// 1100×600 px, 3 px pen) is meshed at several densities as the app meshes it, plus a reference
// mesh of about 100k vertices (the app's mesher stops near 30k: MeshOptions::maxVertices). Every
// mesh gets the same bend (arap_quality.h's: the left 6 % of the drawing held, the right 6 %
// turned 45° about the held end; the bands are the drawing's, so each mesh pins what lies in
// them), its stored pose is solved as the app solves it (ArapStage::Final), and the drawing's
// own points are carried by each pose (geometry::embed, as the app carries strokes). One row per
// drawing and density: vertices, pins, the stored pose's wall and thread-CPU time and passes,
// and how far the drawing lands from where the 100k mesh puts it (median, p99 and max over the
// drawing's points, in px), then a summary row per density; --png DIR draws the poses over each
// other (drawPicture). The question it answers: which density draws the same picture as
// 100k vertices, so the app never needs to solve 100k.
#include "../geometry/geometry_test_support.h"
#include "arap_quality.h"
#include "bench.h"

#include <finbook/deform/arap.h>
#include <finbook/geometry/embedding.h>
#include <finbook/geometry/object_mesh.h>

#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPainter>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>
#include <optional>

namespace {

using finbook::bench::threadCpuMs;

using namespace finbook;
using Clock = std::chrono::steady_clock;

constexpr double kPenWidth = 3.0;     // px, as `finbook-bench import` draws
constexpr double kBand = 0.06;        // of the drawing's width, pinned at each end
constexpr double kBendDegrees = 45.0; // the right band's turn about the left band
constexpr int kReferenceVertices = 100000;

// The drawing as the app holds it after `finbook-bench import`: strokes fitted into 1100×600.
// Contour files (silhouettes) are outlines: meshed as a region, their points are the outline.
struct Drawing {
    std::vector<geometry::StrokeInput> strokes; // empty for a contour file
    std::optional<geometry::Polygon> region;
    Eigen::MatrixX2d points;        // every point the drawing is made of
    std::vector<Eigen::Index> ends; // where each stroke (or ring) ends in `points`
};

std::optional<Drawing> loadDrawing(const QString &path, QString &error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        error = QStringLiteral("unreadable");
        return std::nullopt;
    }
    const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
    std::vector<Eigen::MatrixX2d> lines;
    const bool contours = json.contains(QStringLiteral("contours"));
    for (const QJsonValue &line :
         json.value(contours ? QStringLiteral("contours") : QStringLiteral("strokes")).toArray())
        lines.push_back(test::toMatrix(line.toArray()));
    Eigen::Index count = 0;
    for (const auto &line : lines)
        count += line.rows();
    if (count == 0) {
        error = QStringLiteral("neither strokes nor contours");
        return std::nullopt;
    }
    Drawing d;
    d.points.resize(count, 2);
    count = 0;
    for (const auto &line : lines) {
        d.points.middleRows(count, line.rows()) = line;
        count += line.rows();
        d.ends.push_back(count);
    }
    const Eigen::RowVector2d low = d.points.colwise().minCoeff(),
                             high = d.points.colwise().maxCoeff();
    const double scale = std::min(1100.0 / std::max(1.0, high.x() - low.x()),
                                  600.0 / std::max(1.0, high.y() - low.y()));
    const Eigen::RowVector2d centre = 0.5 * (low + high), canvas(640.0, 360.0);
    const auto place = [&](Eigen::MatrixX2d &m) {
        m = ((m.rowwise() - centre) * scale).rowwise() + canvas;
    };
    place(d.points);
    if (contours) {
        geometry::Polygon polygon;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            place(lines[i]);
            (i == 0 ? polygon.outer : polygon.holes.emplace_back()) = lines[i];
        }
        d.region = std::move(polygon);
    } else {
        for (auto &line : lines) {
            place(line);
            d.strokes.push_back({std::move(line), kPenWidth});
        }
    }
    return d;
}

struct Posed {
    Eigen::Index vertices = 0, triangles = 0, pins = 0;
    double ms = 0.0, cpuMs = 0.0;
    int passes = 0;
    bool converged = false;
    int snapped = 0;
    Eigen::MatrixX2d points; // the drawing's points, carried by the stored pose
};

std::optional<Posed> pose(const Drawing &drawing, const geometry::MeshOptions &options,
                          const deform::ArapOptions &arapOptions, QString &error)
{
    auto mesh = drawing.region
                    ? geometry::buildObjectMesh(geometry::Region{*drawing.region}, options)
                    : geometry::buildObjectMesh(drawing.strokes, options);
    if (!mesh) {
        error = QString::fromStdString(mesh.error().message);
        return std::nullopt;
    }
    const Eigen::MatrixX2d &V = mesh->V;
    // The bands and the turn's centre come from the drawing, not the mesh: every mesh gets the
    // same bend.
    const double low = drawing.points.col(0).minCoeff(), high = drawing.points.col(0).maxCoeff();
    const double width = high - low;
    Eigen::RowVector2d centre = Eigen::RowVector2d::Zero();
    int held = 0;
    for (Eigen::Index k = 0; k < drawing.points.rows(); ++k)
        if (drawing.points(k, 0) <= low + kBand * width) {
            centre += drawing.points.row(k);
            ++held;
        }
    const test::BendPins bend =
        test::bendBands(V, low, high, centre / double(std::max(1, held)), kBendDegrees);
    auto data = deform::arapPrecompute(V, mesh->F, bend.b, arapOptions);
    if (!data) {
        error = QStringLiteral("precompute failed");
        return std::nullopt;
    }
    Posed p;
    p.vertices = V.rows();
    p.triangles = mesh->F.rows();
    p.pins = bend.b.size();
    Eigen::MatrixX2d U;
    const double cpuStart = threadCpuMs();
    const auto start = Clock::now();
    auto report = deform::arapSolve(**data, bend.bc, U, deform::ArapStage::Final);
    p.ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    p.cpuMs = threadCpuMs() - cpuStart;
    if (!report) {
        error = QStringLiteral("solve failed");
        return std::nullopt;
    }
    p.passes = report->passes;
    p.converged = report->converged;
    const geometry::Embedding embedding = geometry::embed(V, mesh->F, drawing.points);
    p.snapped = embedding.snapped;
    p.points = geometry::applyEmbedding(embedding, U, mesh->F);
    return p;
}

// The rest drawing in light grey, the 100k pose in black and each density's pose in its colour
// (1 red, 2 orange, 4 blue), fitted into 800 px wide: where the colours leave the black line the
// mesh was too coarse to draw that part the same.
void drawPicture(const QString &file, const Drawing &drawing,
                 const std::vector<std::pair<double, Eigen::MatrixX2d>> &poses,
                 const Eigen::MatrixX2d &reference)
{
    Eigen::MatrixX2d all(drawing.points.rows() * Eigen::Index(poses.size() + 2), 2);
    all.topRows(drawing.points.rows()) = drawing.points;
    all.middleRows(drawing.points.rows(), reference.rows()) = reference;
    for (std::size_t k = 0; k < poses.size(); ++k)
        all.middleRows(drawing.points.rows() * Eigen::Index(k + 2), reference.rows()) =
            poses[k].second;
    const Eigen::RowVector2d low = all.colwise().minCoeff(), high = all.colwise().maxCoeff();
    const double scale = 760.0 / std::max(1.0, high.x() - low.x());
    QImage image(800, int(std::ceil((high.y() - low.y()) * scale)) + 40, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    const auto draw = [&](const Eigen::MatrixX2d &points, const QColor &colour, double width) {
        painter.setPen(QPen(colour, width, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        Eigen::Index begin = 0;
        for (const Eigen::Index end : drawing.ends) {
            QPolygonF line;
            for (Eigen::Index k = begin; k < end; ++k)
                line << QPointF(20.0 + (points(k, 0) - low.x()) * scale,
                                20.0 + (points(k, 1) - low.y()) * scale);
            painter.drawPolyline(line);
            begin = end;
        }
    };
    draw(drawing.points, QColor(200, 200, 200), 1.5);
    draw(reference, Qt::black, 2.5);
    for (const auto &[density, points] : poses)
        draw(points,
             density <= 1.0   ? QColor(220, 40, 40, 200)
             : density <= 2.0 ? QColor(240, 150, 0, 200)
                              : QColor(40, 90, 230, 200),
             1.2);
    painter.end();
    image.save(file);
}

int benchArapResolution(const QStringList &arguments)
{
    QStringList files = arguments;
    QList<double> densities{1.0, 2.0, 4.0};
    if (const int at = int(files.indexOf(QStringLiteral("--densities")));
        at >= 0 && at + 1 < files.size()) {
        densities.clear();
        for (const QString &s : files[at + 1].split(QLatin1Char(','), Qt::SkipEmptyParts))
            densities.append(std::clamp(s.toDouble(), 0.01, 100.0));
        files.remove(at, 2);
    }
    QString pngDirectory;
    if (const int at = int(files.indexOf(QStringLiteral("--png")));
        at >= 0 && at + 1 < files.size()) {
        pngDirectory = files[at + 1];
        files.remove(at, 2);
    }
    // --tight: the reference runs until no vertex moves by 1e-9 of the size in a pass (the app
    // stops at 1e-6 with the energy settled), to tell the coarse meshes' error from the
    // reference's own.
    deform::ArapOptions referenceOptions;
    if (const int at = int(files.indexOf(QStringLiteral("--tight"))); at >= 0) {
        referenceOptions.finalTolerance = 1e-9;
        referenceOptions.finalEnergyTolerance = 0.0;
        referenceOptions.finalPassCap = 20000;
        files.remove(at);
    }
    int failures = 0;
    std::map<QString, std::vector<QJsonObject>> byDensity; // for the summary rows
    for (const QString &path : files) {
        const QString name = QFileInfo(path).fileName();
        QString error;
        const auto drawing = loadDrawing(path, error);
        // The reference: the app's mesher with its ceiling raised to 100k vertices.
        geometry::MeshOptions fine;
        fine.maxVertices = kReferenceVertices;
        fine.targetVertices = kReferenceVertices;
        const auto reference =
            drawing ? pose(*drawing, fine, referenceOptions, error) : std::nullopt;
        if (!reference) {
            std::printf("%s\n", QJsonDocument(QJsonObject{{QStringLiteral("bench"),
                                                           QStringLiteral("arap-resolution")},
                                                          {QStringLiteral("file"), name},
                                                          {QStringLiteral("error"), error}})
                                    .toJson(QJsonDocument::Compact)
                                    .constData());
            ++failures;
            continue;
        }
        const Eigen::RowVector2d extent =
            drawing->points.colwise().maxCoeff() - drawing->points.colwise().minCoeff();
        const auto row = [&](const QJsonValue &density, const Posed &p) {
            std::vector<double> distance(std::size_t(p.points.rows()));
            for (Eigen::Index k = 0; k < p.points.rows(); ++k)
                distance[std::size_t(k)] = (p.points.row(k) - reference->points.row(k)).norm();
            const bool finite = p.points.allFinite();
            QJsonObject out{
                {QStringLiteral("bench"), QStringLiteral("arap-resolution")},
                {QStringLiteral("file"), name},
                {QStringLiteral("density"), density},
                {QStringLiteral("vertices"), qint64(p.vertices)},
                {QStringLiteral("triangles"), qint64(p.triangles)},
                {QStringLiteral("pins"), qint64(p.pins)},
                {QStringLiteral("stored_ms"), p.ms},
                {QStringLiteral("stored_cpu_ms"), p.cpuMs},
                {QStringLiteral("stored_passes"), p.passes},
                {QStringLiteral("stored_converged"), p.converged},
                {QStringLiteral("points"), qint64(p.points.rows())},
                {QStringLiteral("points_snapped"), p.snapped},
                {QStringLiteral("drawing_diagonal_px"), extent.norm()},
                {QStringLiteral("from_100k_median_px"),
                 finite ? QJsonValue(finbook::bench::median(distance)) : QJsonValue()},
                {QStringLiteral("from_100k_p99_px"),
                 finite ? QJsonValue(finbook::bench::percentile(distance, 0.99)) : QJsonValue()},
                {QStringLiteral("from_100k_max_px"),
                 finite ? QJsonValue(*std::max_element(distance.begin(), distance.end()))
                        : QJsonValue()},
            };
            std::printf("%s\n", QJsonDocument(out).toJson(QJsonDocument::Compact).constData());
            std::fflush(stdout);
            byDensity[density.isString() ? density.toString() : QString::number(density.toDouble())]
                .push_back(out);
        };
        std::vector<std::pair<double, Eigen::MatrixX2d>> poses;
        for (const double density : densities) {
            geometry::MeshOptions options;
            options.density = density;
            const auto posed = pose(*drawing, options, deform::ArapOptions{}, error);
            if (!posed) {
                ++failures;
                continue;
            }
            row(density, *posed);
            poses.emplace_back(density, posed->points);
        }
        if (!pngDirectory.isEmpty())
            drawPicture(pngDirectory + QLatin1Char('/') + QFileInfo(path).completeBaseName() +
                            QStringLiteral(".png"),
                        *drawing, poses, reference->points);
        row(QStringLiteral("100k"), *reference);
    }
    // One summary row per density: the worst drawing decides whether it draws the same picture.
    for (const auto &[density, rows] : byDensity) {
        const auto column = [&rows](const char *key) {
            std::vector<double> values;
            for (const QJsonObject &r : rows)
                if (r.value(QLatin1String(key)).isDouble())
                    values.push_back(r.value(QLatin1String(key)).toDouble());
            return values;
        };
        const auto maxOf = [](const std::vector<double> &v) {
            return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
        };
        int converged = 0;
        for (const QJsonObject &r : rows)
            converged += r.value(QStringLiteral("stored_converged")).toBool() ? 1 : 0;
        const QJsonObject summary{
            {QStringLiteral("bench"), QStringLiteral("arap-resolution")},
            {QStringLiteral("summary"), true},
            {QStringLiteral("density"), density},
            {QStringLiteral("files"), qint64(rows.size())},
            {QStringLiteral("vertices_median"), finbook::bench::median(column("vertices"))},
            {QStringLiteral("vertices_max"), maxOf(column("vertices"))},
            {QStringLiteral("from_100k_median_px_median"),
             finbook::bench::median(column("from_100k_median_px"))},
            {QStringLiteral("from_100k_max_px_median"),
             finbook::bench::median(column("from_100k_max_px"))},
            {QStringLiteral("from_100k_max_px_worst"), maxOf(column("from_100k_max_px"))},
            {QStringLiteral("stored_cpu_ms_median"),
             finbook::bench::median(column("stored_cpu_ms"))},
            {QStringLiteral("stored_cpu_ms_max"), maxOf(column("stored_cpu_ms"))},
            {QStringLiteral("stored_ms_median"), finbook::bench::median(column("stored_ms"))},
            {QStringLiteral("stored_ms_max"), maxOf(column("stored_ms"))},
            {QStringLiteral("stored_converged"), converged},
        };
        std::printf("%s\n", QJsonDocument(summary).toJson(QJsonDocument::Compact).constData());
    }
    return failures == 0 ? 0 : 1;
}

} // namespace

FINBOOK_BENCH("arap-resolution", "[--densities 1,2,4] [--tight] [--png DIR] FILE...",
              benchArapResolution);
