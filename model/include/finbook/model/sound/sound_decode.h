// Decoding a clip's encoded bytes to PCM, and the waveform drawn on the sound row.
//
// The decoder is FFmpeg's libraries (libavformat, libavcodec, libswresample), chosen for
// format coverage: WAV, FLAC, MP3, Ogg Vorbis/Opus and AAC/M4A all decode with the stock
// Debian build, whereas Qt 6.4's QAudioDecoder on Linux goes through GStreamer and reads only
// what the machine's GStreamer plugins happen to provide. Everything here is pure and
// thread-safe: the sound cache (sound_cache.h) calls it on a worker thread.
#pragma once

#include <finbook/geometry/expected.h>

#include <QByteArray>
#include <QString>

#include <atomic>
#include <memory>
#include <vector>

namespace finbook::model {

constexpr int kSoundRate = 48000; // every clip is resampled to this, stereo
constexpr int kSoundChannels = 2;
constexpr double kMaxSoundSeconds = 3600; // longer sound is refused (memory: 1.4 GB/hour)
constexpr int kWaveformBucketsPerSecond = 1000;

// Interleaved stereo float samples at kSoundRate, in -1 … 1 (louder input is clipped when
// mixed, not here).
struct DecodedSound {
    std::vector<float> samples;
    qint64 frames() const { return qint64(samples.size()) / kSoundChannels; }
    double seconds() const { return double(frames()) / kSoundRate; }
};
using DecodedSoundPtr = std::shared_ptr<const DecodedSound>;

// Peak envelope: per bucket of 1 / kWaveformBucketsPerSecond s, the largest absolute sample of
// either channel (0 … 1).
struct Waveform {
    std::vector<float> peaks;
    // The largest peak over [from, to) seconds; 0 outside the sound.
    float peakBetween(double from, double to) const;
};
using WaveformPtr = std::shared_ptr<const Waveform>;

// Decodes a whole sound file held in memory. Fails with one translated sentence for the user
// when the bytes are not a sound FFmpeg reads, hold no audio stream, are cut short (less sound
// than the file announces), or are longer than kMaxSoundSeconds. `cancelled`, if given, is
// polled between packets.
Expected<DecodedSound, QString> decodeSound(const QByteArray &bytes,
                                            const std::atomic<bool> *cancelled = nullptr);

Waveform computeWaveform(const DecodedSound &sound);

} // namespace finbook::model
