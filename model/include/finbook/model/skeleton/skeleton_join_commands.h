// Joining the parts of a character (issue 9), as undoable commands. None of them makes the
// drawing jump: a part that is joined, detached or turned around keeps the pose it shows
// (its root takes up the difference, SkeletonRig::keepingShownPose).
#pragma once

#include <finbook/model/rig/rig_commands.h>
#include <finbook/model/skeleton/skeleton_join.h>

namespace finbook::model {

// Hangs `child`'s skeleton from `join.parent`'s (join.parentAt on the parent's rest
// skeleton). A part at rest is re-rooted at its joint nearest join.childAt, so it turns about
// where it attaches. Obsolete when either has no skeleton, they are in different frames, the
// parent is part of the child's character already below it (a loop), or nothing changes.
class JoinPartCommand : public QUndoCommand {
public:
    JoinPartCommand(Document *doc, Id child, const SkeletonJoin &join,
                    QUndoCommand *parent = nullptr);
};

// The part stands alone again (a character root of its own). Obsolete when not joined.
class DetachPartCommand : public SetRigCommand {
public:
    DetachPartCommand(Document *doc, Id child, QUndoCommand *parent = nullptr);
};

// Every part of the frame hangs from the part it overlaps best (proposeJoin), from
// `root`'s character outwards; parts already joined keep their joins. Obsolete when no new
// join is found.
class JoinOverlappingPartsCommand : public QUndoCommand {
public:
    JoinOverlappingPartsCommand(Document *doc, Id frameId, QUndoCommand *parent = nullptr);
    int joined() const { return m_joined; }

private:
    int m_joined = 0;
};

// Makes `part` the root of its character: the joins on the way from it to the old root turn
// around (each join's two points swap roles). Obsolete when it is the root already.
class MakeCharacterRootCommand : public QUndoCommand {
public:
    MakeCharacterRootCommand(Document *doc, Id part, QUndoCommand *parent = nullptr);
};

// Apply Pose to Drawing for an object; for a part of a character, for all its parts at once
// (a part's rest is its parent's pose, so they are baked together). One undo step.
QUndoCommand *makeApplyPoseCommand(Document *doc, Id groupId);

} // namespace finbook::model
