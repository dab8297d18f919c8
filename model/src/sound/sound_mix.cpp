#include <finbook/model/sound/sound_mix.h>

#include <QtEndian>

#include <algorithm>
#include <cmath>

namespace finbook::model {

qint64 sampleOfTick(double tick, int fps)
{
    return qint64(std::llround(tick * kSoundRate / std::max(1, fps)));
}

namespace {
// The part of a clip inside [from, from + count): offsets into the output and the clip.
struct Overlap {
    qint64 outAt = 0;
    qint64 clipAt = 0;
    qint64 length = 0;
};

Overlap overlap(const SoundClip &clip, const DecodedSound &sound, int fps, qint64 from,
                qint64 count)
{
    const qint64 begin = sampleOfTick(double(clip.start), fps);
    const qint64 first = std::max(from, begin);
    const qint64 last = std::min(from + count, begin + sound.frames());
    if (last <= first)
        return {};
    return {first - from, first - begin, last - first};
}
} // namespace

void mixSoundtrack(const std::vector<SoundClip> &clips, const SoundLookup &lookup, int fps,
                   qint64 from, qint64 count, float *out)
{
    if (count <= 0)
        return;
    bool any = false;
    for (const SoundClip &clip : clips) {
        if (clip.muted || clip.volume <= 0.0)
            continue;
        const DecodedSoundPtr sound = lookup ? lookup(clip.id) : nullptr;
        if (!sound)
            continue;
        const Overlap o = overlap(clip, *sound, fps, from, count);
        if (o.length <= 0)
            continue;
        any = true;
        const auto gain = float(clip.volume) * DecodedSound::kScale;
        const qint16 *src = sound->samples.data() + o.clipAt * kSoundChannels;
        float *dst = out + o.outAt * kSoundChannels;
        for (qint64 i = 0; i < o.length * kSoundChannels; ++i)
            dst[i] += gain * float(src[i]);
    }
    if (any)
        for (qint64 i = 0; i < count * kSoundChannels; ++i)
            out[i] = std::clamp(out[i], -1.0f, 1.0f);
}

bool soundtrackSoundsIn(const std::vector<SoundClip> &clips, const SoundLookup &lookup, int fps,
                        qint64 from, qint64 count)
{
    for (const SoundClip &clip : clips) {
        if (clip.muted || clip.volume <= 0.0)
            continue;
        const DecodedSoundPtr sound = lookup ? lookup(clip.id) : nullptr;
        if (sound && overlap(clip, *sound, fps, from, count).length > 0)
            return true;
    }
    return false;
}

QByteArray mixToWav(const std::vector<SoundClip> &clips, const SoundLookup &lookup, int fps,
                    qint64 from, qint64 count)
{
    count = std::max<qint64>(0, count);
    std::vector<float> mix(std::size_t(count) * kSoundChannels, 0.0f);
    mixSoundtrack(clips, lookup, fps, from, count, mix.data());
    return wavBytes(mix, kSoundRate, kSoundChannels);
}

QByteArray wavBytes(const std::vector<float> &samples, int rate, int channels)
{
    return wavHeader(qint64(samples.size()), rate, channels) + pcmBytes(samples);
}

QByteArray wavHeader(qint64 samples, int rate, int channels)
{
    // A WAV counts its bytes in 32 bits: a longer mix says the most it can (players read on).
    const auto dataBytes = quint32(std::min<qint64>(samples * 2, 0xffffffffll - 36));
    QByteArray wav(44, '\0');
    char *p = wav.data();
    const auto u32 = [&p](quint32 v) {
        qToLittleEndian<quint32>(v, p);
        p += 4;
    };
    const auto u16 = [&p](quint16 v) {
        qToLittleEndian<quint16>(v, p);
        p += 2;
    };
    const auto text = [&p](const char *four) {
        std::copy(four, four + 4, p);
        p += 4;
    };
    text("RIFF");
    u32(36 + dataBytes);
    text("WAVE");
    text("fmt ");
    u32(16);
    u16(1); // PCM
    u16(quint16(channels));
    u32(quint32(rate));
    u32(quint32(rate * channels * 2));
    u16(quint16(channels * 2));
    u16(16);
    text("data");
    u32(dataBytes);
    return wav;
}

QByteArray pcmBytes(const std::vector<float> &samples)
{
    QByteArray pcm(qsizetype(samples.size() * 2), '\0');
    char *p = pcm.data();
    for (float s : samples) {
        qToLittleEndian<quint16>(
            quint16(qint16(std::lround(std::clamp(s, -1.0f, 1.0f) * 32767.0f))), p);
        p += 2;
    }
    return pcm;
}

} // namespace finbook::model
