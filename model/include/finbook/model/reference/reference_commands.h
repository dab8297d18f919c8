// Undoable edits of the reference layer: import (or replace), remove, and every property
// (opacity, visibility, lock, place, scale, rotation, rate). Each replaces the whole Reference
// value, so undo restores it exactly; media bytes are shared, never copied.
#pragma once

#include <finbook/model/commands.h>
#include <finbook/model/reference/reference.h>

namespace finbook::model {

// Which property an edit changes: consecutive edits of one property (a slider's drag, a spin
// box's steps) merge into one undo step.
enum class ReferenceEdit { Replace, Opacity, Visible, Locked, Place, Scale, Rotation, Rate };

class SetReferenceCommand : public DocumentCommand {
public:
    SetReferenceCommand(Document *doc, Reference reference, ReferenceEdit edit, const QString &text,
                        QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    Reference m_new;
    Reference m_old;
    ReferenceEdit m_edit;
};

// The command that imports `reference` (replacing any reference there is).
std::unique_ptr<QUndoCommand> importReferenceCommand(Document *doc, Reference reference);
// Removes the reference; null when there is none.
std::unique_ptr<QUndoCommand> removeReferenceCommand(Document *doc);
// `reference` with one property edited; null when nothing would change, when the values are
// out of range, or when a locked reference would move (a locked reference keeps its place,
// scale and rotation; its opacity, visibility and lock still change).
std::unique_ptr<QUndoCommand> editReferenceCommand(Document *doc, Reference reference,
                                                   ReferenceEdit edit);

} // namespace finbook::model
