#include "export_text.h"

#include <finbook/model/export/export_plan.h>
#include <finbook/model/reference/reference_layer.h>
#include <finbook/model/render.h>

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace finbook::model {

namespace {
int holdOf(const Frame &frame)
{
    return std::clamp(frame.hold, 1, kMaxHold);
}

Unexpected<ExportError> badOptions(const QString &message)
{
    return unexpected(exportError(ExportErrorCode::BadOptions, message));
}

// Video encoders subsample chroma 2×2: both sides must be even. The exact side is rounded to
// the nearest even number, so the picture changes by at most one pixel.
int evenSide(double side)
{
    return std::max(2, int(std::lround(side / 2.0)) * 2);
}

std::optional<ExportError> resolveRange(const ExportSource &source, const ExportOptions &options,
                                        int &first, int &last)
{
    const int count = int(source.frames.size());
    if (options.firstFrame == -1 && options.lastFrame == -1) {
        const DocumentSettings &s = source.settings;
        first = std::clamp(s.playStart, 0, count - 1);
        last = std::clamp(s.playEnd < 0 ? count - 1 : s.playEnd, first, count - 1);
        return std::nullopt;
    }
    first = options.firstFrame;
    last = options.lastFrame;
    if (first < 0 || last < first || last >= count)
        return exportError(ExportErrorCode::BadOptions,
                           Export::tr("The frame range %1-%2 is not within the animation's "
                                      "frames 1-%3; choose a range inside it.")
                               .arg(first + 1)
                               .arg(last + 1)
                               .arg(count));
    return std::nullopt;
}

// Sets plan.cameras when the document's camera shows anything but the page as it is, and splits
// the holds the camera moves during into single ticks.
std::optional<ExportError> frameThroughCamera(const ExportSource &source,
                                              const ExportOptions &options, int first,
                                              ExportPlan &plan)
{
    const CameraTrack &camera = source.camera;
    const QSizeF page(source.settings.canvasSize);
    if (camera.isEmpty() || !camera.isUsed(page))
        return std::nullopt;
    qint64 tick = exposureTicks(source.frames, 0, first - 1);
    std::vector<int> frames, holds;
    bool split = false;
    for (std::size_t i = 0; i < plan.frames.size(); ++i) {
        const int hold = plan.holds[i];
        const bool moves = hold > 1 && camera.movesBetween(double(tick), double(tick + hold - 1));
        split = split || moves;
        for (int k = 0; k < (moves ? hold : 1); ++k) {
            frames.push_back(plan.frames[i]);
            holds.push_back(moves ? 1 : hold);
            plan.cameras.push_back(cameraAt(camera, double(tick + k), page));
        }
        tick += hold;
    }
    if (split && options.onePerDrawing)
        return exportError(ExportErrorCode::BadOptions,
                           Export::tr("The camera moves while a drawing is held, so one file per "
                                      "drawing cannot show the shot; export one file per frame, "
                                      "or without the camera."));
    plan.frames = std::move(frames);
    plan.holds = std::move(holds);
    return std::nullopt;
}

} // namespace

qint64 exposureTicks(const std::vector<Frame> &frames, int first, int last)
{
    qint64 ticks = 0;
    first = std::max(first, 0);
    last = std::min(last, int(frames.size()) - 1);
    for (int i = first; i <= last; ++i)
        ticks += holdOf(frames[std::size_t(i)]);
    return ticks;
}

qint64 playbackTicks(const std::vector<Frame> &frames, const DocumentSettings &settings)
{
    if (frames.empty())
        return 0;
    const int count = int(frames.size());
    const int first = std::clamp(settings.playStart, 0, count - 1);
    const int last =
        std::clamp(settings.playEnd < 0 ? count - 1 : settings.playEnd, first, count - 1);
    return exposureTicks(frames, first, last);
}

Expected<ExportPlan, ExportError> planExport(const ExportSource &source,
                                             const ExportOptions &options)
{
    const DocumentSettings &settings = source.settings;
    if (source.frames.empty())
        return badOptions(Export::tr("The animation has no frames to export."));
    if (settings.canvasSize.isEmpty())
        return badOptions(Export::tr("The canvas has no size; set one in Document Settings."));
    ExportPlan plan;
    int first = 0, last = 0;
    if (auto error = resolveRange(source, options, first, last))
        return unexpected(*error);
    if (exportsModel(options.format)) {
        // A 3D model is one drawing: the play range's first, or the one frame asked for.
        if (options.firstFrame != -1 && first != last)
            return badOptions(Export::tr("A 3D model holds one frame, not the frames %1-%2; "
                                         "choose a single frame.")
                                  .arg(first + 1)
                                  .arg(last + 1));
        last = first;
    }
    for (int i = first; i <= last; ++i) {
        plan.frames.push_back(i);
        plan.holds.push_back(holdOf(source.frames[std::size_t(i)]));
        plan.ticks += plan.holds.back();
    }

    const double scale = options.scale;
    const double w = settings.canvasSize.width() * scale;
    const double h = settings.canvasSize.height() * scale;
    // Checked before any rounding: lround of an infinite or huge value is undefined.
    const bool usable = std::isfinite(w) && std::isfinite(h) && scale > 0;
    if (!usable || w > kMaxCanvasSide || h > kMaxCanvasSide || std::lround(w) < 1 ||
        std::lround(h) < 1) {
        if (!usable)
            return badOptions(Export::tr("The scale %1 is not a size a picture can have; choose "
                                         "a scale that gives 1 to %2 pixels a side.")
                                  .arg(scale)
                                  .arg(kMaxCanvasSide));
        return badOptions(Export::tr("The scale %1 would make a %2 x %3 pixel picture; choose a "
                                     "scale that gives 1 to %4 pixels a side.")
                              .arg(scale)
                              .arg(w, 0, 'g', 4)
                              .arg(h, 0, 'g', 4)
                              .arg(kMaxCanvasSide));
    }
    plan.size = QSize(int(std::lround(w)), int(std::lround(h)));
    if (options.format == ExportFormat::Mp4 || options.format == ExportFormat::WebM)
        plan.size = QSize(evenSide(w), evenSide(h));

    plan.fps = options.fps == 0 ? std::clamp(settings.fps, kMinFps, kMaxFps) : options.fps;
    if (plan.fps < kMinFps || plan.fps > kMaxFps)
        return badOptions(Export::tr("The frame rate %1 is not possible; choose %2 to %3 frames "
                                     "per second.")
                              .arg(options.fps)
                              .arg(kMinFps)
                              .arg(kMaxFps));
    plan.loop = options.loop.value_or(settings.loop);
    plan.transparent = options.transparent;
    if (plan.transparent && !exportSupportsTransparency(options.format))
        return badOptions(Export::tr("%1 video cannot be transparent; choose WebM, APNG, GIF or "
                                     "PNG for a transparent background.")
                              .arg(exportFormatName(options.format).toUpper()));
    // Video and GIF have no partial transparency outside the transparent mode: keep it opaque.
    plan.background = options.background.value_or(settings.background) | 0xff000000u;
    // A 3D model is seen through the camera at its frame's first tick (export_model.cpp).
    if (options.camera)
        if (auto error = frameThroughCamera(source, options, first, plan))
            return unexpected(*error);
    return plan;
}

qint64 exportFrameCount(const ExportPlan &plan, const ExportOptions &options)
{
    if (exportsSequence(options.format) && options.onePerDrawing)
        return qint64(plan.frames.size()) + 1;
    return plan.ticks;
}

std::optional<ExportError> checkExportSize(const ExportPlan &plan, const ExportOptions &options)
{
    const qint64 count = exportFrameCount(plan, options);
    const bool sequence = exportsSequence(options.format);
    const double seconds = double(plan.ticks) / std::max(1, plan.fps);
    if (options.maxFrames > 0) {
        if (count <= options.maxFrames)
            return std::nullopt;
        return exportError(ExportErrorCode::TooLarge,
                           Export::tr("This export would write %1 frames, more than the %2 "
                                      "allowed; nothing was exported.")
                               .arg(count)
                               .arg(options.maxFrames));
    }
    if (sequence && count > kMaxSequenceFiles)
        return exportError(ExportErrorCode::TooLarge,
                           Export::tr("This export would write %1 files (%2 playback ticks), "
                                      "more than %3 without your explicit permission; nothing "
                                      "was exported.")
                               .arg(count)
                               .arg(plan.ticks)
                               .arg(kMaxSequenceFiles));
    if (!sequence && seconds > double(kMaxVideoSeconds))
        return exportError(ExportErrorCode::TooLarge,
                           Export::tr("This export would make %1 hours of animation (%2 frames), "
                                      "more than %3 hours without your explicit permission; "
                                      "nothing was exported.")
                               .arg(seconds / 3600.0, 0, 'f', 1)
                               .arg(count)
                               .arg(kMaxVideoSeconds / 3600));
    return std::nullopt;
}

QImage renderExportFrame(const Frame &frame, const DocumentSettings &settings,
                         const ExportPlan &plan, const Reference *reference, const QImage &picture,
                         const CameraState *camera)
{
    return renderExportBand(frame, settings, plan, 0, plan.size.height(), reference, picture,
                            camera);
}

QImage renderExportBand(const Frame &frame, const DocumentSettings &settings,
                        const ExportPlan &plan, int top, int rows, const Reference *reference,
                        const QImage &picture, const CameraState *camera)
{
    QImage image(QSize(plan.size.width(), std::max(0, rows)), QImage::Format_ARGB32_Premultiplied);
    if (image.isNull())
        return image;
    image.fill(plan.transparent ? QColor(Qt::transparent) : QColor::fromRgba(plan.background));
    const QSizeF canvas(settings.canvasSize);
    if (!canvas.isEmpty() && !plan.size.isEmpty()) {
        QPainter painter(&image);
        const qreal scale =
            std::min(plan.size.width() / canvas.width(), plan.size.height() / canvas.height());
        painter.translate((plan.size.width() - canvas.width() * scale) / 2,
                          (plan.size.height() - canvas.height() * scale) / 2 - top);
        painter.scale(scale, scale);
        RenderOptions options;
        if (camera) {
            painter.setTransform(cameraTransform(*camera, canvas), true);
            options.camera = *camera; // planes at a depth are seen through their own cameras
        }
        options.paintBackground = false;
        if (reference)
            options.underlay = [&](QPainter &p) { paintReference(p, *reference, picture); };
        paintFrame(painter, frame, settings, options);
    }
    // Opaque pixels are the same premultiplied or not: skip the conversion pass.
    if (!plan.transparent && image.reinterpretAsFormat(QImage::Format_ARGB32))
        return image;
    return image.convertToFormat(QImage::Format_ARGB32);
}

int exportBandRows(const ExportPlan &plan)
{
    if (plan.size.isEmpty())
        return 0;
    return int(std::clamp<qint64>(kExportBandPixels / plan.size.width(), 1, plan.size.height()));
}

} // namespace finbook::model
