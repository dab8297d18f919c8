// ReferenceMedia: the still image, or a video decoder behind a byte-bounded LRU frame cache.
#include "reference_svg.h"
#include "video_decoder.h"

#include <finbook/model/reference/reference_media.h>

#include <QBuffer>
#include <QCoreApplication>
#include <QImageReader>

#include <algorithm>
#include <cmath>
#include <list>
#include <mutex>
#include <unordered_map>

namespace finbook::model {

namespace {
constexpr qint64 kDefaultCacheBytes = qint64(256) << 20;
constexpr qint64 kKeptOnTheWay = 16; // frames before the one asked for, kept from a seek

constexpr int kMaxStillSide = 16384;
constexpr qint64 kMaxStillPixels = qint64(8192) * 8192;

// Qt's own readers first (they know a picture's orientation, colour space, animation); null
// when none reads the bytes. `svg` is set when the bytes are SVG (renderSvg's alone).
QImage readWithQt(const QByteArray &bytes, bool *svg)
{
    QBuffer buffer;
    buffer.setData(bytes);
    buffer.open(QIODevice::ReadOnly);
    QImageReader reader(&buffer);
    reader.setAutoTransform(true);
    if (!reader.canRead())
        return {};
    if (reader.format() == "svg" || reader.format() == "svgz") {
        *svg = true; // Qt's SVG reader has no limits: never through it
        return {};
    }
    const QSize size = reader.size();
    if (size.isValid() && (size.width() > kMaxStillSide || size.height() > kMaxStillSide ||
                           qint64(size.width()) * size.height() > kMaxStillPixels))
        return {};
    // What decoded is checked as well as what the header said.
    QImage image = reader.read();
    if (image.width() > kMaxStillSide || image.height() > kMaxStillSide ||
        qint64(image.width()) * image.height() > kMaxStillPixels)
        return {};
    return image;
}

// One still picture in the cache's format; null with `error` set when none decodes.
QImage decodeStill(const QByteArray &bytes, QString *error, double *svgBudget = nullptr)
{
    bool svg = reference_detail::looksLikeSvg(bytes);
    QImage image = svg ? QImage() : readWithQt(bytes, &svg);
    if (svg) {
        image = reference_detail::renderSvg(bytes, error, svgBudget);
        if (image.isNull())
            return {};
    } else if (image.isNull()) {
        auto decoder = reference_detail::VideoDecoder::open(bytes, error);
        if (!decoder)
            return {};
        image = decoder->frameAt(0.0);
    }
    if (image.isNull()) {
        *error = QCoreApplication::translate("Reference", "Its picture cannot be decoded.");
        return {};
    }
    return image.convertToFormat(image.hasAlphaChannel() ? QImage::Format_ARGB32_Premultiplied
                                                         : QImage::Format_RGB32);
}
} // namespace

struct ReferenceMedia::Cache {
    // Two locks: the decoder's is held while a frame decodes (up to a keyframe interval's
    // work), the cache's only for a lookup, so a look into the cache never waits for a decode.
    std::mutex decoder;
    mutable std::mutex mutex;
    std::list<std::pair<qint64, QImage>> order; // most recently used first
    std::unordered_map<qint64, std::list<std::pair<qint64, QImage>>::iterator> index;
    qint64 bytes = 0;
    qint64 limit = kDefaultCacheBytes;
    // CPU seconds left for a sequence's SVG pictures (reference_svg.h), under `decoder`.
    double svgSeconds = 10.0;

    void trim()
    {
        while (order.size() > 1 && bytes > limit) {
            bytes -= order.back().second.sizeInBytes();
            index.erase(order.back().first);
            order.pop_back();
        }
    }
};

ReferenceMedia::ReferenceMedia()
    : m_cache(std::make_unique<Cache>())
{}

ReferenceMedia::~ReferenceMedia() = default;

Expected<std::shared_ptr<ReferenceMedia>, QString> ReferenceMedia::open(ReferenceKind kind,
                                                                        const QByteArray &bytes)
{
    std::shared_ptr<ReferenceMedia> media(new ReferenceMedia());
    media->m_kind = kind;
    if (bytes.isEmpty() || kind == ReferenceKind::None)
        return unexpected(QCoreApplication::translate("Reference", "The file is empty."));
    if (kind == ReferenceKind::Image) {
        QString error;
        media->m_still = decodeStill(bytes, &error);
        if (media->m_still.isNull())
            return unexpected(error);
        media->m_size = media->m_still.size();
        return media;
    }
    QString error;
    media->m_decoder = reference_detail::VideoDecoder::open(bytes, &error);
    if (!media->m_decoder)
        return unexpected(error);
    media->m_size = media->m_decoder->size();
    media->m_frameRate = media->m_decoder->frameRate();
    media->m_duration = media->m_decoder->duration();
    return media;
}

Expected<std::shared_ptr<ReferenceMedia>, QString> ReferenceMedia::open(const Reference &reference)
{
    if (reference.kind != ReferenceKind::Sequence)
        return open(reference.kind, reference.bytes);
    if (reference.pictures.isEmpty() || reference.pictures.front().isEmpty())
        return unexpected(QCoreApplication::translate("Reference", "The file is empty."));
    std::shared_ptr<ReferenceMedia> media(new ReferenceMedia());
    media->m_kind = ReferenceKind::Sequence;
    QString error;
    const QImage first =
        decodeStill(reference.pictures.front(), &error, &media->m_cache->svgSeconds);
    if (first.isNull())
        return unexpected(error);
    media->m_size = first.size();
    media->m_pictures = reference.pictures;
    std::lock_guard lock(media->m_cache->mutex);
    media->m_cache->order.emplace_front(0, first);
    media->m_cache->index[0] = media->m_cache->order.begin();
    media->m_cache->bytes = first.sizeInBytes();
    return media;
}

qint64 ReferenceMedia::frameAtTick(const Reference &reference, qint64 tick, int fps) const
{
    if (m_kind != ReferenceKind::Sequence)
        return frameIndex(referenceSeconds(reference, tick, fps));
    const double perTick = reference.rate > 0.0 ? reference.rate / double(std::max(1, fps)) : 1.0;
    const double at = double(std::max<qint64>(0, tick)) * perTick;
    return std::clamp<qint64>(qint64(std::floor(at + 1e-6)), 0, frameCount() - 1);
}

qint64 ReferenceMedia::frameCount() const
{
    if (m_kind == ReferenceKind::Sequence)
        return std::max<qint64>(1, m_pictures.size());
    if (m_kind != ReferenceKind::Video)
        return 1;
    return std::max<qint64>(1, qint64(std::ceil(m_duration * m_frameRate - 1e-6)));
}

qint64 ReferenceMedia::frameIndex(double seconds) const
{
    if (m_kind != ReferenceKind::Video || !std::isfinite(seconds) || seconds <= 0.0)
        return 0;
    return std::min(frameCount() - 1, qint64(std::floor(seconds * m_frameRate + 1e-6)));
}

QImage ReferenceMedia::cachedFrame(qint64 index) const
{
    if (m_kind != ReferenceKind::Video && m_kind != ReferenceKind::Sequence)
        return m_still;
    std::lock_guard lock(m_cache->mutex);
    const auto it = m_cache->index.find(index);
    return it == m_cache->index.end() ? QImage() : it->second->second;
}

QImage ReferenceMedia::frame(qint64 index)
{
    if (m_kind != ReferenceKind::Video && m_kind != ReferenceKind::Sequence)
        return m_still;
    index = std::clamp<qint64>(index, 0, frameCount() - 1);
    Cache &c = *m_cache;
    const auto lookUp = [&]() -> QImage {
        std::lock_guard lock(c.mutex);
        const auto it = c.index.find(index);
        if (it == c.index.end())
            return {};
        c.order.splice(c.order.begin(), c.order, it->second);
        return it->second->second;
    };
    if (QImage cached = lookUp(); !cached.isNull())
        return cached;
    std::lock_guard decoding(c.decoder);
    if (QImage cached = lookUp(); !cached.isNull()) // decoded while this thread waited
        return cached;
    const auto insert = [&c](qint64 at, const QImage &image) {
        std::lock_guard lock(c.mutex);
        if (c.index.count(at))
            return;
        c.order.emplace_front(at, image);
        c.index[at] = c.order.begin();
        c.bytes += image.sizeInBytes();
        c.trim();
    };
    if (m_kind == ReferenceKind::Sequence) {
        QString error;
        // Under the decoder's lock: the SVG time left is this media's alone.
        const QImage image = decodeStill(m_pictures[qsizetype(index)], &error, &c.svgSeconds);
        if (!image.isNull())
            insert(index, image);
        return image;
    }
    // A seek decodes from the keyframe before: the frames just before `index` come on the
    // way, and keeping some (half the cache at most) makes scrubbing backwards cheap.
    const qint64 frameBytes = qint64(m_size.width()) * m_size.height() * 4;
    qint64 keep = 0;
    {
        std::lock_guard lock(c.mutex);
        keep = frameBytes > 0 ? std::min<qint64>(kKeptOnTheWay, c.limit / frameBytes / 2) : 0;
    }
    const auto indexOf = [this](double seconds) {
        return qint64(std::floor(seconds * m_frameRate + 1e-3));
    };
    const auto wants = [&](double seconds) {
        const qint64 at = indexOf(seconds);
        if (at < index - keep || at >= index)
            return false;
        std::lock_guard lock(c.mutex);
        return c.index.count(at) == 0;
    };
    const auto passed = [&](double seconds, const QImage &image) {
        insert(indexOf(seconds), image);
    };
    // The middle of the frame's time: safe from rounding either way.
    const QImage image = m_decoder->frameAt((double(index) + 0.5) / m_frameRate, wants, passed);
    if (image.isNull())
        return image;
    // Inserted last: the frame asked for is the most recently used.
    insert(index, image);
    return image;
}

void ReferenceMedia::setCacheLimit(qint64 bytes)
{
    std::lock_guard lock(m_cache->mutex);
    m_cache->limit = std::max<qint64>(0, bytes);
    m_cache->trim();
}

qint64 ReferenceMedia::cacheBytes() const
{
    std::lock_guard lock(m_cache->mutex);
    return m_cache->bytes;
}

qint64 ReferenceMedia::decodedFrames() const
{
    std::lock_guard lock(m_cache->decoder);
    return m_decoder ? m_decoder->decodedFrames() : 0;
}

} // namespace finbook::model
