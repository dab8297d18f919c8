// The light handle on the canvas (light_handle.h).
#include <finbook/model/document.h>
#include <finbook/model/shade/shade_commands.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/shade/light_handle.h>

#include <QDockWidget>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QUndoStack>

#include <algorithm>
#include <cmath>

namespace finbook::ui {

namespace {
constexpr double kSunRadius = 7.0; // px on screen
constexpr double kGrab = 12.0;     // a press this close to the sun's centre takes it
} // namespace

LightHandle::LightHandle(CanvasWidget *canvas, QDockWidget *panel)
    : QObject(canvas)
    , m_canvas(canvas)
    , m_panel(panel)
{
    setObjectName(QStringLiteral("lightHandle"));
    canvas->installEventFilter(this);
    // visibilityChanged, not isVisible(): a dock behind another's tab still says visible.
    m_panelShown = panel->isVisible();
    connect(panel, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        m_panelShown = visible;
        if (!visible && m_dragging)
            finish(true);
        m_canvas->update();
    });
    if (model::Document *doc = canvas->document())
        connect(doc, &model::Document::settingsChanged, canvas, [canvas] { canvas->update(); });
}

bool LightHandle::shown() const
{
    return m_panelShown && m_panel->isVisible() && m_canvas->document();
}

QPointF LightHandle::centre() const
{
    const QSize size = m_canvas->document()->settings().canvasSize;
    return m_canvas->mapFromCanvas(QPointF(size.width() / 2.0, size.height() / 2.0));
}

double LightHandle::radius() const
{
    const QSize size = m_canvas->document()->settings().canvasSize;
    return 0.4 * std::min(size.width(), size.height()) * m_canvas->zoom();
}

QPointF LightHandle::sunPos() const
{
    const model::DocumentSettings &s = m_canvas->document()->settings();
    const double a = s.lightAzimuth * M_PI / 180.0;
    const double reach =
        radius() * std::cos(std::clamp(s.lightElevation, 0.0, 90.0) * M_PI / 180.0);
    // Counter-clockwise on screen from the right: y grows downward.
    return centre() + reach * QPointF(std::cos(a), -std::sin(a));
}

void LightHandle::paint(QPainter &painter) const
{
    if (!shown())
        return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    const QPointF c = centre(), sun = sunPos();
    QPen dashed(QColor(120, 120, 120, m_dragging ? 200 : 110), 1.0, Qt::DashLine);
    painter.setPen(dashed);
    painter.setBrush(Qt::NoBrush);
    painter.drawEllipse(c, radius(), radius());
    painter.setPen(QPen(QColor(200, 140, 0, 200), 1.5));
    painter.drawLine(c, sun);
    // The sun: a disc with eight rays.
    painter.setPen(QPen(QColor(90, 60, 0), 1.5));
    for (int k = 0; k < 8; ++k) {
        const double a = k * M_PI / 4.0;
        const QPointF d(std::cos(a), std::sin(a));
        painter.drawLine(sun + d * (kSunRadius + 2.0), sun + d * (kSunRadius + 5.0));
    }
    painter.setBrush(QColor(255, 205, 40));
    painter.drawEllipse(sun, kSunRadius, kSunRadius);
    painter.restore();
}

void LightHandle::dragTo(const QPointF &widgetPos)
{
    model::Document *doc = m_canvas->document();
    const QPointF d = widgetPos - centre();
    const double length = std::hypot(d.x(), d.y());
    double azimuth = doc->settings().lightAzimuth;
    if (length > 1e-6)
        azimuth = std::fmod(std::atan2(-d.y(), d.x()) * 180.0 / M_PI + 360.0, 360.0);
    const double r = std::max(radius(), 1e-6);
    const double elevation = std::acos(std::min(length / r, 1.0)) * 180.0 / M_PI;
    // Whole degrees, as the panel shows them.
    azimuth = std::fmod(std::round(azimuth), 360.0);
    const double height = std::round(elevation);
    // The drag's one step: the previous position's command is taken back and dropped from
    // the stack before the new one is pushed.
    dropPushed();
    if (auto command = model::setLightCommand(doc, azimuth, height)) {
        m_pushed = command.get();
        doc->undoStack()->push(command.release());
    }
}

void LightHandle::dropPushed()
{
    if (!m_pushed)
        return;
    // Undone here, then marked obsolete: QUndoStack::undo() then removes it without undoing
    // it again, and leaves nothing to redo.
    m_pushed->undo();
    m_pushed->setObsolete(true);
    m_pushed = nullptr;
    m_canvas->document()->undoStack()->undo();
}

void LightHandle::finish(bool keep)
{
    if (!keep)
        dropPushed();
    m_pushed = nullptr;
    m_dragging = false;
    m_canvas->update();
}

bool LightHandle::eventFilter(QObject *watched, QEvent *event)
{
    if (watched != m_canvas)
        return false;
    switch (event->type()) {
    case QEvent::MouseButtonPress: {
        auto *mouse = static_cast<QMouseEvent *>(event);
        if (m_dragging || mouse->button() != Qt::LeftButton || !shown())
            return m_dragging;
        const QPointF d = mouse->position() - sunPos();
        if (std::hypot(d.x(), d.y()) > kGrab)
            return false;
        m_dragging = true;
        m_pushed = nullptr;
        m_canvas->setFocus();
        m_canvas->update();
        return true;
    }
    case QEvent::MouseMove:
        if (!m_dragging)
            return false;
        dragTo(static_cast<QMouseEvent *>(event)->position());
        return true;
    case QEvent::MouseButtonRelease:
        if (!m_dragging)
            return false;
        if (static_cast<QMouseEvent *>(event)->button() == Qt::LeftButton)
            finish(true);
        return true;
    case QEvent::ShortcutOverride:
    case QEvent::KeyPress: {
        auto *key = static_cast<QKeyEvent *>(event);
        if (!m_dragging || key->key() != Qt::Key_Escape)
            return false;
        if (event->type() == QEvent::ShortcutOverride) {
            event->accept(); // Escape is the drag's, not a window shortcut's
            return true;
        }
        finish(false);
        return true;
    }
    case QEvent::FocusOut:
    case QEvent::Hide:
        if (m_dragging)
            finish(true); // the drag ends where it was
        return false;
    default:
        return false;
    }
}

} // namespace finbook::ui
