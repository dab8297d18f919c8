// ReferenceLayer: the reference value, its media opened lazily, and its picture per frame.
#include "reference_decode_worker.h"

#include <finbook/model/document.h>
#include <finbook/model/reference/reference_layer.h>
#include <finbook/model/render.h>

#include <QPainter>

#include <algorithm>

namespace finbook::model {

ReferenceLayer::ReferenceLayer(Document *document)
    : QObject(document)
    , m_doc(document)
{}

ReferenceLayer::~ReferenceLayer()
{
    if (m_thread) {
        m_worker->latest = -1; // what is queued is dropped; a decode under way finishes
        m_worker->dropQueued();
        m_thread->quit();
        m_thread->wait();
        delete m_worker;
    }
}

std::shared_ptr<ReferenceMedia> ReferenceLayer::shownMedia(int frameIndex, qint64 &index) const
{
    if (m_reference.isEmpty() || !m_reference.visible || m_reference.opacity <= 0.0)
        return nullptr;
    auto m = media();
    if (m)
        index = videoFrameAt(frameIndex);
    return m;
}

void ReferenceLayer::startWorker()
{
    if (m_thread)
        return;
    m_thread = new QThread(this);
    m_thread->setObjectName(QStringLiteral("reference decoder"));
    m_worker = new reference_detail::ReferenceDecodeWorker;
    m_worker->moveToThread(m_thread);
    connect(m_worker, &reference_detail::ReferenceDecodeWorker::decoded, this,
            &ReferenceLayer::pictureReady);
    connect(m_worker, &reference_detail::ReferenceDecodeWorker::pictureDecoded, this,
            [this](quint64 generation, qint64 index, const QImage &picture) {
                if (generation == m_mediaGeneration)
                    emit pictureDecoded(index, picture);
            });
    m_thread->start(QThread::LowPriority);
}

QImage ReferenceLayer::pictureWithoutWaiting(int frameIndex)
{
    qint64 index = 0;
    const auto m = shownMedia(frameIndex, index);
    if (!m)
        return {};
    if (QImage ready = m->cachedFrame(index); !ready.isNull()) {
        m_lastShown = ready;
        return ready;
    }
    startWorker();
    if (m_worker->latest.exchange(index) != index) {
        auto *worker = m_worker;
        QMetaObject::invokeMethod(
            worker, [worker, m, index] { worker->decode(m, index); }, Qt::QueuedConnection);
    }
    return m_lastShown;
}

QImage ReferenceLayer::requestPicture(int frameIndex, qint64 *pending)
{
    *pending = -1;
    qint64 index = 0;
    const auto m = shownMedia(frameIndex, index);
    if (!m)
        return {};
    if (QImage ready = m->cachedFrame(index); !ready.isNull())
        return ready;
    startWorker();
    m_worker->enqueue(m, m_mediaGeneration, index);
    *pending = index;
    return {};
}

void ReferenceLayer::setReference(Reference reference)
{
    if (reference == m_reference)
        return;
    if (reference.kind != m_reference.kind || reference.bytes != m_reference.bytes ||
        reference.pictures != m_reference.pictures) {
        m_lastShown = QImage();
        ++m_mediaGeneration;
        if (m_worker) {
            m_worker->latest = -1;
            m_worker->dropQueued();
        }
        m_media.reset();
        m_mediaOpened = false;
        m_mediaError.clear();
    }
    m_reference = std::move(reference);
    emit referenceChanged();
}

std::shared_ptr<ReferenceMedia> ReferenceLayer::media() const
{
    if (!m_mediaOpened && !m_reference.isEmpty()) {
        m_mediaOpened = true;
        auto opened = ReferenceMedia::open(m_reference);
        if (opened) {
            m_media = *opened;
        } else {
            m_mediaError = opened.error();
            // Queued: media() is asked for in the middle of painting.
            auto *self = const_cast<ReferenceLayer *>(this);
            QMetaObject::invokeMethod(
                self,
                [self, name = m_reference.name, why = m_mediaError] {
                    emit self->mediaFailed(name, why);
                },
                Qt::QueuedConnection);
        }
    }
    return m_media;
}

qint64 ReferenceLayer::tickOfFrame(int frameIndex) const
{
    qint64 tick = 0;
    const int end = std::min(frameIndex, m_doc->frameCount());
    for (int i = 0; i < end; ++i)
        tick += std::max(1, m_doc->frameAt(i).hold);
    return tick;
}

qint64 ReferenceLayer::videoFrameAt(int frameIndex) const
{
    const auto m = media();
    if (!m)
        return 0;
    return m->frameAtTick(m_reference, tickOfFrame(frameIndex), m_doc->settings().fps);
}

QImage ReferenceLayer::pictureAt(int frameIndex, bool decode) const
{
    qint64 index = 0;
    const auto m = shownMedia(frameIndex, index);
    if (!m)
        return {};
    return decode ? m->frame(index) : m->cachedFrame(index);
}

void paintReference(QPainter &painter, const Reference &reference, const QImage &picture)
{
    if (picture.isNull() || reference.isEmpty() || !reference.visible)
        return;
    painter.save();
    painter.setOpacity(painter.opacity() * reference.opacity);
    painter.setRenderHint(QPainter::SmoothPixmapTransform, true);
    painter.setTransform(referenceTransform(reference), true);
    // A video frame may come at another size than the one recorded at import: fit it.
    painter.drawImage(QRectF(QPointF(0, 0), reference.mediaSize), picture);
    painter.restore();
}

QImage renderFrameWithReference(const Frame &frame, const DocumentSettings &settings, QSize size,
                                const Reference &reference, const QImage &picture)
{
    RenderOptions options;
    options.underlay = [&](QPainter &painter) { paintReference(painter, reference, picture); };
    return renderFrame(frame, settings, size, options);
}

} // namespace finbook::model
