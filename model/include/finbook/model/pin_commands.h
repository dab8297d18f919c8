// Commands over an object's deformation: ARAP pins, reset, bake, mesh density.
//
// Pins live in rest space (`rest`) and carry where they are dragged (`target`), so a pin
// survives re-meshing: the solver snaps it to the nearest vertex of whatever mesh is current.
#pragma once

#include <finbook/model/commands.h>

namespace finbook::model {

class AddPinCommand : public DocumentCommand {
public:
    // A pin at `rest` on the rest drawing, shown at `target` (equal for an undeformed object).
    AddPinCommand(Document *doc, Id groupId, QPointF rest, QPointF target,
                  QUndoCommand *parent = nullptr);
    Id pinId() const { return m_pin.id; }
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    Pin m_pin;
};

class RemovePinCommand : public DocumentCommand {
public:
    RemovePinCommand(Document *doc, Id groupId, Id pinId, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    Id m_pinId;
    std::vector<Pin> m_before;
};

// Moves a pin's target. Consecutive moves with the same drag serial merge, so one drag is one
// undo step and the next drag of the same pin is another.
class MovePinCommand : public DocumentCommand {
public:
    MovePinCommand(Document *doc, Id groupId, Id pinId, QPointF target, int dragSerial,
                   QUndoCommand *parent = nullptr);
    int id() const override { return int(CommandId::MovePin); }
    bool mergeWith(const QUndoCommand *other) override;
    void redo() override;
    void undo() override;

private:
    void apply(QPointF target);
    Id m_groupId;
    Id m_pinId;
    int m_serial;
    QPointF m_new;
    QPointF m_old;
};

// Sends every pin of an object back to its rest position (pins stay).
class ResetDeformationCommand : public DocumentCommand {
public:
    ResetDeformationCommand(Document *doc, Id groupId, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    std::vector<Pin> m_before;
};

// Makes the object's deformed pose its new rest drawing: strokes take the posed points, pins
// go, and the object is re-meshed from the new strokes. Obsolete when there is no pose.
class BakeDeformationCommand : public DocumentCommand {
public:
    BakeDeformationCommand(Document *doc, Id groupId, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    std::vector<Stroke> m_oldStrokes;
    std::vector<Stroke> m_newStrokes;
    std::vector<Pin> m_oldPins;
    DeformedStrokesPtr m_oldDeformed;
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
