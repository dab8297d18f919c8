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
constexpr int kWaveformBucketsPerSecond = 1000;

// Limits on what a clip decodes to, not only on the bytes it reads: a few kilobytes of
// sound file can announce hours of sound (a WAV at 1 Hz, a FLAC of silence), and decoding
// them whole filled the memory. A decoded second costs 192 KB (48 kHz stereo, 16 bits).
constexpr int kMinSoundSourceRate = 4000;          // Hz; lower is refused (no real recording is)
constexpr int kMaxSoundSourceRate = 384000;        // Hz; higher is refused
constexpr int kMaxSoundSourceChannels = 8;         // 7.1
constexpr double kMaxSoundSeconds = 3600;          // per clip (an hour: 691 MB decoded)
constexpr double kMaxSoundtrackSeconds = 2 * 3600; // all clips of a document together
// Decoded sound must be paid for by the file's bytes: past kFreeSoundSeconds, each second of
// sound needs kMinSoundBytesPerSecond bytes of file (24 kbit/s, below any real recording's
// bitrate but far above silence's: an hour needs a file of at least 10.8 MB). The same holds
// for all the clips of a document together, so a file of N MB decodes to at most
// 60 s + N × 350 s of sound, whatever it announces.
constexpr double kFreeSoundSeconds = 60;
constexpr qint64 kMinSoundBytesPerSecond = 3000;
// What decoding may read: source samples (seconds × source rate × channels), at most this
// many times what the same time costs at 48 kHz stereo (an hour of 96 kHz stereo or of
// 48 kHz 7.1 fits; a 384 kHz 8-channel clip gets an eighth of the time).
constexpr int kMaxSoundSourceFactor = 4;

// The most sound (seconds) that files of `encodedBytes` bytes may decode to, at most `cap`.
double soundSecondsAllowed(qint64 encodedBytes, double cap = kMaxSoundSeconds);

// Interleaved stereo 16-bit samples at kSoundRate (full scale 32767): half the memory of
// floats, and the precision every export writes. Louder input is clipped when decoded.
struct DecodedSound {
    std::vector<qint16> samples;
    qint64 frames() const { return qint64(samples.size()) / kSoundChannels; }
    double seconds() const { return double(frames()) / kSoundRate; }
    static constexpr float kScale = 1.0f / 32767.0f; // sample × kScale: -1 … 1
};
using DecodedSoundPtr = std::shared_ptr<const DecodedSound>;

// How much of a clip to decode.
struct SoundDecodeLimits {
    // More sound than this (frames at kSoundRate) refuses the clip, with `tooLong` as the
    // message (empty: one that names the file's size). -1: soundSecondsAllowed(bytes).
    qint64 maxFrames = -1;
    QString tooLong;
    // Decoding stops, without an error, once this many frames are decoded (an export needs
    // the sound up to its last frame only). -1: the whole clip.
    qint64 wantedFrames = -1;
};

// Peak envelope: per bucket of 1 / kWaveformBucketsPerSecond s, the largest absolute sample of
// either channel (0 … 1).
struct Waveform {
    std::vector<float> peaks;
    // The largest peak over [from, to) seconds; 0 outside the sound.
    float peakBetween(double from, double to) const;
};
using WaveformPtr = std::shared_ptr<const Waveform>;

// Decodes a whole sound file held in memory, resampling as it goes (never the whole clip at
// once). Fails with one translated sentence for the user when the bytes are not a sound FFmpeg
// reads, hold no audio stream, are cut short (less sound than the file announces), have a
// sample rate or channel count outside the limits above, or decode to more than `limits`
// allow. Memory: the decoded sound plus a few MB, never more than the limit allows. `cancelled`,
// if given, is polled between packets.
Expected<DecodedSound, QString> decodeSound(const QByteArray &bytes,
                                            const std::atomic<bool> *cancelled = nullptr,
                                            const SoundDecodeLimits &limits = {});

Waveform computeWaveform(const DecodedSound &sound);

// What the clips of one soundtrack may decode to together: soundSecondsAllowed() of all their
// bytes, at most kMaxSoundtrackSeconds, so 256 tiny clips cannot each take a clip's share.
// Clips are charged as they decode (first come, first served). Thread-safe.
class SoundBudget {
public:
    explicit SoundBudget(qint64 soundtrackBytes = 0) { setSoundtrackBytes(soundtrackBytes); }
    void setSoundtrackBytes(qint64 bytes);
    // The limits for a clip of `clipBytes`: its own, or what is left of the soundtrack's
    // when that is less (with a message that says so).
    SoundDecodeLimits limitsFor(qint64 clipBytes, qint64 wantedFrames = -1) const;
    void spend(qint64 frames) { m_spent += frames; }
    void refund(qint64 frames) { m_spent -= frames; }
    qint64 spentFrames() const { return m_spent; }

private:
    std::atomic<qint64> m_allowed{0};
    std::atomic<qint64> m_spent{0};
};

} // namespace finbook::model
