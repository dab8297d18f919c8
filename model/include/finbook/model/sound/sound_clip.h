// A sound clip of the document's soundtrack: the imported file's original encoded bytes
// (never decoded PCM) and where and how loud it plays.
//
// Time on the sound row is counted in ticks, the animation's own clock: tick t plays at
// t / fps seconds after the first frame starts, and a frame held n times lasts n ticks. A
// clip's start is the tick its first sample plays at ("start frame" in the interface, since
// without holds a tick is a frame).
#pragma once

#include <finbook/model/types.h>

#include <QByteArray>
#include <QString>

namespace finbook::model {

constexpr double kMaxSoundVolume = 4.0;          // 1 = as recorded; above amplifies
constexpr qint64 kMaxSoundStart = 1'000'000;     // ticks (over 4 hours at 60 fps)
constexpr qint64 kMaxSoundClipBytes = 1ll << 30; // 1 GiB of encoded sound per clip
constexpr int kMaxSoundClips = 256;
constexpr int kMaxSoundNameBytes = 4096;

struct SoundClip {
    Id id = kNoId;
    QString name;        // the imported file's name, shown on the row
    QByteArray bytes;    // the file as imported (WAV, FLAC, MP3, Ogg, M4A…), implicitly shared
    qint64 start = 0;    // tick of its first sample, 0 … kMaxSoundStart
    double volume = 1.0; // 0 … kMaxSoundVolume
    bool muted = false;

    bool operator==(const SoundClip &other) const = default;
};

} // namespace finbook::model
