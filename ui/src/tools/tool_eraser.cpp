#include "stroke_hit.h"

#include <finbook/model/cage/cage_commands.h>
#include <finbook/model/commands.h>
#include <finbook/model/erase/stroke_cut.h>
#include <finbook/model/render.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/skeleton/skeleton_follow.h>
#include <finbook/ui/tools/stroke_editing.h>
#include <finbook/ui/tools/tool_eraser.h>
#include <finbook/ui/window/editor_state.h>

#include <QKeyEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <utility>

namespace finbook::ui {

EraserTool::EraserTool(QObject *parent)
    : CanvasTool(parent)
{}

QIcon EraserTool::icon() const
{
    return QIcon::fromTheme(QStringLiteral("draw-eraser"),
                            QIcon(QStringLiteral(":/icons/tool_eraser.svg")));
}

void EraserTool::setMode(EraserMode mode)
{
    if (mode == m_mode)
        return;
    m_mode = mode;
    emit modeChanged(mode);
    if (canvas())
        canvas()->updateCanvasRect();
}

void EraserTool::setSize(qreal size)
{
    if (!std::isfinite(size))
        return;
    size = std::clamp(size, kMinSize, kMaxSize);
    if (size == m_size)
        return;
    m_size = size;
    emit sizeChanged(size);
    if (canvas())
        canvas()->updateCanvasRect();
}

qreal EraserTool::radius() const
{
    return m_size / 2;
}

void EraserTool::press(const ToolEvent &event)
{
    m_erasing = true;
    m_wholeStrokes =
        (m_mode == EraserMode::WholeStrokes) != bool(event.modifiers & Qt::ShiftModifier);
    m_last = event.pos;
    moveCursor(event.pos);
    eraseAlong(event.pos, event.pos);
}

void EraserTool::move(const ToolEvent &event)
{
    moveCursor(event.pos);
    if (!m_erasing || event.pos == m_last)
        return;
    eraseAlong(m_last, event.pos);
    m_last = event.pos;
}

void EraserTool::release(const ToolEvent &event)
{
    if (m_erasing && event.pos != m_last)
        eraseAlong(m_last, event.pos);
    finish();
}

void EraserTool::hover(const ToolEvent &event)
{
    moveCursor(event.pos);
}

void EraserTool::deactivate()
{
    finish();
    m_cursorShown = false;
    if (canvas())
        canvas()->updateCanvasRect();
}

bool EraserTool::claimsKey(const QKeyEvent &event) const
{
    return m_erasing && event.key() == Qt::Key_Escape;
}

bool EraserTool::keyPress(QKeyEvent *event)
{
    if (!claimsKey(*event))
        return false;
    // Escape takes the rub in progress back.
    const bool erased = m_macroOpen;
    finish();
    if (erased)
        state()->document()->undoStack()->undo();
    return true;
}

void EraserTool::finish()
{
    m_erasing = false;
    if (!m_macroOpen)
        return;
    m_macroOpen = false;
    model::Document *doc = state()->document();
    // An object erased to nothing keeps no pins or cage around nothing (its skeleton goes
    // with skeleton_follow's rule, or here when the skeleton does not follow).
    for (model::Id id : m_erasedFrom)
        if (const model::StrokeGroup *g = doc->group(id);
            g && !g->hasContent() && !g->rig.empty() &&
            std::find(m_following.begin(), m_following.end(), id) == m_following.end())
            doc->undoStack()->push(new model::RemoveRigCommand(doc, id));
    m_erasedFrom.clear();
    // A head rubbed out shows the arms' tops that Apply Pose hid behind it.
    StrokeEditing::showUncoveredLines(doc, std::exchange(m_before, {}));
    StrokeEditing::endRestEdit(*state(), std::exchange(m_following, {}));
}

std::vector<model::Id> EraserTool::touchedStrokes(const QLineF &path) const
{
    std::vector<model::Id> hits;
    const model::Frame *frame = state()->currentFrame();
    if (!frame)
        return hits;
    for (const model::StrokeGroup &g : frame->groups) {
        if (!isEditable(g))
            continue;
        for (std::size_t i = 0; i < g.strokes.size(); ++i) {
            const model::Stroke &s = g.strokes[i];
            if (s.data &&
                strokeTouched(model::displayedPoints(g, i), s.data->width, path, radius()))
                hits.push_back(s.id);
        }
    }
    return hits;
}

bool EraserTool::openMacro(const std::vector<model::Id> &strokes)
{
    model::Document *doc = state()->document();
    // The macro opens at the first hit, so a rub that erases nothing leaves no undo step.
    if (!m_macroOpen) {
        doc->undoStack()->beginMacro(tr("Erase"));
        m_macroOpen = true;
    }
    std::vector<model::Id> groups;
    for (model::Id id : strokes)
        if (const model::StrokeLocation at = doc->locateStroke(id); at.isValid())
            groups.push_back(doc->frameAt(at).groups[std::size_t(at.group)].id);
    // Whether a skeleton follows is decided when the rub first reaches its object, before
    // its pose (if any) is applied.
    for (model::Id id : groups)
        if (std::find(m_erasedFrom.begin(), m_erasedFrom.end(), id) == m_erasedFrom.end()) {
            m_erasedFrom.push_back(id);
            for (model::Id f : skeletonsFollowing(*state(), {id}))
                m_following.push_back(f);
        }
    // Erasing from a posed object makes its pose the drawing first, so what is left stays
    // where it is shown.
    const bool applied = StrokeEditing::applyPoses(doc, groups);
    std::vector<model::Id> reached;
    for (model::Id id : groups)
        if (std::none_of(m_before.begin(), m_before.end(),
                         [id](const model::StrokeGroup &b) { return b.id == id; }))
            reached.push_back(id);
    for (model::StrokeGroup &g : StrokeEditing::objectsNow(doc, reached))
        m_before.push_back(std::move(g));
    return applied;
}

void EraserTool::eraseAlong(const QPointF &from, const QPointF &to)
{
    const std::vector<model::Id> hits = touchedStrokes(QLineF(from, to));
    if (hits.empty())
        return;
    model::Document *doc = state()->document();
    if (m_wholeStrokes) {
        // A baked cut-out pose splits a line into the parts its pieces showed (new ids beside
        // the first's): what the rub touches is looked up again on the baked drawing.
        const std::vector<model::Id> baked =
            openMacro(hits) ? touchedStrokes(QLineF(from, to)) : hits;
        for (model::Id id : baked)
            doc->undoStack()->push(new model::RemoveStrokeCommand(doc, id));
        return;
    }
    cut(hits, from, to);
}

void EraserTool::cut(const std::vector<model::Id> &strokes, const QPointF &from, const QPointF &to)
{
    model::Document *doc = state()->document();
    const std::vector<QPointF> rub =
        from == to ? std::vector<QPointF>{from} : std::vector<QPointF>{from, to};
    // Cut what is shown (the posed points of a posed object): applying the pose first makes
    // exactly those points the rest strokes, so the pieces fit them.
    const auto cutsOf = [&](const std::vector<model::Id> &ids) {
        std::vector<std::pair<model::Id, std::vector<model::StrokeDataPtr>>> out;
        for (model::Id id : ids) {
            const model::StrokeLocation at = doc->locateStroke(id);
            if (!at.isValid())
                continue;
            const model::StrokeGroup &g = doc->frameAt(at).groups[std::size_t(at.group)];
            model::StrokeData shown = *g.strokes[std::size_t(at.stroke)].data;
            shown.points = model::displayedPoints(g, std::size_t(at.stroke));
            if (auto pieces = model::cutStroke(shown, rub, radius()))
                out.emplace_back(id, std::move(*pieces));
        }
        return out;
    };
    auto cuts = cutsOf(strokes);
    if (cuts.empty())
        return;
    std::vector<model::Id> cutIds;
    for (const auto &c : cuts)
        cutIds.push_back(c.first);
    // A cut-out pose bakes a line into the parts its pieces showed, and the parts a piece hid
    // as unseen lines: the first part keeps the line's id, the others are new. Cut as worked
    // out on the posed line, the whole line came back beside its other parts (an arm's
    // outline twice, its fill gone); the cuts are worked out again on the baked strokes.
    if (openMacro(cutIds))
        cuts = cutsOf(touchedStrokes(QLineF(from, to)));
    for (const auto &[id, pieces] : cuts)
        model::pushStrokeCut(doc, id, pieces); // nothing when the stroke has gone
}

void EraserTool::moveCursor(const QPointF &pos)
{
    const qreal r = radius() + 4 / canvas()->zoom();
    const auto dirty = [r](QPointF c) { return QRectF(c - QPointF(r, r), QSizeF(2 * r, 2 * r)); };
    if (m_cursorShown)
        canvas()->updateCanvasRect(dirty(m_cursor));
    m_cursor = pos;
    m_cursorShown = true;
    canvas()->updateCanvasRect(dirty(m_cursor));
}

void EraserTool::paintOverlay(QPainter &painter, const QTransform &canvasToWidget)
{
    if (!m_cursorShown || !canvas()->underMouse())
        return;
    const QPointF c = canvasToWidget.map(m_cursor);
    // The circle is the eraser's size on the canvas (never smaller than a visible ring).
    const qreal r = std::max(2.0, radius() * canvas()->zoom());
    const bool whole = m_erasing ? m_wholeStrokes : m_mode == EraserMode::WholeStrokes;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(255, 255, 255, 200), 3));
    painter.drawEllipse(c, r, r);
    painter.setPen(QPen(QColor(0, 0, 0, 220), 1, whole ? Qt::DashLine : Qt::SolidLine));
    painter.drawEllipse(c, r, r);
    painter.restore();
}

} // namespace finbook::ui
