// Decodes reference video frames on a worker thread for the canvas (ReferenceLayer::
// pictureWithoutWaiting). Only the latest request is decoded: scrubbing fast skips the
// frames passed over. The worker never touches the document; the frame lands in the media's
// cache and decoded() tells the layer.
#pragma once

#include <finbook/model/reference/reference_media.h>

#include <QObject>

#include <atomic>
#include <memory>

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

signals:
    void decoded(qint64 index);
};

} // namespace finbook::model::reference_detail
