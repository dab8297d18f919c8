// SoundSource: the QIODevice QAudioSink pulls the mixed soundtrack from (private to the ui).
// It holds a snapshot of the clips and their decoded sound, so what it reads never changes
// under it while the document is edited.
#pragma once

#include <finbook/model/sound/sound_mix.h>

#include <QIODevice>

#include <unordered_map>

namespace finbook::ui {

class SoundSource : public QIODevice {
    Q_OBJECT
public:
    using QIODevice::QIODevice;

    // Mixes samples [from, end) (end < 0: on and on, silence past the sound).
    void setRange(std::vector<model::SoundClip> clips,
                  std::unordered_map<model::Id, model::DecodedSoundPtr> sounds, int fps,
                  qint64 from, qint64 end)
    {
        m_clips = std::move(clips);
        m_sounds = std::move(sounds);
        m_fps = fps;
        m_at = from;
        m_end = end;
    }
    qint64 position() const { return m_at; }
    bool isSequential() const override { return true; }
    qint64 bytesAvailable() const override
    {
        constexpr qint64 kPlenty = qint64(1) << 20;
        const qint64 left = m_end < 0 ? kPlenty : (m_end - m_at) * kBytesPerFrame;
        return std::max<qint64>(0, left) + QIODevice::bytesAvailable();
    }

protected:
    qint64 readData(char *data, qint64 maxSize) override
    {
        qint64 frames = maxSize / kBytesPerFrame;
        if (m_end >= 0)
            frames = std::min(frames, m_end - m_at);
        if (frames <= 0)
            return 0;
        auto *out = reinterpret_cast<float *>(data);
        std::fill(out, out + frames * model::kSoundChannels, 0.0f);
        model::mixSoundtrack(
            m_clips,
            [this](model::Id id) {
                const auto it = m_sounds.find(id);
                return it == m_sounds.end() ? nullptr : it->second;
            },
            m_fps, m_at, frames, out);
        m_at += frames;
        return frames * kBytesPerFrame;
    }
    qint64 writeData(const char *, qint64) override { return -1; }

private:
    static constexpr qint64 kBytesPerFrame = qint64(sizeof(float)) * model::kSoundChannels;
    std::vector<model::SoundClip> m_clips;
    std::unordered_map<model::Id, model::DecodedSoundPtr> m_sounds;
    int m_fps = 12;
    qint64 m_at = 0;
    qint64 m_end = -1;
};

} // namespace finbook::ui
