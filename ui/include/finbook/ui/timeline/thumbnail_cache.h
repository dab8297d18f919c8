// ThumbnailCache: frame thumbnails rendered lazily, only for frames a view is showing.
//
// thumbnail() never renders: it returns what is cached (possibly an older revision, shown
// until the new one is ready) and queues the frame. A zero-timer renders queued frames in
// small time slices, asking the visibility filter first so frames scrolled away meanwhile are
// skipped. Entries are keyed by frame id and a revision bumped on Document::frameChanged
// (and for all frames when canvas size or background change), and evicted least recently used.
// A reference video's frames are decoded on the reference layer's worker thread: a thumbnail
// is drawn without its picture (or keeps its older one) until the picture comes.
#pragma once

#include <finbook/model/document.h>

#include <QCache>
#include <QHash>
#include <QImage>
#include <QObject>
#include <QPixmap>
#include <QTimer>

#include <functional>
#include <optional>
#include <vector>

namespace finbook::ui {

class ThumbnailCache : public QObject {
    Q_OBJECT
public:
    explicit ThumbnailCache(model::Document *document, QObject *parent = nullptr);

    // Logical size of the thumbnails; a change drops every cached one.
    void setThumbnailSize(QSize size, qreal devicePixelRatio = 1.0);
    QSize thumbnailSize() const { return m_size; }
    // How many thumbnails are kept (default 256).
    void setCapacity(int count) { m_cache.setMaxCost(qsizetype(count)); }
    int capacity() const { return int(m_cache.maxCost()); }
    // Off: a thumbnail is the cel's drawing alone, on the page (the dope sheet's blocks),
    // without the camera or the reference. On by default.
    void setShowsShot(bool on) { m_showsShot = on; }
    // Called before rendering a queued frame; a frame it rejects is dropped from the queue.
    void setVisibilityFilter(std::function<bool(model::Id)> isVisible);

    // The cached pixmap (may be stale) or a null pixmap; queues a render when not current.
    QPixmap thumbnail(model::Id frameId);
    bool isCurrent(model::Id frameId) const;
    // Renders everything queued now (tests and benches); the timer does this in slices.
    void renderPending();

    int renderedCount() const { return m_rendered; }
    int pendingCount() const { return int(m_pending.size()); }
    int cachedCount() const { return int(m_cache.count()); }

signals:
    void thumbnailRendered(model::Id frameId);
    void thumbnailsInvalidated();

private:
    struct Entry {
        QPixmap pixmap;
        quint64 revision = 0;
        std::optional<model::CameraState> shot; // the camera it was seen through
    };
    // The camera at the frame's first tick, when the document's camera frames anything but
    // the page (thumbnails show the shot, as playback and exports do).
    std::optional<model::CameraState> shotOf(model::Id frameId) const;
    quint64 currentRevision(model::Id frameId) const;
    void renderSlice();
    bool renderOne(model::Id frameId);
    void store(model::Id frameId, const QImage &picture); // renders and caches, current
    void pictureDecoded(qint64 mediaFrame, const QImage &picture);
    void invalidateAll();

    model::Document *m_doc;
    QSize m_size{96, 54};
    qreal m_dpr = 1.0;
    QCache<model::Id, Entry> m_cache{256};
    QHash<model::Id, quint64> m_revisions;
    quint64 m_generation = 1; // bumped when every thumbnail is stale at once
    std::vector<model::Id> m_pending;
    QHash<model::Id, qint64> m_awaiting; // frames whose reference video frame is decoding
    std::function<bool(model::Id)> m_isVisible;
    QTimer m_timer;
    int m_rendered = 0;
    QSize m_canvasSize;
    QRgb m_background = 0;
    double m_closeGap = -1.0; // fills' regions depend on it
    bool m_showsShot = true;
};

} // namespace finbook::ui
