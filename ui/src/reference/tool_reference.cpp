// ReferenceTool: the drag turned into one undo macro of merging reference edits.
#include <finbook/model/document.h>
#include <finbook/model/reference/reference_layer.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/reference/tool_reference.h>

#include <QCoreApplication>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace finbook::ui {

namespace {
QString macroText(model::ReferenceEdit edit)
{
    // The reference commands' own texts, already translated.
    switch (edit) {
    case model::ReferenceEdit::Scale:
        return QCoreApplication::translate("Reference", "Scale Reference");
    case model::ReferenceEdit::Rotation:
        return QCoreApplication::translate("Reference", "Rotate Reference");
    default:
        return QCoreApplication::translate("Reference", "Move Reference");
    }
}

double angleOf(QPointF v)
{
    return std::atan2(v.y(), v.x()) * 180.0 / std::numbers::pi;
}
} // namespace

QIcon ReferenceTool::icon() const
{
    return QIcon::fromTheme(QStringLiteral("transform-move"),
                            QIcon(QStringLiteral(":/icons/tool_reference.svg")));
}

QCursor ReferenceTool::cursor() const
{
    if (m_dragging)
        return Qt::ClosedHandCursor;
    return m_over ? Qt::SizeAllCursor : Qt::ArrowCursor;
}

bool ReferenceTool::movable() const
{
    const model::Reference &r = canvas()->document()->referenceLayer().reference();
    return !r.isEmpty() && r.visible && !r.locked;
}

bool ReferenceTool::grabs(QPointF canvasPos) const
{
    const model::Reference &r = canvas()->document()->referenceLayer().reference();
    bool invertible = false;
    const QTransform toMedia = model::referenceTransform(r).inverted(&invertible);
    return invertible && QRectF(QPointF(0, 0), r.mediaSize).contains(toMedia.map(canvasPos));
}

void ReferenceTool::hover(const ToolEvent &event)
{
    const bool over = movable() && grabs(event.pos);
    if (over != m_over) {
        m_over = over;
        canvas()->setCursor(cursor());
    }
}

void ReferenceTool::press(const ToolEvent &event)
{
    if (!movable() || !grabs(event.pos))
        return;
    m_start = canvas()->document()->referenceLayer().reference();
    m_pressPos = event.pos;
    m_edit = event.modifiers & Qt::ShiftModifier     ? model::ReferenceEdit::Scale
             : event.modifiers & Qt::ControlModifier ? model::ReferenceEdit::Rotation
                                                     : model::ReferenceEdit::Place;
    m_dragging = true;
    canvas()->setCursor(cursor());
}

void ReferenceTool::move(const ToolEvent &event)
{
    if (!m_dragging)
        return;
    model::Document *doc = canvas()->document();
    model::Reference r = doc->referenceLayer().reference();
    const QPointF from = m_pressPos - m_start.center;
    const QPointF to = event.pos - m_start.center;
    switch (m_edit) {
    case model::ReferenceEdit::Scale: {
        const double a = std::hypot(from.x(), from.y());
        const double b = std::hypot(to.x(), to.y());
        if (a < 1e-6 || !std::isfinite(b))
            return;
        r.scale =
            std::clamp(m_start.scale * b / a, model::kMinReferenceScale, model::kMaxReferenceScale);
        break;
    }
    case model::ReferenceEdit::Rotation:
        if (QLineF(QPointF(), from).length() < 1e-6 || QLineF(QPointF(), to).length() < 1e-6)
            return;
        r.rotation = std::remainder(m_start.rotation + angleOf(to) - angleOf(from), 360.0);
        break;
    default:
        r.center = m_start.center + (event.pos - m_pressPos);
        break;
    }
    auto command = model::editReferenceCommand(doc, r, m_edit);
    if (!command)
        return; // nothing changes, or out of range
    if (!m_macroOpen) {
        // Opened on the first change: a click that moves nothing leaves no undo step.
        doc->undoStack()->beginMacro(macroText(m_edit));
        m_macroOpen = true;
    }
    doc->undoStack()->push(command.release());
}

void ReferenceTool::release(const ToolEvent &)
{
    finish();
}

void ReferenceTool::deactivate()
{
    finish();
    m_over = false;
}

void ReferenceTool::finish()
{
    if (m_macroOpen)
        canvas()->document()->undoStack()->endMacro();
    m_macroOpen = false;
    m_dragging = false;
    canvas()->setCursor(cursor());
}

void ReferenceTool::paintOverlay(QPainter &painter, const QTransform &canvasToWidget)
{
    const model::Reference &r = canvas()->document()->referenceLayer().reference();
    if (r.isEmpty() || !r.visible)
        return;
    // The picture's outline, so that it can be found under a busy drawing; grey when locked.
    const QPolygonF outline =
        (model::referenceTransform(r) * canvasToWidget).map(QRectF(QPointF(0, 0), r.mediaSize));
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    QPen pen(r.locked ? QColor(128, 128, 128) : QColor(0, 120, 215), 1.5, Qt::DashLine);
    pen.setCosmetic(true);
    painter.setPen(pen);
    painter.setBrush(Qt::NoBrush);
    painter.drawPolygon(outline);
    painter.restore();
}

} // namespace finbook::ui
