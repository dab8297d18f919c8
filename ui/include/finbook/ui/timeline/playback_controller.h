// PlaybackController: plays the document's play range at its frame rate.
//
// The frame shown is computed from elapsed time, never from counting timer ticks: at any
// moment the position is floor(elapsed × fps) ticks past where playback started, mapped
// through the frames' holds (a frame held 2 stays for 2 ticks). A single-shot precise timer is
// aimed at the next tick boundary, so a late or dropped timeout delays one change by that
// much instead of shifting every later frame. Playing sets EditorState::setPlaying (the
// canvas hides onion skins) and moves EditorState::currentFrameIndex.
//
// With a PlaybackClock set (the soundtrack's player), the elapsed time is read from it: the
// frame shown follows the audio clock. Looping restarts the clock at the range's start.
//
// Loop, fps and the play range are document settings: the loop action changes them through
// ChangeSettingsCommand, so toggling loop is undoable like any edit.
//
// objectName        default shortcut   what it does
// playback.toggle   Return             play / pause (checkable; checked while playing)
// playback.loop     Ctrl+L             loop at the end of the play range (checkable)
#pragma once

#include <finbook/model/document.h>

#include <QAction>
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace finbook::ui {

class EditorState;
class PlaybackClock;

// Ticks the play range lasts: the sum of its frames' holds.
qint64 playRangeTicks(const model::Document &document);
// Ticks from the start of the play range to the first tick of frame `frameIndex` (clamped
// into the range).
qint64 tickOfFrame(const model::Document &document, int frameIndex);
// Ticks from the document's first frame to the start of the play range (the sound's time of
// the range's start is this over the fps).
qint64 firstTickOfRange(const model::Document &document);
// The frame index on screen `tick` ticks after the play range started. Past the end it is
// the range's last frame without loop, and wraps around with loop. -1 for an empty document.
int frameAtTick(const model::Document &document, qint64 tick, bool loop);

class PlaybackController : public QObject {
    Q_OBJECT
public:
    explicit PlaybackController(EditorState *state, QObject *parent = nullptr);

    bool isPlaying() const { return m_playing; }
    QAction *toggleAction() const { return m_toggle; }
    QAction *loopAction() const { return m_loop; }
    // Nanoseconds since the current run started and the tick it started at (for benches).
    qint64 elapsedNs() const { return m_playing ? clockNs() : 0; }
    // Where elapsed time comes from while playing; null: the controller's own timer.
    void setClock(PlaybackClock *clock) { m_external = clock; }
    qint64 startTick() const { return m_startTick; }

public slots:
    // Starts at the current frame, or at the start of the play range when the current frame
    // is outside it or already its last frame.
    void play();
    void pause();
    void toggle();

signals:
    void playingChanged(bool playing);

private:
    void tick();
    void scheduleTick(qint64 ticksSinceStart);
    void show(int frameIndex);
    void rebase(qint64 tick);
    void settingsChanged();
    void updateActions();
    qint64 clockNs() const;

    EditorState *m_state;
    QAction *m_toggle;
    QAction *m_loop;
    QTimer m_timer;
    QElapsedTimer m_clock;
    PlaybackClock *m_external = nullptr;
    qint64 m_startTick = 0;
    int m_fps = 12;
    bool m_playing = false;
    bool m_showing = false; // true while this controller moves the current frame
};

} // namespace finbook::ui
