#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/fill/fill_regions.h>
#include <finbook/model/fill/fill_resolve.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/fill/tool_fill.h>
#include <finbook/ui/tools/tool_pen.h>
#include <finbook/ui/window/editor_state.h>

#include <QPainter>
#include <QPixmap>

namespace finbook::ui {

FillTool::FillTool(const PenTool *pen, QObject *parent)
    : CanvasTool(parent)
    , m_pen(pen)
{}

QIcon FillTool::icon() const
{
    return QIcon::fromTheme(QStringLiteral("color-fill"),
                            QIcon(QStringLiteral(":/icons/tool_fill.svg")));
}

QCursor FillTool::cursor() const
{
    // The bucket, its drip at the hot spot: where the paint lands.
    const QPixmap bucket = QIcon(QStringLiteral(":/icons/tool_fill.svg")).pixmap(24, 24);
    return bucket.isNull() ? QCursor(Qt::CrossCursor) : QCursor(bucket, 21, 21);
}

void FillTool::activate()
{
    if (canvas())
        canvas()->update(); // the gap lines
}

void FillTool::deactivate()
{
    m_hover = {};
    m_hoverShown = false;
    if (canvas())
        canvas()->update();
}

FillTool::Target FillTool::targetAt(const QPointF &pos) const
{
    const model::Frame *frame = state() ? state()->currentFrame() : nullptr;
    if (!frame || !canvas())
        return {};
    const double closeGap = canvas()->document()->settings().closeGap;
    for (auto g = frame->groups.rbegin(); g != frame->groups.rend(); ++g) { // topmost first
        if (!g->visible || g->locked || g->strokes.empty())
            continue;
        const model::ObjectRegionsPtr regions = model::objectRegions(*g, closeGap);
        const int face = model::displayedFaceAt(*regions, *g, pos);
        if (face >= 0)
            return Target{g->id, regions->displayedPath(*g, face)};
    }
    return {};
}

void FillTool::fillAt(const QPointF &pos, bool remove)
{
    const Target target = targetAt(pos);
    model::Document *doc = canvas() ? canvas()->document() : nullptr;
    if (!doc)
        return;
    if (target.groupId == model::kNoId) {
        emit messagePosted(tr("No closed region here: close the outline, or raise Close gaps"));
        return;
    }
    std::unique_ptr<QUndoCommand> command =
        remove ? model::removeFillCommand(doc, target.groupId, pos)
               : model::fillRegionCommand(doc, target.groupId, pos, m_pen->settings().color.rgba());
    if (command)
        doc->undoStack()->push(command.release());
}

void FillTool::press(const ToolEvent &event)
{
    fillAt(event.pos, event.modifiers & Qt::ShiftModifier);
    setHover(event.pos);
}

void FillTool::secondaryClick(const ToolEvent &event)
{
    fillAt(event.pos, true);
    setHover(event.pos);
}

void FillTool::hover(const ToolEvent &event)
{
    setHover(event.pos);
}

void FillTool::setHover(const QPointF &pos)
{
    Target target = targetAt(pos);
    if (target.groupId == m_hover.groupId && target.outline == m_hover.outline && m_hoverShown)
        return;
    m_hover = std::move(target);
    m_hoverShown = true;
    if (canvas())
        canvas()->update();
}

void FillTool::paintOverlay(QPainter &painter, const QTransform &canvasToWidget)
{
    const model::Frame *frame = state() ? state()->currentFrame() : nullptr;
    if (!frame || !canvas())
        return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    if (m_hover.groupId != model::kNoId && !m_hover.outline.isEmpty()) {
        QColor tint = m_pen->settings().color;
        tint.setAlpha(90);
        const QPainterPath shown = canvasToWidget.map(m_hover.outline);
        painter.fillPath(shown, tint);
        painter.setPen(QPen(QColor(30, 120, 230), 1.5));
        painter.drawPath(shown);
    }
    // The gap lines the closing adds, dashed, in the objects one can fill.
    const double closeGap = canvas()->document()->settings().closeGap;
    QPen dashed(QColor(230, 60, 140), 1.5, Qt::DashLine, Qt::RoundCap);
    painter.setPen(dashed);
    for (const model::StrokeGroup &g : frame->groups) {
        if (!g.visible || g.locked || g.strokes.empty())
            continue;
        for (const QLineF &line : model::objectRegions(g, closeGap)->displayedClosures(g))
            painter.drawLine(canvasToWidget.map(line));
    }
    painter.restore();
}

} // namespace finbook::ui
