#include "../rig/rig_prompt.h"
#include "../tools/stroke_hit.h"

#include <finbook/deform/nearest_vertex.h>
#include <finbook/model/pins/pin_commands.h>
#include <finbook/model/render.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/pins/tool_pin.h>
#include <finbook/ui/window/editor_state.h>

#include <QPainter>
#include <QPainterPath>

#include <cmath>

namespace finbook::ui {

namespace {
constexpr qreal kPinRadius = 6.0;      // widget px
constexpr qreal kPinGrab = 10.0;       // widget px
constexpr qreal kPinObjectGrab = 12.0; // widget px around a stroke

bool pinEditable(const model::StrokeGroup &g)
{
    return g.visible && !g.locked;
}
} // namespace

PinTool::PinTool(model::DeformController *controller, QObject *parent)
    : CanvasTool(parent)
    , m_controller(controller)
{
    connect(m_controller, &model::DeformController::busyChanged, this, [this] {
        if (canvas())
            canvas()->update();
    });
}

QIcon PinTool::icon() const
{
    return QIcon(QStringLiteral(":/icons/tool_pin.svg"));
}

void PinTool::activate()
{
    // Prepare every pinned object of the frame, so the first drag does not wait.
    if (const model::Frame *f = state()->currentFrame())
        for (const model::StrokeGroup &g : f->groups)
            if (!g.rig.pins.empty())
                m_controller->prepare(g.id);
}

void PinTool::deactivate()
{
    m_drag = {};
    m_hover = {};
}

PinTool::PinRef PinTool::pinAt(const ToolEvent &event) const
{
    const model::Frame *f = state()->currentFrame();
    if (!f)
        return {};
    const qreal zoom = canvas()->zoom();
    PinRef best;
    qreal bestDistance = kPinGrab / zoom;
    const model::Id current = state()->currentGroupId();
    for (const model::StrokeGroup &g : f->groups) {
        if (!pinEditable(g))
            continue;
        for (const model::Pin &p : g.rig.pins) {
            qreal d = QLineF(p.target, event.pos).length();
            if (g.id == current)
                d *= 0.5; // ties go to the object being worked on
            if (d <= bestDistance) {
                bestDistance = d;
                best = {g.id, p.id};
            }
        }
    }
    return best;
}

bool PinTool::objectHit(const model::StrokeGroup &group, const ToolEvent &event) const
{
    const qreal zoom = canvas()->zoom();
    for (std::size_t s = 0; s < group.strokes.size(); ++s) {
        const auto &points = model::displayedPoints(group, s);
        const qreal reach = kPinObjectGrab / zoom + group.strokes[s].data->width / 2;
        for (const model::StrokePoint &p : points)
            if (std::abs(p.x - event.pos.x()) <= reach && std::abs(p.y - event.pos.y()) <= reach &&
                std::hypot(p.x - event.pos.x(), p.y - event.pos.y()) <= reach)
                return true;
    }
    // Inside the object's (posed) mesh counts too: a pin in the middle of a filled shape.
    // Before the first pin there is no mesh yet: the silhouette it will be built from answers.
    const model::DeformSetup *setup = m_controller->setup(group.id);
    if (!setup || !m_controller->poseVertices(group.id))
        return insideShape(group, state()->document()->settings().closeGap, event.pos);
    const Eigen::MatrixX2d &U = *m_controller->poseVertices(group.id);
    const Eigen::MatrixX3i &F = setup->meshTriangles();
    const QPointF p = event.pos;
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        const QPointF a(U(F(t, 0), 0), U(F(t, 0), 1)), b(U(F(t, 1), 0), U(F(t, 1), 1)),
            c(U(F(t, 2), 0), U(F(t, 2), 1));
        auto side = [&p](QPointF u, QPointF v) {
            return (v.x() - u.x()) * (p.y() - u.y()) - (v.y() - u.y()) * (p.x() - u.x());
        };
        const qreal s1 = side(a, b), s2 = side(b, c), s3 = side(c, a);
        if ((s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0))
            return true;
    }
    return false;
}

model::Id PinTool::objectAt(const ToolEvent &event) const
{
    const model::Frame *f = state()->currentFrame();
    if (!f)
        return model::kNoId;
    if (const model::StrokeGroup *current = state()->currentGroup();
        current && pinEditable(*current) && objectHit(*current, event))
        return current->id;
    for (auto it = f->groups.rbegin(); it != f->groups.rend(); ++it)
        if (pinEditable(*it) && it->hasContent() && objectHit(*it, event))
            return it->id;
    return model::kNoId;
}

void PinTool::removePin(const PinRef &pin)
{
    model::Document *doc = state()->document();
    doc->undoStack()->push(new model::RemovePinCommand(doc, pin.groupId, pin.pinId));
}

void PinTool::startDrag(const PinRef &pin)
{
    m_drag = pin;
    ++m_dragSerial;
    state()->setCurrentGroupId(pin.groupId);
    m_controller->prepare(pin.groupId);
}

void PinTool::press(const ToolEvent &event)
{
    m_pressPos = event.pos;
    m_pressWidgetPos = event.widgetPos;
    m_dragStarted = false;
    const bool removing =
        event.button == Qt::RightButton || (event.modifiers & Qt::ControlModifier);
    if (const PinRef hit = pinAt(event); hit.isValid()) {
        if (removing)
            removePin(hit);
        else
            startDrag(hit);
        return;
    }
    if (removing)
        return;
    const model::Id groupId = objectAt(event);
    if (groupId == model::kNoId) {
        canvas()->postMessage(tr("Click on a visible, unlocked drawing to pin it."));
        return;
    }
    model::Document *doc = state()->document();
    // Pins replace a cage: ask before its pose is lost.
    if (const model::StrokeGroup *g = doc->group(groupId);
        g->rig.kind() == model::RigKind::Cage && !confirmDiscardingPose(canvas()->window(), *g))
        return;
    const auto [rest, target] = newPin(groupId, event.pos);
    auto *add = new model::AddPinCommand(doc, groupId, rest, target);
    const PinRef added{groupId, add->pinId()};
    doc->undoStack()->push(add);
    startDrag(added);
}

std::pair<QPointF, QPointF> PinTool::newPin(model::Id groupId, QPointF shown) const
{
    const model::StrokeGroup *g = state()->document()->group(groupId);
    // Unposed (or about to lose a cage's pose): what is shown is the rest drawing, and a pin
    // whose target is its rest position leaves the object unposed.
    if (!g || g->rig.kind() != model::RigKind::Pins || !g->rig.isPosed())
        return {shown, shown};
    // On a posed object the click is on the posed drawing; the pin belongs where that point
    // is on the rest drawing, and its target keeps the vertex it snaps to where the pose has
    // it now, so adding the pin does not move the drawing.
    const QPointF rest = m_controller->restPointFor(groupId, shown);
    const model::DeformSetup *setup = m_controller->setup(groupId);
    const Eigen::MatrixX2d *U = m_controller->poseVertices(groupId);
    if (!setup || !U || !setup->matches(*g, state()->document()->settings().closeGap))
        return {rest, shown};
    const Eigen::MatrixX2d &V = setup->meshVertices();
    const int v = deform::nearestVertex(V, Eigen::Vector2d(rest.x(), rest.y()));
    if (v < 0 || v >= U->rows() || v >= V.rows())
        return {rest, shown};
    return {rest, rest + QPointF((*U)(v, 0) - V(v, 0), (*U)(v, 1) - V(v, 1))};
}

void PinTool::secondaryClick(const ToolEvent &event)
{
    if (const PinRef hit = pinAt(event); hit.isValid())
        removePin(hit);
}

void PinTool::move(const ToolEvent &event)
{
    // A click must not leave a "Move Pin" step behind, nor a hand's tremble a pose: the pin
    // moves once the pointer has gone a few screen pixels (then it follows it exactly).
    if (!m_drag.isValid() || event.pos == m_pressPos)
        return;
    if (!m_dragStarted) {
        if (QLineF(event.widgetPos, m_pressWidgetPos).length() < kDragThreshold)
            return;
        m_dragStarted = true;
    }
    model::Document *doc = state()->document();
    doc->undoStack()->push(
        new model::MovePinCommand(doc, m_drag.groupId, m_drag.pinId, event.pos, m_dragSerial));
    canvas()->update();
}

void PinTool::release(const ToolEvent &event)
{
    move(event);
    m_drag = {};
}

void PinTool::hover(const ToolEvent &event)
{
    const PinRef h = pinAt(event);
    if (h.pinId != m_hover.pinId) {
        m_hover = h;
        canvas()->update();
    }
}

void PinTool::paintOverlay(QPainter &painter, const QTransform &canvasToWidget)
{
    const model::Frame *f = canvas()->shownFrame();
    if (!f)
        return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    const model::Id current = state()->currentGroupId();
    for (const model::StrokeGroup &g : f->groups) {
        if (!g.visible)
            continue;
        const bool waiting = m_controller->isWaiting(g.id);
        for (const model::Pin &p : g.rig.pins) {
            const QPointF at = canvasToWidget.map(p.target);
            const bool active = p.id == m_drag.pinId || p.id == m_hover.pinId;
            QColor fill = g.id == current ? QColor(230, 60, 40) : QColor(150, 150, 150);
            if (g.locked)
                fill = fill.lighter(150);
            painter.setPen(QPen(Qt::white, 2));
            painter.setBrush(fill);
            const qreal r = active ? kPinRadius + 2 : kPinRadius;
            painter.drawEllipse(at, r, r);
            painter.setPen(QPen(QColor(40, 40, 40), 1));
            painter.setBrush(Qt::NoBrush);
            painter.drawEllipse(at, r + 1.5, r + 1.5);
            if (waiting) {
                // Busy: a dashed ring while the worker prepares this object.
                painter.setPen(QPen(QColor(40, 120, 220), 2, Qt::DashLine));
                painter.drawEllipse(at, r + 5, r + 5);
            }
        }
    }
    painter.restore();
}

} // namespace finbook::ui
