#include "../command_text.h"

#include <finbook/model/camera/camera_commands.h>
#include <finbook/model/document.h>

namespace finbook::model {

SetCameraCommand::SetCameraCommand(Document *doc, CameraTrack camera, const QString &text,
                                   qint64 mergeKey, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_old(doc->camera())
    , m_new(std::move(camera))
    , m_mergeKey(mergeKey)
{
    setText(text);
}

void SetCameraCommand::redo()
{
    m_doc->setCamera(m_new);
}

void SetCameraCommand::undo()
{
    m_doc->setCamera(m_old);
}

int SetCameraCommand::id() const
{
    return m_mergeKey >= 0 ? int(CommandId::EditCamera) : -1;
}

bool SetCameraCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = dynamic_cast<const SetCameraCommand *>(other);
    if (!next || next->m_mergeKey != m_mergeKey || m_mergeKey < 0)
        return false;
    m_new = next->m_new;
    setObsolete(m_new == m_old);
    return true;
}

namespace {

std::unique_ptr<QUndoCommand> cameraCommand(Document *doc, CameraTrack track, const QString &text,
                                            qint64 mergeKey = -1)
{
    if (track == doc->camera() || !isValidCameraTrack(track))
        return nullptr;
    return std::make_unique<SetCameraCommand>(doc, std::move(track), text, mergeKey);
}

} // namespace

std::unique_ptr<QUndoCommand> setCameraKeyCommand(Document *doc, const CameraKey &key,
                                                  qint64 mergeKey)
{
    const bool exists = doc->camera().keyAt(key.tick) >= 0;
    return cameraCommand(doc, withKey(doc->camera(), key),
                         exists ? Command::tr("Change Camera Key") : Command::tr("Add Camera Key"),
                         mergeKey);
}

std::unique_ptr<QUndoCommand> removeCameraKeyCommand(Document *doc, qint64 tick)
{
    return cameraCommand(doc, withoutKey(doc->camera(), tick), Command::tr("Delete Camera Key"));
}

std::unique_ptr<QUndoCommand> moveCameraKeyCommand(Document *doc, qint64 from, qint64 to)
{
    const int index = doc->camera().keyAt(from);
    if (index < 0 || from == to || doc->camera().keyAt(to) >= 0)
        return nullptr;
    CameraKey key = doc->camera().keys[std::size_t(index)];
    key.tick = to;
    return cameraCommand(doc, withKey(withoutKey(doc->camera(), from), key),
                         Command::tr("Move Camera Key"));
}

} // namespace finbook::model
