// The camera's frame over the page at the current tick (dashed), whatever the tool, when the
// document has a camera: the animator sees what the shot will hold while drawing.
#pragma once

#include <finbook/ui/canvas/canvas_tool.h>

namespace finbook::ui {

class CanvasWidget;

class CameraFrameOverlay : public CanvasOverlay {
public:
    explicit CameraFrameOverlay(CanvasWidget *canvas)
        : m_canvas(canvas)
    {}
    void paint(QPainter &painter, const QTransform &canvasToWidget) override;

private:
    CanvasWidget *m_canvas;
};

} // namespace finbook::ui
