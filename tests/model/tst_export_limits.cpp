// Export bombs: small documents that ask for huge work. Holds worth millions of ticks (refused
// beyond the limits, planned without memory per tick), one stroke referenced thousands of
// times in an SVG (written once), points near 1e30 (clipped in floating point, drawn the
// right way in every renderer).
#include "export_support.h"

#include <finbook/model/export/export_plan.h>
#include <finbook/model/export/exporter.h>
#include <finbook/model/render.h>

#include <QFile>
#include <QPainter>
#include <QRegularExpression>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QtTest>

#include <sys/resource.h>

using namespace finbook;
using namespace finbook::test;
using namespace finbook::model;

namespace {

ExportOptions optionsFor(ExportFormat format, const QString &target)
{
    ExportOptions o;
    o.format = format;
    o.target = target;
    return o;
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

StrokeDataPtr strokeOf(std::vector<StrokePoint> points, QRgb color = 0xff203040, float width = 6)
{
    auto data = std::make_shared<StrokeData>();
    data->points = std::move(points);
    data->color = color;
    data->width = width;
    return data;
}

ExportSource sourceWith(std::vector<StrokeDataPtr> strokes, QSize size = QSize(100, 100))
{
    Frame frame;
    frame.id = 1;
    StrokeGroup g;
    g.id = 2;
    Id next = 3;
    for (StrokeDataPtr &s : strokes)
        g.strokes.push_back({next++, std::move(s)});
    frame.groups.push_back(std::move(g));
    ExportSource source;
    source.frames.push_back(std::move(frame));
    source.settings.canvasSize = size;
    source.settings.background = 0xffffffff;
    return source;
}

// `frames` drawings held 1000 ticks each.
ExportSource heldFor(int frames)
{
    ExportSource source = sourceWith({strokeOf({{10, 10, 1}, {90, 90, 1}})});
    source.frames.front().hold = 1000;
    source.frames.resize(std::size_t(frames), source.frames.front());
    for (int i = 0; i < frames; ++i)
        source.frames[std::size_t(i)].id = Id(100 + i);
    source.settings.playEnd = -1;
    return source;
}

long peakMiB()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024;
}

int maxChannelDifference(const QImage &a, const QImage &b)
{
    const QImage x = a.convertToFormat(QImage::Format_RGBA8888);
    const QImage y = b.convertToFormat(QImage::Format_RGBA8888);
    if (x.size() != y.size())
        return 256;
    int worst = 0;
    for (int row = 0; row < x.height(); ++row) {
        const uchar *p = x.constScanLine(row), *q = y.constScanLine(row);
        for (int i = 0; i < x.width() * 4; ++i)
            worst = std::max(worst, std::abs(int(p[i]) - int(q[i])));
    }
    return worst;
}

QImage renderSvg(const QByteArray &svg, QSize size)
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QSvgRenderer renderer(svg);
    QPainter painter(&image);
    renderer.render(&painter);
    return image;
}

} // namespace

class TestExportLimits : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }
    void longExportsNeedPermission();
    void planningCostsNothingPerTick();
    void repeatedStrokeIsWrittenOnceInSvg();
    void farPointsDrawTheRightWay_data();
    void farPointsDrawTheRightWay();
    void farPointsKeepSvgNumbersSmall();

private:
    QTemporaryDir m_dir;
};

// 101 drawings held 1,000 ticks: 101,000 PNG files, or 2.3 hours of GIF at 12 fps.
void TestExportLimits::longExportsNeedPermission()
{
    const ExportSource source = heldFor(101);
    ExportOptions png = optionsFor(ExportFormat::PngSequence, m_dir.filePath(QStringLiteral("p")));
    const auto plan = planExport(source, png);
    QVERIFY(plan);
    QCOMPARE(exportFrameCount(*plan, png), qint64(101000));
    const auto refused = exportAnimation(source, png);
    QVERIFY(!refused);
    QCOMPARE(refused.error().code, ExportErrorCode::TooLarge);
    QVERIFY2(refused.error().message.contains(QLatin1String("101000")),
             qPrintable(refused.error().message));
    QVERIFY(!QFileInfo::exists(png.target));
    QVERIFY(exportTargetFiles(source, png).isEmpty());
    png.maxFrames = 101000;
    QVERIFY(!checkExportSize(*plan, png));
    png.maxFrames = 100999;
    QCOMPARE(checkExportSize(*plan, png)->code, ExportErrorCode::TooLarge);
    png.maxFrames = 0;
    png.onePerDrawing = true; // 101 drawings + the sheet
    QVERIFY(!checkExportSize(*plan, png));

    // Video: the duration counts. 2.3 hours pass; at 1 fps (28 hours) they do not.
    ExportOptions gif = optionsFor(ExportFormat::Gif, m_dir.filePath(QStringLiteral("g.gif")));
    QVERIFY(!checkExportSize(*planExport(source, gif), gif));
    gif.fps = 1;
    QCOMPARE(checkExportSize(*planExport(source, gif), gif)->code, ExportErrorCode::TooLarge);
    gif.maxFrames = 101000;
    QVERIFY(!checkExportSize(*planExport(source, gif), gif));
}

// 5,000 drawings held 1,000 ticks each: five million files. Allowed explicitly and cancelled
// at the first file, the export must not have made a name (or anything) per tick first: it
// used to build every file name up front, hundreds of megabytes before the first PNG.
void TestExportLimits::planningCostsNothingPerTick()
{
    const ExportSource source = heldFor(5000);
    ExportOptions o = optionsFor(ExportFormat::PngSequence, m_dir.filePath(QStringLiteral("five")));
    o.maxFrames = qint64(1) << 40;
    const long before = peakMiB();
    qint64 seenTotal = 0;
    const auto result = exportAnimation(source, o, [&](qint64, qint64 total) {
        seenTotal = total;
        return false;
    });
    const long grown = peakMiB() - before;
    qInfo("5,000,000-tick PNG export cancelled at the first file: peak grew by %ld MiB", grown);
    QVERIFY(!result);
    QCOMPARE(result.error().code, ExportErrorCode::Cancelled);
    QCOMPARE(seenTotal, qint64(5000000));
    QVERIFY2(grown < 64, qPrintable(QString::number(grown)));
    QCOMPARE(filesIn(m_dir.path()), QStringList());
}

// One stroke referenced 10,000 times used to be written out 10,000 times (870 MB per frame
// for the file); now its outline is written once and placed with <use>.
void TestExportLimits::repeatedStrokeIsWrittenOnceInSvg()
{
    std::vector<StrokePoint> points;
    for (int i = 0; i < 200; ++i)
        points.push_back({float(10 + (i * 7) % 80), float(10 + (i * 13) % 80), 1.0f});
    const StrokeDataPtr shared = strokeOf(points);
    const ExportSource many = sourceWith(std::vector<StrokeDataPtr>(10000, shared));
    const ExportSource one = sourceWith({shared});
    const QString folder = m_dir.filePath(QStringLiteral("svg"));
    const QString single = m_dir.filePath(QStringLiteral("svg1"));
    QVERIFY(exportAnimation(many, optionsFor(ExportFormat::SvgSequence, folder)));
    QVERIFY(exportAnimation(one, optionsFor(ExportFormat::SvgSequence, single)));
    const QByteArray svg = readAll(QDir(folder).filePath(QStringLiteral("frame_0001.svg")));
    const QByteArray path = readAll(QDir(single).filePath(QStringLiteral("frame_0001.svg")));
    qInfo("10,000 references: %lld bytes (one reference: %lld)", qint64(svg.size()),
          qint64(path.size()));
    QVERIFY2(svg.size() < path.size() + 10000 * 80, qPrintable(QString::number(svg.size())));
    QCOMPARE(svg.count("<use "), 10000);
    // Drawn like the plain path: coats of opaque ink only darken its antialiased rim (no ink
    // lost, none far from the stroke). (A
    // hundred references: the renderer's time is not what is tested.)
    const QString hundred = m_dir.filePath(QStringLiteral("svg100"));
    QVERIFY(exportAnimation(sourceWith(std::vector<StrokeDataPtr>(100, shared)),
                            optionsFor(ExportFormat::SvgSequence, hundred)));
    const QByteArray used = readAll(QDir(hundred).filePath(QStringLiteral("frame_0001.svg")));
    QVERIFY(QSvgRenderer(used).isValid());
    const QImage a = renderSvg(used, QSize(100, 100)), b = renderSvg(path, QSize(100, 100));
    int wrong = 0;
    for (int y = 0; y < 100; ++y)
        for (int x = 0; x < 100; ++x) {
            const int coated = qGray(a.pixel(x, y)), once = qGray(b.pixel(x, y));
            wrong += (once < 128 && coated >= 128) || (once == 255 && coated < 128);
        }
    QCOMPARE(wrong, 0);
}

void TestExportLimits::farPointsDrawTheRightWay_data()
{
    QTest::addColumn<bool>("farFirst");
    QTest::newRow("far end first") << true;
    QTest::newRow("far end last") << false;
}

// A segment from (50, 50) towards a point near (1e30, 5e29) leaves the canvas along the
// direction (2, 1). Clipping it from the far end used to lose every digit that matters on the
// canvas: the piece drawn pointed elsewhere (or vanished). It must look like the segment to
// (250, 150), which goes the same way.
void TestExportLimits::farPointsDrawTheRightWay()
{
    QFETCH(bool, farFirst);
    std::vector<StrokePoint> far{{1e30f, 5e29f, 1}, {50, 50, 1}};
    std::vector<StrokePoint> near{{250, 150, 1}, {50, 50, 1}};
    if (!farFirst) {
        std::reverse(far.begin(), far.end());
        std::reverse(near.begin(), near.end());
    }
    const ExportSource a = sourceWith({strokeOf(far)}), b = sourceWith({strokeOf(near)});
    const QImage farImage = renderFrame(a.frames[0], a.settings, QSize(100, 100));
    const QImage nearImage = renderFrame(b.frames[0], b.settings, QSize(100, 100));
    QVERIFY(qAlpha(nearImage.pixel(80, 65)) > 200); // on the way to (250, 150)
    QVERIFY(maxChannelDifference(farImage, nearImage) <= 2);
}

// The SVG of the same segment held "-92233720368547758.08" (a rounding overflow): its numbers
// stay near the canvas and it draws like the near segment.
void TestExportLimits::farPointsKeepSvgNumbersSmall()
{
    const ExportSource a = sourceWith({strokeOf({{1e30f, 5e29f, 1}, {50, 50, 1}})});
    const ExportSource b = sourceWith({strokeOf({{250, 150, 1}, {50, 50, 1}})});
    const QString farFolder = m_dir.filePath(QStringLiteral("farsvg"));
    const QString nearFolder = m_dir.filePath(QStringLiteral("nearsvg"));
    QVERIFY(exportAnimation(a, optionsFor(ExportFormat::SvgSequence, farFolder)));
    QVERIFY(exportAnimation(b, optionsFor(ExportFormat::SvgSequence, nearFolder)));
    const QByteArray farSvg = readAll(QDir(farFolder).filePath(QStringLiteral("frame_0001.svg")));
    const QByteArray nearSvg = readAll(QDir(nearFolder).filePath(QStringLiteral("frame_0001.svg")));
    static const QRegularExpression number(QStringLiteral("-?[0-9]+(\\.[0-9]+)?"));
    for (auto it = number.globalMatch(QString::fromUtf8(farSvg)); it.hasNext();) {
        const double value = it.next().captured().toDouble();
        QVERIFY2(std::abs(value) < 1e6, qPrintable(QString::number(value, 'g', 17)));
    }
    QVERIFY(maxChannelDifference(renderSvg(farSvg, QSize(100, 100)),
                                 renderSvg(nearSvg, QSize(100, 100))) <= 8);
}

QTEST_GUILESS_MAIN(TestExportLimits)
#include "tst_export_limits.moc"
