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
    ~ReferenceMedia();

    ReferenceKind kind() const { return m_kind; }
    QSize size() const { return m_size; }
    double frameRate() const { return m_frameRate; } // video frames per second
    double duration() const { return m_duration; }   // seconds; 0 for an image
    qint64 frameCount() const;                       // 1 for an image

    // The video frame shown at `seconds` (an image: the image), clamped to the video.
    qint64 frameIndex(double seconds) const;
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
    std::unique_ptr<reference_detail::VideoDecoder> m_decoder;
    std::unique_ptr<Cache> m_cache;
};

// Reads a file to import as a reference: a picture when Qt's image readers or FFmpeg find one
// still picture, a video when FFmpeg finds moving pictures. The reference is placed to fit
// `canvas`. A sentence (with the file's name) when the file cannot be read or decoded, is
// empty, or is larger than kMaxReferenceBytes.
Expected<Reference, QString> importReferenceFile(const QString &path, QSizeF canvas);

} // namespace finbook::model
