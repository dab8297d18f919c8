// Camera (A, the key of OpenToonz's Animate tool, which moves its camera): frames the shot. A
// drag moves the camera's frame, Shift+drag zooms it about its centre, Ctrl+drag turns it;
// each drag is one undo step that adds or changes the camera key at the current tick (the
// first tick of the current frame). While the tool is current the camera's path is drawn
// (its centre at every tick, a dot at each key, the frame of each key faint). Right-click:
// the easing of the move from this key to the next (linear, ease in, ease out, ease in-out,
// hold, or a Bézier curve edited in a small graph), Delete Camera Key and Reset Camera;
// Delete (or Backspace) deletes the key at the current tick. In Camera View the picture
// follows the pointer instead (the camera goes the other way).
#pragma once

#include <finbook/model/camera/camera_track.h>
#include <finbook/ui/canvas/canvas_tool.h>

#include <functional>

class QMenu;

namespace finbook::ui {

class CameraTool : public CanvasTool {
    Q_OBJECT
public:
    explicit CameraTool(QObject *parent = nullptr)
        : CanvasTool(parent)
    {}

    QString id() const override { return QStringLiteral("tool.camera"); }
    bool editsLayer() const override { return false; }
    QString name() const override { return tr("Camera"); }
    QString description() const override
    {
        return tr("frame the shot: move, zoom and turn the camera");
    }
    QIcon icon() const override;
    QKeySequence defaultShortcut() const override { return QKeySequence(Qt::Key_A); }
    QCursor cursor() const override;

    void press(const ToolEvent &event) override;
    void move(const ToolEvent &event) override;
    void release(const ToolEvent &event) override;
    void deactivate() override;
    void secondaryClick(const ToolEvent &event) override;
    bool keyPress(QKeyEvent *event) override;
    bool claimsKey(const QKeyEvent &event) const override;
    void paintOverlay(QPainter &painter, const QTransform &canvasToWidget) override;

    // The camera where it is at the current tick, and the key there (if any).
    model::CameraState currentState() const;
    qint64 currentTick() const;
    // Test seam: runs the context menu instead of QMenu::exec (returns the chosen action).
    void setMenuExec(std::function<QAction *(QMenu &, QPoint)> exec)
    {
        m_menuExec = std::move(exec);
    }

private:
    enum class Edit { Move, Zoom, Turn };
    void setKey(const model::CameraState &state, qint64 mergeKey);
    void setEasing(model::CameraEasing easing);
    void editBezier();
    void deleteKey();

    Edit m_edit = Edit::Move;
    bool m_dragging = false;
    model::CameraState m_start; // as the drag found it
    QTransform m_startView;     // canvas to widget when the drag began (Camera View moves it)
    QPointF m_pressWidget;
    qint64 m_dragSerial = 0;
    std::function<QAction *(QMenu &, QPoint)> m_menuExec;
};

} // namespace finbook::ui
