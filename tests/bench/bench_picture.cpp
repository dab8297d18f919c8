// finbook-bench picture [--silhouettes DIR [--render-to DIR]] [--redraws N] [--vertices N]
// [--view-turn DEG] [FILE...]: pictures as deformable objects (issue 51). Per layer of each PNG
// or OpenRaster file: read time, alpha trace time and outline size, quality mesh time and size
// (the outline meshed as object shapes are, with MeshOptions::targetVertices = --vertices, 2000
// by default; the mesher lands at 1.2-3 times that), the rest pose drawn through the mesh
// against the original pixels (PSNR), the redraw time of a posed picture into a 1920 × 1080
// canvas (median and p99 over --redraws; --view-turn DEG turns the canvas view by DEG degrees),
// and the memory a picture holds (texture + mesh). --silhouettes renders each shape of
// shared/data/silhouettes as a 1024 × 1024 RGBA picture with a painted texture and an
// anti-aliased edge (kept in --render-to's folder), and benches those too. One JSON object per
// layer per line; never gates.
#include "bench.h"

#include <finbook/geometry/object_mesh.h>
#include <finbook/geometry/region.h>
#include <finbook/model/commands.h>
#include <finbook/model/document.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/picture/picture_commands.h>
#include <finbook/model/picture/picture_import.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/picture/picture_shape.h>
#include <finbook/model/picture/textured_mesh.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPainter>
#include <QPainterPath>
#include <QTemporaryDir>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace {

using namespace finbook;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double processCpuMs()
{
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

struct PictureBenchOptions {
    int redraws = 200;
    int vertices = 2000;
    double viewTurn = 0.0; // degrees the canvas view is turned by (View → Rotate)
};

// A painted texture: two colour gradients, soft stripes and a little grain, like a painted
// character's fill (not flat, so resampling errors show in the PSNR).
QImage paintedTexture(int size)
{
    QImage texture(size, size, QImage::Format_RGB32);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double s = 0.5 + 0.5 * std::sin((x + 2 * y) * 0.05);
            const int grain = int(((unsigned(x) * 73856093u) ^ (unsigned(y) * 19349663u)) & 15u);
            texture.setPixel(x, y,
                             qRgb(int(60 + 150 * x / size + 20 * s) & 255,
                                  int(40 + 120 * y / size + grain) & 255, int(90 + 100 * s)));
        }
    return texture;
}

// A shared/data silhouette (outer contour and holes) filled into a size × size RGBA picture
// with the painted texture, anti-aliased; null when the file is not a silhouette.
QImage renderSilhouette(const QString &path, int size, const QImage &texture)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    const QJsonArray contours = QJsonDocument::fromJson(file.readAll())
                                    .object()
                                    .value(QStringLiteral("contours"))
                                    .toArray();
    QPainterPath shape;
    shape.setFillRule(Qt::OddEvenFill);
    for (const QJsonValue &contour : contours) {
        QPolygonF ring;
        for (const QJsonValue &p : contour.toArray())
            ring << QPointF(p.toArray().at(0).toDouble(), p.toArray().at(1).toDouble());
        shape.addPolygon(ring);
        shape.closeSubpath();
    }
    if (shape.isEmpty())
        return {};
    const QRectF box = shape.boundingRect();
    const double scale = (size - 32) / std::max(box.width(), box.height());
    QImage picture(size, size, QImage::Format_ARGB32_Premultiplied);
    picture.fill(Qt::transparent);
    QPainter painter(&picture);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.translate(size / 2.0, size / 2.0);
    painter.scale(scale, scale);
    painter.translate(-box.center());
    painter.setPen(Qt::NoPen);
    QBrush brush(texture);
    brush.setTransform(painter.transform().inverted()); // texture pixels are picture pixels
    painter.setBrush(brush);
    painter.drawPath(shape);
    return picture;
}

// PSNR (dB) of two same-sized premultiplied images over every channel; NaN when identical.
std::pair<double, int> psnrAndWorst(const QImage &a, const QImage &b)
{
    double sum = 0.0;
    int worst = 0;
    for (int y = 0; y < a.height(); ++y) {
        const auto *p = reinterpret_cast<const QRgb *>(a.constScanLine(y));
        const auto *q = reinterpret_cast<const QRgb *>(b.constScanLine(y));
        for (int x = 0; x < a.width(); ++x)
            for (int shift = 0; shift < 32; shift += 8) {
                const int d = int((p[x] >> shift) & 0xff) - int((q[x] >> shift) & 0xff);
                sum += double(d) * d;
                worst = std::max(worst, std::abs(d));
            }
    }
    const double mse = sum / (4.0 * a.width() * a.height());
    return {mse == 0.0 ? std::nan("") : 10.0 * std::log10(255.0 * 255.0 / mse), worst};
}

// The mesh must hold the centre of every pixel that shows (textured_mesh.h): the outline at
// alpha ≥ 1, simplified by less than the half pixel between such a centre and the outline.
geometry::AlphaOutlineOptions meshOutlineOptions()
{
    geometry::AlphaOutlineOptions options;
    options.threshold = 1;
    options.simplify = 0.3; // with the mesher's own 0.1 below: 0.4 < 0.5
    options.minArea = 0.0;
    return options;
}

// A smooth pose: every vertex pushed by a few pixels along slow waves, as a pin drag bends a
// character, then the whole placed in the middle of the canvas.
Eigen::MatrixX2d posed(const Eigen::MatrixX2d &V, double amplitude)
{
    Eigen::MatrixX2d out = V;
    for (Eigen::Index i = 0; i < V.rows(); ++i) {
        out(i, 0) += amplitude * std::sin(V(i, 1) * 0.01);
        out(i, 1) += amplitude * std::cos(V(i, 0) * 0.013);
    }
    return out;
}

// Redraws of the posed picture into a 1920 × 1080 canvas: drawTexturedMesh alone and with the
// canvas cleared first (what a canvas repaint does).
void benchRedraw(QJsonObject &row, const model::PictureLayer &layer,
                 const geometry::ObjectMesh &mesh, int redraws, double viewTurn)
{
    QImage canvas(1920, 1080, QImage::Format_ARGB32_Premultiplied);
    QTransform view; // the picture's centre in the canvas's middle, turned about it
    view.translate(960, 540).rotate(viewTurn).translate(-layer.image.width() / 2.0,
                                                        -layer.image.height() / 2.0);
    std::vector<double> draw, redraw, cpu;
    for (int i = 0; i < redraws; ++i) {
        const Eigen::MatrixX2d V = posed(mesh.V, 4.0 + (i % 10)); // a drag: a new pose each time
        const auto start = Clock::now();
        canvas.fill(Qt::transparent);
        const auto cleared = Clock::now();
        const double cpuBefore = processCpuMs();
        model::drawTexturedMesh(canvas, view, layer.image, mesh.V, V, mesh.F);
        cpu.push_back(processCpuMs() - cpuBefore);
        draw.push_back(msSince(cleared));
        redraw.push_back(msSince(start));
    }
    // CPU time of both drawing threads together: on a busy machine the wall time above is
    // longer by the time other processes take the cores away.
    row[QStringLiteral("draw_cpu_median_ms")] = bench::median(cpu);
    row[QStringLiteral("draw_cpu_p99_ms")] = bench::percentile(cpu, 0.99);
    row[QStringLiteral("redraws")] = redraws;
    row[QStringLiteral("draw_median_ms")] = bench::median(draw);
    row[QStringLiteral("draw_p99_ms")] = bench::percentile(draw, 0.99);
    row[QStringLiteral("redraw_median_ms")] = bench::median(redraw);
    row[QStringLiteral("redraw_p99_ms")] = bench::percentile(redraw, 0.99);
}

// The rest pose drawn through the mesh against the picture's own pixels.
void benchRest(QJsonObject &row, const model::PictureLayer &layer, const geometry::ObjectMesh &mesh)
{
    QImage rest(layer.image.size(), QImage::Format_ARGB32_Premultiplied);
    rest.fill(Qt::transparent);
    model::drawTexturedMesh(rest, QTransform(), layer.image, mesh.V, mesh.V, mesh.F);
    const auto [psnr, worst] = psnrAndWorst(rest, layer.image);
    row[QStringLiteral("rest_psnr_db")] = std::isnan(psnr) ? QJsonValue() : QJsonValue(psnr);
    row[QStringLiteral("rest_identical")] = std::isnan(psnr);
    row[QStringLiteral("rest_max_channel_diff")] = worst;
}

QJsonObject benchLayer(const model::PictureLayer &layer, const PictureBenchOptions &options)
{
    QJsonObject row;
    row[QStringLiteral("layer")] = layer.name;
    row[QStringLiteral("width")] = layer.image.width();
    row[QStringLiteral("height")] = layer.image.height();
    auto start = Clock::now();
    const auto shape = model::pictureShape(layer.image);
    row[QStringLiteral("trace_ms")] = msSince(start);
    if (!shape) {
        row[QStringLiteral("error")] = QString::fromStdString(shape.error().message);
        return row;
    }
    row[QStringLiteral("outline_polygons")] = qint64(shape->size());
    row[QStringLiteral("outline_vertices")] = qint64(geometry::regionVertexCount(*shape));
    start = Clock::now();
    const auto cover = model::pictureShape(layer.image, meshOutlineOptions());
    geometry::MeshOptions meshOptions;
    meshOptions.targetVertices = options.vertices;
    meshOptions.repair.cornerRadius = 0.0; // rounding corners would cut visible pixels off
    meshOptions.repair.simplifyTolerance = 0.1;
    if (!cover) {
        row[QStringLiteral("error")] = QString::fromStdString(cover.error().message);
        return row;
    }
    auto mesh = geometry::buildObjectMesh(*cover, meshOptions);
    row[QStringLiteral("mesh_ms")] = msSince(start); // its own trace at alpha ≥ 1 included
    if (!mesh) {
        row[QStringLiteral("error")] = QString::fromStdString(mesh.error().message);
        return row;
    }
    mesh->F = model::drawingOrder(mesh->V, mesh->F); // as meshPicture orders them
    row[QStringLiteral("mesh_area_px")] = geometry::regionArea(mesh->region); // pixels drawn
    row[QStringLiteral("mesh_vertices")] = qint64(mesh->V.rows());
    row[QStringLiteral("mesh_triangles")] = qint64(mesh->F.rows());
    benchRest(row, layer, *mesh);
    benchRedraw(row, layer, *mesh, options.redraws, options.viewTurn);
    if (options.viewTurn != 0.0)
        row[QStringLiteral("view_turn_deg")] = options.viewTurn;
    // uv and V (n × 2 doubles each) and F (m × 3 ints): what a posed picture object holds.
    const qint64 meshBytes = mesh->V.rows() * 2 * 8 * 2 + mesh->F.rows() * 3 * 4;
    row[QStringLiteral("texture_bytes")] = qint64(layer.image.sizeInBytes());
    row[QStringLiteral("mesh_bytes")] = meshBytes;
    return row;
}

void benchFile(const QString &path, const PictureBenchOptions &options)
{
    const auto start = Clock::now();
    const auto layers = model::readPictureLayers(path);
    const double readMs = msSince(start);
    if (!layers) {
        QJsonObject row{{QStringLiteral("bench"), QStringLiteral("picture")},
                        {QStringLiteral("file"), QFileInfo(path).fileName()},
                        {QStringLiteral("error"), layers.error()}};
        std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
        return;
    }
    for (const model::PictureLayer &layer : *layers) {
        QJsonObject row = benchLayer(layer, options);
        row[QStringLiteral("bench")] = QStringLiteral("picture");
        row[QStringLiteral("file")] = QFileInfo(path).fileName();
        row[QStringLiteral("layers_in_file")] = qint64(layers->size());
        row[QStringLiteral("read_ms")] = readMs; // the whole file
        row[QStringLiteral("peak_rss_mb")] = double(bench::peakResidentBytes()) / (1 << 20);
        std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
        std::fflush(stdout);
    }
}

// --finbook OUT: every file's pictures as picture objects (File → Import Picture's work), one
// frame per file, saved as a document to open in Finbook; each file's import time and the
// saved size are printed.
int saveDocument(const QStringList &files, const QString &out)
{
    model::Document doc;
    std::vector<std::vector<model::StrokeGroup>> imported;
    for (const QString &file : files) {
        const auto start = Clock::now();
        auto objects = model::pictureObjectsFromFile(file, QSizeF(1920, 1080));
        QJsonObject row{{QStringLiteral("bench"), QStringLiteral("picture_import")},
                        {QStringLiteral("file"), QFileInfo(file).fileName()},
                        {QStringLiteral("import_ms"), msSince(start)}};
        if (!objects)
            row[QStringLiteral("error")] = objects.error();
        else
            row[QStringLiteral("objects")] = qint64(objects->size());
        std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
        if (objects)
            imported.push_back(std::move(*objects));
    }
    model::DocumentSettings settings = doc.settings();
    settings.canvasSize = QSize(1920, 1080);
    doc.undoStack()->push(new model::ChangeSettingsCommand(&doc, settings));
    for (std::size_t i = 0; i < imported.size(); ++i) {
        doc.undoStack()->push(new model::InsertFrameCommand(&doc, int(i)));
        doc.undoStack()->push(new model::ImportPictureCommand(&doc, doc.frameAt(int(i)).id, -1,
                                                              std::move(imported[i])));
    }
    if (const auto error = model::saveFinbook(doc, out)) {
        std::fprintf(stderr, "%s\n", qPrintable(error->message));
        return 1;
    }
    QJsonObject row{{QStringLiteral("bench"), QStringLiteral("picture_document")},
                    {QStringLiteral("file"), out},
                    {QStringLiteral("bytes"), QFileInfo(out).size()}};
    std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
    return 0;
}

int benchPicture(const QStringList &args)
{
    PictureBenchOptions options;
    QStringList files;
    QString silhouettes, renderTo, finbook;
    for (int i = 0; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--silhouettes") && i + 1 < args.size())
            silhouettes = args[++i];
        else if (args[i] == QLatin1String("--render-to") && i + 1 < args.size())
            renderTo = args[++i];
        else if (args[i] == QLatin1String("--redraws") && i + 1 < args.size())
            options.redraws = std::max(1, args[++i].toInt());
        else if (args[i] == QLatin1String("--finbook") && i + 1 < args.size())
            finbook = args[++i];
        else if (args[i] == QLatin1String("--vertices") && i + 1 < args.size())
            options.vertices = std::max(10, args[++i].toInt());
        else if (args[i] == QLatin1String("--view-turn") && i + 1 < args.size())
            options.viewTurn = args[++i].toDouble();
        else
            files << args[i];
    }
    QTemporaryDir temporary;
    const QDir rendered(renderTo.isEmpty() ? temporary.path() : renderTo);
    if (!silhouettes.isEmpty()) {
        const QImage texture = paintedTexture(1024);
        const QDir dir(silhouettes);
        for (const QString &name : dir.entryList({QStringLiteral("*.json")}, QDir::Files)) {
            const QImage picture = renderSilhouette(dir.filePath(name), 1024, texture);
            const QString png = rendered.filePath(QFileInfo(name).completeBaseName() + ".png");
            if (!picture.isNull() && picture.save(png))
                files << png;
        }
    }
    if (files.isEmpty()) {
        std::fprintf(stderr, "usage: finbook-bench picture [--silhouettes DIR [--render-to DIR]] "
                             "[--redraws N] [--vertices N] [--view-turn DEG] [--finbook OUT] "
                             "FILE...\n");
        return 2;
    }
    if (!finbook.isEmpty())
        return saveDocument(files, finbook);
    for (const QString &file : files)
        benchFile(file, options);
    return 0;
}

} // namespace

FINBOOK_BENCH("picture",
              "[--silhouettes DIR [--render-to DIR]] [--redraws N] [--vertices N] "
              "[--view-turn DEG] [--finbook OUT] FILE...  "
              "pictures (PNG, .ora) as "
              "deformable objects: trace, mesh, rest PSNR, 1080p redraw",
              benchPicture);
