// CanvasWidget painting: the page, the cached frame and onion-skin layers, overlays.
#include "stroke_raster.h"

#include <finbook/model/reference/reference_layer.h>
#include <finbook/model/render.h>
#include <finbook/ui/canvas/canvas_tool.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/window/editor_state.h>

#include <QPaintEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace finbook::ui {

namespace {

const QColor kDeskColor(0x70, 0x70, 0x70);
const QColor kBorderColor(0x30, 0x30, 0x30);

// A copy of `frame` without `hidden` strokes. Copies share stroke data, so this costs
// pointers; a deformed pose is filtered alongside so displayedPoints() stays aligned.
model::Frame withoutStrokes(const model::Frame &frame, const std::vector<model::Id> &hidden)
{
    model::Frame copy = frame;
    for (model::StrokeGroup &g : copy.groups) {
        // A picture object's id among them: its picture is being dragged.
        if (g.picture && std::find(hidden.begin(), hidden.end(), g.id) != hidden.end())
            g.picture = nullptr;
        const bool deformed = g.isDeformed() && g.deformed->strokes.size() == g.strokes.size();
        model::DeformedStrokes pose;
        if (deformed) {
            pose.pictureVertices = g.deformed->pictureVertices;
            pose.pictureLayers = g.deformed->pictureLayers;
        }
        std::vector<model::Stroke> kept;
        for (std::size_t i = 0; i < g.strokes.size(); ++i) {
            if (std::find(hidden.begin(), hidden.end(), g.strokes[i].id) != hidden.end())
                continue;
            kept.push_back(g.strokes[i]);
            if (deformed)
                pose.strokes.push_back(g.deformed->strokes[i]);
        }
        if (kept.size() == g.strokes.size())
            continue;
        g.strokes = std::move(kept);
        g.deformed =
            deformed ? std::make_shared<const model::DeformedStrokes>(std::move(pose)) : nullptr;
    }
    return copy;
}

} // namespace

void CanvasWidget::connectDocument()
{
    model::Document *doc = document();
    const auto all = [this] {
        invalidateFrameLayer();
        invalidateOnionLayer();
    };
    connect(doc, &model::Document::documentReset, this, [this, all] {
        all();
        m_suppressed.clear();
        fitToView();
    });
    // Other layers: their cels at the playhead, under and over the current one.
    const auto layers = [this, all] {
        all();
        invalidateOtherLayers();
    };
    connect(doc, &model::Document::celsChanged, this, &CanvasWidget::invalidateOtherLayers);
    connect(doc, &model::Document::layersChanged, this, layers);
    connect(doc, &model::Document::currentLayerChanged, this, layers);
    connect(m_state, &EditorState::dimOtherLayersChanged, this,
            &CanvasWidget::invalidateOtherLayers);
    connect(doc, &model::Document::framesInserted, this, all);
    connect(doc, &model::Document::framesRemoved, this, all);
    connect(doc, &model::Document::frameMoved, this, all);
    connect(doc, &model::Document::settingsChanged, this, [this, all] {
        all();
        if (m_fitted)
            fitToView();
    });
    connect(doc, &model::Document::frameChanged, this, &CanvasWidget::frameEdited);
    connect(&doc->referenceLayer(), &model::ReferenceLayer::referenceChanged, this,
            qOverload<>(&QWidget::update));
    connect(&doc->referenceLayer(), &model::ReferenceLayer::pictureReady, this,
            qOverload<>(&QWidget::update));
    connect(m_state, &EditorState::currentFrameChanged, this, all);
    connect(m_state, &EditorState::onionSkinChanged, this, &CanvasWidget::invalidateOnionLayer);
    connect(m_state, &EditorState::playingChanged, this, qOverload<>(&QWidget::update));
    connect(m_state, &EditorState::showMeshChanged, this, qOverload<>(&QWidget::update));
    connect(m_state, &EditorState::selectionChanged, this, qOverload<>(&QWidget::update));
    // The camera's frame is drawn over the page, and Camera View looks through it.
    connect(doc, &model::Document::cameraChanged, this, qOverload<>(&QWidget::update));
    connect(m_state, &EditorState::cameraViewChanged, this, qOverload<>(&QWidget::update));
    connect(m_state, &EditorState::tickChanged, this, [this] {
        if (!document()->camera().isEmpty() || document()->layerCount() > 1)
            update();
    });
}

void CanvasWidget::frameEdited(model::Id frameId)
{
    const int index = document()->frameIndex(frameId);
    if (index < 0) { // another layer's cel
        invalidateOtherLayers();
        return;
    }
    const int current = m_state->currentFrameIndex();
    if (index == current)
        invalidateFrameLayer();
    const OnionSkin &onion = m_state->onionSkin();
    if (index != current && index >= current - onion.before && index <= current + onion.after)
        invalidateOnionLayer();
}

void CanvasWidget::invalidateFrameLayer()
{
    m_frameLayerValid = false;
    update();
}

void CanvasWidget::invalidateOnionLayer()
{
    m_onionLayerValid = false;
    update();
}

void CanvasWidget::invalidateCache()
{
    m_frameLayerValid = false;
    m_onionLayerValid = false;
    m_otherLayersValid = false;
}

void CanvasWidget::setSuppressedStrokes(std::vector<model::Id> strokeIds)
{
    if (strokeIds == m_suppressed)
        return;
    m_suppressed = std::move(strokeIds);
    invalidateFrameLayer();
}

void CanvasWidget::setPreviewFrame(std::optional<model::Frame> frame)
{
    m_preview = std::move(frame);
    invalidateFrameLayer();
}

void CanvasWidget::updateCanvasRect(const QRectF &canvasRect)
{
    if (canvasRect.isNull()) {
        update();
        return;
    }
    // Clipped to the widget in floating point first: a stroke at 1e30 px (a tablet or a file
    // can give one) must not overflow QRect's int coordinates.
    const QRectF mapped = canvasToWidget().mapRect(canvasRect);
    if (!std::isfinite(mapped.left()) || !std::isfinite(mapped.top()) ||
        !std::isfinite(mapped.width()) || !std::isfinite(mapped.height())) {
        update();
        return;
    }
    const QRectF visible = mapped.adjusted(-2, -2, 2, 2) & QRectF(rect());
    if (!visible.isEmpty())
        update(visible.toAlignedRect());
}

QRectF CanvasWidget::pageRect() const
{
    return screenTransform().mapRect(
        QRectF(QPointF(0, 0), QSizeF(document()->settings().canvasSize)));
}

QPolygonF CanvasWidget::pagePolygon() const
{
    return screenTransform().map(
        QPolygonF(QRectF(QPointF(0, 0), QSizeF(document()->settings().canvasSize))));
}

bool CanvasWidget::pageIsUpright() const
{
    return std::fmod(m_rotation, 90.0) == 0.0;
}

void CanvasWidget::clipToPage(QPainter &painter, const QRect &dirty) const
{
    if (pageIsUpright()) {
        painter.setClipRect(pageRect() & QRectF(dirty));
        return;
    }
    QPainterPath page;
    page.addPolygon(pagePolygon());
    page.closeSubpath();
    QPainterPath shown;
    shown.addRect(QRectF(dirty));
    painter.setClipPath(page.intersected(shown));
}

// Camera View: the shot, drawn through the camera each time (the camera moves with the
// playhead, so the page's cached layers do not serve); the onion skin's neighbours through the
// same camera, so that they show how the drawing moves within this shot.
void CanvasWidget::paintShot(QPainter &painter, const QRect &dirty) const
{
    painter.save();
    clipToPage(painter, dirty);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setTransform(canvasToWidget());
    model::ReferenceLayer &reference = document()->referenceLayer();
    if (!reference.isEmpty()) {
        const QImage picture = reference.pictureWithoutWaiting(m_state->currentFrameIndex());
        if (!picture.isNull())
            model::paintReference(painter, reference.reference(), picture);
    }
    if (m_state->onionSkin().enabled && !m_state->isPlaying() &&
        document()->currentLayer().properties.onionSkin)
        for (const auto &[index, options] : onionNeighbours())
            model::paintFrame(painter, document()->frameAt(index), document()->settings(), options);
    // Every layer, each plane through its own camera (multiplane depth).
    const model::CameraState camera =
        model::cameraAt(document()->camera(), double(m_state->currentTick()),
                        QSizeF(document()->settings().canvasSize));
    rasterizeShot(painter, dirty, camera);
    painter.restore();
}

QImage CanvasWidget::newLayerImage(QImage recycled) const
{
    // Reusing the old layer's buffer spares a 4 MB allocation and its page faults per render.
    const qreal dpr = devicePixelRatioF();
    const QSize size = (QSizeF(this->size()) * dpr).toSize();
    QImage image = recycled.size() == size && recycled.isDetached()
                       ? std::move(recycled)
                       : QImage(size, QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(dpr);
    image.fill(Qt::transparent);
    return image;
}

void CanvasWidget::rasterize(QImage &image, const std::function<void(StrokeRaster &)> &draw) const
{
    // The view is a similarity (zoom, turn, mirror, move), which the rasterizer takes whole; a
    // turned page is clipped to its bounds here, then masked to itself below.
    const qreal dpr = image.devicePixelRatio();
    const QRectF page = pageRect();
    const QRect clip(
        QPoint(int(std::floor(page.left() * dpr)), int(std::floor(page.top() * dpr))),
        QPoint(int(std::ceil(page.right() * dpr)) - 1, int(std::ceil(page.bottom() * dpr)) - 1));
    StrokeRaster::drawParallel(&image, clip, screenTransform() * QTransform::fromScale(dpr, dpr),
                               draw);
    // A turned page: what lies beyond its edges within its bounds is cleared once here, so a
    // repaint blits the layer with no clip path (a clip path cost ~5 ms a repaint).
    // The mask is made once per view and size, not once per layer.
    if (!pageIsUpright()) {
        const QTransform view = screenTransform();
        if (m_pageMask.size() != image.size() || m_pageMaskView != view) {
            m_pageMask = QImage(image.size(), QImage::Format_Alpha8);
            m_pageMask.setDevicePixelRatio(dpr);
            m_pageMask.fill(0);
            QPainter mask(&m_pageMask);
            mask.setRenderHint(QPainter::Antialiasing, true);
            mask.setPen(Qt::NoPen);
            mask.setBrush(Qt::black);
            mask.drawPolygon(pagePolygon());
            m_pageMaskView = view;
        }
        QPainter painter(&image);
        painter.setCompositionMode(QPainter::CompositionMode_DestinationIn);
        painter.drawImage(QPointF(0, 0), m_pageMask);
    }
}

QImage CanvasWidget::renderFrameLayer(QImage recycled) const
{
    QImage image = newLayerImage(std::move(recycled));
    const model::Frame *frame = m_preview ? &*m_preview : m_state->currentFrame();
    if (!frame)
        return image;
    model::RenderOptions options;
    options.paintBackground = false;
    const model::Frame shown =
        m_suppressed.empty() ? model::Frame{} : withoutStrokes(*frame, m_suppressed);
    const model::Frame &drawn = m_suppressed.empty() ? *frame : shown;
    const model::DocumentSettings &settings = document()->settings();
    StrokeRaster::prepareFills(drawn, options, settings);
    rasterize(image, [&](StrokeRaster &raster) { raster.drawFrame(drawn, options, settings); });
    return image;
}

std::vector<std::pair<int, model::RenderOptions>> CanvasWidget::onionNeighbours() const
{
    const OnionSkin &onion = m_state->onionSkin();
    const int current = m_state->currentFrameIndex();
    const model::Document *doc = document();
    // Farthest first so nearer neighbours lie on top; opacity falls off linearly with distance.
    std::vector<std::pair<int, model::RenderOptions>> layers;
    const auto addSide = [&](int count, int direction, const QColor &tint) {
        for (int k = count; k >= 1; --k) {
            const int index = current + direction * k;
            if (index < 0 || index >= doc->frameCount())
                continue;
            model::RenderOptions options;
            options.paintBackground = false;
            options.tint = tint;
            options.opacity = onion.opacity * qreal(count - k + 1) / qreal(count);
            layers.emplace_back(index, options);
        }
    };
    addSide(onion.before, -1, onion.beforeTint);
    addSide(onion.after, +1, onion.afterTint);
    return layers;
}

QImage CanvasWidget::renderOnionLayer(QImage recycled) const
{
    QImage image = newLayerImage(std::move(recycled));
    const model::Document *doc = document();
    const std::vector<std::pair<int, model::RenderOptions>> layers = onionNeighbours();
    const model::DocumentSettings &settings = doc->settings();
    for (const auto &[index, options] : layers)
        StrokeRaster::prepareFills(doc->frameAt(index), options, settings);
    if (!layers.empty())
        rasterize(image, [&](StrokeRaster &raster) {
            for (const auto &[index, options] : layers)
                raster.drawFrame(doc->frameAt(index), options, settings);
        });
    return image;
}

void CanvasWidget::ensureLayers()
{
    const QTransform view = canvasToWidget();
    const QSize layerSize = (QSizeF(size()) * devicePixelRatioF()).toSize();
    if (view != m_layerTransform || layerSize != m_layerSize) {
        m_layerTransform = view;
        m_layerSize = layerSize;
        m_frameLayerValid = false;
        m_onionLayerValid = false;
        m_otherLayersValid = false;
    }
    if (document()->layerCount() > 1)
        ensureOtherLayers();
    if (!m_frameLayerValid) {
        m_frameLayer = renderFrameLayer(std::move(m_frameLayer));
        m_frameLayerValid = true;
    }
    const bool onionShown = m_state->onionSkin().enabled && !m_state->isPlaying();
    if (onionShown && !m_onionLayerValid) {
        m_onionLayer = renderOnionLayer(std::move(m_onionLayer));
        m_onionLayerValid = true;
    }
}

void CanvasWidget::paintPage(QPainter &painter) const
{
    if (pageIsUpright()) {
        const QRectF page = pageRect();
        painter.fillRect(page.translated(3, 3), QColor(0, 0, 0, 60));
        painter.fillRect(page, QColor::fromRgba(document()->settings().background));
        return;
    }
    // Filled without antialiasing (a repaint's cost; the border drawn over it smooths the edge).
    const QPolygonF page = pagePolygon();
    painter.save();
    painter.setPen(Qt::NoPen);
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setBrush(QColor(0, 0, 0, 60));
    painter.drawPolygon(page.translated(3, 3));
    painter.setBrush(QColor::fromRgba(document()->settings().background));
    painter.drawPolygon(page);
    painter.restore();
}

void CanvasWidget::paintEvent(QPaintEvent *event)
{
    QPainter painter(this);
    const QRect dirty = event->rect();
    painter.fillRect(dirty, kDeskColor);
    paintPage(painter);
    if (looksThroughCamera()) {
        paintShot(painter, dirty);
        paintOverlays(painter);
        return;
    }
    ensureLayers();
    // The reference lies under the onion skin and the drawing, clipped to the page.
    model::ReferenceLayer &reference = document()->referenceLayer();
    if (!reference.isEmpty()) {
        const QImage picture = reference.pictureWithoutWaiting(m_state->currentFrameIndex());
        if (!picture.isNull()) {
            painter.save();
            clipToPage(painter, dirty);
            painter.setTransform(canvasToWidget());
            model::paintReference(painter, reference.reference(), picture);
            painter.restore();
        }
    }
    const qreal dpr = devicePixelRatioF();
    const QRectF source(QPointF(dirty.topLeft()) * dpr, QSizeF(dirty.size()) * dpr);
    const bool others = document()->layerCount() > 1;
    // (The layers of a turned page hold nothing beyond its edges: rasterize().)
    const bool turned = !pageIsUpright();
    if (others && !m_underCels.empty())
        painter.drawImage(QRectF(dirty), m_underLayer, source);
    if (m_state->onionSkin().enabled && !m_state->isPlaying() && !m_onionLayer.isNull() &&
        document()->currentLayer().properties.onionSkin)
        painter.drawImage(QRectF(dirty), m_onionLayer, source);
    // The current layer at its opacity (hidden: not at all; its tools still work).
    const model::LayerProperties &current = document()->currentLayer().properties;
    painter.setOpacity(current.visible ? current.opacity : 0.0);
    painter.drawImage(QRectF(dirty), m_frameLayer, source);
    painter.setOpacity(1.0);
    if (others && !m_overCels.empty())
        painter.drawImage(QRectF(dirty), m_overLayer, source);
    painter.setPen(QPen(kBorderColor, 1));
    painter.setBrush(Qt::NoBrush);
    if (turned) {
        painter.save();
        painter.setRenderHint(QPainter::Antialiasing, true);
        painter.drawPolygon(pagePolygon());
        painter.restore();
    } else {
        painter.drawRect(pageRect().adjusted(-0.5, -0.5, 0.5, 0.5));
    }
    paintOverlays(painter);
}

void CanvasWidget::paintOverlays(QPainter &painter)
{
    // Playback shows the animation, not the editing handles (pins, cages, bones, the mesh, the
    // tool's cursor); scrubbing is not playing, so they stay while the timeline is dragged.
    if (m_state->isPlaying())
        return;
    const QTransform view = canvasToWidget();
    for (const std::unique_ptr<CanvasOverlay> &overlay : m_overlays) {
        painter.save();
        overlay->paint(painter, view);
        painter.restore();
    }
    if (m_tool) {
        painter.setRenderHint(QPainter::Antialiasing, true);
        m_tool->paintOverlay(painter, view);
    }
}

} // namespace finbook::ui
