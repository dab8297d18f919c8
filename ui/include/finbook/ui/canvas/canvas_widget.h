// The drawing surface: shows the current frame (with onion skin) and routes pointer input to
// the current CanvasTool in canvas coordinates.
//
// Speed: the current frame and the onion-skin neighbours are each rendered once into an image
// the size of the widget and reused until the document, the view or the settings change
// (Document::frameChanged for that frame, zoom, pan, resize, onion settings). A repaint with
// a warm cache is two image blits plus the tool's overlay, whatever the frame holds. The
// layers are drawn by a capsule rasterizer (stroke_raster.h) that gives QPainter's round-join
// stroke shape at a fraction of its cost, so a cold repaint stays fast too.
//
// View: the wheel zooms about the cursor (Krita's convention); the middle button, Space-drag
// and the hand tool pan; Shift+Space-drag turns the view about the widget's centre, and the
// view can be mirrored left to right. Turning and mirroring change the view only, never the
// document: every tool takes its positions through mapToCanvas(). Until the user zooms or pans,
// the page is kept fitted to the widget.
#pragma once

#include <finbook/model/types.h>

#include <QImage>
#include <QPolygonF>
#include <QTransform>
#include <QWidget>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace finbook::model {
class Document;
struct RenderOptions;
} // namespace finbook::model

namespace finbook::ui {

class CanvasOverlay;
class CanvasTool;
class StrokeRaster;
class EditorState;
struct ToolEvent;

class CanvasWidget : public QWidget {
    Q_OBJECT
public:
    static constexpr qreal kMinZoom = 0.05;
    static constexpr qreal kMaxZoom = 32.0;

    explicit CanvasWidget(EditorState *state, QWidget *parent = nullptr);
    ~CanvasWidget() override;

    EditorState *state() const { return m_state; }
    model::Document *document() const;

    // --- tools: the canvas owns them; the first one added becomes current.
    CanvasTool *addTool(std::unique_ptr<CanvasTool> tool);
    const std::vector<CanvasTool *> &tools() const { return m_toolList; }
    CanvasTool *tool(const QString &id) const;
    CanvasTool *currentTool() const { return m_tool; }
    void setCurrentTool(const QString &id);
    void addOverlay(std::unique_ptr<CanvasOverlay> overlay);

    // --- view
    // Widget pixels per canvas pixel (tools size their grab radii by it): the view's zoom, and
    // in Camera View the camera's zoom times it.
    qreal zoom() const;
    // Canvas (page) coordinates to widget pixels: the zoom and pan, and when looking through
    // the camera the camera's shot at the current tick before them.
    QTransform canvasToWidget() const;
    // Whether the canvas shows the camera's shot: in Camera View (EditorState::cameraView),
    // and while playing a document whose camera frames anything but the page.
    bool looksThroughCamera() const;
    QPointF mapToCanvas(const QPointF &widgetPos) const;
    QPointF mapFromCanvas(const QPointF &canvasPos) const;
    // Zooms so that the canvas point under `widgetAnchor` stays under it.
    void setZoom(qreal zoom, const QPointF &widgetAnchor);
    void zoomIn();
    void zoomOut();
    void fitToView();  // whole page visible, centred; kept fitted on resize
    void actualSize(); // 100 %, centred
    void panBy(const QPointF &widgetDelta);
    // The view's turn in degrees, (-180, 180], clockwise on screen as QPainter turns, about
    // the widget's centre (or the anchor), and whether it is mirrored left to right (applied
    // before the turn: a mirrored view turned by 30° shows the mirrored page turned by 30°).
    qreal rotation() const { return m_rotation; }
    bool isMirrored() const { return m_mirrored; }
    void setRotation(qreal degrees);
    void setRotation(qreal degrees, const QPointF &widgetAnchor);
    void rotateBy(qreal degrees) { setRotation(m_rotation + degrees); }
    void resetRotation() { setRotation(0); }
    // Flips what is on screen left to right about the widget's centre.
    void setMirrored(bool mirrored);
    // The canvas point under the mouse while the mouse is over the canvas (paste lands there).
    std::optional<QPointF> cursorPos() const;

    // --- for tools
    // Strokes left out of the cached frame while a tool draws them itself (transform preview);
    // a picture object's id leaves out its picture.
    void setSuppressedStrokes(std::vector<model::Id> strokeIds);
    // Repaints the widget area covering `canvasRect` (an empty rect repaints everything).
    void updateCanvasRect(const QRectF &canvasRect = {});
    void postMessage(const QString &message);
    // A frame shown instead of the current one (a dialog's live preview); std::nullopt shows
    // the document again. The document is never touched.
    void setPreviewFrame(std::optional<model::Frame> frame);
    bool hasPreviewFrame() const { return m_preview.has_value(); }
    // The frame on show: the preview while there is one, else the current frame (null when
    // there is none). Overlays draw the handles of this frame, so a preview shows its own pins.
    const model::Frame *shownFrame() const;
    // Every visible layer's cel at the playhead, the current layer's as shownFrame() shows it,
    // composed into one frame with a plane per layer (scene/shot.h).
    model::Frame shownShot() const;
    // Marks the cached frame and onion images stale (the repaint benchmark's cold case).
    void invalidateCache();

signals:
    void toolAdded(finbook::ui::CanvasTool *tool);
    void currentToolChanged(finbook::ui::CanvasTool *tool);
    void zoomChanged(qreal zoom);
    void viewTurned(qreal rotation, bool mirrored);
    void cursorMoved(const QPointF &canvasPos);
    void messagePosted(const QString &message);

protected:
    bool event(QEvent *event) override;
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void tabletEvent(QTabletEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void keyReleaseEvent(QKeyEvent *event) override;
    void focusOutEvent(QFocusEvent *event) override;
    void leaveEvent(QEvent *event) override;

private:
    enum class Drag { None, Tool, Pan, Rotate };

    void connectDocument();
    void frameEdited(model::Id frameId);
    void invalidateFrameLayer();
    void invalidateOnionLayer();
    void ensureLayers();
    QImage renderFrameLayer(QImage recycled) const;
    QImage renderOnionLayer(QImage recycled) const;
    QImage newLayerImage(QImage recycled) const;
    void rasterize(QImage &image, const std::function<void(StrokeRaster &)> &draw) const;
    QRectF pageRect() const; // the page's (in Camera View the shot's) bounds in widget coordinates
    // The page (or shot) on screen, turned with the view; pageRect() is its bounds.
    QPolygonF pagePolygon() const;
    // Whether the page's edges on screen are the widget's axes (the view unturned or turned by
    // a multiple of 90°): then clipping to pageRect() is clipping to the page.
    bool pageIsUpright() const;
    // Clips `painter` to the page on screen within `dirty`.
    void clipToPage(QPainter &painter, const QRect &dirty) const;
    QTransform viewLinear() const; // the view's zoom, mirror and turn, without its move
    void setViewLinear(const QTransform &before, const QPointF &widgetAnchor);
    QTransform screenTransform() const;     // the view's space (page or shot) to the widget
    QTransform cameraViewTransform() const; // page to shot in Camera View, else identity
    void paintShot(QPainter &painter, const QRect &dirty) const;
    // The shot's layers for Camera View: each plane rasterized through its own camera and the
    // view (canvas_layers.cpp), as fast as the page's cached layers.
    void rasterizeShot(QPainter &painter, const QRect &dirty,
                       const model::CameraState &camera) const;
    void paintOverlays(QPainter &painter);
    // The onion skin's frames, farthest first, with their tints and opacities.
    std::vector<std::pair<int, model::RenderOptions>> onionNeighbours() const;
    void paintPage(QPainter &painter) const;
    void clampPan();
    void setPanning(bool spaceHeld);
    void updateCursor();
    void beginDrag(const ToolEvent &event, bool pan, bool rotate = false);
    qreal angleFromCentre(const QPointF &widgetPos) const;
    // True (and a message posted) when the current layer is locked or hidden and the tool
    // would edit it.
    bool refusedOnLockedLayer();
    void continueDrag(const ToolEvent &event);
    void endDrag(const ToolEvent &event);
    ToolEvent toolEvent(const QPointF &widgetPos, qreal pressure) const;

    EditorState *m_state;
    std::vector<std::unique_ptr<CanvasTool>> m_ownedTools;
    std::vector<CanvasTool *> m_toolList;
    CanvasTool *m_tool = nullptr;
    std::vector<std::unique_ptr<CanvasOverlay>> m_overlays;

    qreal m_zoom = 1.0;
    qreal m_rotation = 0.0; // degrees, (-180, 180]
    bool m_mirrored = false;
    QPointF m_offset;         // widget position of the canvas origin
    qreal m_rotateFrom = 0.0; // a Rotate drag: the view's turn and the pointer's angle at its start
    qreal m_rotateGrab = 0.0;
    bool m_fitted = true;

    Drag m_drag = Drag::None;
    QPointF m_lastPanPos;
    std::optional<QPointF> m_hover; // widget position of the mouse, while over the canvas
    bool m_spaceHeld = false;
    bool m_tabletDown = false;

    std::vector<model::Id> m_suppressed;
    std::optional<model::Frame> m_preview;
    QImage m_frameLayer; // current frame, strokes only, transparent elsewhere
    QImage m_onionLayer; // tinted neighbours
    bool m_frameLayerValid = false;
    bool m_onionLayerValid = false;
    // The other layers' cels at the playhead (canvas_layers.cpp): those under the current
    // layer and those over it, each image holding every such cel at its layer's opacity.
    struct OtherCel {
        const model::Frame *frame = nullptr;
        double opacity = 1.0;
        bool operator==(const OtherCel &) const = default;
    };
    std::vector<OtherCel> otherCels(bool above) const;
    QImage renderOtherLayers(QImage recycled, const std::vector<OtherCel> &cels) const;
    void ensureOtherLayers();
    void invalidateOtherLayers();
    QImage m_underLayer, m_overLayer;
    mutable QImage m_shotLayer;                    // Camera View's picture, its buffer reused
    std::vector<OtherCel> m_underCels, m_overCels; // what they show
    bool m_otherLayersValid = false;
    QTransform m_layerTransform; // the view the layers were rendered for
    // A turned page's shape on screen, which rasterize() keeps of each layer, and its view.
    mutable QImage m_pageMask;
    mutable QTransform m_pageMaskView;
    QSize m_layerSize;
};

} // namespace finbook::ui
