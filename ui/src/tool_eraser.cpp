#include "stroke_hit.h"

#include <finbook/model/commands.h>
#include <finbook/model/render.h>
#include <finbook/ui/canvas_widget.h>
#include <finbook/ui/editor_state.h>
#include <finbook/ui/skeleton/skeleton_follow.h>
#include <finbook/ui/stroke_editing.h>
#include <finbook/ui/tool_eraser.h>

#include <QPainter>

#include <algorithm>
#include <utility>

namespace finbook::ui {

StrokeEraserTool::StrokeEraserTool(QObject *parent)
    : CanvasTool(parent)
{}

QIcon StrokeEraserTool::icon() const
{
    return QIcon::fromTheme(QStringLiteral("draw-eraser"),
                            QIcon(QStringLiteral(":/icons/tool_eraser.svg")));
}

void StrokeEraserTool::press(const ToolEvent &event)
{
    m_erasing = true;
    m_last = event.pos;
    moveCursor(event.pos);
    eraseAlong(event.pos, event.pos);
}

void StrokeEraserTool::move(const ToolEvent &event)
{
    moveCursor(event.pos);
    if (!m_erasing)
        return;
    eraseAlong(m_last, event.pos);
    m_last = event.pos;
}

void StrokeEraserTool::release(const ToolEvent &event)
{
    if (m_erasing)
        eraseAlong(m_last, event.pos);
    finish();
}

void StrokeEraserTool::hover(const ToolEvent &event)
{
    moveCursor(event.pos);
}

void StrokeEraserTool::deactivate()
{
    finish();
    m_cursorShown = false;
    if (canvas())
        canvas()->updateCanvasRect();
}

void StrokeEraserTool::finish()
{
    m_erasing = false;
    if (m_macroOpen) {
        m_macroOpen = false;
        m_erasedFrom.clear();
        StrokeEditing::endRestEdit(*state(), std::exchange(m_following, {}));
    }
}

void StrokeEraserTool::eraseAlong(const QPointF &from, const QPointF &to)
{
    const model::Frame *frame = state()->currentFrame();
    if (!frame)
        return;
    const qreal tolerance = kRadius / canvas()->zoom();
    const QLineF path(from, to);
    std::vector<model::Id> hits;
    for (const model::StrokeGroup &g : frame->groups) {
        if (!isEditable(g))
            continue;
        for (std::size_t i = 0; i < g.strokes.size(); ++i) {
            const model::Stroke &s = g.strokes[i];
            if (s.data &&
                strokeTouched(model::displayedPoints(g, i), s.data->width, path, tolerance))
                hits.push_back(s.id);
        }
    }
    if (hits.empty())
        return;
    model::Document *doc = state()->document();
    // The macro opens at the first hit, so a drag that erases nothing leaves no undo step.
    if (!m_macroOpen) {
        doc->undoStack()->beginMacro(tr("Erase"));
        m_macroOpen = true;
    }
    // Erasing from a posed object makes its pose the drawing first, so the strokes left
    // stay where they are shown (re-meshing without them would shift the pose).
    std::vector<model::Id> groups;
    for (model::Id id : hits)
        if (const model::StrokeLocation at = doc->locateStroke(id); at.isValid())
            groups.push_back(doc->frameAt(at.frame).groups[std::size_t(at.group)].id);
    // Whether a skeleton follows is decided when the gesture first reaches its object,
    // before its pose (if any) is applied.
    for (model::Id id : groups)
        if (std::find(m_erasedFrom.begin(), m_erasedFrom.end(), id) == m_erasedFrom.end()) {
            m_erasedFrom.push_back(id);
            for (model::Id f : skeletonsFollowing(*state(), {id}))
                m_following.push_back(f);
        }
    StrokeEditing::applyPoses(doc, groups);
    for (model::Id id : hits)
        doc->undoStack()->push(new model::RemoveStrokeCommand(doc, id));
}

void StrokeEraserTool::moveCursor(const QPointF &pos)
{
    const qreal r = (kRadius + 2) / canvas()->zoom();
    if (m_cursorShown)
        canvas()->updateCanvasRect(QRectF(m_cursor - QPointF(r, r), QSizeF(2 * r, 2 * r)));
    m_cursor = pos;
    m_cursorShown = true;
    canvas()->updateCanvasRect(QRectF(m_cursor - QPointF(r, r), QSizeF(2 * r, 2 * r)));
}

void StrokeEraserTool::paintOverlay(QPainter &painter, const QTransform &canvasToWidget)
{
    if (!m_cursorShown || !canvas()->underMouse())
        return;
    const QPointF c = canvasToWidget.map(m_cursor);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(255, 255, 255, 200), 3));
    painter.drawEllipse(c, kRadius, kRadius);
    painter.setPen(QPen(QColor(0, 0, 0, 200), 1));
    painter.drawEllipse(c, kRadius, kRadius);
}

} // namespace finbook::ui
