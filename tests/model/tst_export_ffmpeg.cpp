// GIF, MP4, WebM and APNG through ffmpeg, checked with ffprobe and by decoding frames back:
// frame counts with holds, durations, sizes, pixel formats, loop flags, transparency, and the
// failures (no ffmpeg, a failing encoder, a full disk, a cancel) that must leave nothing.
// Skips when ffmpeg or ffprobe is missing (.ci/setup installs them).
#include "../../model/src/export/ffmpeg_arguments.h"
#include "export_support.h"

#include <finbook/model/export/export_plan.h>
#include <finbook/model/export/exporter.h>

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <sys/resource.h>

using namespace finbook;
using namespace finbook::test;
using model::ExportFormat;

namespace {

constexpr double kFps = 12.0;

model::ExportOptions optionsFor(ExportFormat format, const QString &target)
{
    model::ExportOptions o;
    o.format = format;
    o.target = target;
    o.scale = 0.5; // 640 x 360: quick, and the scale is checked too
    return o;
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

double probedDuration(const QJsonObject &stream)
{
    bool ok = false;
    const double d =
        stream[QStringLiteral("format")].toObject()[QStringLiteral("duration")].toString().toDouble(
            &ok);
    return ok ? d : -1;
}

// The GIF loop count from its NETSCAPE2.0 block; -1 without one (the GIF plays once).
int gifLoopCount(const QByteArray &gif)
{
    const qsizetype at = gif.indexOf("NETSCAPE2.0");
    if (at < 0 || at + 15 > gif.size())
        return -1;
    return uchar(gif[at + 13]) | (uchar(gif[at + 14]) << 8);
}

// APNG's acTL num_plays (0 = forever); -1 when there is no acTL chunk.
int apngPlays(const QByteArray &png)
{
    const qsizetype at = png.indexOf("acTL");
    if (at < 0 || at + 12 > png.size())
        return -1;
    return int(qFromBigEndian<quint32>(png.constData() + at + 8));
}

class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes)
    {
        m_handler = std::signal(SIGXFSZ, SIG_IGN);
        getrlimit(RLIMIT_FSIZE, &m_saved);
        rlimit limit = m_saved;
        limit.rlim_cur = bytes;
        m_ok = setrlimit(RLIMIT_FSIZE, &limit) == 0;
    }
    ~FileSizeLimit()
    {
        setrlimit(RLIMIT_FSIZE, &m_saved);
        std::signal(SIGXFSZ, m_handler);
    }
    bool ok() const { return m_ok; }

private:
    rlimit m_saved{};
    void (*m_handler)(int) = nullptr;
    bool m_ok = false;
};

// Points $FINBOOK_FFMPEG somewhere else for one scope.
class FfmpegOverride {
public:
    explicit FfmpegOverride(const QString &program)
    {
        qputenv("FINBOOK_FFMPEG", program.toLocal8Bit());
    }
    ~FfmpegOverride() { qunsetenv("FINBOOK_FFMPEG"); }
};

QString writeScript(const QTemporaryDir &dir, const QString &name, const QByteArray &body)
{
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write("#!/bin/sh\n" + body);
    f.close();
    f.setPermissions(f.permissions() | QFileDevice::ExeOwner | QFileDevice::ExeUser);
    return path;
}

} // namespace

class TestExportFfmpeg : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void probesAsExpected_data();
    void probesAsExpected();
    void gifHoldsAreLongerDelays();
    void loopFollowsTheDocument();
    void framesLookLikeTheRender();
    void transparencyAndBackground();
    void rangeScaleAndRate();
    void missingFfmpegIsReported();
    void failingEncoderIsReported();
    void fullDiskLeavesNothing_data();
    void fullDiskLeavesNothing();
    void cancelLeavesNothing();
    void stuckEncoderIsStopped();
    void gifRunsKeepNoFrames();
    void thousandDrawingsOnTwos_data();
    void thousandDrawingsOnTwos();
    void longGifInBoundedMemory();

private:
    QString exportTo(ExportFormat format, const QString &name,
                     model::ExportOptions *changes = nullptr);

    model::ExportSource m_source;
    QTemporaryDir m_dir;
};

void TestExportFfmpeg::initTestCase()
{
    m_source = exampleWithHolds();
    QVERIFY(m_source.frames.size() == 12);
    QVERIFY(m_dir.isValid());
}

QString TestExportFfmpeg::exportTo(ExportFormat format, const QString &name,
                                   model::ExportOptions *changes)
{
    model::ExportOptions o = changes ? *changes : optionsFor(format, QString());
    o.format = format;
    o.target = m_dir.filePath(name);
    const auto result = model::exportAnimation(m_source, o);
    if (!result) {
        qWarning("%s: %s\n%s", qPrintable(name), qPrintable(result.error().message),
                 qPrintable(result.error().detail));
        return {};
    }
    return o.target;
}

void TestExportFfmpeg::probesAsExpected_data()
{
    QTest::addColumn<int>("format");
    QTest::addColumn<bool>("transparent");
    QTest::addColumn<QString>("codec");
    QTest::addColumn<QString>("pixelFormat");
    QTest::addColumn<int>("frames");
    // GIF: each drawing once, its hold as its delay. Video and APNG: one frame per tick.
    QTest::newRow("gif") << int(ExportFormat::Gif) << false << "gif"
                         << "bgra" << 12;
    QTest::newRow("mp4") << int(ExportFormat::Mp4) << false << "h264"
                         << "yuv420p" << 18;
    QTest::newRow("webm") << int(ExportFormat::WebM) << false << "vp9"
                          << "yuv420p" << 18;
    QTest::newRow("webm alpha") << int(ExportFormat::WebM) << true << "vp9"
                                << "yuv420p" << 18;
    QTest::newRow("apng") << int(ExportFormat::Apng) << false << "apng"
                          << "rgb24" << 18;
    QTest::newRow("apng alpha") << int(ExportFormat::Apng) << true << "apng"
                                << "rgba" << 18;
}

void TestExportFfmpeg::probesAsExpected()
{
    if (program("ffmpeg").isEmpty() || program("ffprobe").isEmpty())
        QSKIP("ffmpeg/ffprobe not installed (bash .ci/setup installs them)");
    QFETCH(int, format);
    QFETCH(bool, transparent);
    QFETCH(QString, codec);
    QFETCH(QString, pixelFormat);
    QFETCH(int, frames);
    model::ExportOptions o = optionsFor(ExportFormat(format), QString());
    o.transparent = transparent;
    const QString name = QStringLiteral("probe_%1%2.%3")
                             .arg(QTest::currentDataTag())
                             .arg(transparent ? "_alpha" : "")
                             .arg(model::exportFormatSuffix(ExportFormat(format)))
                             .replace(QLatin1Char(' '), QLatin1Char('_'));
    const QString path = exportTo(ExportFormat(format), name, &o);
    QVERIFY(!path.isEmpty());
    QString error;
    const QJsonObject stream = probe(path, &error);
    QVERIFY2(!stream.isEmpty(), qPrintable(error));
    QCOMPARE(stream[QStringLiteral("codec_name")].toString(), codec);
    QCOMPARE(stream[QStringLiteral("width")].toInt(), 640);
    QCOMPARE(stream[QStringLiteral("height")].toInt(), 360);
    QCOMPARE(stream[QStringLiteral("pix_fmt")].toString(), pixelFormat);
    QCOMPARE(stream[QStringLiteral("nb_read_frames")].toString().toInt(), frames);
    // Duration = ticks / fps within one frame: from the container, or summed over frames
    // (APNG has no container duration).
    double duration = probedDuration(stream);
    if (duration < 0) {
        duration = 0;
        for (double d : frameDurations(path))
            duration += d;
    }
    qInfo("%s: %d frames, %.3f s, %s", qPrintable(name), frames, duration, qPrintable(pixelFormat));
    QVERIFY2(std::abs(duration - 18 / kFps) <= 1 / kFps + 1e-6,
             qPrintable(QString::number(duration)));
    if (ExportFormat(format) == ExportFormat::WebM) {
        const QString alpha =
            stream[QStringLiteral("tags")].toObject()[QStringLiteral("alpha_mode")].toString();
        QCOMPARE(alpha == QLatin1String("1"), transparent);
    }
    if (ExportFormat(format) == ExportFormat::Mp4) {
        QCOMPARE(stream[QStringLiteral("profile")].toString().contains(QLatin1String("High")),
                 true);
        QCOMPARE(stream[QStringLiteral("color_space")].toString(), QStringLiteral("bt709"));
    }
    // Only the finished file is in the folder: no temporary left beside it.
    for (const QString &file : filesIn(m_dir.path()))
        QVERIFY2(!file.endsWith(QLatin1String(".part")), qPrintable(file));
}

void TestExportFfmpeg::gifHoldsAreLongerDelays()
{
    if (program("ffmpeg").isEmpty() || program("ffprobe").isEmpty())
        QSKIP("ffmpeg/ffprobe not installed");
    const QString path = exportTo(ExportFormat::Gif, QStringLiteral("holds.gif"));
    QVERIFY(!path.isEmpty());
    const std::vector<double> durations = frameDurations(path);
    QCOMPARE(durations.size(), std::size_t(12));
    double total = 0;
    for (std::size_t i = 0; i < durations.size(); ++i) {
        const double expected = m_source.frames[i].hold / kFps;
        // GIF delays are whole centiseconds: each within one, and the sum stays on time.
        QVERIFY2(std::abs(durations[i] - expected) <= 0.0101,
                 qPrintable(QStringLiteral("frame %1: %2 s, expected %3 s")
                                .arg(i + 1)
                                .arg(durations[i])
                                .arg(expected)));
        total += durations[i];
    }
    QVERIFY(std::abs(total - 18 / kFps) <= 0.0101);
}

void TestExportFfmpeg::loopFollowsTheDocument()
{
    if (program("ffmpeg").isEmpty())
        QSKIP("ffmpeg not installed");
    QVERIFY(m_source.settings.loop); // the example loops
    const QString looping = exportTo(ExportFormat::Gif, QStringLiteral("loop.gif"));
    QCOMPARE(gifLoopCount(readAll(looping)), 0); // 0 = forever
    model::ExportOptions once = optionsFor(ExportFormat::Gif, QString());
    once.loop = false;
    const QString single = exportTo(ExportFormat::Gif, QStringLiteral("once.gif"), &once);
    QCOMPARE(gifLoopCount(readAll(single)), -1);
    QCOMPARE(apngPlays(readAll(exportTo(ExportFormat::Apng, QStringLiteral("loop.apng")))), 0);
    QCOMPARE(apngPlays(readAll(exportTo(ExportFormat::Apng, QStringLiteral("once.apng"), &once))),
             1);
}

void TestExportFfmpeg::framesLookLikeTheRender()
{
    if (program("ffmpeg").isEmpty())
        QSKIP("ffmpeg not installed");
    const model::ExportOptions o = optionsFor(ExportFormat::Mp4, QString());
    const auto plan = model::planExport(m_source, o);
    QVERIFY(plan);
    // Tick 6 of the MP4 (0-based 5) shows frame 4; GIF frame 6 (0-based 5) is frame 6.
    const QImage frame4 = model::renderExportFrame(m_source.frames[3], m_source.settings, *plan);
    const QImage frame6 = model::renderExportFrame(m_source.frames[5], m_source.settings, *plan);
    const QString mp4 = exportTo(ExportFormat::Mp4, QStringLiteral("look.mp4"));
    const QString gif = exportTo(ExportFormat::Gif, QStringLiteral("look.gif"));
    const QImage fromMp4 = decodeFrame(mp4, 5);
    const QImage fromGif = decodeFrame(gif, 5);
    QCOMPARE(fromMp4.size(), frame4.size());
    QCOMPARE(fromGif.size(), frame6.size());
    const ImageDifference mp4Difference = difference(fromMp4, frame4);
    const ImageDifference gifDifference = difference(fromGif, frame6);
    const ImageDifference wrongFrame = difference(fromGif, frame4);
    qInfo("MP4 tick 6 vs render: mean %.2f / 255; GIF frame 6: mean %.2f; GIF vs another frame: "
          "mean %.2f",
          mp4Difference.meanAbs, gifDifference.meanAbs, wrongFrame.meanAbs);
    QVERIFY(mp4Difference.meanAbs < 2.0);
    QVERIFY(gifDifference.meanAbs < 2.0);
    QVERIFY(wrongFrame.meanAbs > 2 * gifDifference.meanAbs);
}

void TestExportFfmpeg::transparencyAndBackground()
{
    if (program("ffmpeg").isEmpty())
        QSKIP("ffmpeg not installed");
    model::ExportOptions clear = optionsFor(ExportFormat::Gif, QString());
    clear.transparent = true;
    for (ExportFormat format : {ExportFormat::Gif, ExportFormat::WebM, ExportFormat::Apng}) {
        const QString path =
            exportTo(format, QStringLiteral("clear.") + model::exportFormatSuffix(format), &clear);
        // libvpx's own decoder keeps VP9's alpha plane (ffmpeg's native one drops it).
        const QStringList decoder =
            format == ExportFormat::WebM
                ? QStringList{QStringLiteral("-c:v"), QStringLiteral("libvpx-vp9")}
                : QStringList();
        const QImage image = decodeFrame(path, 1, decoder);
        QVERIFY2(!image.isNull(), qPrintable(path));
        QCOMPARE(qAlpha(image.pixel(0, 0)), 0);
        qint64 opaque = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                opaque += qAlpha(image.pixel(x, y)) > 200;
        QVERIFY2(opaque > 500, qPrintable(QStringLiteral("%1: %2").arg(path).arg(opaque)));
    }
    model::ExportOptions red = optionsFor(ExportFormat::Mp4, QString());
    red.background = qRgb(220, 40, 30);
    const QImage corner =
        decodeFrame(exportTo(ExportFormat::Mp4, QStringLiteral("red.mp4"), &red), 0);
    const QRgb c = corner.pixel(2, 2);
    QVERIFY2(std::abs(qRed(c) - 220) < 8 && std::abs(qGreen(c) - 40) < 8 &&
                 std::abs(qBlue(c) - 30) < 8,
             qPrintable(QColor(c).name()));
}

void TestExportFfmpeg::rangeScaleAndRate()
{
    if (program("ffmpeg").isEmpty() || program("ffprobe").isEmpty())
        QSKIP("ffmpeg/ffprobe not installed");
    model::ExportOptions o = optionsFor(ExportFormat::Mp4, QString());
    o.firstFrame = 2;
    o.lastFrame = 7;
    o.scale = 0.25;
    o.fps = 24;
    const QJsonObject stream = probe(exportTo(ExportFormat::Mp4, QStringLiteral("range.mp4"), &o));
    const qint64 ticks = ticksOf(m_source, 2, 7);
    QCOMPARE(ticks, qint64(9));
    QCOMPARE(stream[QStringLiteral("nb_read_frames")].toString().toLongLong(), ticks);
    QCOMPARE(stream[QStringLiteral("width")].toInt(), 320);
    QCOMPARE(stream[QStringLiteral("height")].toInt(), 180);
    QCOMPARE(stream[QStringLiteral("r_frame_rate")].toString(), QStringLiteral("24/1"));
    QVERIFY(std::abs(probedDuration(stream) - ticks / 24.0) <= 1 / 24.0 + 1e-6);
}

void TestExportFfmpeg::missingFfmpegIsReported()
{
    FfmpegOverride missing(m_dir.filePath(QStringLiteral("no/such/ffmpeg")));
    QVERIFY(model::ffmpegProgram().isEmpty());
    const QString target = m_dir.filePath(QStringLiteral("missing/anim.gif"));
    const auto result = model::exportAnimation(m_source, optionsFor(ExportFormat::Gif, target));
    QVERIFY(!result);
    QCOMPARE(result.error().code, model::ExportErrorCode::EncoderMissing);
    QVERIFY(result.error().message.contains(QLatin1String("ffmpeg")));
    QVERIFY(!QFileInfo::exists(m_dir.filePath(QStringLiteral("missing"))));
}

void TestExportFfmpeg::failingEncoderIsReported()
{
    if (program("ffmpeg").isEmpty())
        QSKIP("ffmpeg not installed");
    // The real ffmpeg asked for an encoder it does not have.
    const QString unknown =
        writeScript(m_dir, QStringLiteral("ffmpeg-no-encoder"),
                    "for a do shift; [ \"$a\" = libx264 ] && a=libfinbook_none; "
                    "set -- \"$@\" \"$a\"; done\nexec ffmpeg \"$@\"\n");
    // An encoder that gives up part-way, after reading some frames.
    const QString midway =
        writeScript(m_dir, QStringLiteral("ffmpeg-midway"),
                    "head -c 3000000 > /dev/null\n"
                    "echo 'frame 2: encoding failed: out of luck' >&2\nexit 3\n");
    const QString folder = m_dir.filePath(QStringLiteral("failing"));
    QVERIFY(QDir().mkpath(folder));
    struct Case {
        QString program;
        const char *said;
    };
    for (const Case &c : {Case{unknown, "libfinbook_none"}, Case{midway, "out of luck"}}) {
        FfmpegOverride failing(c.program);
        const QString target = QDir(folder).filePath(QStringLiteral("anim.mp4"));
        const auto result = model::exportAnimation(m_source, optionsFor(ExportFormat::Mp4, target));
        QVERIFY(!result);
        QCOMPARE(result.error().code, model::ExportErrorCode::EncoderFailed);
        qInfo("%s | %s", qPrintable(result.error().message), qPrintable(result.error().detail));
        QVERIFY2(result.error().detail.contains(QLatin1String(c.said)),
                 qPrintable(result.error().detail));
        QVERIFY2(result.error().message.contains(QLatin1String(c.said)),
                 qPrintable(result.error().message));
        QCOMPARE(filesIn(folder), QStringList());
    }
}

void TestExportFfmpeg::fullDiskLeavesNothing_data()
{
    QTest::addColumn<int>("format");
    QTest::newRow("gif") << int(ExportFormat::Gif);
    QTest::newRow("mp4") << int(ExportFormat::Mp4);
    QTest::newRow("webm") << int(ExportFormat::WebM);
    QTest::newRow("apng") << int(ExportFormat::Apng);
}

void TestExportFfmpeg::fullDiskLeavesNothing()
{
    if (program("ffmpeg").isEmpty())
        QSKIP("ffmpeg not installed");
    QFETCH(int, format);
    const QString folder = m_dir.filePath(QStringLiteral("full_%1").arg(format));
    QVERIFY(QDir().mkpath(folder));
    const QString target = QDir(folder).filePath(QStringLiteral("anim.") +
                                                 model::exportFormatSuffix(ExportFormat(format)));
    model::ExportOptions o = optionsFor(ExportFormat(format), target);
    o.scale = 1; // every output is larger than the limit
    Expected<model::ExportResult, model::ExportError> result =
        unexpected(model::ExportError{model::ExportErrorCode::BadOptions, {}, {}});
    {
        // ffmpeg inherits the limit: its writes fail part-way, as on a full disk.
        FileSizeLimit limit(16 * 1024);
        QVERIFY(limit.ok());
        result = model::exportAnimation(m_source, o);
    }
    QVERIFY(!result);
    qInfo("%s | %s", qPrintable(result.error().message), qPrintable(result.error().detail));
    QVERIFY(result.error().code == model::ExportErrorCode::EncoderFailed ||
            result.error().code == model::ExportErrorCode::WriteFailed);
    QCOMPARE(filesIn(folder), QStringList());
}

void TestExportFfmpeg::cancelLeavesNothing()
{
    if (program("ffmpeg").isEmpty())
        QSKIP("ffmpeg not installed");
    const QString folder = m_dir.filePath(QStringLiteral("cancel"));
    QVERIFY(QDir().mkpath(folder));
    for (ExportFormat format : {ExportFormat::Gif, ExportFormat::Mp4, ExportFormat::WebM}) {
        int calls = 0;
        const QString target =
            QDir(folder).filePath(QStringLiteral("anim.") + model::exportFormatSuffix(format));
        const auto result = model::exportAnimation(m_source, optionsFor(format, target),
                                                   [&](qint64, qint64) { return ++calls < 5; });
        QVERIFY(!result);
        QCOMPARE(result.error().code, model::ExportErrorCode::Cancelled);
        QCOMPARE(filesIn(folder), QStringList());
    }
}

// An encoder that never reads its input, or reads it all and never exits, used to make the
// export wait for ever. With no progress for the timeout ($FINBOOK_ENCODER_TIMEOUT, 2 s here)
// it is killed and the export fails, leaving nothing.
void TestExportFfmpeg::stuckEncoderIsStopped()
{
    const QString deaf = writeScript(m_dir, QStringLiteral("ffmpeg-deaf"), "exec sleep 600\n");
    const QString mute =
        writeScript(m_dir, QStringLiteral("ffmpeg-mute"), "cat > /dev/null\nexec sleep 600\n");
    const QString folder = m_dir.filePath(QStringLiteral("stuck"));
    QVERIFY(QDir().mkpath(folder));
    qputenv("FINBOOK_ENCODER_TIMEOUT", "2");
    for (const QString &encoder : {deaf, mute}) {
        FfmpegOverride stuck(encoder);
        QElapsedTimer clock;
        clock.start();
        const auto result = model::exportAnimation(
            m_source,
            optionsFor(ExportFormat::Mp4, QDir(folder).filePath(QStringLiteral("a.mp4"))));
        qInfo("%s: stopped after %.1f s", qPrintable(QFileInfo(encoder).fileName()),
              clock.elapsed() / 1000.0);
        QVERIFY(!result);
        QCOMPARE(result.error().code, model::ExportErrorCode::EncoderFailed);
        QVERIFY2(result.error().message.contains(QLatin1String("no progress")),
                 qPrintable(result.error().message));
        QCOMPARE(filesIn(folder), QStringList());
    }
    qunsetenv("FINBOOK_ENCODER_TIMEOUT");
}

// A GIF used to be one ffmpeg run whose graph split the frames into palettegen and paletteuse:
// every frame stayed buffered until palettegen had seen the last (2.4 GB for 2,000 frames at
// 640×480). Now a first run only writes the palette and a second reads it: neither graph
// splits the stream, and each names the palette on its side.
void TestExportFfmpeg::gifRunsKeepNoFrames()
{
    const QString list = QStringLiteral("/tmp/.anim.gif.ghijkl.part/drawings.ffconcat");
    for (const bool holds : {true, false}) {
        model::ExportSource source = m_source;
        if (!holds)
            for (model::Frame &frame : source.frames)
                frame.hold = 1;
        const auto plan = model::planExport(source, optionsFor(ExportFormat::Gif, QString()));
        QVERIFY(plan);
        QCOMPARE(model::holdsVary(plan->holds), holds);
        const QString palette = QStringLiteral("/tmp/.anim.gif.abcdef.part");
        const model::FfmpegJob job =
            model::ffmpegJob(ExportFormat::Gif, *plan, QStringLiteral("file:/tmp/out"), palette,
                             QString(), holds ? list : QString());
        QCOMPARE(job.perTick, !holds);
        const QString first = job.paletteArguments.join(QLatin1Char(' '));
        const QString second = job.arguments.join(QLatin1Char(' '));
        for (const QString &run : {first, second}) {
            QVERIFY2(!run.contains(QLatin1String("split")), qPrintable(run));
            // Held drawings are files with their durations; otherwise every tick is piped.
            QVERIFY2(run.contains(holds ? QStringLiteral("-f concat -safe 0 -i file:") + list
                                        : QStringLiteral("-i pipe:0")),
                     qPrintable(run));
            // No expression that grows with the drawings (ffmpeg failed past ~100 of them).
            QVERIFY2(!run.contains(QLatin1String("setpts")) && !run.contains(QLatin1String("gt(N")),
                     qPrintable(run));
        }
        QVERIFY2(first.contains(QLatin1String("palettegen")) &&
                     !first.contains(QLatin1String("paletteuse")),
                 qPrintable(first));
        QVERIFY2(second.contains(QLatin1String("paletteuse")) &&
                     !second.contains(QLatin1String("palettegen")),
                 qPrintable(second));
        QCOMPARE(job.paletteArguments.last(), QStringLiteral("file:") + palette);
        QVERIFY2(second.contains(QStringLiteral("-i file:") + palette), qPrintable(second));
        QCOMPARE(job.arguments.last(), QStringLiteral("file:/tmp/out"));
    }
    // The list: each drawing once with its hold in seconds; a quote in a name stays inside it.
    const QByteArray text = model::concatList({2, 1, 3}, 12, [](std::size_t i) {
        return i == 1 ? QStringLiteral("it's.png") : QStringLiteral("d%1.png").arg(i);
    });
    QCOMPARE(text, QByteArray("ffconcat version 1.0\n"
                              "file 'd0.png'\noption framerate 1000\nduration 0.166666667\n"
                              "file 'it'\\''s.png'\noption framerate 1000\nduration 0.083333333\n"
                              "file 'd2.png'\noption framerate 1000\nduration 0.250000000\n"));
    // The other formats are one run.
    const auto plan = model::planExport(m_source, optionsFor(ExportFormat::Mp4, QString()));
    QVERIFY(plan);
    QVERIFY(
        model::ffmpegJob(ExportFormat::Mp4, *plan, QStringLiteral("x")).paletteArguments.isEmpty());
}

// 1,000 drawings on twos (a normal 2'47" shot at 12 fps) in every encoded format: the GIF
// failed past about 100 held drawings ("Cannot allocate memory": the timing expression grew
// with them). GIF: each drawing one frame of its hold; the others one frame per tick. And the
// command line is the same length for 10 drawings as for 1,000.
void TestExportFfmpeg::thousandDrawingsOnTwos_data()
{
    QTest::addColumn<int>("format");
    QTest::addColumn<int>("frames");
    QTest::newRow("gif") << int(ExportFormat::Gif) << 1000;
    QTest::newRow("mp4") << int(ExportFormat::Mp4) << 2000;
    QTest::newRow("webm") << int(ExportFormat::WebM) << 2000;
    QTest::newRow("apng") << int(ExportFormat::Apng) << 2000;
}

void TestExportFfmpeg::thousandDrawingsOnTwos()
{
    if (program("ffmpeg").isEmpty() || program("ffprobe").isEmpty())
        QSKIP("ffmpeg/ffprobe not installed");
    QFETCH(int, format);
    QFETCH(int, frames);
    model::ExportSource source{{}, m_source.settings, {}};
    for (int i = 0; i < 1000; ++i) {
        source.frames.push_back(m_source.frames[std::size_t(i) % m_source.frames.size()]);
        source.frames.back().hold = 2;
    }
    model::ExportOptions o = optionsFor(ExportFormat(format), QString());
    o.scale = 0.05; // 64 × 36: the timing is what is checked
    o.firstFrame = 0;
    o.lastFrame = 999;
    o.target = m_dir.filePath(
        QStringLiteral("twos.%1").arg(model::exportFormatSuffix(ExportFormat(format))));
    const auto result = model::exportAnimation(source, o);
    QVERIFY2(result, result ? ""
                            : qPrintable(result.error().message + QLatin1Char('\n') +
                                         result.error().detail));
    const QString path = o.target;
    QString error;
    const QJsonObject stream = probe(path, &error);
    QVERIFY2(!stream.isEmpty(), qPrintable(error));
    QCOMPARE(stream[QStringLiteral("nb_read_frames")].toString().toInt(), frames);
    const std::vector<double> durations = frameDurations(path);
    QCOMPARE(int(durations.size()), frames);
    double total = 0;
    for (double d : durations) {
        QVERIFY2(std::abs(d - 2000.0 / frames / kFps) <= 0.0101, qPrintable(QString::number(d)));
        total += d;
    }
    // On time at the end: GIF centiseconds do not add up their rounding. (WebM gives each
    // frame a whole number of milliseconds, 83 for 1/12 s, while its timestamps stay exact:
    // its container's duration is the one to check.)
    if (ExportFormat(format) == ExportFormat::WebM)
        total = probedDuration(stream);
    QVERIFY2(std::abs(total - 2000 / kFps) <= 0.0101, qPrintable(QString::number(total)));
    for (const QString &file : filesIn(m_dir.path()))
        QVERIFY2(!file.endsWith(QLatin1String(".part")), qPrintable(file));

    model::ExportSource ten{{}, source.settings, {}};
    ten.frames.assign(source.frames.begin(), source.frames.begin() + 10);
    model::ExportOptions tenOptions = o;
    tenOptions.lastFrame = 9;
    const auto small = model::planExport(ten, tenOptions), large = model::planExport(source, o);
    QVERIFY(small && large);
    const auto length = [&](const model::ExportPlan &plan) {
        const QString list =
            model::holdsVary(plan.holds) && ExportFormat(format) == ExportFormat::Gif
                ? QStringLiteral("/tmp/list.ffconcat")
                : QString();
        const model::FfmpegJob job =
            model::ffmpegJob(ExportFormat(format), plan, QStringLiteral("file:/tmp/out"),
                             QStringLiteral("/tmp/palette"), {}, list);
        return (job.arguments + job.paletteArguments).join(QLatin1Char(' ')).size();
    };
    QCOMPARE(length(*large), length(*small));
}

// 1,000 drawings at 640×480 with ffmpeg limited to 600 MB of address space: the frames alone
// are 1.2 GB, so the single run that buffered them failed; the two runs succeed and the GIF
// holds every frame at its size.
void TestExportFfmpeg::longGifInBoundedMemory()
{
    if (program("ffmpeg").isEmpty() || program("ffprobe").isEmpty())
        QSKIP("ffmpeg/ffprobe not installed");
    const QString limited = writeScript(m_dir, QStringLiteral("ffmpeg-600mb"),
                                        "ulimit -v 600000 || exit 9\nexec ffmpeg \"$@\"\n");
    model::ExportSource source{{}, m_source.settings, {}};
    source.settings.canvasSize = QSize(640, 480);
    for (int i = 0; i < 1000; ++i) {
        source.frames.push_back(m_source.frames[std::size_t(i) % m_source.frames.size()]);
        source.frames.back().hold = 1;
    }
    model::ExportOptions o =
        optionsFor(ExportFormat::Gif, m_dir.filePath(QStringLiteral("long.gif")));
    o.scale = 1;
    o.firstFrame = 0;
    o.lastFrame = 999;
    qint64 lastDone = 0, lastTotal = 0;
    Expected<model::ExportResult, model::ExportError> result =
        unexpected(model::ExportError{model::ExportErrorCode::BadOptions, {}, {}});
    {
        FfmpegOverride override(limited);
        result = model::exportAnimation(source, o, [&](qint64 done, qint64 total) {
            lastDone = done;
            lastTotal = total;
            return true;
        });
    }
    QVERIFY2(result, result ? ""
                            : qPrintable(result.error().message + QLatin1Char('\n') +
                                         result.error().detail));
    // Progress runs over both passes, to its end.
    QCOMPARE(lastTotal, qint64(2000));
    QCOMPARE(lastDone, qint64(2000));
    QString error;
    const QJsonObject stream = probe(o.target, &error);
    QVERIFY2(!stream.isEmpty(), qPrintable(error));
    QCOMPARE(stream[QStringLiteral("codec_name")].toString(), QStringLiteral("gif"));
    QCOMPARE(stream[QStringLiteral("width")].toInt(), 640);
    QCOMPARE(stream[QStringLiteral("height")].toInt(), 480);
    QCOMPARE(stream[QStringLiteral("nb_read_frames")].toString().toInt(), 1000);
    // Neither the palette nor the output's temporary stays beside it.
    for (const QString &file : filesIn(m_dir.path()))
        QVERIFY2(!file.endsWith(QLatin1String(".part")), qPrintable(file));
}

QTEST_GUILESS_MAIN(TestExportFfmpeg)
#include "tst_export_ffmpeg.moc"
