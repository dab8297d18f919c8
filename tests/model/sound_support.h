// Shared by the sound tests: generated sound files (a WAV made here, other formats made by
// ffmpeg's `sine` source) and a document with a clip.
#pragma once

#include <finbook/model/document.h>
#include <finbook/model/sound/sound_commands.h>
#include <finbook/model/sound/soundtrack.h>

#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtEndian>

#include <cmath>

namespace sound_test {
using namespace finbook::model;

// A 16-bit mono WAV of a sine at `hz`, `seconds` long, at `rate` Hz.
inline QByteArray sineWav(double seconds, int rate = 44100, double hz = 440.0)
{
    const auto frames = qint64(std::llround(seconds * rate));
    QByteArray wav(44 + frames * 2, '\0');
    char *p = wav.data();
    const auto u32 = [&p](quint32 v) { qToLittleEndian<quint32>(v, p), p += 4; };
    const auto u16 = [&p](quint16 v) { qToLittleEndian<quint16>(v, p), p += 2; };
    const auto text = [&p](const char *four) { std::copy(four, four + 4, p), p += 4; };
    text("RIFF");
    u32(quint32(36 + frames * 2));
    text("WAVE");
    text("fmt ");
    u32(16);
    u16(1);
    u16(1);
    u32(quint32(rate));
    u32(quint32(rate * 2));
    u16(2);
    u16(16);
    text("data");
    u32(quint32(frames * 2));
    for (qint64 i = 0; i < frames; ++i)
        u16(quint16(qint16(std::lround(16000.0 * std::sin(2 * M_PI * hz * double(i) / rate)))));
    return wav;
}

// What ffmpeg writes into `file` (in `dir`) from a lavfi `source` with `options` before the
// output, or an empty array when ffmpeg is missing, fails or takes over `timeoutMs`.
inline QByteArray ffmpegOutput(const QTemporaryDir &dir, const QString &file, const QString &source,
                               const QStringList &options, int timeoutMs)
{
    const QString ffmpeg = QStandardPaths::findExecutable(QStringLiteral("ffmpeg"));
    if (ffmpeg.isEmpty())
        return {};
    const QString path = dir.filePath(file);
    QProcess p;
    p.start(ffmpeg, QStringList{QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-y"),
                                QStringLiteral("-f"), QStringLiteral("lavfi"), QStringLiteral("-i"),
                                source} +
                        options + QStringList{path});
    if (!p.waitForFinished(timeoutMs) || p.exitCode() != 0)
        return {};
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// `seconds` of a sine encoded by ffmpeg into `file` (its extension picks the format), or an
// empty array when ffmpeg is missing or cannot write that format.
inline QByteArray ffmpegSine(const QTemporaryDir &dir, const QString &file, double seconds,
                             const QStringList &codec = {})
{
    return ffmpegOutput(dir, file, QStringLiteral("sine=frequency=440:duration=%1").arg(seconds),
                        QStringList{QStringLiteral("-ac"), QStringLiteral("2")} + codec, 60000);
}

// `seconds` of mono silence at 44.1 kHz encoded by ffmpeg into `file` (a FLAC of an hour of
// silence is under a megabyte), or an empty array when ffmpeg is missing.
inline QByteArray ffmpegSilence(const QTemporaryDir &dir, const QString &file, double seconds)
{
    return ffmpegOutput(dir, file, QStringLiteral("anullsrc=r=44100:cl=mono"),
                        QStringList{QStringLiteral("-t"), QString::number(seconds)}, 120000);
}

// Imports `bytes` as a clip named `name` through the command, as File → Import Sound does.
inline Id importClip(Document &doc, const QByteArray &bytes, const QString &name, qint64 start = 0)
{
    SoundClip clip;
    clip.name = name;
    clip.bytes = bytes;
    clip.start = start;
    auto *command = new AddSoundClipCommand(&doc, clip);
    const Id id = command->clipId();
    doc.undoStack()->push(command);
    return id;
}

} // namespace sound_test
