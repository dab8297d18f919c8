// CanvasWidget: the layers other than the current one, drawn at the playhead under and over
// the current layer's drawing (View → Dim Other Layers draws them at half strength), and the
// whole shot for Camera View.
#include "stroke_raster.h"

#include <finbook/model/scene/shot.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/window/editor_state.h>

#include <algorithm>
#include <cmath>

namespace finbook::ui {

std::vector<CanvasWidget::OtherCel> CanvasWidget::otherCels(bool above) const
{
    const model::Document *doc = document();
    const qint64 tick = m_state->currentTick();
    const int current = doc->currentLayerIndex();
    const double dim = m_state->dimOtherLayers() ? 0.5 : 1.0;
    std::vector<OtherCel> cels;
    const int first = above ? current + 1 : 0, end = above ? doc->layerCount() : current;
    for (int i = first; i < end; ++i) {
        const model::Layer &layer = doc->layerAt(i);
        if (!layer.properties.visible || layer.properties.opacity <= 0.0)
            continue;
        const int cel = model::celAt(layer.cels, tick);
        if (cel >= 0 && !layer.cels[std::size_t(cel)].groups.empty())
            cels.push_back({&layer.cels[std::size_t(cel)], layer.properties.opacity * dim});
    }
    return cels;
}

QImage CanvasWidget::renderOtherLayers(QImage recycled, const std::vector<OtherCel> &cels) const
{
    QImage image = newLayerImage(std::move(recycled));
    if (cels.empty())
        return image;
    const model::DocumentSettings &settings = document()->settings();
    std::vector<model::RenderOptions> options(cels.size());
    for (std::size_t i = 0; i < cels.size(); ++i) {
        options[i].paintBackground = false;
        options[i].opacity = cels[i].opacity;
        StrokeRaster::prepareFills(*cels[i].frame, options[i], settings);
    }
    rasterize(image, [&](StrokeRaster &raster) {
        for (std::size_t i = 0; i < cels.size(); ++i)
            raster.drawFrame(*cels[i].frame, options[i], settings);
    });
    return image;
}

void CanvasWidget::invalidateOtherLayers()
{
    m_otherLayersValid = false;
    update();
}

void CanvasWidget::ensureOtherLayers()
{
    std::vector<OtherCel> under = otherCels(false), over = otherCels(true);
    if (m_otherLayersValid && under == m_underCels && over == m_overCels)
        return;
    m_underLayer = renderOtherLayers(std::move(m_underLayer), under);
    m_overLayer = renderOtherLayers(std::move(m_overLayer), over);
    m_underCels = std::move(under);
    m_overCels = std::move(over);
    m_otherLayersValid = true;
}

void CanvasWidget::rasterizeShot(QPainter &painter, const QRect &dirty,
                                 const model::CameraState &camera) const
{
    const model::DocumentSettings &settings = document()->settings();
    const QSizeF page(settings.canvasSize);
    const model::Frame shot = shownShot();
    m_shotLayer = newLayerImage(std::move(m_shotLayer));
    const qreal dpr = m_shotLayer.devicePixelRatio();
    const QRectF shown = pageRect();
    const QRect clip(
        QPoint(int(std::floor(shown.left() * dpr)), int(std::floor(shown.top() * dpr))),
        QPoint(int(std::ceil(shown.right() * dpr)) - 1, int(std::ceil(shown.bottom() * dpr)) - 1));
    int begin = 0;
    for (const model::FramePlane &plane : shot.planes) {
        const int end = std::clamp(plane.groupEnd, begin, int(shot.groups.size()));
        model::Frame layer;
        layer.id = shot.id;
        layer.groups.assign(shot.groups.begin() + begin, shot.groups.begin() + end);
        begin = end;
        model::RenderOptions options;
        options.paintBackground = false;
        options.opacity = std::clamp(plane.opacity, 0.0, 1.0);
        if (layer.groups.empty() || options.opacity <= 0.0)
            continue;
        // Page → widget for this plane: its own camera, then the view (each a similarity).
        const QTransform view =
            model::cameraTransform(model::planeCamera(camera, plane.depth, page), page) *
            screenTransform() * QTransform::fromScale(dpr, dpr);
        StrokeRaster::prepareFills(layer, options, settings);
        StrokeRaster::drawParallel(&m_shotLayer, clip, view, [&](StrokeRaster &raster) {
            raster.drawFrame(layer, options, settings);
        });
    }
    painter.save();
    painter.resetTransform();
    const QRectF source(QPointF(dirty.topLeft()) * dpr, QSizeF(dirty.size()) * dpr);
    painter.drawImage(QRectF(dirty), m_shotLayer, source);
    painter.restore();
}

model::Frame CanvasWidget::shownShot() const
{
    const model::Document *doc = document();
    const qint64 tick = m_state->currentTick();
    model::Frame shot;
    for (int i = 0; i < doc->layerCount(); ++i) {
        const model::Layer &layer = doc->layerAt(i);
        if (!layer.properties.visible)
            continue;
        const model::Frame *cel = nullptr;
        if (i == doc->currentLayerIndex())
            cel = shownFrame();
        else if (const int at = model::celAt(layer.cels, tick); at >= 0)
            cel = &layer.cels[std::size_t(at)];
        if (!cel)
            continue;
        shot.groups.insert(shot.groups.end(), cel->groups.begin(), cel->groups.end());
        shot.planes.push_back(
            {int(shot.groups.size()), layer.properties.opacity, layer.properties.depth});
    }
    return shot;
}

} // namespace finbook::ui
