#include <finbook/model/commands.h>
#include <finbook/model/scene/shot.h>
#include <finbook/ui/timeline/playback_clock.h>
#include <finbook/ui/timeline/playback_controller.h>
#include <finbook/ui/window/editor_state.h>

#include <algorithm>

namespace finbook::ui {

namespace {
constexpr qint64 kNsPerSecond = 1'000'000'000;
constexpr qint64 kNsPerMs = 1'000'000;
} // namespace

// The play range is the current layer's frames playFirst..playLast, in ticks; played to its end
// ("-1"), it runs to the end of the longest layer, so a scene plays whole from any layer.
qint64 firstTickOfRange(const model::Document &doc)
{
    return model::celStart(doc.frames(), doc.playFirst());
}

qint64 playRangeTicks(const model::Document &doc)
{
    if (doc.frameCount() == 0)
        return 0;
    qint64 end = model::celStart(doc.frames(), doc.playLast() + 1);
    if (doc.settings().playEnd < 0)
        end = std::max(end, model::shotTicks(doc.layers()));
    return std::max<qint64>(1, end - firstTickOfRange(doc));
}

qint64 tickOfFrame(const model::Document &doc, int frameIndex)
{
    if (doc.frameCount() == 0)
        return 0;
    const int at = std::clamp(frameIndex, doc.playFirst(), doc.playLast());
    return model::celStart(doc.frames(), at) - firstTickOfRange(doc);
}

int frameAtTick(const model::Document &doc, qint64 tick, bool loop)
{
    if (doc.frameCount() == 0)
        return -1;
    const qint64 total = playRangeTicks(doc);
    tick = std::max<qint64>(0, tick);
    if (tick >= total) {
        if (!loop)
            return doc.playLast();
        tick %= total;
    }
    const int index = model::celAt(doc.frames(), firstTickOfRange(doc) + tick);
    // Past the current layer's end (a longer layer plays on), its last frame stays current.
    return index < 0 ? doc.playLast() : std::clamp(index, doc.playFirst(), doc.playLast());
}

PlaybackController::PlaybackController(EditorState *state, QObject *parent)
    : QObject(parent)
    , m_state(state)
{
    m_toggle = new QAction(tr("Pl&ay"), this);
    m_toggle->setObjectName(QStringLiteral("playback.toggle"));
    m_toggle->setCheckable(true);
    m_toggle->setShortcut(QKeySequence(Qt::Key_Return));
    m_toggle->setToolTip(tr("Play or pause the animation"));
    connect(m_toggle, &QAction::triggered, this, [this](bool checked) {
        if (checked)
            play();
        else
            pause();
    });

    m_loop = new QAction(tr("L&oop"), this);
    m_loop->setObjectName(QStringLiteral("playback.loop"));
    m_loop->setCheckable(true);
    m_loop->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    m_loop->setToolTip(tr("Start again at the end of the play range"));
    connect(m_loop, &QAction::triggered, this, [this](bool checked) {
        model::Document *doc = m_state->document();
        model::DocumentSettings settings = doc->settings();
        if (settings.loop == checked)
            return;
        settings.loop = checked;
        doc->undoStack()->push(new model::ChangeSettingsCommand(doc, settings));
    });

    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &PlaybackController::tick);
    model::Document *doc = m_state->document();
    connect(doc, &model::Document::settingsChanged, this, &PlaybackController::settingsChanged);
    connect(doc, &model::Document::documentReset, this, [this] {
        pause();
        updateActions();
    });
    // The user picked a frame while playing: carry on from there.
    connect(m_state, &EditorState::currentFrameChanged, this, [this](int index) {
        if (m_playing && !m_showing)
            rebase(tickOfFrame(*m_state->document(), index));
    });
    updateActions();
}

void PlaybackController::play()
{
    const model::Document &doc = *m_state->document();
    if (m_playing || doc.frameCount() == 0) {
        updateActions();
        return;
    }
    const int first = doc.playFirst();
    const int last = doc.playLast();
    int start = m_state->currentFrameIndex();
    if (start < first || start > last || (start == last && last > first))
        start = first;
    m_playing = true;
    show(start);
    rebase(tickOfFrame(doc, start));
    m_state->setPlaying(true);
    updateActions();
    emit playingChanged(true);
}

void PlaybackController::pause()
{
    m_timer.stop();
    if (!m_playing)
        return;
    if (m_external)
        m_external->stop();
    m_playing = false;
    m_state->setPlaybackTick(-1);
    m_state->setPlaying(false);
    updateActions();
    emit playingChanged(false);
}

void PlaybackController::toggle()
{
    if (m_playing)
        pause();
    else
        play();
}

void PlaybackController::rebase(qint64 tick)
{
    m_startTick = tick;
    m_fps = m_state->document()->settings().fps;
    m_clock.start();
    if (m_external) {
        const model::Document &doc = *m_state->document();
        m_external->startAt(firstTickOfRange(doc) + tick, m_fps);
    }
    scheduleTick(1);
}

qint64 PlaybackController::clockNs() const
{
    return m_external ? m_external->nsecsElapsed() : m_clock.nsecsElapsed();
}

void PlaybackController::settingsChanged()
{
    updateActions();
    if (!m_playing)
        return;
    // A new rate applies from the tick we are in now; a new range may have moved past us.
    const qint64 now = m_startTick + clockNs() * m_fps / kNsPerSecond;
    rebase(now);
    tick();
}

void PlaybackController::tick()
{
    if (!m_playing)
        return;
    const model::Document &doc = *m_state->document();
    const bool loop = doc.settings().loop;
    // One clock reading decides both the frame and the next boundary: reading it twice could
    // straddle a boundary and sleep through a whole tick.
    const qint64 ticks = clockNs() * m_fps / kNsPerSecond;
    const qint64 now = m_startTick + ticks;
    if (!loop && now >= playRangeTicks(doc)) {
        show(doc.playLast());
        pause();
        return;
    }
    if (m_external && loop && now >= playRangeTicks(doc)) {
        // The sound starts again with the range: the clock restarts there too.
        const qint64 wrapped = now % std::max<qint64>(1, playRangeTicks(doc));
        show(frameAtTick(doc, wrapped, loop));
        m_state->setPlaybackTick(firstTickOfRange(doc) + wrapped);
        rebase(wrapped);
        return;
    }
    show(frameAtTick(doc, now, loop));
    const qint64 range = std::max<qint64>(1, playRangeTicks(doc));
    m_state->setPlaybackTick(firstTickOfRange(doc) +
                             (loop ? now % range : std::min(now, range - 1)));
    scheduleTick(ticks + 1);
}

void PlaybackController::scheduleTick(qint64 ticksSinceStart)
{
    // Aim at the boundary, rounded down to the timer's millisecond resolution: an early
    // timeout finds the same frame and re-arms for the sub-millisecond rest, so changes land
    // within a fraction of a millisecond instead of up to one late.
    const qint64 dueNs = (ticksSinceStart * kNsPerSecond + m_fps - 1) / m_fps;
    const qint64 waitMs = (dueNs - clockNs()) / kNsPerMs;
    m_timer.start(int(std::clamp<qint64>(waitMs, 0, 1000)));
}

void PlaybackController::show(int frameIndex)
{
    if (frameIndex < 0)
        return;
    m_showing = true;
    m_state->setCurrentFrameIndex(frameIndex);
    m_showing = false;
}

void PlaybackController::updateActions()
{
    m_toggle->setChecked(m_playing);
    m_toggle->setText(m_playing ? tr("P&ause") : tr("Pl&ay"));
    m_toggle->setEnabled(m_state->document()->frameCount() > 0);
    m_loop->setChecked(m_state->document()->settings().loop);
}

} // namespace finbook::ui
