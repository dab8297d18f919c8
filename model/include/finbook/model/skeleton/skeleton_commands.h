// Building, refining and posing an object's skeleton. Each is a rig command
// (rig/rig_commands.h) with the rig computed beforehand, so undo restores exactly what was
// there (another rig kind, a pose, older settings). Reset Pose and Apply Pose are the generic
// ResetPoseCommand and ApplyPoseCommand; ResetBonePoseCommand resets one bone.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/model/rig/rig_commands.h>

#include <optional>

namespace finbook::model {

// The automatic skeleton of an object's rest drawing (silhouette → straight skeleton →
// refinement with `settings`), at rest. The root is the joint nearest `rootNear`, or the one
// nearest the drawing's centre of mass. A few milliseconds for a typical object, so it runs
// on the GUI thread. Errors: sentences for the user (no strokes, nothing to skeletonise).
// The shape is the object's ink and its regions closed at `closeGap` (the document's Close
// gaps), as its mesh is.
Expected<SkeletonRig, QString> buildSkeletonRig(const StrokeGroup &group,
                                                const SkeletonSettings &settings = {},
                                                std::optional<QPointF> rootNear = {},
                                                double closeGap = -1.0);

// Gives an object `built` (from buildSkeletonRig), replacing any other rig and pose.
class BuildSkeletonCommand : public SetRigCommand {
public:
    BuildSkeletonCommand(Document *doc, Id groupId, SkeletonRig built,
                         QUndoCommand *parent = nullptr);
};

// Re-refines an object's skeleton with other slider settings: `rebuilt` is buildSkeletonRig
// of the object with the new settings (and its old root). The pose goes back to rest (the
// bones are new). Consecutive commands with the same edit serial merge: one slider drag is
// one undo step.
class SetSkeletonSettingsCommand : public SetRigCommand {
public:
    SetSkeletonSettingsCommand(Document *doc, Id groupId, SkeletonRig rebuilt, int editSerial,
                               QUndoCommand *parent = nullptr);
    int id() const override { return int(CommandId::SetSkeletonSettings); }
    bool mergeWith(const QUndoCommand *other) override;

private:
    int m_serial;
};

// Sets the pose (angles, root offset) of an object's skeleton; a drag merges into one step.
class PoseBonesCommand : public PoseRigCommand {
public:
    PoseBonesCommand(Document *doc, Id groupId, std::vector<double> angles, QPointF rootOffset,
                     int dragSerial, QUndoCommand *parent = nullptr);
};

// Switches how the bones move the drawing (it only re-solves).
class SetSkinningModeCommand : public SetRigCommand {
public:
    SetSkinningModeCommand(Document *doc, Id groupId, SkinningMode mode,
                           QUndoCommand *parent = nullptr);
};

// Locks or unlocks one joint: inverse-kinematics drags stop the chain below a locked joint
// and never move it. Neither rest nor pose, so nothing re-solves. Obsolete when the joint is
// already so, or there is no such joint.
class SetJointLockCommand : public SetRigCommand {
public:
    SetJointLockCommand(Document *doc, Id groupId, int joint, bool locked,
                        QUndoCommand *parent = nullptr);
};

// Turns one bone back to rest: its joint's angle becomes zero, so the bones below it keep
// their bends relative to it (the bone only, not its subtree). For a root this also takes
// the root offset back. Obsolete when the bone is already at rest.
class ResetBonePoseCommand : public SetRigCommand {
public:
    ResetBonePoseCommand(Document *doc, Id groupId, int joint, QUndoCommand *parent = nullptr);
};

// Moves a rest joint of an unposed skeleton (skeleton_joint_edit.h); a drag (same serial)
// merges into one step. The rest changes, so the skinning re-precomputes.
class MoveJointCommand : public SetRigCommand {
public:
    MoveJointCommand(Document *doc, Id groupId, int joint, QPointF at, int dragSerial,
                     QUndoCommand *parent = nullptr);
    int id() const override { return int(CommandId::MoveJoint); }
    bool mergeWith(const QUndoCommand *other) override;

private:
    int m_serial;
};

// Splits bone `bone` of an unposed skeleton with a new joint near `at`; insertedJoint() is
// its index (valid unless obsolete).
class InsertJointCommand : public SetRigCommand {
public:
    InsertJointCommand(Document *doc, Id groupId, int bone, QPointF at,
                       QUndoCommand *parent = nullptr);
    int insertedJoint() const { return m_joint; }

private:
    int m_joint = -1;
};

// Deletes a joint of an unposed skeleton; its children hang from its parent.
class DeleteJointCommand : public SetRigCommand {
public:
    DeleteJointCommand(Document *doc, Id groupId, int joint, QUndoCommand *parent = nullptr);
};

} // namespace finbook::model
