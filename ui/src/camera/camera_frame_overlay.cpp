#include <finbook/model/document.h>
#include <finbook/ui/camera/camera_frame_overlay.h>
#include <finbook/ui/canvas/canvas_tool.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/window/editor_state.h>

#include <QPainter>

namespace finbook::ui {

void CameraFrameOverlay::paint(QPainter &painter, const QTransform &canvasToWidget)
{
    const model::Document &doc = *m_canvas->document();
    const EditorState *state = m_canvas->state();
    // Drawn by the Camera tool itself while it is current; nothing to frame in Camera View.
    if (doc.camera().isEmpty() || state->cameraView() ||
        (m_canvas->currentTool() && m_canvas->currentTool()->id() == QLatin1String("tool.camera")))
        return;
    const QSizeF page(doc.settings().canvasSize);
    const model::CameraState now =
        model::cameraAt(doc.camera(), double(state->currentTick()), page);
    painter.setRenderHint(QPainter::Antialiasing, true);
    QPen pen(QColor(230, 120, 20, 200), 1.5, Qt::DashLine);
    pen.setCosmetic(true);
    painter.setPen(pen);
    painter.setBrush(Qt::NoBrush);
    painter.drawPolygon(canvasToWidget.map(model::cameraFrame(now, page)));
}

} // namespace finbook::ui
