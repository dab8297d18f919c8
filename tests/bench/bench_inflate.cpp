// finbook-bench inflate [--sheet OUT.png] [--obj OUT.obj] [--smoothing S] [--contact-angle A]
// FILE...: inflation of each drawing's
// shape (one object per file, shapes as tst_inflate reads them): time per object, inflated volume,
// and the outline's share of zero heights and horizontal normals. One JSON object per file, then a
// summary line. --sheet renders the normals of every file lit from the upper left, smooth and in
// three cel tones, into one contact sheet; --obj writes every shape as a closed solid into one OBJ
// file (one object per input file). Then the GUI-thread cost of re-shading the posed frame of a
// document (--reshade, default the bundled example; shade_bench.h), and with --shaded-sheet a
// contact sheet of the sketch files filled, shaded, at rest and posed by their skeletons.
#include "../geometry/inflate_test_support.h"
#include "bench.h"
#include "inflate_sheet.h"
#include "shade_bench.h"

#include <finbook/geometry/inflate/inflated_solid.h>
#include <finbook/geometry/inflate/inflation.h>
#include <finbook/geometry/object_mesh.h>

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>

namespace {

using finbook::bench::threadCpuMs;

using namespace finbook::geometry;
using finbook::bench::median;
using finbook::bench::percentile;
using Clock = std::chrono::steady_clock;

constexpr int kRuns = 9;

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct Totals {
    std::vector<double> inflateMs, inflateCpuMs;
    std::vector<ObjObject> solids; // filled only for --obj
    long outline = 0, flat = 0, vertical = 0;
};

QJsonObject measure(const QString &path, const InflateOptions &options, Totals &totals,
                    finbook::bench::InflateSheet *sheet, bool keepSolid)
{
    QJsonObject row{{QStringLiteral("file"), QFileInfo(path).fileName()}};
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        row.insert(QStringLiteral("error"), QStringLiteral("unreadable"));
        return row;
    }
    const auto region =
        finbook::test::shapeOfFile(QJsonDocument::fromJson(file.readAll()).object());
    if (!region) {
        row.insert(QStringLiteral("error"), QString::fromStdString(region.error().message));
        return row;
    }
    auto start = Clock::now();
    const auto mesh = meshRegion(*region);
    const double meshMs = msSince(start);
    if (!mesh) {
        row.insert(QStringLiteral("error"), QString::fromStdString(mesh.error().message));
        return row;
    }
    std::vector<double> inflateMs, cpuMs;
    std::optional<Inflation> inflation;
    for (int run = 0; run < kRuns; ++run) {
        start = Clock::now();
        const double cpuStart = threadCpuMs();
        auto result = inflateObjectMesh(*mesh, options);
        cpuMs.push_back(threadCpuMs() - cpuStart);
        inflateMs.push_back(msSince(start));
        if (!result) {
            row.insert(QStringLiteral("error"), QString::fromStdString(result.error().message));
            return row;
        }
        inflation = std::move(*result);
    }
    const finbook::test::OutlineStats stats = finbook::test::outlineStats(*inflation);
    totals.inflateMs.push_back(median(inflateMs));
    totals.inflateCpuMs.push_back(median(cpuMs));
    totals.outline += stats.vertices;
    totals.flat += stats.flat;
    totals.vertical += stats.vertical;
    const double area = regionArea(mesh->region);
    row.insert(QStringLiteral("vertices"), qint64(inflation->V.rows()));
    row.insert(QStringLiteral("outline_vertices"), qint64(stats.vertices));
    row.insert(QStringLiteral("mesh_ms"), meshMs);
    row.insert(QStringLiteral("inflate_ms"), median(inflateMs));
    row.insert(QStringLiteral("inflate_cpu_ms"), median(cpuMs));
    row.insert(QStringLiteral("volume_px3"), inflatedVolume(*inflation));
    row.insert(QStringLiteral("area_px2"), area);
    row.insert(QStringLiteral("max_height_px"), inflation->height.maxCoeff());
    row.insert(QStringLiteral("outline_flat_share"), double(stats.flat) / double(stats.vertices));
    row.insert(QStringLiteral("outline_horizontal_share"),
               double(stats.vertical) / double(stats.vertices));
    row.insert(QStringLiteral("finite"),
               inflation->height.allFinite() && inflation->normal.allFinite());
    if (sheet)
        sheet->add(*inflation, QFileInfo(path).baseName());
    if (keepSolid) {
        totals.solids.push_back(
            {QFileInfo(path).baseName().toStdString(), inflatedSolid(*inflation)});
        row.insert(QStringLiteral("solid_volume_px3"), signedVolume(totals.solids.back().solid));
    }
    return row;
}

int benchInflate(const QStringList &arguments)
{
    QStringList args = arguments;
    const auto option = [&args](const QString &name) {
        const qsizetype at = args.indexOf(name);
        if (at < 0 || at + 1 >= args.size())
            return QString();
        const QString value = args.at(at + 1);
        args.remove(at, 2);
        return value;
    };
    const QString sheetPath = option(QStringLiteral("--sheet"));
    const QString objPath = option(QStringLiteral("--obj"));
    const QString shadedPath = option(QStringLiteral("--shaded-sheet"));
    const QString shadedCell = option(QStringLiteral("--shaded-cell"));
    QString reshade = option(QStringLiteral("--reshade"));
    const QString reshadeRuns = option(QStringLiteral("--reshade-runs"));
    const QString savePosed = option(QStringLiteral("--save-reshaded"));
    if (reshade.isEmpty())
        reshade = QStringLiteral(FINBOOK_SOURCE_DIR "/resources/examples/walk.finbook");
    InflateOptions options;
    const QString smoothing = option(QStringLiteral("--smoothing"));
    const QString angle = option(QStringLiteral("--contact-angle"));
    if (!smoothing.isEmpty())
        options.outlineSmoothing = smoothing.toDouble();
    if (!angle.isEmpty())
        options.contactAngleDegrees = angle.toDouble();
    if (args.isEmpty()) {
        std::fprintf(
            stderr,
            "usage: finbook-bench inflate [--sheet OUT.png] [--obj OUT.obj] [--smoothing S] "
            "[--contact-angle A] [--reshade DOC.finbook] [--reshade-runs N] "
            "[--save-reshaded OUT.finbook] [--shaded-sheet OUT.png] [--shaded-cell PX] FILE...\n");
        return 2;
    }
    finbook::bench::InflateSheet sheet;
    Totals totals;
    int failures = 0;
    for (const QString &path : args) {
        const QJsonObject row = measure(path, options, totals,
                                        sheetPath.isEmpty() ? nullptr : &sheet, !objPath.isEmpty());
        failures += row.contains(QStringLiteral("error")) ? 1 : 0;
        std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
        std::fflush(stdout);
    }
    const QJsonObject summary{
        {QStringLiteral("summary"), QStringLiteral("inflate")},
        {QStringLiteral("outline_smoothing"), options.outlineSmoothing},
        {QStringLiteral("contact_angle_deg"), options.contactAngleDegrees},
        {QStringLiteral("objects"), qint64(totals.inflateMs.size())},
        {QStringLiteral("failures"), failures},
        {QStringLiteral("inflate_ms_median"), median(totals.inflateMs)},
        {QStringLiteral("inflate_ms_p90"), percentile(totals.inflateMs, 0.9)},
        {QStringLiteral("inflate_ms_max"), percentile(totals.inflateMs, 1.0)},
        {QStringLiteral("inflate_cpu_ms_median"), median(totals.inflateCpuMs)},
        {QStringLiteral("inflate_cpu_ms_p90"), percentile(totals.inflateCpuMs, 0.9)},
        {QStringLiteral("inflate_cpu_ms_max"), percentile(totals.inflateCpuMs, 1.0)},
        {QStringLiteral("outline_vertices"), qint64(totals.outline)},
        {QStringLiteral("outline_flat_share"),
         totals.outline ? double(totals.flat) / double(totals.outline) : 0.0},
        {QStringLiteral("outline_horizontal_share"),
         totals.outline ? double(totals.vertical) / double(totals.outline) : 0.0},
    };
    std::printf("%s\n", QJsonDocument(summary).toJson(QJsonDocument::Compact).constData());
    // Shaded fills: the GUI-thread cost of re-shading a posed frame, and the contact sheet.
    const QJsonObject shade = finbook::bench::reshadeCost(
        reshade, reshadeRuns.isEmpty() ? 15 : reshadeRuns.toInt(), savePosed);
    failures += shade.contains(QStringLiteral("error")) ? 1 : 0;
    std::printf("%s\n", QJsonDocument(shade).toJson(QJsonDocument::Compact).constData());
    if (!shadedPath.isEmpty() &&
        !finbook::bench::shadedSheet(args, shadedPath,
                                     shadedCell.isEmpty() ? 200 : shadedCell.toInt())) {
        std::fprintf(stderr, "cannot write %s\n", qPrintable(shadedPath));
        return 1;
    }
    if (!sheetPath.isEmpty() && !sheet.save(sheetPath)) {
        std::fprintf(stderr, "cannot write %s\n", qPrintable(sheetPath));
        return 1;
    }
    if (!objPath.isEmpty()) {
        std::ofstream out(objPath.toStdString(), std::ios::binary);
        if (!out || !writeObj(out, totals.solids)) {
            std::fprintf(stderr, "cannot write %s\n", qPrintable(objPath));
            return 1;
        }
    }
    return failures == 0 ? 0 : 1;
}

} // namespace

FINBOOK_BENCH("inflate",
              "[--sheet OUT.png] [--obj OUT.obj] [--smoothing S] [--contact-angle A] "
              "[--reshade DOC.finbook] [--reshade-runs N] [--save-reshaded OUT.finbook] "
              "[--shaded-sheet OUT.png [--shaded-cell PX]] FILE... "
              "(strokes or contours as "
              "JSON; re-shading times the example's posed frame)",
              benchInflate);
