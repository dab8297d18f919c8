// Commands over an object's ARAP pins, and its mesh density.
//
// Pins live in rest space (`rest`) and carry where they are dragged (`target`), so a pin
// survives re-meshing: the solver snaps it to the nearest vertex of whatever mesh is current.
// Each is a rig command (rig/rig_commands.h) with the pin list computed from the gesture;
// adding a pin to an object that has a cage replaces the cage.
#pragma once

#include <finbook/model/rig/rig_commands.h>

namespace finbook::model {

class AddPinCommand : public SetRigCommand {
public:
    // A pin at `rest` on the rest drawing, shown at `target` (equal for an undeformed object).
    AddPinCommand(Document *doc, Id groupId, QPointF rest, QPointF target,
                  QUndoCommand *parent = nullptr);
    Id pinId() const { return m_pinId; }

private:
    Id m_pinId;
};

class RemovePinCommand : public SetRigCommand {
public:
    RemovePinCommand(Document *doc, Id groupId, Id pinId, QUndoCommand *parent = nullptr);
};

// Moves a pin's target. Consecutive moves with the same drag serial merge, so one drag is one
// undo step and the next drag of the same pin is another.
class MovePinCommand : public PoseRigCommand {
public:
    MovePinCommand(Document *doc, Id groupId, Id pinId, QPointF target, int dragSerial,
                   QUndoCommand *parent = nullptr);
};

// Mesh density of one object (1 = default). Merges while one control is being dragged.
class SetMeshDensityCommand : public DocumentCommand {
public:
    SetMeshDensityCommand(Document *doc, Id groupId, double density, int editSerial,
                          QUndoCommand *parent = nullptr);
    int id() const override { return int(CommandId::SetMeshDensity); }
    bool mergeWith(const QUndoCommand *other) override;
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    int m_serial;
    double m_new;
    double m_old = kDefaultMeshDensity;
};

constexpr double kMinMeshDensity = 0.25;
constexpr double kMaxMeshDensity = 4.0;

} // namespace finbook::model
