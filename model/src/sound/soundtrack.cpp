#include <finbook/model/sound/soundtrack.h>

#include <algorithm>
#include <stdexcept>

namespace finbook::model {

int Soundtrack::indexOf(Id clipId) const
{
    const auto it = std::find_if(m_clips.begin(), m_clips.end(),
                                 [clipId](const SoundClip &c) { return c.id == clipId; });
    return it == m_clips.end() ? -1 : int(it - m_clips.begin());
}

const SoundClip *Soundtrack::clip(Id clipId) const
{
    const int index = indexOf(clipId);
    return index < 0 ? nullptr : &m_clips[std::size_t(index)];
}

void Soundtrack::reset(std::vector<SoundClip> clips)
{
    if (clips.empty() && m_clips.empty())
        return;
    m_clips = std::move(clips);
    emit clipsChanged();
}

void Soundtrack::insertClip(int index, SoundClip clip)
{
    index = std::clamp(index, 0, int(m_clips.size()));
    m_clips.insert(m_clips.begin() + index, std::move(clip));
    emit clipsChanged();
}

SoundClip Soundtrack::takeClip(Id clipId)
{
    const int index = indexOf(clipId);
    if (index < 0)
        throw std::out_of_range("Soundtrack::takeClip: no such clip");
    SoundClip clip = std::move(m_clips[std::size_t(index)]);
    m_clips.erase(m_clips.begin() + index);
    emit clipsChanged();
    return clip;
}

void Soundtrack::replaceClip(const SoundClip &clip)
{
    const int index = indexOf(clip.id);
    if (index < 0)
        throw std::out_of_range("Soundtrack::replaceClip: no such clip");
    SoundClip &at = m_clips[std::size_t(index)];
    const QByteArray bytes = at.bytes;
    at = clip;
    at.bytes = bytes;
    emit clipEdited(clip.id);
}

} // namespace finbook::model
