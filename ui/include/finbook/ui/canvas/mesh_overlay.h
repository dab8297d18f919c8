// View → Show Mesh: draws each visible object's deformation mesh (posed when it has pins)
// over the current frame, the triangles the pose turns inside out filled red. Meshes are
// built on demand by the DeformController's worker.
#pragma once

#include <finbook/model/deform_controller.h>
#include <finbook/ui/canvas/canvas_tool.h>

#include <QObject>

namespace finbook::ui {

class CanvasWidget;
class EditorState;

class MeshOverlay : public QObject, public CanvasOverlay {
    Q_OBJECT
public:
    MeshOverlay(EditorState *state, model::DeformController *controller, CanvasWidget *canvas);
    void paint(QPainter &painter, const QTransform &canvasToWidget) override;

private:
    void requestMissing();
    static void paintFolds(QPainter &painter, const QTransform &canvasToWidget,
                           const model::DeformSetup &setup, const Eigen::MatrixX2d &U);

    EditorState *m_state;
    model::DeformController *m_controller;
    CanvasWidget *m_canvas;
};

} // namespace finbook::ui
