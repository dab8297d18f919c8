// Soundtrack: the document's sound clips, in the order they were imported (later clips mix on
// top of earlier ones; the order matters only for drawing). Owned by the Document (one member,
// Document::soundtrack()); changed only by the commands in sound_commands.h and the loader.
#pragma once

#include <finbook/model/sound/sound_clip.h>

#include <QObject>

#include <vector>

namespace finbook::model {

class Soundtrack : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    const std::vector<SoundClip> &clips() const { return m_clips; }
    bool isEmpty() const { return m_clips.empty(); }
    int indexOf(Id clipId) const; // -1 if there is none
    const SoundClip *clip(Id clipId) const;

    // --- low-level mutators (commands and loader only)
    void reset(std::vector<SoundClip> clips);
    void insertClip(int index, SoundClip clip);
    SoundClip takeClip(Id clipId);
    // Start, volume, mute or name of the clip with clip.id; its bytes stay as they are.
    void replaceClip(const SoundClip &clip);

signals:
    // Clips were added, removed or all replaced.
    void clipsChanged();
    // Start, volume or mute of one clip changed (its sound did not).
    void clipEdited(Id clipId);

private:
    std::vector<SoundClip> m_clips;
};

} // namespace finbook::model
