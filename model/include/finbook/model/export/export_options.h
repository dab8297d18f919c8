// What an export makes and where: the format, the frames, size, background, rate and target.
//
// Every format goes through exportAnimation() (exporter.h) with these options; the window's
// Export dialog and `finbook export` only fill them in.
#pragma once

#include <finbook/model/camera/camera_track.h>
#include <finbook/model/reference/reference.h>
#include <finbook/model/scene/shot.h>
#include <finbook/model/sound/sound_clip.h>
#include <finbook/model/types.h>

#include <QString>
#include <QStringList>

#include <functional>
#include <optional>
#include <vector>

namespace finbook::model {

class Document;

enum class ExportFormat {
    PngSequence, // one PNG per playback tick (or per drawing + an exposure sheet) in a folder
    SvgSequence, // the same as vector files: strokes as filled outlines
    Gif,         // ffmpeg palettegen/paletteuse; holds become longer frame delays
    Mp4,         // ffmpeg H.264, yuv420p, even dimensions
    WebM,        // ffmpeg VP9, with alpha when transparent
    Apng,        // ffmpeg animated PNG
    Html,        // one self-contained page that plays the animation
    Obj,         // one frame's objects inflated to 3D: a Wavefront OBJ file and its .mtl
    Glb,         // the same 3D model as one glTF 2.0 binary file
    Lottie,      // Lottie JSON (vector animation for web pages and apps): strokes as outlines
    DotLottie,   // the same Lottie animation in a dotLottie container (.lottie, a zip)
};

struct ExportOptions {
    ExportFormat format = ExportFormat::PngSequence;
    QString target; // the file, or the folder of a PNG/SVG sequence (created when missing)
    // A file target's own name as bytes, when they are not valid in the file name encoding
    // (a Latin-1 name given on the command line): `target` then names the file with U+FFFD
    // for messages, the lock and the temporaries beside it, and the finished file is put
    // under these bytes. Empty: the name `target` encodes.
    QByteArray nativeName;
    // Document frame indices, inclusive. Both -1: the document's play range. A 3D model (Obj, Glb)
    // holds one frame: first == last, or both -1 for the play range's first frame.
    int firstFrame = -1;
    int lastFrame = -1;
    double scale = 1.0;             // output pixels = canvas size × scale, at least 1×1
    bool transparent = false;       // no background (refused for MP4, which has no alpha)
    std::optional<QRgb> background; // replaces the document's background colour (opaque)
    int fps = 0;                    // 0 = the document's frame rate
    std::optional<bool> loop;       // GIF, APNG and HTML: empty = the document's setting
    bool onePerDrawing = false;     // PNG/SVG: one file per drawing plus an exposure sheet
    bool overwrite = false;         // replace files already at the target
    QString baseName = QStringLiteral("frame"); // sequences: <baseName>_0001.png, ...
    QString title;                              // HTML: the page title
    bool includeReference = false;              // paint the reference layer under the drawing
    // Through the document's camera (camera/camera_track.h), when it has keys: each exported
    // picture is the shot at its tick. Off: the whole page, as without a camera.
    bool camera = true;
    // Frames the user allowed this export to write (see exportFrameCount). 0: the default
    // limits, kMaxSequenceFiles files or kMaxVideoSeconds of video (export_plan.h); a larger
    // export is refused with TooLarge until the user sets this to at least its frame count.
    qint64 maxFrames = 0;
    // A sound clip or the reference that cannot be used (it does not decode, or passes the
    // media limits) fails the export with MediaUnusable, before anything is written. Off: it
    // is left out and ExportResult::note says so.
    bool strictMedia = false;
};

// The frames and settings an export reads: a value snapshot (strokes are shared, immutable),
// so a worker thread can export while the user keeps editing the document.
struct ExportSource {
    std::vector<Frame> frames;
    DocumentSettings settings;
    Reference reference = {};          // the reference layer (its media bytes shared, not copied)
    std::vector<SoundClip> sound = {}; // the soundtrack: MP4 and WebM carry its mix
    CameraTrack camera = {};           // the camera's keys
    // The layers' ids and names, back to front (Lottie names its layers after them; a composed
    // frame's planes say which layer they show). Empty: one unnamed layer.
    std::vector<std::pair<Id, QString>> layerNames = {};
};
// What an export shows of `layers`: one plain layer's cels as they are, else the composed
// shot of the layers `filter` admits (scene/shot.h composeShots).
std::vector<Frame> shotFrames(const std::vector<Layer> &layers, const ShotFilter &filter = {});
// The layers' ids and names, back to front (ExportSource::layerNames).
std::vector<std::pair<Id, QString>> layerNamesOf(const std::vector<Layer> &layers);
// The document's shot (its visible layers, or those `filter` admits) for an export.
ExportSource exportSource(const Document &document, const ShotFilter &filter = {});

struct ExportResult {
    // What is at the target now, in order; a sequence lists its first kListedExportFiles
    // files only (fileCount says how many there are), so memory does not grow with its length.
    QStringList files;
    qint64 fileCount = 0;
    qint64 images = 0; // frames rendered and encoded
    qint64 ticks = 0;  // playback ticks covered (holds included)
    QSize size;        // pixel size of the output
    // A sentence about what was left out, for the user (a 3D model's objects that could not
    // be made 3D); empty when nothing was.
    QString note;
};

enum class ExportErrorCode {
    BadOptions,     // a range, scale, rate or format that cannot be exported
    TargetExists,   // a file is in the way and overwrite was not allowed
    WriteFailed,    // the disk is full or read-only, a folder cannot be made
    EncoderMissing, // the ffmpeg program cannot be started
    EncoderFailed,  // ffmpeg stopped with an error
    Cancelled,      // the progress callback asked to stop
    TooLarge,       // more frames than the limits allow without options.maxFrames
    TargetBusy,     // another export is writing to the same target
    MediaUnusable,  // strictMedia: a sound clip or the reference cannot be used
};

struct ExportError {
    ExportErrorCode code;
    QString message; // one translated sentence: what happened and what to do
    QString detail;  // the last lines ffmpeg printed, when ffmpeg was involved
};

// Called after each rendered frame with (frames done, frames in all), on the exporting thread.
// Returning false cancels: the export stops and leaves nothing at the target.
// How many file names an ExportResult lists at most.
constexpr qsizetype kListedExportFiles = 1000;

using ExportProgress = std::function<bool(qint64 done, qint64 total)>;

// "png", "svg", "gif", "mp4", "webm", "apng", "html" (also "htm"), "obj", "glb", "json"
// (Lottie), "lottie" (dotLottie), case-insensitive.
std::optional<ExportFormat> exportFormatFromName(const QString &name);
// The format a path's suffix names (".png" names the PNG sequence); empty for no or an
// unknown suffix.
std::optional<ExportFormat> exportFormatForPath(const QString &path);
QString exportFormatName(ExportFormat format);
// The file suffix of the output (of each file, for sequences).
QString exportFormatSuffix(ExportFormat format);
// The material file an OBJ export writes beside `objTarget`: its name with the suffix .mtl.
QString objMaterialPath(const QString &objTarget);
bool exportsSequence(ExportFormat format);
// OBJ and glTF: one frame's objects as 3D solids, not pictures (no scale, background or rate).
bool exportsModel(ExportFormat format);
bool exportNeedsFfmpeg(ExportFormat format);
bool exportSupportsTransparency(ExportFormat format);
// GIF, APNG and HTML repeat or stop at the end; the videos just end.
bool exportSupportsLoop(ExportFormat format);

} // namespace finbook::model
