// CanvasWidget: tools, pointer input and the view transform. Painting and the layer cache
// are in canvas_render.cpp.
#include <finbook/ui/canvas/canvas_tool.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/window/editor_state.h>

#include <QKeyEvent>
#include <QLineF>
#include <QMouseEvent>
#include <QTabletEvent>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace finbook::ui {

namespace {
constexpr qreal kZoomStep = 1.25;
constexpr qreal kFitMargin = 24.0;
} // namespace

EditorState *CanvasTool::state() const
{
    return m_canvas ? m_canvas->state() : nullptr;
}

CanvasWidget::CanvasWidget(EditorState *state, QWidget *parent)
    : QWidget(parent)
    , m_state(state)
{
    setObjectName(QStringLiteral("canvas"));
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setAttribute(Qt::WA_TabletTracking);
    setMinimumSize(200, 150);
    connectDocument();
}

CanvasWidget::~CanvasWidget()
{
    if (m_tool)
        m_tool->deactivate();
}

model::Document *CanvasWidget::document() const
{
    return m_state->document();
}

CanvasTool *CanvasWidget::addTool(std::unique_ptr<CanvasTool> tool)
{
    CanvasTool *t = tool.get();
    t->m_canvas = this;
    m_ownedTools.push_back(std::move(tool));
    m_toolList.push_back(t);
    emit toolAdded(t);
    if (!m_tool)
        setCurrentTool(t->id());
    return t;
}

CanvasTool *CanvasWidget::tool(const QString &id) const
{
    for (CanvasTool *t : m_toolList)
        if (t->id() == id)
            return t;
    return nullptr;
}

void CanvasWidget::setCurrentTool(const QString &id)
{
    CanvasTool *next = tool(id);
    if (!next || next == m_tool)
        return;
    // deactivate() finishes the old tool's drag, so its release must not reach the new one.
    if (m_drag == Drag::Tool)
        m_drag = Drag::None;
    if (m_tool)
        m_tool->deactivate();
    m_tool = next;
    m_tool->activate();
    updateCursor();
    update();
    emit currentToolChanged(m_tool);
}

void CanvasWidget::addOverlay(std::unique_ptr<CanvasOverlay> overlay)
{
    m_overlays.push_back(std::move(overlay));
    update();
}

// --- view --------------------------------------------------------------------------------

QTransform CanvasWidget::viewLinear() const
{
    QTransform t;
    t.rotate(m_rotation);
    t.scale(m_mirrored ? -m_zoom : m_zoom, m_zoom);
    return t;
}

QTransform CanvasWidget::screenTransform() const
{
    if (m_rotation == 0.0 && !m_mirrored)
        return QTransform(m_zoom, 0, 0, m_zoom, m_offset.x(), m_offset.y());
    return viewLinear() * QTransform::fromTranslate(m_offset.x(), m_offset.y());
}

// Keeps the view-space point that was under `widgetAnchor` with the linear part `before` under
// it with the linear part as it is now.
void CanvasWidget::setViewLinear(const QTransform &before, const QPointF &widgetAnchor)
{
    bool invertible = false;
    const QTransform back = before.inverted(&invertible);
    if (!invertible)
        return;
    const QPointF anchor = back.map(widgetAnchor - m_offset);
    m_offset = widgetAnchor - viewLinear().map(anchor);
}

void CanvasWidget::setRotation(qreal degrees)
{
    setRotation(degrees, QRectF(rect()).center());
}

void CanvasWidget::setRotation(qreal degrees, const QPointF &widgetAnchor)
{
    if (!std::isfinite(degrees) || !std::isfinite(widgetAnchor.x()) ||
        !std::isfinite(widgetAnchor.y()))
        return;
    // (-180, 180], and whole multiples of a hundredth of a degree so that steps add up exactly.
    degrees = std::remainder(degrees, 360.0);
    if (degrees <= -180.0)
        degrees += 360.0;
    degrees = std::round(degrees * 100.0) / 100.0;
    if (degrees == m_rotation)
        return;
    const QTransform before = viewLinear();
    m_rotation = degrees;
    setViewLinear(before, widgetAnchor);
    m_fitted = false;
    update();
    emit viewTurned(m_rotation, m_mirrored);
}

void CanvasWidget::setMirrored(bool mirrored)
{
    if (mirrored == m_mirrored)
        return;
    // Flipping the screen left to right: F·R(θ)·S(±z, z) = R(−θ)·S(∓z, z).
    // The move follows: the screen flipped about the centre c, M'(p) = c + F(M(p) − c).
    m_mirrored = mirrored;
    if (m_rotation != 180.0)
        m_rotation = -m_rotation;
    const QPointF c = QRectF(rect()).center();
    m_offset = QPointF(2 * c.x() - m_offset.x(), m_offset.y());
    update();
    emit viewTurned(m_rotation, m_mirrored);
}

qreal CanvasWidget::angleFromCentre(const QPointF &widgetPos) const
{
    const QPointF d = widgetPos - QRectF(rect()).center();
    return std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi;
}

QTransform CanvasWidget::cameraViewTransform() const
{
    if (!looksThroughCamera())
        return {};
    const model::Document &doc = *document();
    const QSizeF page(doc.settings().canvasSize);
    return model::cameraTransform(
        model::cameraAt(doc.camera(), double(m_state->currentTick()), page), page);
}

bool CanvasWidget::looksThroughCamera() const
{
    if (m_state->cameraView())
        return true;
    // Playback shows what the audience will see: the shot, once the camera frames one.
    const model::Document &doc = *document();
    return m_state->isPlaying() && doc.camera().isUsed(QSizeF(doc.settings().canvasSize));
}

qreal CanvasWidget::zoom() const
{
    if (!looksThroughCamera())
        return m_zoom;
    const model::Document &doc = *document();
    const QSizeF page(doc.settings().canvasSize);
    return m_zoom * model::cameraAt(doc.camera(), double(m_state->currentTick()), page).zoom;
}

QTransform CanvasWidget::canvasToWidget() const
{
    return cameraViewTransform() * screenTransform();
}

QPointF CanvasWidget::mapToCanvas(const QPointF &widgetPos) const
{
    if (!looksThroughCamera() && m_rotation == 0.0 && !m_mirrored)
        return (widgetPos - m_offset) / m_zoom;
    bool invertible = false;
    const QTransform back = canvasToWidget().inverted(&invertible);
    return invertible ? back.map(widgetPos) : (widgetPos - m_offset) / m_zoom;
}

QPointF CanvasWidget::mapFromCanvas(const QPointF &canvasPos) const
{
    if (!looksThroughCamera() && m_rotation == 0.0 && !m_mirrored)
        return canvasPos * m_zoom + m_offset;
    return canvasToWidget().map(canvasPos);
}

void CanvasWidget::setZoom(qreal zoom, const QPointF &widgetAnchor)
{
    if (!std::isfinite(zoom))
        return;
    zoom = std::clamp(zoom, kMinZoom, kMaxZoom);
    // In the view's own space (the page, or the shot in Camera View).
    const QTransform before = viewLinear();
    m_zoom = zoom;
    setViewLinear(before, widgetAnchor);
    m_fitted = false;
    update();
    emit zoomChanged(m_zoom);
}

void CanvasWidget::zoomIn()
{
    setZoom(m_zoom * kZoomStep, QRectF(rect()).center());
}
void CanvasWidget::zoomOut()
{
    setZoom(m_zoom / kZoomStep, QRectF(rect()).center());
}

void CanvasWidget::fitToView()
{
    const QSizeF page(document()->settings().canvasSize);
    if (page.isEmpty())
        return;
    const qreal w = std::max(1.0, width() - 2 * kFitMargin);
    const qreal h = std::max(1.0, height() - 2 * kFitMargin);
    // The page's bounds as the view turns it, at 100 %.
    m_zoom = 1.0;
    const QSizeF turned = viewLinear().mapRect(QRectF(QPointF(0, 0), page)).size();
    m_zoom = std::clamp(std::min(w / turned.width(), h / turned.height()), kMinZoom, kMaxZoom);
    m_offset = QRectF(rect()).center() - viewLinear().map(QPointF(page.width(), page.height()) / 2);
    m_fitted = true;
    update();
    emit zoomChanged(m_zoom);
}

void CanvasWidget::actualSize()
{
    const QSizeF page(document()->settings().canvasSize);
    m_zoom = 1.0;
    m_offset = QRectF(rect()).center() - viewLinear().map(QPointF(page.width(), page.height()) / 2);
    m_fitted = false;
    update();
    emit zoomChanged(m_zoom);
}

std::optional<QPointF> CanvasWidget::cursorPos() const
{
    if (!m_hover)
        return std::nullopt;
    return mapToCanvas(*m_hover); // through the view as it is now, zoomed or panned since
}

void CanvasWidget::panBy(const QPointF &widgetDelta)
{
    if (widgetDelta.isNull())
        return;
    m_offset += widgetDelta;
    m_fitted = false;
    update();
}

void CanvasWidget::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    if (m_fitted)
        fitToView();
}

// --- input -------------------------------------------------------------------------------

ToolEvent CanvasWidget::toolEvent(const QPointF &widgetPos, qreal pressure) const
{
    ToolEvent e;
    e.widgetPos = widgetPos;
    e.pos = mapToCanvas(widgetPos);
    e.pressure = std::isfinite(pressure) ? std::clamp(pressure, 0.0, 1.0) : 1.0;
    return e;
}

bool CanvasWidget::refusedOnLockedLayer()
{
    const model::Layer &layer = document()->currentLayer();
    if ((!layer.properties.locked && layer.properties.visible) || !m_tool || !m_tool->editsLayer())
        return false;
    emit messagePosted(
        layer.properties.locked
            ? tr("The layer \"%1\" is locked: unlock it (Layer > Lock Layer, or its padlock in "
                 "the timeline) to draw on it.")
                  .arg(layer.properties.name)
            : tr("The layer \"%1\" is hidden: show it (Layer > Show Layer, or its eye in the "
                 "timeline) to draw on it.")
                  .arg(layer.properties.name));
    return true;
}

void CanvasWidget::beginDrag(const ToolEvent &event, bool pan, bool rotate)
{
    if (rotate) {
        m_drag = Drag::Rotate;
        m_rotateFrom = m_rotation;
        m_rotateGrab = angleFromCentre(event.widgetPos);
        setCursor(Qt::SizeAllCursor);
        return;
    }
    if (pan) {
        m_drag = Drag::Pan;
        m_lastPanPos = event.widgetPos;
        setCursor(Qt::ClosedHandCursor);
        return;
    }
    if (!m_tool)
        return;
    // Ctrl+click with a painting tool: the eyedropper's click, and no drag.
    if ((event.modifiers & Qt::ControlModifier) && m_tool->picksColourOnCtrlClick())
        if (CanvasTool *picker = tool(QStringLiteral("tool.eyedropper"))) {
            picker->press(event);
            return;
        }
    if (refusedOnLockedLayer())
        return;
    m_drag = Drag::Tool;
    m_tool->press(event);
}

void CanvasWidget::continueDrag(const ToolEvent &event)
{
    m_hover = event.widgetPos;
    emit cursorMoved(event.pos);
    switch (m_drag) {
    case Drag::Pan:
        panBy(event.widgetPos - m_lastPanPos);
        m_lastPanPos = event.widgetPos;
        break;
    case Drag::Rotate:
        // Turned as the pointer goes round the widget's centre (not too near it, where the
        // angle jumps).
        if (QLineF(QRectF(rect()).center(), event.widgetPos).length() > 4.0)
            setRotation(m_rotateFrom + angleFromCentre(event.widgetPos) - m_rotateGrab);
        break;
    case Drag::Tool:
        m_tool->move(event);
        break;
    case Drag::None:
        if (m_tool)
            m_tool->hover(event);
        break;
    }
}

void CanvasWidget::endDrag(const ToolEvent &event)
{
    const Drag was = m_drag;
    m_drag = Drag::None;
    if (was == Drag::Tool && m_tool)
        m_tool->release(event);
    updateCursor();
}

void CanvasWidget::mousePressEvent(QMouseEvent *event)
{
    setFocus(Qt::MouseFocusReason);
    if (m_drag != Drag::None || m_tabletDown)
        return;
    ToolEvent e = toolEvent(event->position(), 1.0);
    e.button = event->button();
    e.buttons = event->buttons();
    e.modifiers = event->modifiers();
    if (event->button() == Qt::LeftButton && m_spaceHeld &&
        (event->modifiers() & Qt::ShiftModifier))
        beginDrag(e, false, true);
    else if (event->button() == Qt::MiddleButton ||
             (event->button() == Qt::LeftButton && m_spaceHeld))
        beginDrag(e, true);
    else if (event->button() == Qt::LeftButton)
        beginDrag(e, false);
    else if (event->button() == Qt::RightButton && m_tool && !refusedOnLockedLayer())
        m_tool->secondaryClick(e);
}

void CanvasWidget::mouseMoveEvent(QMouseEvent *event)
{
    if (m_tabletDown)
        return;
    ToolEvent e = toolEvent(event->position(), 1.0);
    e.buttons = event->buttons();
    e.modifiers = event->modifiers();
    continueDrag(e);
}

void CanvasWidget::mouseReleaseEvent(QMouseEvent *event)
{
    if (m_tabletDown || m_drag == Drag::None)
        return;
    const bool panButton = event->button() == Qt::MiddleButton || event->button() == Qt::LeftButton;
    if (((m_drag == Drag::Pan || m_drag == Drag::Rotate) && !panButton) ||
        (m_drag == Drag::Tool && event->button() != Qt::LeftButton))
        return;
    ToolEvent e = toolEvent(event->position(), 1.0);
    e.button = event->button();
    e.buttons = event->buttons();
    e.modifiers = event->modifiers();
    endDrag(e);
}

void CanvasWidget::tabletEvent(QTabletEvent *event)
{
    // Accepting keeps Qt from synthesising mouse events for the same motion.
    event->accept();
    // A tablet driver can report a position that is not a number: such an event is dropped
    // before it can move the view or a tool (a NaN pan offset would blank the canvas).
    if (!std::isfinite(event->position().x()) || !std::isfinite(event->position().y()))
        return;
    ToolEvent e = toolEvent(event->position(), event->pressure());
    e.button = event->button();
    e.buttons = event->buttons();
    e.modifiers = event->modifiers();
    e.tablet = true;
    switch (event->type()) {
    case QEvent::TabletPress:
        if (m_drag != Drag::None)
            return;
        m_tabletDown = true;
        setFocus(Qt::MouseFocusReason);
        beginDrag(e, m_spaceHeld || event->button() == Qt::MiddleButton,
                  m_spaceHeld && (event->modifiers() & Qt::ShiftModifier));
        break;
    case QEvent::TabletMove:
        continueDrag(e);
        break;
    case QEvent::TabletRelease:
        m_tabletDown = false;
        if (m_drag != Drag::None)
            endDrag(e);
        break;
    default:
        break;
    }
}

void CanvasWidget::wheelEvent(QWheelEvent *event)
{
    const QPoint angle = event->angleDelta();
    if (angle.y() != 0) {
        setZoom(m_zoom * std::pow(kZoomStep, angle.y() / 120.0), event->position());
    } else if (angle.x() != 0) {
        panBy(QPointF(angle.x() / 2.0, 0));
    }
    event->accept();
}

const model::Frame *CanvasWidget::shownFrame() const
{
    return m_preview ? &*m_preview : m_state->currentFrame();
}

bool CanvasWidget::event(QEvent *event)
{
    // A shortcut override accepted here turns the key into a key press for the tool instead
    // of a window shortcut.
    if (event->type() == QEvent::ShortcutOverride && m_tool &&
        m_tool->claimsKey(*static_cast<QKeyEvent *>(event))) {
        event->accept();
        return true;
    }
    return QWidget::event(event);
}

void CanvasWidget::keyPressEvent(QKeyEvent *event)
{
    // Space pans; Shift+Space turns the view (Krita's keys). Shift may come before or after.
    if (event->key() == Qt::Key_Space &&
        (event->modifiers() == Qt::NoModifier || event->modifiers() == Qt::ShiftModifier)) {
        if (!event->isAutoRepeat())
            setPanning(true);
        event->accept();
        return;
    }
    if (m_tool && m_tool->keyPress(event)) {
        event->accept();
        return;
    }
    QWidget::keyPressEvent(event);
}

void CanvasWidget::keyReleaseEvent(QKeyEvent *event)
{
    if (event->key() == Qt::Key_Space && !event->isAutoRepeat()) {
        setPanning(false);
        event->accept();
        return;
    }
    QWidget::keyReleaseEvent(event);
}

void CanvasWidget::focusOutEvent(QFocusEvent *event)
{
    setPanning(false);
    QWidget::focusOutEvent(event);
}

void CanvasWidget::leaveEvent(QEvent *event)
{
    m_hover.reset();
    if (m_tool && m_drag == Drag::None)
        update();
    QWidget::leaveEvent(event);
}

void CanvasWidget::setPanning(bool spaceHeld)
{
    if (m_spaceHeld == spaceHeld)
        return;
    m_spaceHeld = spaceHeld;
    if (m_drag != Drag::Pan)
        updateCursor();
}

void CanvasWidget::updateCursor()
{
    if (m_drag == Drag::Pan)
        setCursor(Qt::ClosedHandCursor);
    else if (m_drag == Drag::Rotate)
        setCursor(Qt::SizeAllCursor);
    else if (m_spaceHeld)
        setCursor(Qt::OpenHandCursor);
    else if (m_tool)
        setCursor(m_tool->cursor());
    else
        unsetCursor();
}

void CanvasWidget::postMessage(const QString &message)
{
    emit messagePosted(message);
}

} // namespace finbook::ui
