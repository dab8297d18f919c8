#include <finbook/model/export/export_plan.h>
#include <finbook/model/reference/reference_layer.h>
#include <finbook/model/render.h>
#include <finbook/ui/timeline/thumbnail_cache.h>

#include <QElapsedTimer>

#include <algorithm>

namespace finbook::ui {

namespace {
// One slice of rendering per event-loop turn stays well under a frame at 60 Hz.
constexpr qint64 kSliceNs = 8'000'000;
} // namespace

ThumbnailCache::ThumbnailCache(model::Document *document, QObject *parent)
    : QObject(parent)
    , m_doc(document)
    , m_canvasSize(document->settings().canvasSize)
    , m_background(document->settings().background)
    , m_closeGap(document->settings().closeGap)
{
    m_timer.setSingleShot(true);
    m_timer.setInterval(0);
    connect(&m_timer, &QTimer::timeout, this, &ThumbnailCache::renderSlice);
    connect(m_doc, &model::Document::frameChanged, this,
            [this](model::Id frameId) { m_revisions[frameId] += 1; });
    connect(m_doc, &model::Document::documentReset, this, [this] {
        m_cache.clear();
        m_revisions.clear();
        m_pending.clear();
        m_awaiting.clear();
        emit thumbnailsInvalidated();
    });
    connect(&m_doc->referenceLayer(), &model::ReferenceLayer::referenceChanged, this,
            &ThumbnailCache::invalidateAll);
    connect(&m_doc->referenceLayer(), &model::ReferenceLayer::pictureDecoded, this,
            &ThumbnailCache::pictureDecoded);
    // Each thumbnail knows the shot it shows (Entry::shot): after a camera edit the ones whose
    // shot changed are drawn again as they come into view.
    connect(m_doc, &model::Document::cameraChanged, this, &ThumbnailCache::thumbnailsInvalidated);
    connect(m_doc, &model::Document::settingsChanged, this, [this] {
        const model::DocumentSettings &s = m_doc->settings();
        if (s.canvasSize == m_canvasSize && s.background == m_background &&
            s.closeGap == m_closeGap)
            return; // fps, loop and range do not show in a thumbnail
        m_canvasSize = s.canvasSize;
        m_background = s.background;
        m_closeGap = s.closeGap;
        ++m_generation;
        emit thumbnailsInvalidated();
    });
}

void ThumbnailCache::setThumbnailSize(QSize size, qreal devicePixelRatio)
{
    size = size.expandedTo(QSize(1, 1));
    if (size == m_size && qFuzzyCompare(devicePixelRatio, m_dpr))
        return;
    m_size = size;
    m_dpr = devicePixelRatio;
    invalidateAll();
}

void ThumbnailCache::invalidateAll()
{
    m_cache.clear();
    m_pending.clear();
    m_awaiting.clear();
    emit thumbnailsInvalidated();
}

void ThumbnailCache::setVisibilityFilter(std::function<bool(model::Id)> isVisible)
{
    m_isVisible = std::move(isVisible);
}

quint64 ThumbnailCache::currentRevision(model::Id frameId) const
{
    // The generation in the high bits: a settings change makes every entry stale at once.
    return (m_generation << 40) + m_revisions.value(frameId, 0);
}

std::optional<model::CameraState> ThumbnailCache::shotOf(model::Id frameId) const
{
    const model::CameraTrack &camera = m_doc->camera();
    const QSizeF page(m_doc->settings().canvasSize);
    if (!m_showsShot || camera.isEmpty() || !camera.isUsed(page))
        return std::nullopt;
    const qint64 tick = model::exposureTicks(m_doc->frames(), 0, m_doc->frameIndex(frameId) - 1);
    return model::cameraAt(camera, double(tick), page);
}

bool ThumbnailCache::isCurrent(model::Id frameId) const
{
    const Entry *e = m_cache.object(frameId);
    return e && e->revision == currentRevision(frameId) && e->shot == shotOf(frameId);
}

QPixmap ThumbnailCache::thumbnail(model::Id frameId)
{
    const Entry *e = m_cache.object(frameId); // also marks it most recently used
    if (e && e->revision == currentRevision(frameId) && e->shot == shotOf(frameId))
        return e->pixmap;
    if (m_awaiting.contains(frameId)) // drawn again when its reference picture comes
        return e ? e->pixmap : QPixmap();
    if (std::find(m_pending.begin(), m_pending.end(), frameId) == m_pending.end())
        m_pending.push_back(frameId);
    if (!m_timer.isActive())
        m_timer.start();
    return e ? e->pixmap : QPixmap();
}

bool ThumbnailCache::renderOne(model::Id frameId)
{
    if (isCurrent(frameId) || (m_isVisible && !m_isVisible(frameId)))
        return false;
    if (!m_doc->frame(frameId))
        return false;
    // A reference video's frame is never decoded here: the layer's worker does it, and the
    // thumbnail is drawn again with it when it comes (pictureDecoded).
    model::ReferenceLayer &reference = m_doc->referenceLayer();
    qint64 pending = -1;
    const QImage picture = reference.isEmpty() || !m_showsShot
                               ? QImage()
                               : reference.requestPicture(m_doc->frameIndex(frameId), &pending);
    if (pending >= 0) {
        m_awaiting[frameId] = pending;
        if (m_cache.contains(frameId))
            return false; // the older thumbnail stays until the picture is decoded
    } else {
        m_awaiting.remove(frameId);
    }
    store(frameId, picture);
    return true;
}

void ThumbnailCache::store(model::Id frameId, const QImage &picture)
{
    const model::Frame *frame = m_doc->frame(frameId);
    const QSize device = (QSizeF(m_size) * m_dpr).toSize().expandedTo(QSize(1, 1));
    model::RenderOptions options;
    options.camera = shotOf(frameId);
    if (!picture.isNull()) {
        const model::Reference &reference = m_doc->referenceLayer().reference();
        options.underlay = [&](QPainter &painter) {
            model::paintReference(painter, reference, picture);
        };
    }
    QImage image = model::renderFrame(*frame, m_doc->settings(), device, options);
    image.setDevicePixelRatio(m_dpr);
    m_cache.insert(frameId, new Entry{QPixmap::fromImage(std::move(image)),
                                      currentRevision(frameId), options.camera});
    ++m_rendered;
    emit thumbnailRendered(frameId);
}

void ThumbnailCache::pictureDecoded(qint64 mediaFrame, const QImage &picture)
{
    std::vector<model::Id> ready;
    for (auto it = m_awaiting.begin(); it != m_awaiting.end();) {
        if (it.value() == mediaFrame) {
            ready.push_back(it.key());
            it = m_awaiting.erase(it);
        } else {
            ++it;
        }
    }
    for (model::Id frameId : ready) {
        // Only a frame still showing that media frame; one whose holds or place changed
        // meanwhile is asked for again.
        const int index = m_doc->frameIndex(frameId);
        if (index < 0)
            continue;
        if (m_doc->referenceLayer().videoFrameAt(index) == mediaFrame)
            store(frameId, picture);
        else
            thumbnail(frameId);
    }
}

void ThumbnailCache::renderSlice()
{
    QElapsedTimer clock;
    clock.start();
    std::size_t done = 0;
    while (done < m_pending.size() && clock.nsecsElapsed() < kSliceNs)
        renderOne(m_pending[done++]);
    m_pending.erase(m_pending.begin(), m_pending.begin() + long(done));
    if (!m_pending.empty())
        m_timer.start();
}

void ThumbnailCache::renderPending()
{
    std::vector<model::Id> queue;
    queue.swap(m_pending);
    for (model::Id id : queue)
        renderOne(id);
}

} // namespace finbook::ui
