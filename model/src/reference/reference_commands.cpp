// SetReferenceCommand and the functions that make reference edits.
#include <finbook/model/document.h>
#include <finbook/model/reference/reference_commands.h>
#include <finbook/model/reference/reference_layer.h>

#include <QCoreApplication>

namespace finbook::model {

namespace {

QString editText(ReferenceEdit edit)
{
    switch (edit) {
    case ReferenceEdit::Replace:
        return QCoreApplication::translate("Reference", "Import Reference");
    case ReferenceEdit::Opacity:
        return QCoreApplication::translate("Reference", "Reference Opacity");
    case ReferenceEdit::Visible:
        return QCoreApplication::translate("Reference", "Show or Hide Reference");
    case ReferenceEdit::Locked:
        return QCoreApplication::translate("Reference", "Lock or Unlock Reference");
    case ReferenceEdit::Place:
        return QCoreApplication::translate("Reference", "Move Reference");
    case ReferenceEdit::Scale:
        return QCoreApplication::translate("Reference", "Scale Reference");
    case ReferenceEdit::Rotation:
        return QCoreApplication::translate("Reference", "Rotate Reference");
    case ReferenceEdit::Rate:
        return QCoreApplication::translate("Reference", "Reference Frame Rate");
    }
    return {};
}

bool movesIt(const Reference &a, const Reference &b)
{
    return a.center != b.center || a.scale != b.scale || a.rotation != b.rotation;
}
} // namespace

SetReferenceCommand::SetReferenceCommand(Document *doc, Reference reference, ReferenceEdit edit,
                                         const QString &text, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_new(std::move(reference))
    , m_old(doc->referenceLayer().reference())
    , m_edit(edit)
{
    setText(text);
    setObsolete(m_new == m_old);
}

void SetReferenceCommand::redo()
{
    m_doc->referenceLayer().setReference(m_new);
}

void SetReferenceCommand::undo()
{
    m_doc->referenceLayer().setReference(m_old);
}

int SetReferenceCommand::id() const
{
    return m_edit == ReferenceEdit::Replace ? -1 : int(CommandId::EditReference);
}

bool SetReferenceCommand::mergeWith(const QUndoCommand *other)
{
    const auto *o = dynamic_cast<const SetReferenceCommand *>(other);
    if (!o || o->m_edit != m_edit || o->m_old != m_new)
        return false;
    m_new = o->m_new;
    setObsolete(m_new == m_old);
    return true;
}

std::unique_ptr<QUndoCommand> importReferenceCommand(Document *doc, Reference reference)
{
    if (reference.isEmpty() || !referenceValuesValid(reference))
        return nullptr;
    return std::make_unique<SetReferenceCommand>(doc, std::move(reference), ReferenceEdit::Replace,
                                                 editText(ReferenceEdit::Replace));
}

std::unique_ptr<QUndoCommand> removeReferenceCommand(Document *doc)
{
    if (doc->referenceLayer().isEmpty())
        return nullptr;
    return std::make_unique<SetReferenceCommand>(
        doc, Reference(), ReferenceEdit::Replace,
        QCoreApplication::translate("Reference", "Remove Reference"));
}

std::unique_ptr<QUndoCommand> editReferenceCommand(Document *doc, Reference reference,
                                                   ReferenceEdit edit)
{
    const Reference &now = doc->referenceLayer().reference();
    if (now.isEmpty() || reference == now || !referenceValuesValid(reference) ||
        reference.bytes != now.bytes || reference.kind != now.kind)
        return nullptr;
    if (now.locked && reference.locked && movesIt(now, reference))
        return nullptr;
    return std::make_unique<SetReferenceCommand>(doc, std::move(reference), edit, editText(edit));
}

} // namespace finbook::model
