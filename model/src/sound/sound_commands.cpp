#include "../command_text.h"

#include <finbook/model/sound/sound_commands.h>
#include <finbook/model/sound/soundtrack.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace finbook::model {

AddSoundClipCommand::AddSoundClipCommand(Document *doc, SoundClip clip, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_clip(std::move(clip))
{
    m_clip.id = doc->allocateId();
    m_index = int(doc->soundtrack().clips().size());
    setText(Command::tr("Import Sound"));
}

void AddSoundClipCommand::redo()
{
    if (!m_doc->soundtrack().clip(m_clip.id))
        m_doc->soundtrack().insertClip(m_index, m_clip);
}

void AddSoundClipCommand::undo()
{
    if (m_doc->soundtrack().clip(m_clip.id))
        m_doc->soundtrack().takeClip(m_clip.id);
}

RemoveSoundClipCommand::RemoveSoundClipCommand(Document *doc, Id clipId, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_clipId(clipId)
{
    setText(Command::tr("Delete Sound"));
    m_index = doc->soundtrack().indexOf(clipId);
    if (m_index < 0)
        setObsolete(true);
}

void RemoveSoundClipCommand::redo()
{
    Soundtrack &track = m_doc->soundtrack();
    const int index = track.indexOf(m_clipId);
    if (index < 0)
        return;
    m_index = index;
    m_clip = track.takeClip(m_clipId);
}

void RemoveSoundClipCommand::undo()
{
    if (m_clip.id != kNoId && !m_doc->soundtrack().clip(m_clipId))
        m_doc->soundtrack().insertClip(m_index, m_clip);
}

namespace {
double valueOf(const SoundClip &clip, SoundProperty property)
{
    switch (property) {
    case SoundProperty::Start:
        return double(clip.start);
    case SoundProperty::Volume:
        return clip.volume;
    case SoundProperty::Muted:
        break;
    }
    return clip.muted ? 1.0 : 0.0;
}

QString textOf(SoundProperty property, double value)
{
    switch (property) {
    case SoundProperty::Start:
        return Command::tr("Move Sound");
    case SoundProperty::Volume:
        return Command::tr("Change Sound Volume");
    case SoundProperty::Muted:
        break;
    }
    return value != 0.0 ? Command::tr("Mute Sound") : Command::tr("Unmute Sound");
}

// The value a property may take: starts and volumes clamped, NaN refused (nullopt).
std::optional<double> sanitized(SoundProperty property, double value)
{
    if (!std::isfinite(value))
        return std::nullopt;
    switch (property) {
    case SoundProperty::Start:
        return std::clamp(std::round(value), 0.0, double(kMaxSoundStart));
    case SoundProperty::Volume:
        return std::clamp(value, 0.0, kMaxSoundVolume);
    case SoundProperty::Muted:
        break;
    }
    return value != 0.0 ? 1.0 : 0.0;
}

std::unique_ptr<QUndoCommand> editCommand(Document *doc, Id clipId, SoundProperty property,
                                          double value)
{
    const SoundClip *now = doc->soundtrack().clip(clipId);
    const std::optional<double> v = sanitized(property, value);
    if (!now || !v || valueOf(*now, property) == *v)
        return nullptr;
    return std::make_unique<EditSoundClipCommand>(doc, clipId, property, *v);
}
} // namespace

EditSoundClipCommand::EditSoundClipCommand(Document *doc, Id clipId, SoundProperty property,
                                           double value, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_clipId(clipId)
    , m_property(property)
    , m_new(sanitized(property, value).value_or(0.0))
{
    setText(textOf(property, m_new));
    const SoundClip *now = doc->soundtrack().clip(clipId);
    if (!now)
        setObsolete(true);
    else
        m_old = valueOf(*now, property);
}

void EditSoundClipCommand::set(double value)
{
    const SoundClip *now = m_doc->soundtrack().clip(m_clipId);
    if (!now)
        return;
    SoundClip edited = *now;
    switch (m_property) {
    case SoundProperty::Start:
        edited.start = qint64(value);
        break;
    case SoundProperty::Volume:
        edited.volume = value;
        break;
    case SoundProperty::Muted:
        edited.muted = value != 0.0;
        break;
    }
    m_doc->soundtrack().replaceClip(edited);
}

void EditSoundClipCommand::redo()
{
    set(m_new);
}

void EditSoundClipCommand::undo()
{
    set(m_old);
}

std::unique_ptr<QUndoCommand> moveSoundClipCommand(Document *doc, Id clipId, qint64 start)
{
    return editCommand(doc, clipId, SoundProperty::Start, double(start));
}

std::unique_ptr<QUndoCommand> soundClipVolumeCommand(Document *doc, Id clipId, double volume)
{
    return editCommand(doc, clipId, SoundProperty::Volume, volume);
}

std::unique_ptr<QUndoCommand> soundClipMutedCommand(Document *doc, Id clipId, bool muted)
{
    return editCommand(doc, clipId, SoundProperty::Muted, muted ? 1.0 : 0.0);
}

} // namespace finbook::model
