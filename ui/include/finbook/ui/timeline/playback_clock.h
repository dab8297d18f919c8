// PlaybackClock: what PlaybackController reads the time from while playing. Without one it
// uses its own elapsed timer; the soundtrack's player (sound/sound_player.h) is one, so the
// frame shown follows the audio clock rather than the other way round.
#pragma once

#include <QtGlobal>

namespace finbook::ui {

class PlaybackClock {
public:
    virtual ~PlaybackClock() = default;
    // Playback (re)starts now at `tick` ticks after the document's first frame starts.
    virtual void startAt(qint64 tick, int fps) = 0;
    // Nanoseconds played since the last startAt().
    virtual qint64 nsecsElapsed() const = 0;
    virtual void stop() = 0;
};

} // namespace finbook::ui
