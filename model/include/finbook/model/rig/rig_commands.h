// Commands every rig kind shares: replace a rig, pose it (a drag merges into one step), send it
// back to rest, and make its pose the drawing. Pins (pins/pin_commands.h) and cages
// (cage/cage_commands.h) are these commands with a rig computed from the user's gesture.
#pragma once

#include <finbook/model/commands.h>

#include <functional>

namespace finbook::model {

// Replaces an object's rig (adding or removing a pin, placing, editing or removing a cage,
// switching kinds). Undo restores the old rig and the pose that was shown with it. Obsolete
// when the object is gone or the rig would not change.
class SetRigCommand : public DocumentCommand {
public:
    SetRigCommand(Document *doc, Id groupId, Rig rig, const QString &text,
                  QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

protected:
    Id m_groupId;
    Rig m_new;
    Rig m_old;
    DeformedStrokesPtr m_oldDeformed;
};

// Moves an object's targets (pin targets, posed cage corners); the rest definition must stay
// as it is (else the command is obsolete). Consecutive commands of one drag (same object, same
// drag serial) merge, so a drag is one undo step and the next drag another.
class PoseRigCommand : public DocumentCommand {
public:
    PoseRigCommand(Document *doc, Id groupId, Rig posed, int dragSerial, const QString &text,
                   QUndoCommand *parent = nullptr);
    int id() const override { return int(CommandId::PoseRig); }
    bool mergeWith(const QUndoCommand *other) override;
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    int m_serial;
    Rig m_new;
    Rig m_old;
};

// Sends every target back to its rest position (the rig stays). Obsolete when not posed.
class ResetPoseCommand : public DocumentCommand {
public:
    ResetPoseCommand(Document *doc, Id groupId, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    Rig m_before;
};

// Makes the object's pose its rest drawing: the strokes take the posed points and the rig is
// rebased onto them (pins and corners stay where they are shown, now at rest), so the user
// can go on dragging. Obsolete when there is no pose.
// What Apply Pose makes of a posed object (group.isDeformed()): its strokes as posed (ids kept;
// new ids from `newId` for the parts and lines of no ink it adds — gaps the pose showed closed,
// cut-out cuts, seams between colours the pose showed apart) and its fills tied to the faces
// of those strokes that showed their colours (fill_resolve.h fillsAfterBake).
// A picture object's picture is resampled as posed (picture_object.h bakedPicture).
struct AppliedPose {
    std::vector<Stroke> strokes;
    std::vector<Fill> fills;
    std::shared_ptr<const ObjectPicture> picture;
};
AppliedPose applyPoseToDrawing(const StrokeGroup &group, double closeGap,
                               const std::function<Id()> &newId);

class ApplyPoseCommand : public DocumentCommand {
public:
    ApplyPoseCommand(Document *doc, Id groupId, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    std::vector<Stroke> m_oldStrokes;
    std::vector<Stroke> m_newStrokes;
    std::vector<Fill> m_oldFills; // seeds follow the pose (fill/fill_resolve.h fillsAfterBake)
    std::vector<Fill> m_newFills;
    Rig m_oldRig;
    DeformedStrokesPtr m_oldDeformed;
    std::shared_ptr<const ObjectPicture> m_oldPicture;
    std::shared_ptr<const ObjectPicture> m_newPicture;
};

// Whether `a` and `b` have the same rest definition (kind, pin rest positions in order, rest
// corners): the part of a rig a precompute depends on. Targets and pin ids do not count.
bool sameRestDefinition(const Rig &a, const Rig &b);

} // namespace finbook::model
