#include "thumbnail_command.h"

#include "cli.h"
#include "first_frame.h"

#include <finbook/model/io/printable_text.h>
#include <finbook/model/render.h>
#include <finbook/model/shade/fill_shading.h>
#include <finbook/model/skeleton/cut_out_layers.h>

#include <QBuffer>
#include <QCoreApplication>
#include <QFileInfo>
#include <QSaveFile>
#include <QTextStream>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace finbook::app {

namespace {

class Thumbnail {
    Q_DECLARE_TR_FUNCTIONS(Thumbnail)
};

int fail(QTextStream &err, const QString &message, ExitCode code)
{
    err << model::printableText(message.simplified()) << Qt::endl;
    return int(code);
}

// The canvas scaled so that its longer side is `size` (never below one pixel).
QSize thumbnailSize(QSize canvas, int size)
{
    const double scale = double(size) / std::max(canvas.width(), canvas.height());
    return QSize(std::max(1, int(canvas.width() * scale + 0.5)),
                 std::max(1, int(canvas.height() * scale + 0.5)));
}

// Sanitizer builds run several times slower: their thumbnails get that much more time, so the
// tests that compare a thumbnail with the full picture mean the same there.
#if defined(__SANITIZE_ADDRESS__)
constexpr int kSlowdown = 8;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr int kSlowdown = 8;
#else
constexpr int kSlowdown = 1;
#endif
#else
constexpr int kSlowdown = 1;
#endif

std::atomic<int> g_running{0}; // pictures still being painted after their time ran out

// One picture painted on its own thread, so that the command can stop waiting for it.
struct Painting {
    std::mutex mutex;
    std::condition_variable done;
    bool finished = false;
    QImage image;
};

// Paints `frame` as `options` say on a thread of its own and waits at most `waitMs` for it:
// the picture, or a null image when it failed or was not ready in time (the thread is then
// left to finish alone; g_running counts it). The thread owns copies of everything it reads.
QImage paintWithin(const model::Frame &frame, const model::DocumentSettings &settings, QSize size,
                   const model::RenderOptions &options, int waitMs)
{
    auto painting = std::make_shared<Painting>();
    ++g_running;
    try {
        std::thread([painting, frames = std::vector<model::Frame>{frame}, settings, size,
                     options]() mutable {
            QImage image;
            try {
                model::restoreCutOutLayers(frames, settings.closeGap);
                image = model::renderFrame(frames.front(), settings, size, options);
            } catch (const std::exception &) { // out of memory: no picture at this level
                image = QImage();
            }
            {
                std::lock_guard lock(painting->mutex);
                painting->image = std::move(image);
                painting->finished = true;
            }
            painting->done.notify_all();
            --g_running;
        }).detach();
    } catch (const std::exception &) { // no thread to be had
        --g_running;
        return QImage();
    }
    std::unique_lock lock(painting->mutex);
    if (!painting->done.wait_for(lock, std::chrono::milliseconds(waitMs),
                                 [&] { return painting->finished; }))
        return QImage();
    return painting->image;
}

// The picture within the budget: the first frame as the editor shows it when that is ready in
// kFullPictureMs (and its shading does not ask for more than kShadingVertexBudget vertices),
// else with its fills flat when that is ready in kFlatPictureMs, else its strokes alone, whose
// cost follows the points the file holds.
QImage budgetedPicture(const model::Frame &frame, const model::DocumentSettings &settings,
                       QSize size)
{
    if (model::shadingVertexEstimate(frame) <= kShadingVertexBudget) {
        QImage full = paintWithin(frame, settings, size, {}, kFullPictureMs * kSlowdown);
        if (!full.isNull())
            return full;
    }
    model::RenderOptions flat;
    flat.shading = false;
    if (QImage picture = paintWithin(frame, settings, size, flat, kFlatPictureMs * kSlowdown);
        !picture.isNull())
        return picture;
    model::RenderOptions strokes;
    strokes.fills = false;
    return model::renderFrame(frame, settings, size, strokes);
}

} // namespace

bool thumbnailWorkLeftRunning()
{
    return g_running.load() > 0;
}

int runThumbnailCommand(const QStringList &arguments, QTextStream &err)
{
    if (arguments.size() != 3)
        return fail(err, Thumbnail::tr("Usage: finbook thumbnail FILE OUT.png SIZE"),
                    ExitCode::BadInput);
    bool ok = false;
    const int size = arguments[2].toInt(&ok);
    if (!ok || size < 1 || size > kMaxThumbnailSize)
        return fail(err,
                    Thumbnail::tr("The thumbnail size \"%1\" is not a whole number from 1 to %2.")
                        .arg(arguments[2])
                        .arg(kMaxThumbnailSize),
                    ExitCode::BadInput);
    auto loaded = readFirstFrame(arguments[0]);
    if (!loaded)
        return fail(err, loaded.error().message, ExitCode::BadInput);
    if (loaded->frames.empty())
        return fail(err,
                    Thumbnail::tr("Cannot make a thumbnail of \"%1\": it has no frame.")
                        .arg(QFileInfo(arguments[0]).fileName()),
                    ExitCode::BadInput);
    const QImage image = budgetedPicture(loaded->frames.front(), loaded->settings,
                                         thumbnailSize(loaded->settings.canvasSize, size));
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    if (image.isNull() || !image.save(&buffer, "PNG"))
        return fail(err,
                    Thumbnail::tr("Cannot make a thumbnail of \"%1\": there is not enough memory.")
                        .arg(QFileInfo(arguments[0]).fileName()),
                    ExitCode::Failure);
    QSaveFile out(arguments[1]);
    if (!out.open(QIODevice::WriteOnly) || out.write(png) != png.size() || !out.commit())
        return fail(err,
                    Thumbnail::tr("Cannot write the thumbnail \"%1\": %2.")
                        .arg(arguments[1], out.errorString()),
                    ExitCode::Failure);
    return int(ExitCode::Ok);
}

} // namespace finbook::app
