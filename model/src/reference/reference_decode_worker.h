// Decodes reference video frames on a worker thread, so the GUI thread never waits for a seek.
//
// Two kinds of request (ReferenceLayer):
// - the canvas's (pictureWithoutWaiting): only the latest is decoded, so scrubbing fast skips
//   the frames passed over; decoded() tells the layer;
// - the thumbnails' (requestPicture): every frame asked for is decoded once, in order, and
//   handed back with pictureDecoded(). They are taken one at a time, each posted after the
//   last, so a canvas request waits for at most one thumbnail's decode.
// The worker never touches the document; the frames also land in the media's cache.
#pragma once

#include <finbook/model/reference/reference_media.h>

#include <QImage>
#include <QObject>

#include <atomic>
#include <deque>
#include <memory>
#include <mutex>
#include <set>

namespace finbook::model::reference_detail {

class ReferenceDecodeWorker : public QObject {
    Q_OBJECT
public:
    // Set on the GUI thread before the request is posted; a request that is no longer the
    // latest when the worker gets to it is dropped.
    std::atomic<qint64> latest{-1};

    void decode(const std::shared_ptr<ReferenceMedia> &media, qint64 index)
    {
        if (latest.load() != index)
            return;
        media->frame(index);
        // Done: the same frame may be asked for again after the cache dropped it.
        qint64 expected = index;
        latest.compare_exchange_strong(expected, -1);
        emit decoded(index);
    }

    // GUI thread. Queues `index` of `media` (tagged `generation`) unless it is queued already.
    void enqueue(std::shared_ptr<ReferenceMedia> media, quint64 generation, qint64 index)
    {
        bool post = false;
        {
            std::lock_guard lock(m_mutex);
            if (!m_queued.insert({generation, index}).second)
                return;
            post = m_queue.empty();
            m_queue.push_back({std::move(media), generation, index});
        }
        if (post)
            QMetaObject::invokeMethod(this, &ReferenceDecodeWorker::decodeNext,
                                      Qt::QueuedConnection);
    }

    // GUI thread: drops what is queued (the media changed); a decode under way finishes.
    void dropQueued()
    {
        std::lock_guard lock(m_mutex);
        m_queue.clear();
        m_queued.clear();
    }

signals:
    void decoded(qint64 index);
    void pictureDecoded(quint64 generation, qint64 index, QImage picture);

private:
    struct Request {
        std::shared_ptr<ReferenceMedia> media;
        quint64 generation = 0;
        qint64 index = 0;
    };

    void decodeNext()
    {
        Request request;
        {
            std::lock_guard lock(m_mutex);
            if (m_queue.empty())
                return;
            request = std::move(m_queue.front());
            m_queue.pop_front();
        }
        QImage picture = request.media->frame(request.index);
        bool more = false;
        {
            std::lock_guard lock(m_mutex);
            m_queued.erase({request.generation, request.index});
            more = !m_queue.empty();
        }
        emit pictureDecoded(request.generation, request.index, std::move(picture));
        if (more)
            QMetaObject::invokeMethod(this, &ReferenceDecodeWorker::decodeNext,
                                      Qt::QueuedConnection);
    }

    std::mutex m_mutex;
    std::deque<Request> m_queue;
    // Queued or being decoded: a request for a frame under way is not queued again.
    std::set<std::pair<quint64, qint64>> m_queued;
};

} // namespace finbook::model::reference_detail
