// The Bone tool (K): poses objects by their skeletons. Click an object without a skeleton to
// build one; drag a bone to turn it about its parent joint (forward kinematics); drag a joint
// to pull it and the chain above it, up to the nearest locked joint or the root (inverse
// kinematics); drag the root to move the whole object. L over a joint (or Alt-click it, where
// the window manager leaves Alt to the application) locks or unlocks it (locks are saved with
// the skeleton). Right-click a joint or bone for its menu: Lock Joint,
// Reset Bone Pose, Edit Joints and, while editing, Insert Joint Here and Delete Joint.
//
// Characters (issue 9): a skeleton built on a drawing that overlaps another part's skeleton
// joins it (RealSkel's bone split or joint connect); posing the parent moves the part, and
// dragging a joined part's root moves the whole character.
// Shift-drag a part's root onto a bone of another part to join it there; the menu detaches a
// part, joins the frame's overlapping parts, makes a part the character's root or a joint its
// part's root.
//
// Edit Joints (a mode, from the menu or Deform → Edit Joints) changes the rest skeleton of an
// unposed object instead of posing it: drag a joint to move it, click a bone to split it with
// a new joint. Every drag, click and menu choice is one undo step.
#pragma once

#include <finbook/deform/skeleton/skeleton.h>
#include <finbook/model/deform_controller.h>
#include <finbook/ui/canvas/canvas_tool.h>

#include <functional>

class QAction;
class QMenu;
class QUndoCommand;
#include <vector>

namespace finbook::ui {

class BoneTool : public CanvasTool {
    Q_OBJECT
public:
    explicit BoneTool(model::DeformController *controller, QObject *parent = nullptr);

    QString id() const override { return QStringLiteral("tool.bone"); }
    QString name() const override { return tr("Bone"); }
    QString description() const override
    {
        return tr("build a skeleton and pose the drawing by its bones");
    }
    QIcon icon() const override;
    QKeySequence defaultShortcut() const override { return QKeySequence(Qt::Key_K); }

    void activate() override;
    void deactivate() override;
    void press(const ToolEvent &event) override;
    void move(const ToolEvent &event) override;
    void release(const ToolEvent &event) override;
    void hover(const ToolEvent &event) override;
    void secondaryClick(const ToolEvent &event) override;
    bool keyPress(QKeyEvent *event) override;
    bool claimsKey(const QKeyEvent &event) const override;
    void paintOverlay(QPainter &painter, const QTransform &canvasToWidget) override;

    static constexpr Qt::Key kLockKey = Qt::Key_L; // locks the joint under the mouse

    enum class Part { None, Joint, Bone };
    struct Hit {
        model::Id groupId = model::kNoId;
        Part part = Part::None;
        int joint = -1; // the joint, or the bone's child joint
    };
    // The joint or bone drawn under the cursor (screen tolerance), current object first.
    Hit hitAt(const ToolEvent &event) const;
    bool isLocked(model::Id groupId, int joint) const;
    // The joint or bone last pressed or right-clicked (part None when there is none).
    Hit selection() const;
    // Whether Reset Bone Pose has something to do for the selection, and doing it.
    bool canResetSelectedBone() const;
    void resetSelectedBone();
    bool editJoints() const { return m_editJoints; }
    void setEditJoints(bool on);
    // Shows the context menu and returns the chosen action; the default runs QMenu::exec.
    void setMenuExec(std::function<QAction *(QMenu &, QPoint)> exec)
    {
        m_menuExec = std::move(exec);
    }
    // Asked before a new skeleton replaces a posed rig; the default asks with a message box.
    void setConfirmDiscard(std::function<bool()> confirm) { m_confirmDiscard = std::move(confirm); }

signals:
    void selectionChanged();
    void editJointsChanged(bool on);

private:
    enum class DragKind { None, Bone, Joint, Root, MoveJoint, Attach };
    struct Drag {
        model::Id groupId = model::kNoId;
        DragKind kind = DragKind::None;
        int joint = -1;
        deform::Skeleton skeleton;
        deform::SkeletonPose start;
        QPointF grabbed;
        QPointF jointRest; // MoveJoint: where the joint was when grabbed
        // A joined part poses in its parent bone's rest frame: the cursor is taken back by
        // the bone's motion (fixed during the drag: the parent does not move).
        model::RigidMotion anchor;
        QPointF cursor; // Attach: where the rubber band ends
    };

    model::Id objectAt(const ToolEvent &event) const;
    void build(model::Id groupId);
    void toggleLock(const Hit &hit);
    // The joint L locks: the one under the mouse, else the one last clicked.
    Hit lockTarget() const;
    bool startDrag(const Hit &hit, QPointF at);
    void pressEditing(const Hit &hit, QPointF at);
    void select(const Hit &hit);
    void insertJoint(const Hit &hit, QPointF at);
    void deleteJoint(const Hit &hit);
    void setRootJoint(const Hit &hit);
    void joinOverlappingParts();
    void push(QUndoCommand *command);
    // Attach: the part's root dropped at `at` joins the part under it (a bone or joint of
    // another object's skeleton).
    void attach(QPointF at);
    // After building a part's skeleton: join it to the part it overlaps, if any.
    void joinIfOverlapping(model::Id groupId);

    model::DeformController *m_controller;
    Drag m_drag;
    Hit m_hover;
    QPointF m_pressPos;
    int m_dragSerial = 0;
    Hit m_selected;
    bool m_editJoints = false;
    std::function<bool()> m_confirmDiscard;
    std::function<QAction *(QMenu &, QPoint)> m_menuExec;
};

} // namespace finbook::ui
