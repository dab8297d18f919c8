// The reference layer's state: a picture or a video lying under every object of every frame,
// to trace over. It is not an object: tools, selection, deformers and onion skin never see it.
//
// The media's original bytes are kept (and saved) as they were imported; a video is stored
// once and its frames are decoded on demand (reference_media.h). Everything else here is a
// value the reference commands replace as a whole, so undo restores it exactly.
#pragma once

#include <QByteArray>
#include <QList>
#include <QPointF>
#include <QSizeF>
#include <QString>
#include <QTransform>

namespace finbook::model {

enum class ReferenceKind : quint8 {
    None = 0,
    Image = 1, // one picture (PNG, JPEG, WebP, ... whatever Qt's readers or FFmpeg decode)
    Video = 2, // one video frame per animation tick at `rate`
    // Several pictures, one per animation tick (or `rate` pictures per second of animation);
    // saved as the picture `bytes` (the first, which an older Finbook shows as a still) and the
    // others after it in their own section.
    Sequence = 3,
};

struct Reference {
    ReferenceKind kind = ReferenceKind::None;
    QByteArray bytes; // the file as imported (implicitly shared: copies cost a pointer)
    // A sequence: every picture's bytes in order, the first being `bytes`; empty otherwise.
    QList<QByteArray> pictures;
    QString name;     // the imported file's name, shown to the user
    QSizeF mediaSize; // pixels of the picture / of a video frame, known at import
    QPointF center;   // where the media's centre lies, in canvas coordinates
    double scale = 1.0;
    double rotation = 0.0; // degrees, clockwise on screen
    double opacity = 0.5;
    bool visible = true;
    bool locked = false;
    // Video: the animation ticks per second of video (0 = the document's fps: real time).
    // Sequence: pictures per second of animation (0 = one per tick).
    double rate = 0.0;

    bool isEmpty() const { return kind == ReferenceKind::None || bytes.isEmpty(); }
    bool operator==(const Reference &) const = default;
};

// Maps media pixels (0..mediaSize) to canvas coordinates.
QTransform referenceTransform(const Reference &reference);

// The reference placed as import does: centred on the canvas, scaled to fit inside it.
void fitReferenceToCanvas(Reference &reference, QSizeF canvas);

// The video time (seconds) shown at playback tick `tick` of a document playing at `fps`.
double referenceSeconds(const Reference &reference, qint64 tick, int fps);

// Limits: a reference file larger than this is refused on import and in a .finbook.
constexpr qint64 kMaxReferenceBytes = qint64(2) << 30;
constexpr double kMinReferenceScale = 1e-3;
constexpr double kMaxReferenceScale = 1e3;
constexpr double kMaxReferenceRate = 1000.0;
constexpr qsizetype kMaxReferencePictures = 100000; // pictures in one sequence
constexpr double kMaxReferenceCoordinate = 1e7;

// Whether the numbers of `reference` are ones a reference may have (finite, in range).
bool referenceValuesValid(const Reference &reference);

} // namespace finbook::model
