#include "stroke_hit.h"

#include <finbook/model/fill/fill_render.h>
#include <finbook/model/scene/shot.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/tools/tool_eyedropper.h>
#include <finbook/ui/tools/tool_pen.h>
#include <finbook/ui/window/editor_state.h>

#include <cmath>

namespace finbook::ui {

EyedropperTool::EyedropperTool(PenTool *pen, QObject *parent)
    : CanvasTool(parent)
    , m_pen(pen)
{}

QIcon EyedropperTool::icon() const
{
    return QIcon::fromTheme(QStringLiteral("color-picker"),
                            QIcon(QStringLiteral(":/icons/tool_eyedropper.svg")));
}

std::optional<QColor> EyedropperTool::colourAt(const model::Frame &frame,
                                               const model::DocumentSettings &settings, QPointF pos,
                                               double tolerance, bool *fromLine)
{
    // In painting order, so the last hit is what is on top.
    std::optional<QColor> picked;
    bool line = false;
    for (const model::StrokeGroup &group : frame.groups) {
        if (!group.visible)
            continue;
        for (const model::PaintLayer &layer : model::paintLayers(group, settings)) {
            for (const model::FillItem &fill : layer.fills)
                if (fill.path.contains(pos)) {
                    picked = QColor::fromRgba(fill.color);
                    line = false;
                }
            for (const model::PaintItem &item : layer.strokes)
                if (item.points &&
                    strokeTouched(*item.points, item.width, QLineF(pos, pos), tolerance)) {
                    picked = QColor::fromRgba(item.color);
                    line = true;
                }
        }
    }
    if (fromLine)
        *fromLine = line;
    return picked;
}

void EyedropperTool::press(const ToolEvent &event)
{
    // What the page shows now: every visible layer's drawing at this tick, front ones on top.
    const model::Frame shown =
        model::composeShot(state()->document()->layers(), qint64(state()->currentTick()));
    bool line = false;
    const auto colour = colourAt(shown, state()->document()->settings(), event.pos,
                                 2.0 / std::max(canvas()->zoom(), 1e-6), &line);
    if (!colour) {
        canvas()->postMessage(tr("Nothing here to take a colour from: click a line or a fill."));
        return;
    }
    PenSettings s = m_pen->settings();
    s.color = *colour;
    m_pen->setSettings(s);
    canvas()->postMessage(
        line ? tr("The pen takes the line's colour %1.").arg(colour->name(QColor::HexRgb))
             : tr("The pen takes the fill's colour %1.").arg(colour->name(QColor::HexRgb)));
}

} // namespace finbook::ui
