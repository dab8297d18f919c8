// The light handle (issue 27): while the Shading panel is visible, a small sun on the canvas
// shows where the document's light comes from, and dragging it moves the light. Its distance
// from the page's centre is the light's height: on the dashed circle the light grazes the
// drawing (0°), at the centre it shines from the viewer (90°). The shading follows the drag;
// one drag is one undo step ("Move Light"), and Escape during a drag puts the light back.
//
// It sits on the canvas as an event filter (only presses on the sun are taken, every other
// input reaches the current tool) plus an overlay that paints it.
#pragma once

#include <QObject>
#include <QPointF>

#include <optional>

class QDockWidget;
class QPainter;
class QTransform;
class QUndoCommand;

namespace finbook::ui {

class CanvasWidget;

class LightHandle : public QObject {
    Q_OBJECT
public:
    // `panel`: the Shading dock; the handle shows while it does. Child of `canvas`.
    LightHandle(CanvasWidget *canvas, QDockWidget *panel);

    bool shown() const;
    // Widget positions: the sun, and the centre and radius of the circle it moves on.
    QPointF sunPos() const;
    QPointF centre() const;
    double radius() const;

    void paint(QPainter &painter) const;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void dragTo(const QPointF &widgetPos);
    void dropPushed();
    void finish(bool keep);

    CanvasWidget *m_canvas;
    QDockWidget *m_panel;
    bool m_panelShown = false;
    bool m_dragging = false;
    QUndoCommand *m_pushed = nullptr; // this drag's command on the undo stack, if any
};

} // namespace finbook::ui
