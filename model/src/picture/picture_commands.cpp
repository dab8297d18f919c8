// ImportPictureCommand (picture_commands.h).
#include "../command_text.h"

#include <finbook/model/document.h>
#include <finbook/model/picture/picture_commands.h>

#include <QCoreApplication>

namespace finbook::model {

ImportPictureCommand::ImportPictureCommand(Document *doc, Id frameId, int index,
                                           std::vector<StrokeGroup> objects, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_frameId(frameId)
    , m_index(index)
    , m_objects(std::move(objects))
{
    setText(Command::tr("Import Picture"));
    const Frame *f = doc->frame(frameId);
    if (!f || m_objects.empty()) {
        setObsolete(true);
        return;
    }
    if (m_index < 0 || m_index > int(f->groups.size()))
        m_index = int(f->groups.size());
    for (StrokeGroup &g : m_objects) {
        g.id = doc->allocateId();
        m_ids.push_back(g.id);
    }
}

void ImportPictureCommand::redo()
{
    if (isObsolete())
        return;
    for (std::size_t i = 0; i < m_objects.size(); ++i)
        m_doc->insertGroup(m_frameId, m_index + int(i), m_objects[i]);
}

void ImportPictureCommand::undo()
{
    if (isObsolete())
        return;
    for (auto it = m_ids.rbegin(); it != m_ids.rend(); ++it)
        m_doc->takeGroup(*it);
}

SetPictureCommand::SetPictureCommand(Document *doc, Id groupId,
                                     std::shared_ptr<const ObjectPicture> picture,
                                     const QString &text, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
    , m_new(std::move(picture))
{
    setText(text);
    const StrokeGroup *g = doc->group(groupId);
    if (!g) {
        setObsolete(true);
        return;
    }
    m_old = g->picture;
    m_oldDeformed = g->deformed;
}

void SetPictureCommand::redo()
{
    if (!isObsolete())
        m_doc->setPicture(m_groupId, m_new);
}

void SetPictureCommand::undo()
{
    if (isObsolete())
        return;
    m_doc->setPicture(m_groupId, m_old);
    m_doc->setDeformed(m_groupId, m_oldDeformed);
}

} // namespace finbook::model
