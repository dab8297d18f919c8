// Which drawings an export shows, for how long, at what size: the part every format shares.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/model/export/export_options.h>

#include <QImage>
#include <QSize>

#include <vector>

namespace finbook::model {

struct ExportPlan {
    std::vector<int> frames; // document frame indices, in playback order
    std::vector<int> holds;  // ticks each of them stays on screen (1..kMaxHold), same length
    qint64 ticks = 0;        // sum of holds
    QSize size;              // output pixels: canvas × scale, rounded; even for MP4 and WebM
    int fps = 12;
    bool loop = true;
    bool transparent = false;
    QRgb background = 0xffffffff; // opaque; unused when transparent
    // The camera at the first tick of each entry (same length as `frames`), or empty: the
    // page as it is. Where the camera moves during a drawing's hold, the hold is split into
    // entries of one tick each (the same drawing, a new shot each tick).
    std::vector<CameraState> cameras;
};

// An export of a few kilobytes can ask for millions of ticks. Without options.maxFrames an
// export writes at most this many sequence files, or a video (GIF, HTML) this long.
constexpr qint64 kMaxSequenceFiles = 100000;
constexpr qint64 kMaxVideoSeconds = 3 * 3600;

// Playback ticks of frames first..last (clamped to the frames there are), holds included.
qint64 exposureTicks(const std::vector<Frame> &frames, int first, int last);

// Ticks the document's play range lasts: what playback shows and an export covers by default.
qint64 playbackTicks(const std::vector<Frame> &frames, const DocumentSettings &settings);

// Checks the options against the source and works out the plan. BadOptions names the field
// (range, scale, rate, transparency) and the values allowed.
Expected<ExportPlan, ExportError> planExport(const ExportSource &source,
                                             const ExportOptions &options);

// The frames an export writes: files of a sequence (the exposure sheet included), or the
// playback ticks of a video, GIF or HTML page (each a frame of the result at plan.fps).
qint64 exportFrameCount(const ExportPlan &plan, const ExportOptions &options);

// Refuses with TooLarge (the count and the limit in the message) an export beyond the
// default limits that options.maxFrames does not allow, or one beyond options.maxFrames.
std::optional<ExportError> checkExportSize(const ExportPlan &plan, const ExportOptions &options);

// The frame as it is exported: plan.size pixels, QImage::Format_ARGB32 (straight alpha), the
// canvas scaled to fit and centred, over the plan's background unless it is transparent.
// `reference` (optional) is painted under the drawing with `picture` as its media. With
// `camera`, the page is seen through it (cameraTransform): the picture is the shot.
QImage renderExportFrame(const Frame &frame, const DocumentSettings &settings,
                         const ExportPlan &plan, const Reference *reference = nullptr,
                         const QImage &picture = {}, const CameraState *camera = nullptr);

// Pixels rendered at once by exports that go band by band: a 16384-pixel-wide picture
// renders 256 rows (16 MiB) at a time instead of 1 GiB for the whole frame.
constexpr qint64 kExportBandPixels = qint64(1) << 22;

// Rows [top, top + rows) of renderExportFrame (the same pixels); a null image when even the
// band cannot be allocated.
QImage renderExportBand(const Frame &frame, const DocumentSettings &settings,
                        const ExportPlan &plan, int top, int rows,
                        const Reference *reference = nullptr, const QImage &picture = {},
                        const CameraState *camera = nullptr);

// The rows of one band for plan.size: kExportBandPixels / width, at least 1, at most the
// height (a picture of up to kExportBandPixels pixels is one band).
int exportBandRows(const ExportPlan &plan);

} // namespace finbook::model
