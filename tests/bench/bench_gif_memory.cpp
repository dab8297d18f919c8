// finbook-bench gif-memory [--frames N] [--save FILE]: peak memory of a long GIF export, the
// bundled example's drawings repeated to N frames (default 2000) on a 640×480 canvas, each
// drawing held one tick. Prints the seconds, the peak resident size of this process and of
// the largest ffmpeg it ran (getrusage of the waited-for children). With --save, writes the
// document to FILE instead, for measuring `finbook export` from outside.
#include "bench.h"

#include <finbook/model/document.h>
#include <finbook/model/export/exporter.h>
#include <finbook/model/finbook_file.h>

#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>

#include <cstdio>
#include <sys/resource.h>

namespace {
using namespace finbook;

int benchGifMemory(const QStringList &args)
{
    int frames = 2000;
    QString save;
    for (int i = 0; i + 1 < args.size(); ++i) {
        if (args[i] == QLatin1String("--frames"))
            frames = std::max(1, args[++i].toInt());
        else if (args[i] == QLatin1String("--save"))
            save = args[++i];
    }
    auto loaded =
        model::loadFinbook(QStringLiteral(FINBOOK_SOURCE_DIR "/resources/examples/walk.finbook"));
    if (!loaded) {
        std::fprintf(stderr, "%s\n", qPrintable(loaded.error().message));
        return 2;
    }
    model::ExportSource source{{}, loaded->settings, {}};
    source.settings.canvasSize = QSize(640, 480);
    source.settings.playStart = 0;
    source.settings.playEnd = -1;
    for (int i = 0; i < frames; ++i) {
        model::Frame frame = loaded->frames[std::size_t(i) % loaded->frames.size()];
        frame.hold = 1;
        // Every copy gets its own ids (a saved file must not repeat one); rigs (and their
        // poses) are dropped: the rest drawings are drawn.
        const model::Id offset = model::Id(i + 1) * 1000000;
        frame.id += offset;
        for (model::StrokeGroup &group : frame.groups) {
            group.id += offset;
            group.rig = {};
            group.deformed = nullptr;
            for (model::Stroke &stroke : group.strokes)
                stroke.id += offset;
            for (model::Fill &fill : group.fills)
                for (model::Id &id : fill.strokes)
                    id += offset;
        }
        source.frames.push_back(std::move(frame));
    }
    if (!save.isEmpty()) {
        model::Document doc;
        doc.reset(source.frames, source.settings, model::Id(frames + 2) * 1000000);
        QFile f(save);
        if (!f.open(QIODevice::WriteOnly) || f.write(model::serializeFinbook(doc)) < 0)
            return 1;
        return 0;
    }
    QTemporaryDir dir;
    model::ExportOptions o;
    o.format = model::ExportFormat::Gif;
    o.target = dir.filePath(QStringLiteral("long.gif"));
    QElapsedTimer timer;
    timer.start();
    const auto result = model::exportAnimation(source, o);
    const double seconds = timer.nsecsElapsed() / 1e9;
    rusage children{};
    getrusage(RUSAGE_CHILDREN, &children);
    if (!result) {
        std::printf("{\"bench\":\"gif-memory\",\"error\":\"%s\"}\n",
                    qPrintable(result.error().message));
        return 1;
    }
    std::printf("{\"bench\":\"gif-memory\",\"frames\":%lld,\"width\":%d,\"height\":%d,"
                "\"seconds\":%.2f,\"peak_rss_mib\":%.1f,\"ffmpeg_peak_rss_mib\":%.1f,"
                "\"bytes\":%lld}\n",
                result->images, result->size.width(), result->size.height(), seconds,
                double(bench::peakResidentBytes()) / (1 << 20), double(children.ru_maxrss) / 1024,
                QFileInfo(o.target).size());
    return 0;
}
} // namespace

FINBOOK_BENCH("gif-memory", "[--frames N] [--save FILE] (peak memory of a long GIF export)",
              benchGifMemory);
