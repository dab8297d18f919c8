// finbook-bench export [FILE] [--repeat N]: frames per second of every export format for the
// bundled example (or FILE) at its canvas size (the example: 1280×720), the drawings repeated
// N times (default 4: 48 frames) so each run lasts long enough to time. One JSON line per
// format, plus the render alone as the floor every format starts from.
#include "bench.h"

#include <finbook/model/export/export_plan.h>
#include <finbook/model/export/exporter.h>
#include <finbook/model/finbook_file.h>

#include <QDirIterator>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTemporaryDir>

#include <cstdio>

namespace {
using namespace finbook;
using model::ExportFormat;

qint64 bytesAt(const QString &path)
{
    if (QFileInfo(path).isFile())
        return QFileInfo(path).size();
    qint64 total = 0;
    QDirIterator it(path, QDir::Files);
    while (it.hasNext())
        total += QFileInfo(it.next()).size();
    return total;
}

void printRender(const model::ExportSource &source)
{
    model::ExportOptions o;
    const auto plan = model::planExport(source, o);
    QElapsedTimer timer;
    timer.start();
    for (const model::Frame &f : source.frames)
        model::renderExportFrame(f, source.settings, *plan);
    const double seconds = timer.nsecsElapsed() / 1e9;
    std::printf("{\"bench\":\"export\",\"format\":\"render only\",\"width\":%d,\"height\":%d,"
                "\"frames\":%zu,\"seconds\":%.3f,\"fps\":%.1f}\n",
                plan->size.width(), plan->size.height(), source.frames.size(), seconds,
                double(source.frames.size()) / seconds);
}

int benchExport(const QStringList &args)
{
    QString file = QStringLiteral(FINBOOK_SOURCE_DIR "/resources/examples/walk.finbook");
    int repeat = 4;
    for (int i = 0; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--repeat") && i + 1 < args.size())
            repeat = std::max(1, args[++i].toInt());
        else
            file = args[i];
    }
    auto loaded = model::loadFinbook(file);
    if (!loaded) {
        std::fprintf(stderr, "%s\n", qPrintable(loaded.error().message));
        return 2;
    }
    model::ExportSource source{{}, loaded->settings, {}};
    for (int r = 0; r < repeat; ++r)
        source.frames.insert(source.frames.end(), loaded->frames.begin(), loaded->frames.end());
    source.settings.playStart = 0;
    source.settings.playEnd = -1;
    printRender(source);

    QTemporaryDir dir;
    for (ExportFormat format :
         {ExportFormat::PngSequence, ExportFormat::SvgSequence, ExportFormat::Html,
          ExportFormat::Gif, ExportFormat::Mp4, ExportFormat::WebM, ExportFormat::Apng,
          ExportFormat::Lottie, ExportFormat::DotLottie}) {
        const QString name = model::exportFormatName(format);
        if (model::exportNeedsFfmpeg(format) && model::ffmpegProgram().isEmpty()) {
            std::printf("{\"bench\":\"export\",\"format\":\"%s\",\"skipped\":\"ffmpeg not "
                        "found\"}\n",
                        qPrintable(name));
            continue;
        }
        model::ExportOptions o;
        o.format = format;
        o.target = dir.filePath(QStringLiteral("out.") + name);
        QElapsedTimer timer;
        timer.start();
        const auto result = model::exportAnimation(source, o);
        const double seconds = timer.nsecsElapsed() / 1e9;
        if (!result) {
            std::printf("{\"bench\":\"export\",\"format\":\"%s\",\"error\":\"%s\"}\n",
                        qPrintable(name), qPrintable(result.error().message));
            continue;
        }
        std::printf("{\"bench\":\"export\",\"format\":\"%s\",\"width\":%d,\"height\":%d,"
                    "\"frames\":%lld,\"seconds\":%.3f,\"fps\":%.1f,\"bytes\":%lld}\n",
                    qPrintable(name), result->size.width(), result->size.height(), result->ticks,
                    seconds, double(result->ticks) / seconds, bytesAt(o.target));
        std::fflush(stdout);
    }
    return 0;
}
} // namespace

FINBOOK_BENCH("export", "[FILE] [--repeat N] (frames/s of each export format at canvas size)",
              benchExport);
