// The camera's undoable edits. Each replaces the whole track (a few keys of a few dozen bytes):
// undo puts back exactly the track there was.
#pragma once

#include <finbook/model/camera/camera_track.h>
#include <finbook/model/commands.h>

#include <memory>

namespace finbook::model {

class SetCameraCommand : public DocumentCommand {
public:
    // `mergeKey` ≥ 0: successive commands with the same value (one drag of the camera at one
    // tick) merge into one undo step; < 0 never merges.
    SetCameraCommand(Document *doc, CameraTrack camera, const QString &text, qint64 mergeKey = -1,
                     QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    CameraTrack m_old, m_new;
    qint64 m_mergeKey;
};

// Null when nothing would change or the result would be invalid (isValidCameraTrack): a key
// at key.tick added or replaced; the key at `tick` removed; the key at `from` moved to tick
// `to` (refused when another key is there).
std::unique_ptr<QUndoCommand> setCameraKeyCommand(Document *doc, const CameraKey &key,
                                                  qint64 mergeKey = -1);
std::unique_ptr<QUndoCommand> removeCameraKeyCommand(Document *doc, qint64 tick);
std::unique_ptr<QUndoCommand> moveCameraKeyCommand(Document *doc, qint64 from, qint64 to);

} // namespace finbook::model
