// SoundPlayer: plays the soundtrack through Qt Multimedia's QAudioSink, and is the clock that
// playback follows (PlaybackClock): the time played is the sink's processed audio, so the frame
// shown follows the sound. Stepping or scrubbing plays the slice of sound under the frame.
//
// With no audio output (a headless machine, CI) playback runs on an elapsed timer instead,
// silently, and `silent` is emitted once so the window can say so.
#pragma once

#include <finbook/model/sound/sound_decode.h>
#include <finbook/ui/timeline/playback_clock.h>

#include <QElapsedTimer>
#include <QObject>

class QAudioSink;

namespace finbook::model {
class Document;
class SoundCache;
} // namespace finbook::model

namespace finbook::ui {

class SoundSource;

class SoundPlayer : public QObject, public PlaybackClock {
    Q_OBJECT
public:
    SoundPlayer(model::Document *document, model::SoundCache *cache, QObject *parent = nullptr);
    ~SoundPlayer() override;

    void startAt(qint64 tick, int fps) override;
    qint64 nsecsElapsed() const override;
    void stop() override;
    // Plays ticks [tick, tick + ticks) of the soundtrack once, unless playing.
    void playSlice(qint64 tick, int ticks, int fps);

    // Whether sound reaches an audio output (false: the elapsed-timer clock runs silently).
    bool isAudible() const { return m_sink != nullptr; }
    // The sample the next read would mix (for tests and the bench).
    qint64 sourcePosition() const;
    // How often the audio output ran dry since the player was made (each one a gap in the
    // sound, and the sound clock, hence the frames, held back by it; for the bench).
    int underruns() const { return m_underruns; }
    // For tests: behave as on a machine without audio output.
    void setAudioOutputAllowed(bool allowed) { m_allowed = allowed; }

signals:
    void silent(const QString &message);

private:
    bool openSink();
    void begin(qint64 fromSample, qint64 endSample, int fps);

    model::Document *m_doc;
    model::SoundCache *m_cache;
    QAudioSink *m_sink = nullptr;
    SoundSource *m_source;
    QElapsedTimer m_fallback;
    bool m_playing = false;
    bool m_allowed = true;
    bool m_triedSink = false;
    bool m_saidSilent = false;
    int m_underruns = 0;
};

} // namespace finbook::ui
