// The pictures of a reference (reference.h): decoded from its original bytes on demand.
//
// An image is decoded once. A video's frames are decoded when asked for and kept in a cache
// bounded in bytes (least recently used first out), so a long 1080p reference costs the memory
// of a few dozen frames however long it is. Thread-safe: the canvas, thumbnails and an export
// on a worker may ask at once (one decoder, one mutex; an export opens its own media).
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/model/reference/reference.h>

#include <QImage>
#include <QStringList>

#include <memory>
#include <optional>

namespace finbook::model {

namespace reference_detail {
class VideoDecoder;
}

class ReferenceMedia {
public:
    // Decodes the first picture; a sentence saying what is wrong when none decodes.
    static Expected<std::shared_ptr<ReferenceMedia>, QString> open(ReferenceKind kind,
                                                                   const QByteArray &bytes);
    // The media of `reference`: as above, or for a sequence its pictures, decoded one by one
    // when asked for (only the first is decoded here; a later one that does not decode shows
    // as null).
    static Expected<std::shared_ptr<ReferenceMedia>, QString> open(const Reference &reference);
    ~ReferenceMedia();

    ReferenceKind kind() const { return m_kind; }
    QSize size() const { return m_size; }
    double frameRate() const { return m_frameRate; } // video frames per second
    double duration() const { return m_duration; }   // seconds; 0 for an image
    qint64 frameCount() const;                       // 1 for an image; a sequence's picture count

    // The video frame shown at `seconds` (an image: the image), clamped to the video.
    qint64 frameIndex(double seconds) const;
    // The frame shown at playback tick `tick` of a document at `fps`, placed in time by
    // `reference` (its rate): a video's frame at that time, a sequence's picture.
    qint64 frameAtTick(const Reference &reference, qint64 tick, int fps) const;
    // Blocking: decodes the frame when it is not in the cache. Null only when decoding fails.
    QImage frame(qint64 index);
    // The frame if it is in the cache; null otherwise (never decodes).
    QImage cachedFrame(qint64 index) const;

    // The cache's bound in bytes (at least one frame is always kept).
    void setCacheLimit(qint64 bytes);
    qint64 cacheBytes() const;
    qint64 decodedFrames() const; // frames the decoder produced (cache misses cost several)

private:
    ReferenceMedia();
    struct Cache;
    ReferenceKind m_kind = ReferenceKind::None;
    QSize m_size;
    double m_frameRate = 0.0;
    double m_duration = 0.0;
    QImage m_still;
    QList<QByteArray> m_pictures; // a sequence's
    std::unique_ptr<reference_detail::VideoDecoder> m_decoder;
    std::unique_ptr<Cache> m_cache;
};

// The pictures of a numbered run the file at `path` belongs to (shot_0001.png, shot_0002.png …:
// same name before and after the number, as many digits when they are zero-padded), in
// numeric order; just `path` when it has no number or no neighbours.
QStringList numberedSequence(const QString &path);

// Reads several picture files, in the order given, as one sequence reference placed to fit
// `canvas` (one file: a still). A sentence naming the file when one cannot be read or is not a
// single still picture, or when together they pass kMaxReferenceBytes.
Expected<Reference, QString> importReferenceSequence(const QStringList &paths, QSizeF canvas);

// Reads a file to import as a reference: a picture when Qt's image readers or FFmpeg find one
// still picture, a video when FFmpeg finds moving pictures. The reference is placed to fit
// `canvas`. A sentence (with the file's name) when the file cannot be read or decoded, is
// empty, or is larger than kMaxReferenceBytes.
Expected<Reference, QString> importReferenceFile(const QString &path, QSizeF canvas);

} // namespace finbook::model
