// The interface every canvas tool implements (pen, eraser, select, hand; later the pin tool).
//
// A tool is added to a CanvasWidget with CanvasWidget::addTool(); the canvas then owns it,
// and the main window gives it a checkable action in the Tools menu and toolbar (objectName
// = id(), shortcut = defaultShortcut() unless the user changed it). Only the current tool
// receives events. Events arrive in CANVAS coordinates (document pixels, y down), so a tool
// never deals with zoom or pan except for screen-space tolerances (use ToolEvent::widgetPos
// or CanvasWidget::zoom()).
//
// A tool edits the document only by pushing commands onto Document::undoStack(). Anything it
// shows while a drag is in progress (the stroke being drawn, a lasso, a transform preview)
// it paints in paintOverlay() and asks for with CanvasWidget::updateCanvasRect().
#pragma once

#include <QCursor>
#include <QIcon>
#include <QKeySequence>
#include <QObject>
#include <QPointF>
#include <QTransform>

class QKeyEvent;
class QPainter;

namespace finbook::ui {

class CanvasWidget;
class EditorState;

// One pointer sample.
struct ToolEvent {
    QPointF pos;                                      // canvas pixels
    QPointF widgetPos;                                // widget pixels (screen-space tolerances)
    qreal pressure = 1.0;                             // 0..1; 1.0 for a mouse
    Qt::MouseButton button = Qt::NoButton;            // the button pressed or released
    Qt::MouseButtons buttons = Qt::NoButton;          // buttons held now
    Qt::KeyboardModifiers modifiers = Qt::NoModifier; // Shift, Ctrl, Alt
    bool tablet = false;                              // from a QTabletEvent
};

class CanvasTool : public QObject {
    Q_OBJECT
public:
    explicit CanvasTool(QObject *parent = nullptr)
        : QObject(parent)
    {}

    // Stable key: the objectName of the tool's action and its shortcut-registry name,
    // e.g. "tool.pen". Never translated.
    virtual QString id() const = 0;
    // Translated name for the menu, the toolbar tooltip and the status bar.
    virtual QString name() const = 0;
    // What the tool does, in a few translated words for its tooltip ("build a skeleton and pose
    // the drawing by its bones"): the tooltip reads "Bone (K): build a skeleton ...".
    virtual QString description() const { return {}; }
    virtual QIcon icon() const { return {}; }
    virtual QKeySequence defaultShortcut() const { return {}; }
    virtual QCursor cursor() const { return Qt::CrossCursor; }
    // Whether the tool edits the current layer's drawing: such tools do nothing on a locked
    // layer (the canvas says so instead). The hand, the camera and the reference do not.
    virtual bool editsLayer() const { return true; }
    // Whether Ctrl+click with this tool takes a colour from the drawing (the eyedropper's
    // click) instead of using the tool: the tools that paint with the pen's colour. Ctrl, as
    // in Krita: Alt+click moves the window on many Linux desktops.
    virtual bool picksColourOnCtrlClick() const { return false; }

    // Called when the tool becomes current / stops being current. deactivate() must finish
    // or cancel a drag in progress, close any undo macro the tool opened and drop its overlay.
    virtual void activate() {}
    virtual void deactivate() {}

    // Pointer input. press/move/release form one drag of the left button (middle button and
    // Space-drag pan the view and never reach the tool). hover() comes with no button held.
    virtual void press(const ToolEvent &) {}
    virtual void move(const ToolEvent &) {}
    virtual void release(const ToolEvent &) {}
    virtual void hover(const ToolEvent &) {}
    // A right-button press outside any drag: the tool's context action (the Pin tool removes
    // the pin under the cursor). Not part of a drag; no move or release follows.
    virtual void secondaryClick(const ToolEvent &) {}
    // Keys while the canvas has focus; return true when consumed (e.g. Escape cancels).
    virtual bool keyPress(QKeyEvent *) { return false; }
    // Whether the tool, in the middle of a gesture, claims `event`'s key before the window's
    // shortcuts do (Return closes a cage rather than starting playback; Escape, Backspace and
    // Delete act on the gesture). A claimed key reaches keyPress().
    virtual bool claimsKey(const QKeyEvent &event) const
    {
        Q_UNUSED(event)
        return false;
    }

    // Paints on top of the frame. The painter is in WIDGET coordinates; use canvasToWidget to
    // map canvas points (or painter.setTransform(canvasToWidget, true) for canvas-space
    // drawing). Keep handles and lines a constant size on screen by drawing them unscaled.
    virtual void paintOverlay(QPainter &, const QTransform &canvasToWidget)
    {
        Q_UNUSED(canvasToWidget)
    }

    // The canvas the tool was added to (null before addTool()).
    CanvasWidget *canvas() const { return m_canvas; }
    EditorState *state() const;

private:
    friend class CanvasWidget;
    CanvasWidget *m_canvas = nullptr;
};

// Something drawn over every frame regardless of the tool, e.g. the mesh of "Show Mesh".
// Added with CanvasWidget::addOverlay(); painted after the frame, before the tool's overlay.
// An overlay that changes asks for a repaint with canvas->update().
class CanvasOverlay {
public:
    virtual ~CanvasOverlay() = default;
    virtual void paint(QPainter &painter, const QTransform &canvasToWidget) = 0;
};

} // namespace finbook::ui
