// Exports that need no other program: the plan (holds, range, scale, rate), PNG and SVG
// sequences, the HTML flipbook's self-containment, and the promises of every export — nothing
// at the target after a refusal, a cancel or a failing disk.
#include "export_support.h"

#include <finbook/model/export/export_plan.h>
#include <finbook/model/export/exporter.h>

#include <QFile>
#include <QJsonArray>
#include <QPainter>
#include <QRegularExpression>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <limits>
#include <sys/resource.h>

using namespace finbook;
using namespace finbook::test;
using model::ExportFormat;

namespace {

model::ExportOptions optionsFor(ExportFormat format, const QString &target)
{
    model::ExportOptions o;
    o.format = format;
    o.target = target;
    return o;
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Files bigger than `bytes` cannot be written while this lives (RLIMIT_FSIZE, SIGXFSZ
// ignored so write() fails with EFBIG): a disk that fills up part-way through a file.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes)
    {
        m_previousHandler = std::signal(SIGXFSZ, SIG_IGN);
        getrlimit(RLIMIT_FSIZE, &m_saved);
        rlimit limit = m_saved;
        limit.rlim_cur = bytes;
        m_ok = setrlimit(RLIMIT_FSIZE, &limit) == 0;
    }
    ~FileSizeLimit()
    {
        setrlimit(RLIMIT_FSIZE, &m_saved);
        std::signal(SIGXFSZ, m_previousHandler);
    }
    bool ok() const { return m_ok; }

private:
    rlimit m_saved{};
    void (*m_previousHandler)(int) = nullptr;
    bool m_ok = false;
};

} // namespace

class TestExport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void planFollowsHoldsRangeAndScale();
    void badOptionsAreRefused_data();
    void badOptionsAreRefused();
    void pngSequenceRepeatsHeldFrames();
    void onePerDrawingWritesAnExposureSheet();
    void backgroundAndTransparency();
    void existingFilesNeedOverwrite();
    void cancelLeavesNothing_data();
    void cancelLeavesNothing();
    void failingDiskLeavesNothing_data();
    void failingDiskLeavesNothing();
    void svgMatchesPng();
    void htmlIsSelfContained();

private:
    model::ExportSource m_source;
    QTemporaryDir m_dir;
};

void TestExport::initTestCase()
{
    m_source = exampleWithHolds();
    QVERIFY2(m_source.frames.size() == 12, "the example has 12 frames");
    QVERIFY(m_dir.isValid());
}

void TestExport::planFollowsHoldsRangeAndScale()
{
    const auto plan = model::planExport(m_source, optionsFor(ExportFormat::Gif, QString()));
    QVERIFY(plan);
    QCOMPARE(plan->frames.size(), std::size_t(12));
    QCOMPARE(plan->ticks, ticksOf(m_source, 0, 11));
    QCOMPARE(plan->ticks, qint64(18));
    QCOMPARE(plan->holds[2], 3);
    QCOMPARE(plan->size, m_source.settings.canvasSize);
    QCOMPARE(plan->fps, m_source.settings.fps);
    QCOMPARE(plan->loop, m_source.settings.loop);
    QCOMPARE(model::playbackTicks(m_source.frames, m_source.settings), plan->ticks);

    // The play range is the default; an explicit range replaces it.
    model::ExportSource ranged = m_source;
    ranged.settings.playStart = 2;
    ranged.settings.playEnd = 7;
    auto byPlayRange = model::planExport(ranged, optionsFor(ExportFormat::Gif, QString()));
    QVERIFY(byPlayRange);
    QCOMPARE(byPlayRange->frames.front(), 2);
    QCOMPARE(byPlayRange->ticks, ticksOf(m_source, 2, 7));
    model::ExportOptions o = optionsFor(ExportFormat::Mp4, QString());
    o.firstFrame = 1;
    o.lastFrame = 3;
    o.scale = 1.0 / 3;
    o.fps = 24;
    o.loop = !m_source.settings.loop;
    auto custom = model::planExport(ranged, o);
    QVERIFY(custom);
    QCOMPARE(custom->frames, (std::vector<int>{1, 2, 3}));
    QCOMPARE(custom->ticks, qint64(1 + 3 + 1));
    QCOMPARE(custom->fps, 24);
    QCOMPARE(custom->loop, o.loop.value());
    // 1280/3 = 426.7 and 720/3 = 240: rounded, and even for video.
    QCOMPARE(custom->size, QSize(426, 240));
    o.scale = 0.3;
    o.format = ExportFormat::Mp4;
    QCOMPARE(model::planExport(ranged, o)->size, QSize(384, 216));
    o.scale = 0.5007; // 640.9 x 360.5: 641 x 361 for PNG, the nearest even 640 x 360 for video
    QCOMPARE(model::planExport(ranged, o)->size, QSize(640, 360));
    o.format = ExportFormat::PngSequence;
    QCOMPARE(model::planExport(ranged, o)->size, QSize(641, 361));
}

void TestExport::badOptionsAreRefused_data()
{
    QTest::addColumn<int>("first");
    QTest::addColumn<int>("last");
    QTest::addColumn<double>("scale");
    QTest::addColumn<int>("fps");
    QTest::addColumn<int>("format");
    QTest::addColumn<bool>("transparent");
    const int png = int(ExportFormat::PngSequence);
    QTest::newRow("range past the end") << 3 << 12 << 1.0 << 0 << png << false;
    QTest::newRow("range backwards") << 5 << 4 << 1.0 << 0 << png << false;
    QTest::newRow("negative first") << -2 << 4 << 1.0 << 0 << png << false;
    QTest::newRow("zero scale") << -1 << -1 << 0.0 << 0 << png << false;
    QTest::newRow("negative scale") << -1 << -1 << -1.0 << 0 << png << false;
    QTest::newRow("NaN scale") << -1 << -1 << std::numeric_limits<double>::quiet_NaN() << 0 << png
                               << false;
    QTest::newRow("infinite scale")
        << -1 << -1 << std::numeric_limits<double>::infinity() << 0 << png << false;
    QTest::newRow("huge scale") << -1 << -1 << 100.0 << 0 << png << false;
    QTest::newRow("tiny scale") << -1 << -1 << 1e-6 << 0 << png << false;
    QTest::newRow("fps too high") << -1 << -1 << 1.0 << 61 << png << false;
    QTest::newRow("fps negative") << -1 << -1 << 1.0 << -5 << png << false;
    QTest::newRow("transparent MP4") << -1 << -1 << 1.0 << 0 << int(ExportFormat::Mp4) << true;
}

void TestExport::badOptionsAreRefused()
{
    QFETCH(int, first);
    QFETCH(int, last);
    QFETCH(double, scale);
    QFETCH(int, fps);
    QFETCH(int, format);
    QFETCH(bool, transparent);
    const QString target = m_dir.filePath(QStringLiteral("refused"));
    model::ExportOptions o = optionsFor(ExportFormat(format), target);
    o.firstFrame = first;
    o.lastFrame = last;
    o.scale = scale;
    o.fps = fps;
    o.transparent = transparent;
    const auto result = model::exportAnimation(m_source, o);
    QVERIFY(!result);
    QCOMPARE(result.error().code, model::ExportErrorCode::BadOptions);
    QVERIFY(!result.error().message.isEmpty());
    QVERIFY(!QFileInfo::exists(target));

    const auto empty = model::exportAnimation(model::ExportSource{}, o);
    QVERIFY(!empty);
    QCOMPARE(empty.error().code, model::ExportErrorCode::BadOptions);
    const auto noTarget = model::exportAnimation(m_source, optionsFor(ExportFormat::Gif, {}));
    QCOMPARE(noTarget.error().code, model::ExportErrorCode::BadOptions);
}

void TestExport::pngSequenceRepeatsHeldFrames()
{
    const QString folder = m_dir.filePath(QStringLiteral("png/nested"));
    qint64 calls = 0, lastDone = 0, lastTotal = 0;
    const auto result = model::exportAnimation(
        m_source, optionsFor(ExportFormat::PngSequence, folder), [&](qint64 done, qint64 total) {
            ++calls;
            lastDone = done;
            lastTotal = total;
            return true;
        });
    QVERIFY2(result, qPrintable(result ? QString() : result.error().message));
    QCOMPARE(result->ticks, qint64(18));
    QCOMPARE(result->files.size(), qsizetype(18));
    QCOMPARE(lastDone, lastTotal);
    QCOMPARE(calls, qint64(18));
    QCOMPARE(filesIn(folder).size(), qsizetype(18)); // no staging folder left over
    QCOMPARE(QFileInfo(result->files.first()).fileName(), QStringLiteral("frame_0001.png"));
    QCOMPARE(QFileInfo(result->files.last()).fileName(), QStringLiteral("frame_0018.png"));
    // Ticks 3-5 show frame 3 (held 3); tick 6 shows frame 4.
    const QByteArray third = readAll(result->files[2]);
    QCOMPARE(readAll(result->files[3]), third);
    QCOMPARE(readAll(result->files[4]), third);
    QVERIFY(readAll(result->files[5]) != third);
    QVERIFY(readAll(result->files[1]) != third);
    // Each image is the frame rendered at canvas size on the document's background.
    const QImage image(result->files[5]);
    QCOMPARE(image.size(), m_source.settings.canvasSize);
    QCOMPARE(image.pixel(0, 0) | 0xff000000u, m_source.settings.background | 0xff000000u);
    const auto plan = model::planExport(m_source, optionsFor(ExportFormat::PngSequence, folder));
    const QImage expected = model::renderExportFrame(m_source.frames[3], m_source.settings, *plan);
    QVERIFY(difference(image, expected).meanAbs < 0.01);
}

void TestExport::onePerDrawingWritesAnExposureSheet()
{
    const QString folder = m_dir.filePath(QStringLiteral("drawings"));
    model::ExportOptions o = optionsFor(ExportFormat::PngSequence, folder);
    o.onePerDrawing = true;
    o.firstFrame = 1;
    o.lastFrame = 8;
    const auto result = model::exportAnimation(m_source, o);
    QVERIFY(result);
    QCOMPARE(result->files.size(), qsizetype(8 + 1));
    QCOMPARE(QFileInfo(result->files.first()).fileName(), QStringLiteral("frame_0002.png"));
    const QJsonObject sheet =
        QJsonDocument::fromJson(
            readAll(QDir(folder).filePath(QStringLiteral("frame_exposures.json"))))
            .object();
    QCOMPARE(sheet[QStringLiteral("fps")].toInt(), m_source.settings.fps);
    QCOMPARE(sheet[QStringLiteral("ticks")].toInteger(), ticksOf(m_source, 1, 8));
    const QJsonArray frames = sheet[QStringLiteral("frames")].toArray();
    QCOMPARE(frames.size(), qsizetype(8));
    qint64 start = 0;
    for (int i = 0; i < 8; ++i) {
        const QJsonObject f = frames[i].toObject();
        QCOMPARE(f[QStringLiteral("frame")].toInt(), i + 2);
        QCOMPARE(f[QStringLiteral("hold")].toInt(), m_source.frames[std::size_t(i + 1)].hold);
        QCOMPARE(f[QStringLiteral("start_tick")].toInteger(), start);
        QVERIFY(QFileInfo::exists(QDir(folder).filePath(f[QStringLiteral("file")].toString())));
        start += f[QStringLiteral("hold")].toInt();
    }
}

void TestExport::backgroundAndTransparency()
{
    model::ExportOptions o =
        optionsFor(ExportFormat::PngSequence, m_dir.filePath(QStringLiteral("clear")));
    o.transparent = true;
    o.firstFrame = o.lastFrame = 0;
    auto clear = model::exportAnimation(m_source, o);
    QVERIFY(clear);
    const QImage transparent(clear->files.first());
    QCOMPARE(transparent.size(), m_source.settings.canvasSize);
    QVERIFY(transparent.hasAlphaChannel());
    QCOMPARE(qAlpha(transparent.pixel(0, 0)), 0);
    qint64 inked = 0;
    for (int y = 0; y < transparent.height(); ++y)
        for (int x = 0; x < transparent.width(); ++x)
            inked += qAlpha(transparent.pixel(x, y)) > 128;
    QVERIFY2(inked > 200, qPrintable(QString::number(inked)));

    o.transparent = false;
    o.background = qRgb(200, 30, 40);
    o.target = m_dir.filePath(QStringLiteral("red"));
    auto red = model::exportAnimation(m_source, o);
    QVERIFY(red);
    const QImage coloured(red->files.first());
    QCOMPARE(coloured.pixel(0, 0), qRgb(200, 30, 40));
    // Where the transparent image is fully inked, the coloured one shows the same ink.
    qint64 opaque = 0, sameInk = 0;
    for (int y = 0; y < coloured.height(); ++y)
        for (int x = 0; x < coloured.width(); ++x)
            if (qAlpha(transparent.pixel(x, y)) == 255) {
                ++opaque;
                sameInk += coloured.pixel(x, y) == transparent.pixel(x, y);
            }
    QVERIFY(opaque > 0);
    QVERIFY2(sameInk >= opaque * 95 / 100,
             qPrintable(QStringLiteral("%1 of %2").arg(sameInk).arg(opaque)));
}

void TestExport::existingFilesNeedOverwrite()
{
    const QString folder = m_dir.filePath(QStringLiteral("twice"));
    model::ExportOptions o = optionsFor(ExportFormat::PngSequence, folder);
    o.firstFrame = 0;
    o.lastFrame = 1;
    QVERIFY(model::exportAnimation(m_source, o));
    const QString first = QDir(folder).filePath(QStringLiteral("frame_0001.png"));
    QFile::remove(first);
    QFile marker(first);
    QVERIFY(marker.open(QIODevice::WriteOnly));
    marker.write("mine");
    marker.close();
    const auto refused = model::exportAnimation(m_source, o);
    QVERIFY(!refused);
    QCOMPARE(refused.error().code, model::ExportErrorCode::TargetExists);
    QCOMPARE(readAll(first), QByteArray("mine"));
    QCOMPARE(model::exportTargetFiles(m_source, o),
             (QStringList{QStringLiteral("frame_0001.png"), QStringLiteral("frame_0002.png")}));

    const QString html = m_dir.filePath(QStringLiteral("twice.html"));
    QFile existing(html);
    QVERIFY(existing.open(QIODevice::WriteOnly));
    existing.write("old");
    existing.close();
    model::ExportOptions h = optionsFor(ExportFormat::Html, html);
    QCOMPARE(model::exportAnimation(m_source, h).error().code,
             model::ExportErrorCode::TargetExists);
    QCOMPARE(readAll(html), QByteArray("old"));
    h.overwrite = true;
    QVERIFY(model::exportAnimation(m_source, h));
    QVERIFY(readAll(html).startsWith("<!DOCTYPE html>"));
    o.overwrite = true;
    QVERIFY(model::exportAnimation(m_source, o));
    QVERIFY(readAll(first).startsWith("\x89PNG"));
    // A folder where the file should go is refused, not replaced.
    h.target = folder;
    QCOMPARE(model::exportAnimation(m_source, h).error().code, model::ExportErrorCode::BadOptions);
}

void TestExport::cancelLeavesNothing_data()
{
    QTest::addColumn<int>("format");
    QTest::addColumn<QString>("name");
    QTest::newRow("png") << int(ExportFormat::PngSequence) << QStringLiteral("cancel/png");
    QTest::newRow("svg") << int(ExportFormat::SvgSequence) << QStringLiteral("cancel/svg");
    QTest::newRow("html") << int(ExportFormat::Html) << QStringLiteral("cancel/page.html");
}

void TestExport::cancelLeavesNothing()
{
    QFETCH(int, format);
    QFETCH(QString, name);
    const QString target = m_dir.filePath(name);
    int calls = 0;
    const auto result = model::exportAnimation(m_source, optionsFor(ExportFormat(format), target),
                                               [&](qint64, qint64) { return ++calls < 3; });
    QVERIFY(!result);
    QCOMPARE(result.error().code, model::ExportErrorCode::Cancelled);
    QCOMPARE(calls, 3);
    QVERIFY(!QFileInfo::exists(target));
    // The folders the export made for itself went with it.
    QVERIFY(!QFileInfo::exists(m_dir.filePath(QStringLiteral("cancel"))));
}

void TestExport::failingDiskLeavesNothing_data()
{
    QTest::addColumn<int>("format");
    QTest::addColumn<QString>("name");
    QTest::newRow("png") << int(ExportFormat::PngSequence) << QStringLiteral("full/png");
    QTest::newRow("svg") << int(ExportFormat::SvgSequence) << QStringLiteral("full/svg");
    QTest::newRow("html") << int(ExportFormat::Html) << QStringLiteral("full/page.html");
}

void TestExport::failingDiskLeavesNothing()
{
    QFETCH(int, format);
    QFETCH(QString, name);
    const QString target = m_dir.filePath(name);
    QVERIFY(QDir().mkpath(m_dir.filePath(QStringLiteral("full"))));
    Expected<model::ExportResult, model::ExportError> result =
        unexpected(model::ExportError{model::ExportErrorCode::BadOptions, {}, {}});
    {
        FileSizeLimit limit(8 * 1024); // every frame is larger than this
        QVERIFY(limit.ok());
        result = model::exportAnimation(m_source, optionsFor(ExportFormat(format), target));
    }
    QVERIFY(!result);
    QCOMPARE(result.error().code, model::ExportErrorCode::WriteFailed);
    QVERIFY2(result.error().message.contains(QLatin1String("Nothing was exported")),
             qPrintable(result.error().message));
    QVERIFY(!QFileInfo::exists(target));
    QCOMPARE(filesIn(m_dir.filePath(QStringLiteral("full"))), QStringList());
}

void TestExport::svgMatchesPng()
{
    const QString pngFolder = m_dir.filePath(QStringLiteral("cmp/png"));
    const QString svgFolder = m_dir.filePath(QStringLiteral("cmp/svg"));
    model::ExportOptions o = optionsFor(ExportFormat::PngSequence, pngFolder);
    o.onePerDrawing = true;
    QVERIFY(model::exportAnimation(m_source, o));
    o.format = ExportFormat::SvgSequence;
    o.target = svgFolder;
    const auto svgs = model::exportAnimation(m_source, o);
    QVERIFY(svgs);
    for (const char *frame : {"frame_0001", "frame_0007"}) {
        const QString svgPath =
            QDir(svgFolder).filePath(QLatin1String(frame) + QLatin1String(".svg"));
        const QByteArray svg = readAll(svgPath);
        // Vector strokes: filled paths, no embedded pixels, one path per visible stroke.
        QVERIFY(svg.contains("<path"));
        QVERIFY(!svg.contains("<image"));
        QVERIFY(svg.contains("width=\"1280\" height=\"720\" viewBox=\"0 0 1280 720\""));
        QSvgRenderer renderer(svgPath);
        QVERIFY(renderer.isValid());
        QImage rendered(m_source.settings.canvasSize, QImage::Format_ARGB32_Premultiplied);
        rendered.fill(Qt::transparent);
        QPainter painter(&rendered);
        renderer.render(&painter);
        painter.end();
        const QImage png(QDir(pngFolder).filePath(QLatin1String(frame) + QLatin1String(".png")));
        const ImageDifference d = difference(rendered, png);
        qInfo("%s: SVG vs PNG mean difference %.3f / 255, %.4f %% of pixels off by > 64", frame,
              d.meanAbs, d.farFraction * 100);
        QVERIFY2(d.meanAbs < 1.0, qPrintable(QString::number(d.meanAbs)));
        QVERIFY2(d.farFraction < 0.003, qPrintable(QString::number(d.farFraction)));
        // and it is a drawing: most pixels are background, a good few are ink.
        QImage background(png.size(), QImage::Format_ARGB32);
        background.fill(QColor::fromRgba(m_source.settings.background));
        const ImageDifference blank = difference(png, background);
        QVERIFY(blank.meanAbs > 10 * d.meanAbs);
    }
    // Twice the scale: twice the pixel size, the same drawing space.
    o.scale = 2;
    o.target = m_dir.filePath(QStringLiteral("cmp/svg2"));
    o.firstFrame = o.lastFrame = 0;
    const auto big = model::exportAnimation(m_source, o);
    QVERIFY(big);
    QSvgRenderer renderer(big->files.first());
    QCOMPARE(renderer.defaultSize(), QSize(2560, 1440));
    QCOMPARE(renderer.viewBoxF(), QRectF(0, 0, 1280, 720));
}

void TestExport::htmlIsSelfContained()
{
    const QString path = m_dir.filePath(QStringLiteral("book.html"));
    model::ExportOptions o = optionsFor(ExportFormat::Html, path);
    o.scale = 0.5;
    o.title = QStringLiteral("Walk <cycle> & \"friends\"");
    const auto result = model::exportAnimation(m_source, o);
    QVERIFY(result);
    const QByteArray html = readAll(path);
    // Every drawing embedded once; its holds and the frame rate beside them.
    QCOMPARE(html.count("data:image/png;base64,"), qsizetype(12));
    QVERIFY(html.contains("const fps = 12;"));
    QVERIFY(html.contains("const holds = [1,1,3,1,1,1,1,2,1,1,1,4];"));
    QVERIFY(html.contains("width=\"640\" height=\"360\""));
    QVERIFY(html.contains("<title>Walk &lt;cycle&gt; &amp; &quot;friends&quot;</title>"));
    // Nothing to fetch: no URL, no external script, style or image, and a policy forbidding it.
    QVERIFY(!html.contains("http://") && !html.contains("https://"));
    QVERIFY(!QRegularExpression(QStringLiteral("<(script|img|link|iframe)[^>]*(src|href)="))
                 .match(QString::fromUtf8(html))
                 .hasMatch());
    QVERIFY(html.contains("default-src 'none'"));
    for (const char *control : {"id=\"play\"", "id=\"loop\" type=\"checkbox\" checked",
                                "id=\"scrub\" type=\"range\"", "id=\"stage\""})
        QVERIFY2(html.contains(control), control);
    // The embedded images are the frames at the chosen scale.
    const int at = int(html.indexOf("data:image/png;base64,")) + 22;
    const QByteArray first = QByteArray::fromBase64(html.mid(at, html.indexOf('"', at) - at));
    QCOMPARE(QImage::fromData(first, "PNG").size(), QSize(640, 360));
}

QTEST_GUILESS_MAIN(TestExport)
#include "tst_export.moc"
