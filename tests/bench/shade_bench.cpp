// Re-shading cost and the shaded contact sheet (shade_bench.h).
#include "shade_bench.h"

#include "bench.h"

#include <finbook/model/deform_setup.h>
#include <finbook/model/document.h>
#include <finbook/model/fill/fill_regions.h>
#include <finbook/model/fill/fill_render.h>
#include <finbook/model/fill/fill_resolve.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/render.h>
#include <finbook/model/skeleton/skeleton_commands.h>

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QPainter>

#include <chrono>
#include <cstdio>
#include <ctime>

namespace finbook::bench {

namespace {
using namespace finbook::model;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

constexpr QRgb kPalette[] = {0xfff2c9a0, 0xff5b8fd6, 0xffe0704a, 0xff7fbf6a, 0xffc58fd8};

// Every fill of the group shaded in three tones with a rim; every enclosed region without a
// fill gets one first (a palette colour per object). Returns the number of fills.
int shadeEverything(StrokeGroup &group, double closeGap, QRgb color)
{
    const ObjectRegionsPtr regions = objectRegions(group, closeGap);
    if (auto fills = fillsWithAllFaces(*regions, group.fills, color))
        group.fills = std::move(*fills);
    for (Fill &f : group.fills)
        f.shading = {ShadeRamp::ThreeTones, true};
    return int(group.fills.size());
}

bool poseWithRig(StrokeGroup &group, const Rig &rig);

// Every bone of the object's automatic skeleton bent by ±0.45 rad (or its own rig, solved).
bool poseBent(StrokeGroup &group)
{
    if (!group.rig.empty() && group.rig.isPosed())
        return poseWithRig(group, group.rig);
    auto skeleton = buildSkeletonRig(group);
    if (!skeleton)
        return false;
    Rig rig;
    rig.skeleton = *skeleton;
    for (std::size_t j = 0; j < rig.skeleton.angles.size(); ++j)
        if (rig.skeleton.parent[j] >= 0)
            rig.skeleton.angles[j] = (j % 2 ? 0.45 : -0.45);
    return poseWithRig(group, rig);
}

bool poseWithRig(StrokeGroup &group, const Rig &rig)
{
    group.rig = rig;
    DeformJob job;
    job.groupId = group.id;
    job.key = MeshKey::of(group, -1.0);
    job.rig = rig.atRest();
    const auto setup = buildDeformSetup(job);
    if (!setup)
        return false;
    const auto solved = solvePose(**setup, group);
    if (!solved)
        return false;
    group.deformed = solved->strokes;
    return true;
}
} // namespace

QJsonObject reshadeCost(const QString &finbook, int runs, const QString &savePosed)
{
    runs = std::clamp(runs, 1, 100000);
    QJsonObject row{{QStringLiteral("reshade"), QFileInfo(finbook).fileName()}};
    auto loaded = loadFinbook(finbook);
    if (!loaded) {
        row.insert(QStringLiteral("error"), loaded.error().message);
        return row;
    }
    std::size_t best = 0;
    int bestPosed = -1;
    for (std::size_t f = 0; f < loaded->frames.size(); ++f) {
        int posed = 0;
        for (const StrokeGroup &g : loaded->frames[f].groups)
            posed += g.isDeformed() ? 1 : 0;
        if (posed > bestPosed) {
            bestPosed = posed;
            best = f;
        }
    }
    if (loaded->frames.empty()) {
        row.insert(QStringLiteral("error"), QStringLiteral("no frame"));
        return row;
    }
    Frame frame = loaded->frames[best];
    DocumentSettings settings = loaded->settings;
    // An object the file shows unposed is posed here: its own rig solved, or its automatic
    // skeleton with every bone bent (the cost of re-shading is that of a posed frame).
    int posedHere = 0;
    for (StrokeGroup &g : frame.groups)
        if (!g.isDeformed())
            posedHere += poseBent(g) ? 1 : 0;
    int fills = 0, k = 0;
    for (StrokeGroup &g : frame.groups)
        fills += shadeEverything(g, settings.closeGap, kPalette[k++ % std::size(kPalette)]);
    // Once per drawing (cached by content; the rest inflation of each face).
    auto start = Clock::now();
    int tones = 0;
    for (const StrokeGroup &g : frame.groups)
        for (const FillItem &item : fillList(g, settings))
            tones += int(item.tones.size());
    const double restMs = msSince(start);
    std::vector<double> wall, cpu, paint;
    QImage image(settings.canvasSize, QImage::Format_ARGB32_Premultiplied);
    for (int run = 0; run < runs; ++run) {
        settings.lightAzimuth =
            100.0 + 15.0 * run / runs; // a new light: every fill re-lit and re-cut
        start = Clock::now();
        const double cpuStart = threadCpuMs();
        for (const StrokeGroup &g : frame.groups)
            fillList(g, settings);
        cpu.push_back(threadCpuMs() - cpuStart);
        wall.push_back(msSince(start));
        start = Clock::now();
        QPainter painter(&image);
        paintFrame(painter, frame, settings);
        painter.end();
        paint.push_back(msSince(start));
    }
    // A new pose of every object (a new frame of an animation): posing, lighting and cutting
    // every fill's tones again.
    std::vector<double> allPosed;
    for (int run = 0; run < runs; ++run) {
        for (StrokeGroup &g : frame.groups)
            if (g.isDeformed())
                g.deformed = std::make_shared<const DeformedStrokes>(*g.deformed);
        const double cpuStart = threadCpuMs();
        for (const StrokeGroup &g : frame.groups)
            fillList(g, settings);
        allPosed.push_back(threadCpuMs() - cpuStart);
    }
    row.insert(QStringLiteral("reshade_new_pose_all_objects_cpu_ms_median"), median(allPosed));
    // A drag poses one object: only its tones are recomputed, the others come from the cache.
    std::size_t largest = 0;
    for (std::size_t i = 0; i < frame.groups.size(); ++i)
        if (frame.groups[i].fills.size() > frame.groups[largest].fills.size())
            largest = i;
    std::vector<double> one;
    for (int run = 0; run < runs && frame.groups[largest].isDeformed(); ++run) {
        StrokeGroup &g = frame.groups[largest];
        g.deformed = std::make_shared<const DeformedStrokes>(*g.deformed); // a new pose
        const double cpuStart = threadCpuMs();
        for (const StrokeGroup &group : frame.groups)
            fillList(group, settings);
        one.push_back(threadCpuMs() - cpuStart);
    }
    row.insert(QStringLiteral("reshade_one_posed_object_cpu_ms_median"), median(one));
    row.insert(QStringLiteral("frame"), qint64(best));
    row.insert(QStringLiteral("objects"), qint64(frame.groups.size()));
    row.insert(QStringLiteral("posed_in_file"), bestPosed);
    row.insert(QStringLiteral("posed_here"), posedHere);
    row.insert(QStringLiteral("shaded_fills"), fills);
    row.insert(QStringLiteral("tone_regions"), tones);
    row.insert(QStringLiteral("rest_inflation_ms_once"), restMs);
    row.insert(QStringLiteral("reshade_ms_median"), median(wall));
    row.insert(QStringLiteral("reshade_cpu_ms_median"), median(cpu));
    row.insert(QStringLiteral("reshade_ms_max"), percentile(wall, 1.0));
    row.insert(QStringLiteral("paint_frame_ms_median"), median(paint));
    if (!savePosed.isEmpty()) { // the frame timed, to look at it in the app
        LoadedDocument shown = *loaded;
        shown.frames = {frame};
        shown.settings.lightAzimuth = 135.0;
        Document doc;
        adoptLoadedDocument(doc, std::move(shown));
        if (saveFinbook(doc, savePosed))
            row.insert(QStringLiteral("error"), QStringLiteral("cannot write ") + savePosed);
    }
    row.insert(QStringLiteral("rendered_as"),
               QStringLiteral("QPainter fills of tone polygons over each fill, under the ink"));
    return row;
}

namespace {
// The drawing of a sketch JSON as one object, moved to leave a margin; canvas size out.
std::optional<StrokeGroup> sketchObject(const QString &path, QSize &canvas)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return std::nullopt;
    const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
    const QJsonArray strokes = json.value(QStringLiteral("strokes")).toArray();
    const QJsonArray bbox = json.value(QStringLiteral("bbox")).toArray();
    if (strokes.isEmpty() || bbox.size() != 4)
        return std::nullopt;
    const double x0 = bbox[0].toDouble(), y0 = bbox[1].toDouble();
    const double w = bbox[2].toDouble() - x0, h = bbox[3].toDouble() - y0;
    const double side = std::max(w, h) * 1.6;
    canvas = QSize(int(side), int(side));
    const double ox = (side - w) / 2 - x0, oy = (side - h) / 2 - y0;
    StrokeGroup group;
    group.id = 1;
    Id id = 2;
    for (const QJsonValue &stroke : strokes) {
        auto data = std::make_shared<StrokeData>();
        data->width = 3.0f;
        for (const QJsonValue &p : stroke.toArray()) {
            const QJsonArray xy = p.toArray();
            data->points.push_back(
                {float(xy[0].toDouble() + ox), float(xy[1].toDouble() + oy), 1.0f});
        }
        group.strokes.push_back({id++, std::move(data)});
    }
    return group;
}
} // namespace

bool shadedSheet(const QStringList &files, const QString &out, int cell)
{
    const int kCell = std::clamp(cell, 50, 2000);
    constexpr int kPairsPerRow = 4;
    std::vector<std::pair<QImage, QImage>> pairs;
    std::vector<QString> labels;
    int k = 0;
    for (const QString &path : files) {
        QSize canvas;
        auto group = sketchObject(path, canvas);
        QJsonObject row{{QStringLiteral("sheet"), QFileInfo(path).fileName()}};
        if (!group) {
            row.insert(QStringLiteral("error"), QStringLiteral("not a sketch"));
            std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
            continue;
        }
        DocumentSettings settings;
        settings.canvasSize = canvas;
        const int fills =
            shadeEverything(*group, settings.closeGap, kPalette[k++ % std::size(kPalette)]);
        Frame frame;
        frame.id = 100;
        frame.groups.push_back(*group);
        const QImage rest = renderFrame(frame, settings, QSize(kCell, kCell));
        const bool posed = poseBent(frame.groups[0]);
        const QImage shown = renderFrame(frame, settings, QSize(kCell, kCell));
        row.insert(QStringLiteral("fills"), fills);
        row.insert(QStringLiteral("posed"), posed);
        std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
        pairs.emplace_back(rest, shown);
        labels.push_back(QFileInfo(path).baseName() +
                         (posed ? QString() : QStringLiteral(" (rest)")));
    }
    const int rows = (int(pairs.size()) + kPairsPerRow - 1) / kPairsPerRow;
    QImage sheet(kPairsPerRow * (2 * kCell + 12), std::max(1, rows) * (kCell + 18),
                 QImage::Format_RGB32);
    sheet.fill(Qt::white);
    QPainter painter(&sheet);
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const int x = int(i % kPairsPerRow) * (2 * kCell + 12),
                  y = int(i / kPairsPerRow) * (kCell + 18);
        painter.drawImage(x, y, pairs[i].first);
        painter.drawImage(x + kCell, y, pairs[i].second);
        painter.setPen(QColor(120, 120, 120));
        painter.drawRect(x, y, 2 * kCell - 1, kCell - 1);
        painter.drawText(QRect(x, y + kCell, 2 * kCell, 16), Qt::AlignCenter,
                         labels[i] + QStringLiteral(": rest | posed"));
    }
    painter.end();
    return sheet.save(out);
}

} // namespace finbook::bench
