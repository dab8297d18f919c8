// The Bone tool (K): poses objects by their skeletons. Click an object without a skeleton to
// build one; drag a bone to turn it about its parent joint (forward kinematics); drag a joint
// to pull it and the chain above it, up to the nearest locked joint or the root (inverse
// kinematics); drag the root to move the whole object. Alt-click or right-click a joint to
// lock or unlock it. Each drag is one undo step.
#pragma once

#include <finbook/deform/skeleton/skeleton.h>
#include <finbook/model/deform_controller.h>
#include <finbook/ui/canvas_tool.h>

#include <functional>
#include <map>
#include <vector>

namespace finbook::ui {

class BoneTool : public CanvasTool {
    Q_OBJECT
public:
    explicit BoneTool(model::DeformController *controller, QObject *parent = nullptr);

    QString id() const override { return QStringLiteral("tool.bone"); }
    QString name() const override { return tr("Bone"); }
    QIcon icon() const override;
    QKeySequence defaultShortcut() const override { return QKeySequence(Qt::Key_K); }

    void activate() override;
    void deactivate() override;
    void press(const ToolEvent &event) override;
    void move(const ToolEvent &event) override;
    void release(const ToolEvent &event) override;
    void hover(const ToolEvent &event) override;
    void secondaryClick(const ToolEvent &event) override;
    void paintOverlay(QPainter &painter, const QTransform &canvasToWidget) override;

    enum class Part { None, Joint, Bone };
    struct Hit {
        model::Id groupId = model::kNoId;
        Part part = Part::None;
        int joint = -1; // the joint, or the bone's child joint
    };
    // The joint or bone drawn under the cursor (screen tolerance), current object first.
    Hit hitAt(const ToolEvent &event) const;
    bool isLocked(model::Id groupId, int joint) const;
    // Asked before a new skeleton replaces a posed rig; the default asks with a message box.
    void setConfirmDiscard(std::function<bool()> confirm) { m_confirmDiscard = std::move(confirm); }

private:
    enum class DragKind { None, Bone, Joint, Root };
    struct Drag {
        model::Id groupId = model::kNoId;
        DragKind kind = DragKind::None;
        int joint = -1;
        deform::Skeleton skeleton;
        deform::SkeletonPose start;
        QPointF grabbed;
    };

    model::Id objectAt(const ToolEvent &event) const;
    void build(model::Id groupId);
    void toggleLock(const Hit &hit);
    bool startDrag(const Hit &hit, QPointF at);
    std::vector<bool> locks(model::Id groupId) const;

    model::DeformController *m_controller;
    Drag m_drag;
    Hit m_hover;
    QPointF m_pressPos;
    int m_dragSerial = 0;
    std::map<model::Id, std::vector<bool>> m_locked;
    std::function<bool()> m_confirmDiscard;
};

} // namespace finbook::ui
