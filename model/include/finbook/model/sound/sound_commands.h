// The soundtrack's undoable edits: import (add), delete, and start / volume / mute changes.
// Like every command they hold ids and values; one whose clip has gone does nothing.
#pragma once

#include <finbook/model/commands.h>
#include <finbook/model/sound/sound_clip.h>

#include <memory>

namespace finbook::model {

class AddSoundClipCommand : public DocumentCommand {
public:
    // Gives `clip` a new id and puts it last on the soundtrack.
    AddSoundClipCommand(Document *doc, SoundClip clip, QUndoCommand *parent = nullptr);
    Id clipId() const { return m_clip.id; }
    void redo() override;
    void undo() override;

private:
    SoundClip m_clip;
    int m_index = -1;
};

class RemoveSoundClipCommand : public DocumentCommand {
public:
    RemoveSoundClipCommand(Document *doc, Id clipId, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_clipId;
    int m_index = -1;
    SoundClip m_clip;
};

// Changes one property of a clip (its bytes never change); the others stay as they are when
// it is done or undone.
enum class SoundProperty { Start, Volume, Muted };
class EditSoundClipCommand : public DocumentCommand {
public:
    EditSoundClipCommand(Document *doc, Id clipId, SoundProperty property, double value,
                         QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    void set(double value);

    Id m_clipId;
    SoundProperty m_property;
    double m_old = 0.0;
    double m_new;
};

// Null when nothing would change (or there is no such clip). Starts are clamped to
// 0 … kMaxSoundStart and volumes to 0 … kMaxSoundVolume.
std::unique_ptr<QUndoCommand> moveSoundClipCommand(Document *doc, Id clipId, qint64 start);
std::unique_ptr<QUndoCommand> soundClipVolumeCommand(Document *doc, Id clipId, double volume);
std::unique_ptr<QUndoCommand> soundClipMutedCommand(Document *doc, Id clipId, bool muted);

} // namespace finbook::model
