// finbook-bench sound: a 3-minute stereo track (an MP3 made by ffmpeg's `sine` source, or a
// WAV made here when ffmpeg is missing): decode and waveform time; the GUI thread's stalls
// while the sound cache decodes it on its worker (a 2 ms timer's lateness, p99 and max); and,
// playing for --play seconds, how far the clock playback follows (the sound player's: the
// audio device's, or its elapsed timer when there is none) drifts from a reference clock, and
// how many frames the frame shown is off from the frame the reference clock calls for; with
// a real output (e.g. a PulseAudio null sink) the offset the output takes to start is told apart
// from the drift once it runs, and its underruns are counted.
#include "bench.h"

#include <finbook/model/commands.h>
#include <finbook/model/sound/sound_cache.h>
#include <finbook/model/sound/sound_commands.h>
#include <finbook/model/sound/sound_decode.h>
#include <finbook/model/sound/soundtrack.h>
#include <finbook/ui/sound/sound_controller.h>
#include <finbook/ui/sound/sound_player.h>
#include <finbook/ui/timeline/playback_controller.h>
#include <finbook/ui/window/editor_state.h>

#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <QtEndian>

#include <cmath>
#include <cstdio>

using namespace finbook;

namespace {

int intArg(const QStringList &args, const QString &name, int fallback)
{
    const int at = int(args.indexOf(name));
    return at >= 0 && at + 1 < args.size() ? args[at + 1].toInt() : fallback;
}

QByteArray stereoWav(int seconds)
{
    constexpr int kRate = 44100;
    const qint64 frames = qint64(seconds) * kRate;
    QByteArray wav(44 + frames * 4, '\0');
    char *p = wav.data();
    const auto put32 = [&p](quint32 v) { qToLittleEndian<quint32>(v, p), p += 4; };
    const auto put16 = [&p](quint16 v) { qToLittleEndian<quint16>(v, p), p += 2; };
    std::memcpy(p, "RIFF", 4), p += 4;
    put32(quint32(36 + frames * 4));
    std::memcpy(p, "WAVEfmt ", 8), p += 8;
    put32(16), put16(1), put16(2), put32(kRate), put32(kRate * 4), put16(4), put16(16);
    std::memcpy(p, "data", 4), p += 4;
    put32(quint32(frames * 4));
    for (qint64 i = 0; i < frames; ++i) {
        const double t = double(i) / kRate;
        put16(quint16(qint16(12000 * std::sin(2 * M_PI * 440 * t))));
        put16(quint16(qint16(12000 * std::sin(2 * M_PI * 660 * t))));
    }
    return wav;
}

// A `seconds` long stereo MP3 from ffmpeg, or a WAV when ffmpeg is missing; `format` says which.
QByteArray makeTrack(int seconds, const char **format)
{
    const QString ffmpeg = QStandardPaths::findExecutable(QStringLiteral("ffmpeg"));
    QTemporaryDir dir;
    if (!ffmpeg.isEmpty() && dir.isValid()) {
        const QString path = dir.filePath(QStringLiteral("track.mp3"));
        QProcess p;
        p.start(ffmpeg,
                {QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-f"),
                 QStringLiteral("lavfi"), QStringLiteral("-i"),
                 QStringLiteral("sine=frequency=440:beep_factor=4:duration=%1").arg(seconds),
                 QStringLiteral("-ac"), QStringLiteral("2"), QStringLiteral("-b:a"),
                 QStringLiteral("192k"), path});
        QFile f(path);
        if (p.waitForFinished(300000) && p.exitCode() == 0 && f.open(QIODevice::ReadOnly)) {
            *format = "mp3";
            return f.readAll();
        }
    }
    *format = "wav";
    return stereoWav(seconds);
}

int benchSound(const QStringList &args)
{
    const int seconds = intArg(args, QStringLiteral("--seconds"), 180);
    const int playSeconds = intArg(args, QStringLiteral("--play"), 60);
    const char *format = "";
    const QByteArray track = makeTrack(seconds, &format);

    // 1. Decode and waveform, on this thread, timed apart.
    QElapsedTimer clock;
    clock.start();
    auto decoded = model::decodeSound(track);
    const double decodeMs = double(clock.nsecsElapsed()) / 1e6;
    if (!decoded) {
        std::fprintf(stderr, "%s\n", qPrintable(decoded.error()));
        return 1;
    }
    clock.restart();
    const model::Waveform waveform = model::computeWaveform(*decoded);
    const double waveformMs = double(clock.nsecsElapsed()) / 1e6;

    // 2. The GUI thread while the cache decodes the same track on its worker.
    // Enough empty frames at 24 fps that playback never reaches the end (no loop restarts).
    model::Document doc;
    model::DocumentSettings settings;
    settings.fps = 24;
    settings.loop = false;
    std::vector<model::Frame> frames(std::size_t(playSeconds + 2) * 24);
    model::Id next = 1;
    for (model::Frame &f : frames)
        f.id = next++;
    doc.reset(std::move(frames), settings, next);
    // The window's sound controller: its cache decodes, its player is playback's clock.
    ui::EditorState state(&doc);
    ui::PlaybackController playback(&state);
    ui::SoundController sound(&state, &playback, nullptr);
    model::SoundCache &cache = *sound.cache();
    std::vector<double> lateMs;
    QTimer probe;
    probe.setTimerType(Qt::PreciseTimer);
    QElapsedTimer sinceTick;
    QObject::connect(&probe, &QTimer::timeout, [&] {
        lateMs.push_back(std::max(0.0, double(sinceTick.nsecsElapsed()) / 1e6 - 2.0));
        sinceTick.restart();
    });
    QEventLoop loop;
    QObject::connect(&cache, &model::SoundCache::soundReady, &loop, &QEventLoop::quit);
    QObject::connect(&cache, &model::SoundCache::soundFailed, &loop, &QEventLoop::quit);
    model::SoundClip clip;
    clip.name = QStringLiteral("track");
    clip.bytes = track;
    clock.restart();
    sinceTick.start();
    probe.start(2);
    doc.undoStack()->push(new model::AddSoundClipCommand(&doc, clip));
    loop.exec();
    probe.stop();
    const double cacheMs = double(clock.nsecsElapsed()) / 1e6;

    // 3. Play: the frames follow the sound player's clock; compare it with a reference clock.
    QElapsedTimer reference;
    state.setCurrentFrameIndex(0);
    playback.play();
    reference.start();
    int worstFramesOff = 0;
    QTimer check;
    QByteArray series = "["; // the sound clock's drift every 5 s, in ms
    int checks = 0;
    // An audio output takes a while to start (the frames wait for it, as the sound does):
    // that offset, then how far the clock drifts once it runs.
    double firstDriftMs = 0.0, lastDriftMs = 0.0;
    QObject::connect(&check, &QTimer::timeout, [&] {
        // The frame the reference clock calls for, against the frame shown.
        const qint64 referenceNow = reference.nsecsElapsed();
        const qint64 tick = referenceNow * settings.fps / 1'000'000'000;
        worstFramesOff = std::max(worstFramesOff, int(std::abs(state.currentFrameIndex() - tick)));
        if (++checks % 20 == 0) {
            lastDriftMs = double(sound.player()->nsecsElapsed() - referenceNow) / 1e6;
            if (checks == 20)
                firstDriftMs = lastDriftMs;
            series += (checks > 20 ? "," : "") + QByteArray::number(lastDriftMs, 'f', 1);
        }
    });
    check.start(250);
    QEventLoop wait;
    QTimer::singleShot(playSeconds * 1000, Qt::PreciseTimer, &wait, &QEventLoop::quit);
    wait.exec();
    const qint64 played = sound.player()->nsecsElapsed();
    const qint64 referenceNs = reference.nsecsElapsed();
    playback.pause();

    std::printf(
        "{\"bench\":\"sound\",\"format\":\"%s\",\"track_seconds\":%d,\"bytes\":%lld,"
        "\"decode_ms\":%.1f,\"waveform_ms\":%.1f,\"waveform_buckets\":%zu,"
        "\"cache_decode_ms\":%.1f,\"gui_stall_p99_ms\":%.3f,\"gui_stall_max_ms\":%.3f,"
        "\"gui_ticks\":%zu,\"audible\":%s,\"play_seconds\":%.2f,"
        "\"clock_drift_ms\":%.3f,\"worst_frames_off\":%d,\"underruns\":%d,"
        "\"start_offset_ms\":%.1f,\"drift_after_start_ms\":%.1f,\"drift_every_5s_ms\":%s]}\n",
        format, seconds, static_cast<long long>(track.size()), decodeMs, waveformMs,
        waveform.peaks.size(), cacheMs, bench::percentile(lateMs, 0.99),
        lateMs.empty() ? 0.0 : *std::max_element(lateMs.begin(), lateMs.end()), lateMs.size(),
        sound.player()->isAudible() ? "true" : "false", double(referenceNs) / 1e9,
        double(played - referenceNs) / 1e6, worstFramesOff, sound.player()->underruns(),
        firstDriftMs, lastDriftMs - firstDriftMs, series.constData());
    return 0;
}

} // namespace

FINBOOK_BENCH("sound",
              "[--seconds S] [--play P]  decode + waveform of an S-second stereo track, GUI "
              "stalls while it decodes, audio-clock drift over P seconds of playback",
              benchSound);
