#include "../rig/rig_prompt.h"
#include "../tools/stroke_hit.h"
#include "cage_paint.h"

#include <finbook/model/cage/cage_commands.h>
#include <finbook/model/cage/cage_setup.h>
#include <finbook/ui/cage/tool_cage.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/window/editor_state.h>

#include <QKeyEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace finbook::ui {

namespace {
constexpr qreal kCornerGrab = 9.0; // widget px
constexpr qreal kEdgeGrab = 6.0;   // widget px
constexpr qreal kCornerSize = 7.0; // widget px

} // namespace

CageTool::CageTool(model::DeformController *controller, QObject *parent)
    : CanvasTool(parent)
    , m_controller(controller)
{
    connect(m_controller, &model::DeformController::poseSolved, this, [this] {
        if (canvas())
            canvas()->update();
    });
}

QIcon CageTool::icon() const
{
    return QIcon(QStringLiteral(":/icons/tool_cage.svg"));
}

void CageTool::activate()
{
    if (!m_watching) {
        // A selection belongs to one cage: when that cage goes (Remove Rig, pins, undo of its
        // placing, another document) its corner numbers mean nothing for the next one.
        m_watching = true;
        model::Document *doc = state()->document();
        connect(doc, &model::Document::constraintsChanged, this, [this, doc](model::Id id) {
            const model::StrokeGroup *g = doc->group(id);
            if (id == m_selectionOf && (!g || g->rig.kind() != model::RigKind::Cage))
                m_selected.clear();
        });
        connect(doc, &model::Document::documentReset, this, [this] { m_selected.clear(); });
    }
    if (const model::StrokeGroup *g = cagedObject())
        m_controller->prepare(g->id);
}

void CageTool::deactivate()
{
    cancelPending();
    m_dragging = m_rubberBand = false;
    m_shapePreview.clear();
}

void CageTool::setEditingShape(bool on)
{
    if (on == m_editShape)
        return;
    m_editShape = on;
    m_selected.clear();
    emit editingShapeChanged(on);
    if (canvas())
        canvas()->update();
}

const model::StrokeGroup *CageTool::cagedObject() const
{
    const model::StrokeGroup *g = state()->currentGroup();
    return g && g->rig.kind() == model::RigKind::Cage ? g : nullptr;
}

const std::vector<QPointF> &CageTool::shownCorners(const model::StrokeGroup &g) const
{
    if (m_editShape)
        return m_shapePreview.empty() ? g.rig.cage.rest : m_shapePreview;
    return g.rig.cage.posed;
}

int CageTool::cornerAt(const model::StrokeGroup &g, QPointF widgetPos) const
{
    const std::vector<QPointF> &corners = shownCorners(g);
    const QTransform t = canvas()->canvasToWidget();
    int best = -1;
    qreal bestDistance = kCornerGrab;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const qreal d = QLineF(t.map(corners[i]), widgetPos).length();
        if (d <= bestDistance) {
            bestDistance = d;
            best = int(i);
        }
    }
    return best;
}

int CageTool::edgeAt(const model::StrokeGroup &g, QPointF pos) const
{
    const std::vector<QPointF> &c = shownCorners(g);
    const qreal reach = kEdgeGrab / canvas()->zoom();
    for (std::size_t i = 0; i < c.size(); ++i)
        if (distanceToSegment(pos, c[i], c[(i + 1) % c.size()]) <= reach)
            return int(i);
    return -1;
}

void CageTool::press(const ToolEvent &event)
{
    m_pressPos = m_dragPos = event.pos;
    if (const model::StrokeGroup *g = cagedObject(); g && m_pending.empty()) {
        pressOnCage(*g, event);
        return;
    }
    // Placing a cage: the first click on the first point closes it.
    if (m_pending.size() >= 3 &&
        QLineF(canvas()->canvasToWidget().map(m_pending.front()), event.widgetPos).length() <=
            kCornerGrab) {
        closePendingCage();
        return;
    }
    if (!state()->currentGroup()) {
        canvas()->postMessage(tr("Choose an object first: the cage goes around it."));
        return;
    }
    m_pending.push_back(event.pos);
    canvas()->update();
}

void CageTool::pressOnCage(const model::StrokeGroup &g, const ToolEvent &event)
{
    if (g.id != m_selectionOf) {
        m_selected.clear();
        m_selectionOf = g.id;
    }
    const int corner = cornerAt(g, event.widgetPos);
    const bool toggle = event.modifiers & Qt::ControlModifier;
    if (m_editShape && (event.modifiers & Qt::AltModifier) && corner < 0)
        if (const int edge = edgeAt(g, event.pos); edge >= 0) {
            insertCorner(g, edge, event.pos);
            return;
        }
    if (m_editShape && toggle && corner >= 0) {
        deleteCorner(g, corner);
        return;
    }
    if (corner < 0) {
        m_rubberBand = true;
        if (!toggle)
            m_selected.clear();
        return;
    }
    if (toggle) {
        if (!m_selected.erase(corner))
            m_selected.insert(corner);
        canvas()->update();
        return;
    }
    if (!m_selected.count(corner))
        m_selected = {corner};
    m_dragging = true;
    ++m_dragSerial;
    m_startCorners = shownCorners(g);
    m_controller->prepare(g.id);
}

void CageTool::move(const ToolEvent &event)
{
    m_dragPos = event.pos;
    if (m_rubberBand) {
        canvas()->update();
        return;
    }
    if (m_dragging && event.pos != m_pressPos)
        dragCorners(event);
}

void CageTool::dragCorners(const ToolEvent &event)
{
    const model::StrokeGroup *g = cagedObject();
    if (!g)
        return;
    QPointF delta = event.pos - m_pressPos;
    if (event.modifiers & Qt::ShiftModifier) // constrain to the dominant axis
        (std::abs(delta.x()) >= std::abs(delta.y()) ? delta.ry() : delta.rx()) = 0;
    std::vector<QPointF> corners = m_startCorners;
    for (int i : m_selected)
        if (i >= 0 && std::size_t(i) < corners.size())
            corners[std::size_t(i)] += delta;
    if (m_editShape) {
        // The rest cage changes on release (one precompute), previewed until then.
        m_shapePreview = std::move(corners);
        canvas()->update();
        return;
    }
    model::Document *doc = state()->document();
    doc->undoStack()->push(
        new model::MoveCageCornersCommand(doc, g->id, std::move(corners), m_dragSerial));
    canvas()->update();
}

void CageTool::release(const ToolEvent &event)
{
    if (m_rubberBand) {
        m_rubberBand = false;
        if (const model::StrokeGroup *g = cagedObject()) {
            const QRectF box = QRectF(m_pressPos, event.pos).normalized();
            const std::vector<QPointF> &c = shownCorners(*g);
            for (std::size_t i = 0; i < c.size(); ++i)
                if (box.contains(c[i]))
                    m_selected.insert(int(i));
        }
        canvas()->update();
        return;
    }
    if (m_dragging) {
        move(event);
        m_dragging = false;
        if (m_editShape)
            finishShapeDrag();
    }
}

void CageTool::finishShapeDrag()
{
    const model::StrokeGroup *g = cagedObject();
    if (!g || m_shapePreview.empty())
        return;
    model::CageRig cage = g->rig.cage;
    // A rest corner moved by d moves its posed corner by d too, so the pose is kept.
    for (std::size_t i = 0; i < cage.rest.size() && i < m_shapePreview.size(); ++i) {
        cage.posed[i] += m_shapePreview[i] - cage.rest[i];
        cage.rest[i] = m_shapePreview[i];
    }
    m_shapePreview.clear();
    if (const auto problem = model::cageProblem(*g, cage.rest)) {
        canvas()->postMessage(*problem);
        canvas()->update();
        return;
    }
    model::Document *doc = state()->document();
    doc->undoStack()->push(new model::EditCageCommand(doc, g->id, std::move(cage)));
}

void CageTool::deleteCorner(const model::StrokeGroup &g, int corner)
{
    model::CageRig cage = g.rig.cage;
    if (cage.rest.size() <= 3) {
        canvas()->postMessage(tr("A cage needs at least three corners."));
        return;
    }
    cage.rest.erase(cage.rest.begin() + corner);
    cage.posed.erase(cage.posed.begin() + corner);
    if (const auto problem = model::cageProblem(g, cage.rest)) {
        canvas()->postMessage(*problem);
        return;
    }
    m_selected.clear();
    model::Document *doc = state()->document();
    doc->undoStack()->push(new model::EditCageCommand(doc, g.id, std::move(cage)));
}

void CageTool::insertCorner(const model::StrokeGroup &g, int edge, QPointF pos)
{
    model::CageRig cage = g.rig.cage;
    const std::size_t a = std::size_t(edge), b = (a + 1) % cage.rest.size();
    // The new corner sits on the edge, at the same fraction in the rest and posed cages.
    const QPointF ab = cage.rest[b] - cage.rest[a];
    const qreal len2 = QPointF::dotProduct(ab, ab);
    const qreal t = len2 > 0 ? std::clamp(QPointF::dotProduct(pos - cage.rest[a], ab) / len2,
                                          qreal(0.05), qreal(0.95))
                             : 0.5;
    cage.rest.insert(cage.rest.begin() + edge + 1, cage.rest[a] + t * ab);
    cage.posed.insert(cage.posed.begin() + edge + 1,
                      cage.posed[a] + t * (cage.posed[b] - cage.posed[a]));
    m_selected.clear();
    model::Document *doc = state()->document();
    doc->undoStack()->push(new model::EditCageCommand(doc, g.id, std::move(cage)));
}

void CageTool::hover(const ToolEvent &event)
{
    m_hoverPos = event.pos;
    if (!m_pending.empty())
        canvas()->update();
}

void CageTool::secondaryClick(const ToolEvent &event)
{
    const model::StrokeGroup *g = cagedObject();
    if (!g || !m_editShape)
        return;
    if (const int corner = cornerAt(*g, event.widgetPos); corner >= 0)
        deleteCorner(*g, corner);
}

bool CageTool::keyPress(QKeyEvent *event)
{
    if (m_pending.empty()) {
        // In Edit Shape, Insert adds a corner on the edge under the mouse (as double-click).
        if (event->key() == Qt::Key_Insert && m_editShape)
            if (const model::StrokeGroup *g = cagedObject())
                if (const int edge = edgeAt(*g, m_hoverPos); edge >= 0) {
                    insertCorner(*g, edge, m_hoverPos);
                    return true;
                }
        return false;
    }
    switch (event->key()) {
    case Qt::Key_Return:
    case Qt::Key_Enter:
        closePendingCage();
        return true;
    case Qt::Key_Escape:
        cancelPending();
        return true;
    case Qt::Key_Backspace:
    case Qt::Key_Delete:
        m_pending.pop_back();
        canvas()->update();
        return true;
    default:
        return false;
    }
}

bool CageTool::claimsKey(const QKeyEvent &event) const
{
    // While corners are being placed, these keys belong to the cage, not to the window.
    static constexpr int kKeys[] = {Qt::Key_Return, Qt::Key_Enter, Qt::Key_Escape,
                                    Qt::Key_Backspace, Qt::Key_Delete};
    return !m_pending.empty() &&
           std::find(std::begin(kKeys), std::end(kKeys), event.key()) != std::end(kKeys);
}

bool CageTool::closePendingCage()
{
    const model::StrokeGroup *g = state()->currentGroup();
    if (!g || m_pending.empty())
        return false;
    if (const auto problem = model::cageProblem(*g, m_pending)) {
        canvas()->postMessage(*problem);
        return false;
    }
    if (!confirmDiscardingPose(canvas()->window(), *g))
        return false;
    model::Document *doc = state()->document();
    m_selected.clear(); // a new cage starts with nothing selected
    m_selectionOf = g->id;
    doc->undoStack()->push(new model::PlaceCageCommand(doc, g->id, m_pending));
    m_controller->prepare(g->id);
    cancelPending();
    return true;
}

void CageTool::cancelPending()
{
    m_pending.clear();
    if (canvas())
        canvas()->update();
}

void CageTool::paintOverlay(QPainter &painter, const QTransform &canvasToWidget)
{
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    if (!m_pending.empty()) {
        QPolygonF open = mappedPolygon(canvasToWidget, m_pending);
        open << canvasToWidget.map(m_hoverPos);
        painter.setPen(QPen(QColor(40, 120, 220), 1.5, Qt::DashLine));
        painter.drawPolyline(open);
        painter.setBrush(QColor(40, 120, 220));
        for (QPointF p : mappedPolygon(canvasToWidget, m_pending))
            painter.drawRect(QRectF(p - QPointF(3, 3), QSizeF(6, 6)));
    }
    if (const model::StrokeGroup *g = cagedObject()) {
        const QPolygonF corners = mappedPolygon(canvasToWidget, shownCorners(*g));
        for (int i = 0; i < corners.size(); ++i) {
            const bool selected = g->id == m_selectionOf && m_selected.count(i);
            painter.setPen(QPen(Qt::white, 1));
            painter.setBrush(selected ? QColor(230, 60, 40) : QColor(40, 40, 40));
            const qreal s = kCornerSize;
            painter.drawRect(QRectF(corners[i] - QPointF(s / 2, s / 2), QSizeF(s, s)));
        }
        if (m_rubberBand) {
            painter.setPen(QPen(QColor(40, 120, 220), 1, Qt::DashLine));
            painter.setBrush(QColor(40, 120, 220, 30));
            // The rectangle in the drawing that picks corners (turned with a turned view).
            painter.drawPolygon(
                canvasToWidget.map(QPolygonF(QRectF(m_pressPos, m_dragPos).normalized())));
        }
    }
    painter.restore();
}

} // namespace finbook::ui
