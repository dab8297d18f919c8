// Commands over an object's harmonic cage. Placing or editing the rest cage re-precomputes;
// moving posed corners only re-solves, and one drag is one undo step. The editor checks a cage
// with cageProblem() (cage/cage_setup.h) before it places one, so the user hears why not.
#pragma once

#include <finbook/model/rig/rig_commands.h>

namespace finbook::model {

// Puts a cage (at rest) on the object, replacing its pins or an earlier cage.
class PlaceCageCommand : public SetRigCommand {
public:
    PlaceCageCommand(Document *doc, Id groupId, std::vector<QPointF> corners,
                     QUndoCommand *parent = nullptr);
};

// Changes the rest cage (corners moved, inserted or deleted) together with its posed corners
// (same count). Obsolete without a cage.
class EditCageCommand : public SetRigCommand {
public:
    EditCageCommand(Document *doc, Id groupId, CageRig cage, QUndoCommand *parent = nullptr);
};

// Moves posed corners: `posed` has one position per corner. Merges within one drag.
class MoveCageCornersCommand : public PoseRigCommand {
public:
    MoveCageCornersCommand(Document *doc, Id groupId, std::vector<QPointF> posed, int dragSerial,
                           QUndoCommand *parent = nullptr);
};

// Takes the cage (or pins) off the object; its pose goes with it.
class RemoveRigCommand : public SetRigCommand {
public:
    RemoveRigCommand(Document *doc, Id groupId, QUndoCommand *parent = nullptr);
};

} // namespace finbook::model
