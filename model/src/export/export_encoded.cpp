// GIF, MP4, WebM and APNG through ffmpeg: rendered frames are piped raw to its standard input
// (one per tick) and it writes a temporary file beside the target, renamed over the target on
// success. GIF takes two runs, the first writing the palette to another temporary beside the
// target; a GIF whose drawings are held for different times reads them as PNG files with
// their durations (concat demuxer) instead, so each drawing is one GIF frame of its hold.
#include "export_formats.h"
#include "export_sound.h"
#include "export_text.h"
#include "ffmpeg_arguments.h"
#include "ffmpeg_encoder.h"
#include "pending_output.h"
#include "target_lock.h"

#include <QDir>
#include <QFileInfo>
#include <QTemporaryDir>

#include <optional>

namespace finbook::model {

namespace {
// Renders each drawing once and pipes it once, or once per tick of its hold. A picture larger
// than one band is rendered and piped band by band (ffmpeg reads raw rows, so the stream is
// the same), again for each tick: memory stays at one band whatever the size.
std::optional<ExportError> pipeFrames(const ExportContext &context, FfmpegEncoder &encoder,
                                      bool perTick, qint64 &done,
                                      const FfmpegEncoder::Cancelled &cancelled)
{
    const ExportPlan &plan = context.plan;
    const int rows = exportBandRows(plan);
    const int height = plan.size.height();
    for (std::size_t i = 0; i < plan.frames.size(); ++i) {
        const QImage whole = rows >= height ? context.render(i) : QImage();
        const int repeats = perTick ? plan.holds[i] : 1;
        for (int r = 0; r < repeats; ++r) {
            for (int top = 0; top < height; top += rows) {
                const QImage band = rows >= height
                                        ? whole
                                        : context.renderBand(i, top, std::min(rows, height - top));
                if (band.isNull())
                    return writeFailed(context.options.target,
                                       Export::tr("there is not enough memory to render it"));
                if (auto error = encoder.write(band, cancelled))
                    return error;
            }
            ++done;
            if (cancelled()) {
                encoder.abort();
                return cancelledError();
            }
        }
    }
    return encoder.finish(cancelled);
}

// A GIF's drawings for the concat demuxer: each rendered once into a PNG in `folder` (a
// hidden folder beside the target), and the list giving each its hold. The list's path.
Expected<QString, ExportError> writeDrawings(const ExportContext &context, const QDir &folder,
                                             qint64 &done, qint64 total)
{
    const ExportPlan &plan = context.plan;
    const auto name = [](std::size_t i) {
        return QStringLiteral("drawing-%1.png").arg(i + 1, 6, 10, QLatin1Char('0'));
    };
    const QString target = context.options.target;
    for (std::size_t i = 0; i < plan.frames.size(); ++i) {
        const QByteArray png = context.png(i);
        if (png.isEmpty())
            return unexpected(
                writeFailed(target, Export::tr("there is not enough memory to render it")));
        if (auto reason = writeFileSynced(folder.filePath(name(i)), png))
            return unexpected(writeFailed(target, *reason));
        if (context.cancelled(++done, total))
            return unexpected(cancelledError());
    }
    const QString list = folder.filePath(QStringLiteral("drawings.ffconcat"));
    if (auto reason = writeFileSynced(list, concatList(plan.holds, plan.fps, name)))
        return unexpected(writeFailed(target, *reason));
    return list;
}
} // namespace

ExportOutcome exportEncoded(const ExportContext &context)
{
    const QString target = context.options.target;
    if (auto error = checkFileTarget(context.options))
        return unexpected(*error);
    FolderGuard guard(QFileInfo(target).path());
    TargetLock lock(target, false);
    if (auto error = claimFileTarget(target, guard, {&lock}))
        return unexpected(*error);
    PendingFile pending(target);
    QString openFailure;
    if (!pending.open(&openFailure))
        return unexpected(writeFailed(target, openFailure));
    pending.file().close(); // ffmpeg writes it; the name stays reserved until commit or cleanup

    // GIF's palette, written by a first ffmpeg run: a temporary like the output's, so the
    // same cleaning removes it (on failure, on a signal, and after a killed export).
    PendingFile palette(target);
    const bool gif = context.options.format == ExportFormat::Gif;
    if (gif) {
        if (!palette.open(&openFailure))
            return unexpected(writeFailed(target, openFailure));
        palette.file().close();
    }

    const ExportPlan &plan = context.plan;
    // The soundtrack's mix of the range (MP4, WebM): a temporary beside the target too.
    PendingFile sound(target);
    if (context.sound.carriesSound()) {
        if (!sound.open(&openFailure))
            return unexpected(writeFailed(target, openFailure));
        if (!context.sound.writeWav(sound.file()) || !sound.file().flush())
            return unexpected(writeFailed(target, sound.file().errorString()));
        sound.file().close();
    }
    // A GIF whose drawings are held for different times: its drawings as PNG files in a
    // hidden folder beside the target (removed after, or by the next export to the target
    // after a kill), read twice by ffmpeg through a concat list.
    const bool drawingFiles = gif && holdsVary(plan.holds);
    std::optional<QTemporaryDir> drawings;
    if (drawingFiles) {
        const QFileInfo info(target);
        drawings.emplace(
            info.dir().filePath(QStringLiteral(".%1.XXXXXX.part").arg(info.fileName())));
        if (!drawings->isValid())
            return unexpected(writeFailed(target, drawings->errorString()));
    }
    // A GIF's frames are rendered and piped twice, once per run (slower, but ffmpeg keeps
    // none of them), or written once as files.
    const int runs = gif ? 2 : 1;
    qint64 total = drawingFiles ? qint64(plan.frames.size()) : plan.ticks * runs;
    qint64 done = 0;
    const auto cancelled = [&] { return context.cancelled(done, total); };
    QString list;
    if (drawingFiles) {
        auto written = writeDrawings(context, QDir(drawings->path()), done, total);
        if (!written)
            return unexpected(written.error());
        list = *written;
    }
    // "file:" keeps ffmpeg from reading a colon in the folder name as a protocol.
    const FfmpegJob job =
        ffmpegJob(context.options.format, plan, QStringLiteral("file:") + pending.path(),
                  palette.path(), sound.path(), list);

    // ffmpeg names the temporary files in its errors; the user knows the target.
    const auto failed = [&](ExportError error) {
        for (QString *text : {&error.message, &error.detail})
            for (const QString &path : {pending.path(), palette.path(), sound.path(), list})
                if (!path.isEmpty())
                    text->replace(QStringLiteral("file:") + path, target).replace(path, target);
        return error;
    };
    // One ffmpeg run: frames piped in, and something must have been written to `written`.
    const auto run = [&](const QStringList &arguments,
                         const QString &written) -> std::optional<ExportError> {
        FfmpegEncoder encoder(job.what, written);
        if (auto error = encoder.start(arguments))
            return failed(*error);
        if (auto error = job.concatList.isEmpty()
                             ? pipeFrames(context, encoder, job.perTick, done, cancelled)
                             : encoder.finish(cancelled))
            return failed(*error);
        if (QFileInfo(written).size() <= 0)
            return failed(exportError(ExportErrorCode::EncoderFailed,
                                      Export::tr("ffmpeg finished without writing the %1; "
                                                 "nothing was exported.")
                                          .arg(job.what),
                                      encoder.errorTail()));
        return std::nullopt;
    };
    if (runs == 2)
        if (auto error = run(job.paletteArguments, palette.path()))
            return unexpected(*error);
    if (auto error = run(job.arguments, pending.path()))
        return unexpected(*error);
    if (auto error = commitFile(pending, context.options))
        return unexpected(*error);
    guard.keep();

    ExportResult result;
    result.files << target;
    result.fileCount = 1;
    result.images = job.perTick ? plan.ticks : qint64(plan.frames.size());
    result.ticks = plan.ticks;
    result.size = plan.size;
    return result;
}

} // namespace finbook::model
