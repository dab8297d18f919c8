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
            for (const model::PaintItem &item : layer.strokes) {
                if (!item.points || item.points->empty())
                    continue;
                const auto &points = *item.points;
                for (std::size_t i = 0; i < points.size(); ++i) {
                    const model::StrokePoint &b = points[i];
                    const model::StrokePoint &a = i > 0 ? points[i - 1] : b;
                    const double reach =
                        std::max(0.25,
                                 double(item.width) * std::clamp(double(b.pressure), 0.0, 1.0)) /
                            2.0 +
                        tolerance;
                    if (distanceToSegment(pos, QPointF(a.x, a.y), QPointF(b.x, b.y)) <= reach) {
                        picked = QColor::fromRgba(item.color);
                        line = true;
                        break;
                    }
                }
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
