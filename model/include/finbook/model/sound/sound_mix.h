// Mixing the soundtrack: what playback plays, scrubbing previews and export encodes.
#pragma once

#include <finbook/model/sound/sound_clip.h>
#include <finbook/model/sound/sound_decode.h>

#include <QByteArray>

#include <functional>
#include <vector>

namespace finbook::model {

using SoundLookup = std::function<DecodedSoundPtr(Id clipId)>;

// The first sample (at kSoundRate) of tick `tick` at `fps` frames a second.
qint64 sampleOfTick(double tick, int fps);

// Adds the unmuted clips' sound over samples [from, from + count) of the soundtrack to `out`
// (interleaved stereo, 2 × count floats), each at its volume, then clips the sum to -1 … 1.
// Clips whose sound `lookup` does not have (yet) are silent.
void mixSoundtrack(const std::vector<SoundClip> &clips, const SoundLookup &lookup, int fps,
                   qint64 from, qint64 count, float *out);

// The mix of samples [from, from + count) as a 16-bit stereo WAV file (export hands it to
// ffmpeg).
QByteArray mixToWav(const std::vector<SoundClip> &clips, const SoundLookup &lookup, int fps,
                    qint64 from, qint64 count);

// A 16-bit WAV file of `samples` (interleaved, `channels` per frame, -1 … 1) at `rate` Hz.
QByteArray wavBytes(const std::vector<float> &samples, int rate, int channels);
// The 44 bytes that start such a file of `samples` samples; pcmBytes() gives what follows,
// block by block (a long mix is written without holding it whole).
QByteArray wavHeader(qint64 samples, int rate, int channels);
QByteArray pcmBytes(const std::vector<float> &samples);

// Whether any unmuted clip sounds anywhere in samples [from, from + count).
bool soundtrackSoundsIn(const std::vector<SoundClip> &clips, const SoundLookup &lookup, int fps,
                        qint64 from, qint64 count);

} // namespace finbook::model
