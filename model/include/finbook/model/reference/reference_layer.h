// The document's reference layer: one Reference (reference.h) and its decoded media.
//
// Owned by the Document (Document::referenceLayer()). Like the document's own mutators,
// setReference() is for the reference commands (reference_commands.h) and the loader only.
#pragma once

#include <finbook/model/reference/reference.h>
#include <finbook/model/reference/reference_media.h>
#include <finbook/model/types.h>

#include <QImage>
#include <QObject>
#include <QThread>

class QPainter;

#include <memory>

namespace finbook::model {

class Document;
namespace reference_detail {
class ReferenceDecodeWorker;
}

class ReferenceLayer : public QObject {
    Q_OBJECT
public:
    explicit ReferenceLayer(Document *document);
    ~ReferenceLayer() override;

    const Reference &reference() const { return m_reference; }
    bool isEmpty() const { return m_reference.isEmpty(); }
    void setReference(Reference reference);

    // The decoded media, opened on first use; null when there is no reference or its bytes do
    // not decode (mediaError() says why).
    std::shared_ptr<ReferenceMedia> media() const;
    QString mediaError() const { return m_mediaError; }

    // Playback tick at which the frame at `frameIndex` starts (the holds before it summed).
    qint64 tickOfFrame(int frameIndex) const;
    // The picture shown under the frame at `frameIndex`: the image, or the video's frame at
    // that frame's time. `decode` false: only what is decoded already (a video frame not in
    // the cache gives a null image). Null when hidden or empty too.
    QImage pictureAt(int frameIndex, bool decode = true) const;
    qint64 videoFrameAt(int frameIndex) const; // the media frame index shown at `frameIndex`
    // For the canvas, which must not wait for a video to seek: the picture at `frameIndex` if
    // it is decoded; otherwise the picture this returned last while a worker thread decodes
    // it, and pictureReady() when it is.
    QImage pictureWithoutWaiting(int frameIndex);
    // For thumbnails, which must not wait either: the picture at `frameIndex` when it needs no
    // decoding (the image, a cached frame; null when hidden or empty). Otherwise null, with
    // `*pending` set to its media frame, which a worker thread decodes and pictureDecoded()
    // hands over. Each frame asked for is decoded once, in the order asked.
    QImage requestPicture(int frameIndex, qint64 *pending);

signals:
    // Anything about the reference changed (placement, opacity, visibility, lock, media).
    void referenceChanged();
    // A frame asked for by pictureWithoutWaiting() is decoded: ask again.
    void pictureReady();
    // A media frame asked for by requestPicture(), for the media shown now (null: it did not
    // decode).
    void pictureDecoded(qint64 mediaFrame, const QImage &picture);
    // The reference's media cannot be used (it does not decode, or passes the media limits);
    // once per reference set, a moment after media() first finds out. `why` is a sentence.
    void mediaFailed(const QString &name, const QString &why);

private:
    Document *m_doc;
    Reference m_reference;
    mutable std::shared_ptr<ReferenceMedia> m_media;
    mutable bool m_mediaOpened = false;
    mutable QString m_mediaError;
    QImage m_lastShown;
    quint64 m_mediaGeneration = 0; // tags thumbnail requests: older media's answers are dropped
    QThread *m_thread = nullptr;   // started on the first video frame not in the cache
    reference_detail::ReferenceDecodeWorker *m_worker = nullptr;

    // The media when a picture shows (not hidden, not transparent), with `index` set to the
    // media frame shown at `frameIndex`; null otherwise.
    std::shared_ptr<ReferenceMedia> shownMedia(int frameIndex, qint64 &index) const;
    void startWorker();
};

// Paints `picture` (the reference's media, mediaSize pixels) where `reference` places it, at
// its opacity; the painter maps canvas coordinates to the device.
void paintReference(QPainter &painter, const Reference &reference, const QImage &picture);

// renderFrame (render.h) with `picture` placed by `reference` between the background and the
// drawing, clipped to the canvas: what thumbnails show.
QImage renderFrameWithReference(const Frame &frame, const DocumentSettings &settings, QSize size,
                                const Reference &reference, const QImage &picture);

} // namespace finbook::model
