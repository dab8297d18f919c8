#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/tools/tool_hand.h>

namespace finbook::ui {

void HandTool::press(const ToolEvent &event)
{
    m_dragging = true;
    m_last = event.widgetPos;
    canvas()->setCursor(cursor());
}

void HandTool::move(const ToolEvent &event)
{
    if (!m_dragging)
        return;
    canvas()->panBy(event.widgetPos - m_last);
    m_last = event.widgetPos;
}

void HandTool::release(const ToolEvent &)
{
    m_dragging = false;
    canvas()->setCursor(cursor());
}

} // namespace finbook::ui
