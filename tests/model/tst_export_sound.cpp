// MP4 (AAC) and WebM (Opus) carry the mixed soundtrack trimmed to the exported range: ffprobe
// sees one audio stream as long as the video, and decoding it back finds the sound where the
// clip lies in the range. Formats without sound, and muted clips, add no audio stream.
#include "export_support.h"
#include "sound_support.h"

#include <finbook/model/sound/sound_decode.h>

#include <QFileInfo>
#include <QtTest>

using namespace finbook;
using model::ExportFormat;

namespace {
// ffprobe's JSON for the audio streams of `path`.
QJsonArray audioStreams(const QString &path)
{
    QProcess p;
    p.start(test::program("ffprobe"),
            {QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-select_streams"),
             QStringLiteral("a"), QStringLiteral("-show_streams"), QStringLiteral("-of"),
             QStringLiteral("json"), path});
    if (!p.waitForFinished(120000) || p.exitCode() != 0)
        return {};
    return QJsonDocument::fromJson(p.readAllStandardOutput())
        .object()[QStringLiteral("streams")]
        .toArray();
}

// The peak level of [from, to) seconds of decoded sound.
float peak(const model::DecodedSound &sound, double from, double to)
{
    float p = 0.0f;
    const auto first = qint64(from * model::kSoundRate) * 2;
    const qint64 last = std::min(qint64(to * model::kSoundRate) * 2, qint64(sound.samples.size()));
    for (qint64 i = std::max<qint64>(0, first); i < last; ++i)
        p = std::max(p, std::abs(float(sound.samples[std::size_t(i)]) * sound.kScale));
    return p;
}
} // namespace

class TestExportSound : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void videoCarriesTheRangesSound_data();
    void videoCarriesTheRangesSound();
    void noAudioWithoutSound();
    void flipbookEmbedsTheSound();
    void unusableMediaIsSaid();

private:
    QString exportTo(ExportFormat format, const QString &name, int first, int last);
    model::ExportSource m_source;
    QTemporaryDir m_dir;
};

void TestExportSound::initTestCase()
{
    if (test::program("ffmpeg").isEmpty() || test::program("ffprobe").isEmpty())
        QSKIP("ffmpeg/ffprobe not installed (bash .ci/setup installs them)");
    m_source = test::loadExample(); // 12 frames at 12 fps
    QCOMPARE(m_source.frames.size(), std::size_t(12));
    m_source.settings.fps = 12;
    // One second of sine starting at tick 6 (half a second in).
    model::SoundClip clip;
    clip.id = 1000;
    clip.name = QStringLiteral("beat.wav");
    clip.bytes = sound_test::sineWav(1.0);
    clip.start = 6;
    m_source.sound = {clip};
}

QString TestExportSound::exportTo(ExportFormat format, const QString &name, int first, int last)
{
    model::ExportOptions o;
    o.format = format;
    o.target = m_dir.filePath(name);
    o.firstFrame = first;
    o.lastFrame = last;
    o.scale = 0.25;
    const auto result = model::exportAnimation(m_source, o);
    if (!result) {
        qWarning("%s: %s\n%s", qPrintable(name), qPrintable(result.error().message),
                 qPrintable(result.error().detail));
        return {};
    }
    return o.target;
}

void TestExportSound::videoCarriesTheRangesSound_data()
{
    QTest::addColumn<ExportFormat>("format");
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("codec");
    QTest::newRow("mp4 aac") << ExportFormat::Mp4 << QStringLiteral("a.mp4")
                             << QStringLiteral("aac");
    QTest::newRow("webm opus") << ExportFormat::WebM << QStringLiteral("a.webm")
                               << QStringLiteral("opus");
}

void TestExportSound::videoCarriesTheRangesSound()
{
    QFETCH(ExportFormat, format);
    QFETCH(QString, name);
    QFETCH(QString, codec);
    // Frames 3 … 10: ticks 2 … 9, 8 ticks = 2/3 s; the clip sounds from tick 6 on, so the
    // video's first 4 ticks (1/3 s) are silent and the rest is the sine.
    const QString path = exportTo(format, name, 2, 9);
    QVERIFY(!path.isEmpty());
    const QJsonArray audio = audioStreams(path);
    QCOMPARE(audio.size(), 1);
    const QJsonObject stream = audio.at(0).toObject();
    QCOMPARE(stream[QStringLiteral("codec_name")].toString(), codec);
    const QJsonObject video = test::probe(path);
    const double videoSeconds = video[QStringLiteral("format")]
                                    .toObject()[QStringLiteral("duration")]
                                    .toString()
                                    .toDouble();
    QVERIFY2(std::abs(videoSeconds - 8.0 / 12) < 0.08, qPrintable(QString::number(videoSeconds)));
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    auto sound = model::decodeSound(f.readAll());
    QVERIFY2(sound, sound ? "" : qPrintable(sound.error()));
    // Encoders add a few milliseconds of priming and padding, never a frame's worth.
    QVERIFY2(std::abs(sound->seconds() - 8.0 / 12) < 1.0 / 12,
             qPrintable(QString::number(sound->seconds())));
    QVERIFY(peak(*sound, 0.02, 0.28) < 0.02f);
    QVERIFY(peak(*sound, 0.38, 0.62) > 0.2f);
}

void TestExportSound::noAudioWithoutSound()
{
    // A GIF has no sound; nor has a video whose clips are all muted.
    const QString gif = exportTo(ExportFormat::Gif, QStringLiteral("a.gif"), 0, 11);
    QVERIFY(!gif.isEmpty());
    QCOMPARE(audioStreams(gif).size(), 0);
    m_source.sound[0].muted = true;
    const QString mp4 = exportTo(ExportFormat::Mp4, QStringLiteral("muted.mp4"), 0, 11);
    m_source.sound[0].muted = false;
    QVERIFY(!mp4.isEmpty());
    QCOMPARE(audioStreams(mp4).size(), 0);
    // No temporaries are left beside the target.
    for (const QString &file : test::filesIn(m_dir.path()))
        QVERIFY2(!file.startsWith(QLatin1Char('.')), qPrintable(file));
}

void TestExportSound::flipbookEmbedsTheSound()
{
    const QString page = exportTo(ExportFormat::Html, QStringLiteral("a.html"), 2, 9);
    QVERIFY(!page.isEmpty());
    QFile f(page);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QByteArray html = f.readAll();
    QVERIFY(html.contains("media-src data:"));
    const QByteArray marker = "<audio id=\"sound\" preload=\"auto\" src=\"data:audio/wav;base64,";
    const qsizetype at = html.indexOf(marker);
    QVERIFY(at > 0);
    const qsizetype end = html.indexOf('"', at + marker.size());
    auto sound = model::decodeSound(
        QByteArray::fromBase64(html.mid(at + marker.size(), end - at - marker.size())));
    QVERIFY(sound);
    QVERIFY(std::abs(sound->seconds() - 8.0 / 12) < 0.01);
    QVERIFY(peak(*sound, 0.02, 0.3) < 0.02f);
    QVERIFY(peak(*sound, 0.36, 0.64) > 0.2f);
    // Muted: no sound, no media source allowed.
    m_source.sound[0].muted = true;
    const QString silent = exportTo(ExportFormat::Html, QStringLiteral("muted.html"), 2, 9);
    m_source.sound[0].muted = false;
    QFile g(silent);
    QVERIFY(g.open(QIODevice::ReadOnly));
    const QByteArray quiet = g.readAll();
    QVERIFY(!quiet.contains("<audio"));
    QVERIFY(!quiet.contains("media-src"));
}

QTEST_GUILESS_MAIN(TestExportSound)
// Issue 47: a clip that no longer decodes was left out of the video without a word. Now the
// result says which and why; strictMedia refuses the export before anything is written.
void TestExportSound::unusableMediaIsSaid()
{
    model::ExportSource source = m_source;
    model::SoundClip bad = source.sound.front();
    bad.id = 1001;
    bad.name = QStringLiteral("slow.wav");
    bad.bytes = sound_test::sineWav(3500, 1, 0.1); // 1 Hz
    source.sound.push_back(bad);
    source.reference.kind = model::ReferenceKind::Image;
    source.reference.name = QStringLiteral("gone.png");
    source.reference.bytes = QByteArray(3000, 'x');
    source.reference.mediaSize = QSizeF(10, 10);
    model::ExportOptions o;
    o.format = ExportFormat::Mp4;
    o.target = m_dir.filePath(QStringLiteral("left_out.mp4"));
    o.scale = 0.25;
    o.includeReference = true;
    const auto result = model::exportAnimation(source, o);
    QVERIFY2(result, result ? "" : qPrintable(result.error().message));
    qInfo("note: %s", qPrintable(result->note));
    QVERIFY(result->note.contains(QStringLiteral("\"slow.wav\" is left out")));
    QVERIFY(result->note.contains(QStringLiteral("1 Hz")));
    QVERIFY(result->note.contains(QStringLiteral("\"gone.png\" is left out")));
    QCOMPARE(audioStreams(o.target).size(), 1); // the good clip still plays

    o.strictMedia = true;
    o.target = m_dir.filePath(QStringLiteral("strict.mp4"));
    const auto strict = model::exportAnimation(source, o);
    QVERIFY(!strict);
    QCOMPARE(strict.error().code, model::ExportErrorCode::MediaUnusable);
    QVERIFY(strict.error().message.contains(QStringLiteral("slow.wav")));
    QVERIFY(!QFileInfo::exists(o.target));
}

#include "tst_export_sound.moc"
