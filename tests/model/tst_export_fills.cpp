// Fills in every export: SVG (parsed: filled paths under the strokes, the region's area), PNG,
// GIF, MP4, WebM, APNG (decoded by ffmpeg) and the HTML page (in headless Chromium). Two frames:
// a filled square at rest, and the same square posed by pins (the fill moved with it).
#include "export_support.h"
#include "fill_support.h"

#include <finbook/model/deform_setup.h>
#include <finbook/model/fill/fill_commands.h>

#include <QPainter>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QUrl>
#include <QXmlStreamReader>
#include <QtTest>

using namespace finbook;
using namespace finbook::model;
using namespace finbook::test;

namespace {
constexpr QRgb kRed = 0xffe03020;
const QPointF kShift(150, 40); // where the pins move the square in frame 2

// Frame 1: a red square at (100, 100, 100, 100); frame 2: its copy posed kShift away.
ExportSource filledSource()
{
    Document doc;
    const Id g = testing::squareDocument(doc);
    doc.undoStack()->push(fillRegionCommand(&doc, g, QPointF(150, 150), kRed).release());
    doc.undoStack()->push(new DuplicateFrameCommand(&doc, doc.frameAt(0).id, 1));
    const Id copy = doc.frameAt(1).groups.at(0).id;
    Rig rig;
    rig.pins = {{1, QPointF(100, 100), QPointF(100, 100) + kShift},
                {2, QPointF(200, 200), QPointF(200, 200) + kShift}};
    doc.setRig(copy, rig);
    DeformJob job;
    job.groupId = copy;
    job.key = MeshKey::of(*doc.group(copy), -1.0);
    job.rig = rig.atRest();
    const auto setup = buildDeformSetup(job);
    if (setup)
        if (const auto pose = solvePose(**setup, *doc.group(copy)))
            doc.setDeformed(copy, pose->strokes);
    DocumentSettings s = doc.settings();
    s.canvasSize = QSize(400, 300);
    return ExportSource{doc.frames(), s, {}};
}

bool nearColor(QRgb a, QRgb b, int tolerance = 24)
{
    return std::abs(qRed(a) - qRed(b)) <= tolerance &&
           std::abs(qGreen(a) - qGreen(b)) <= tolerance &&
           std::abs(qBlue(a) - qBlue(b)) <= tolerance;
}

// The polygon area of an SVG path made of M, L and Z only (the fill paths are).
double pathArea(const QString &d)
{
    double area = 0;
    QPolygonF ring;
    const auto close = [&] {
        for (qsizetype i = 0; i < ring.size(); ++i) {
            const QPointF a = ring[i], b = ring[(i + 1) % ring.size()];
            area += a.x() * b.y() - b.x() * a.y();
        }
        ring.clear();
    };
    QString number;
    std::vector<double> values;
    const auto flush = [&] {
        if (!number.isEmpty())
            values.push_back(number.toDouble());
        number.clear();
        if (values.size() == 2) {
            ring << QPointF(values[0], values[1]);
            values.clear();
        }
    };
    for (const QChar c : d) {
        if (c == QLatin1Char('M') || c == QLatin1Char('L')) {
            flush();
        } else if (c == QLatin1Char('Z')) {
            flush();
            close();
        } else if (c == QLatin1Char(' ')) {
            flush();
        } else {
            number += c;
        }
    }
    return std::abs(area) / 2;
}
} // namespace

class TestExportFills : public QObject {
    Q_OBJECT
private slots:
    void svgHasFillPathsUnderStrokes();
    void rasterFormatsShowFills_data();
    void rasterFormatsShowFills();
    void htmlShowsFillsInChromium();
};

void TestExportFills::svgHasFillPathsUnderStrokes()
{
    QTemporaryDir dir;
    ExportOptions o;
    o.format = ExportFormat::SvgSequence;
    o.target = dir.filePath(QStringLiteral("svg"));
    const auto result = exportAnimation(filledSource(), o);
    QVERIFY(result);
    QCOMPARE(result->files.size(), 2);
    for (int frame = 0; frame < 2; ++frame) {
        const QString path = result->files[frame];
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QXmlStreamReader xml(&file);
        QStringList order; // "fill" / "stroke" in document order
        QString fillD;
        while (!xml.atEnd()) {
            if (xml.readNext() != QXmlStreamReader::StartElement || xml.name() != u"path")
                continue;
            const auto attributes = xml.attributes();
            if (attributes.value(QStringLiteral("class")) == u"fill") {
                order << QStringLiteral("fill");
                QCOMPARE(attributes.value(QStringLiteral("fill")).toString(),
                         QStringLiteral("#e03020"));
                fillD = attributes.value(QStringLiteral("d")).toString();
            } else {
                order << QStringLiteral("stroke");
            }
        }
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QCOMPARE(order, QStringList({QStringLiteral("fill"), QStringLiteral("stroke")}));
        // The region's area: the square's, within the stroke simplification.
        const double area = pathArea(fillD);
        QVERIFY2(std::abs(area - 10000.0) < 300.0, qPrintable(QString::number(area)));
        // Drawn, the fill shows inside the square (moved in frame 2), the paper outside.
        QSvgRenderer renderer(path);
        QImage image(400, 300, QImage::Format_ARGB32);
        image.fill(Qt::white);
        QPainter painter(&image);
        renderer.render(&painter);
        painter.end();
        const QPointF centre = QPointF(150, 150) + (frame == 1 ? kShift : QPointF());
        QVERIFY(nearColor(image.pixel(centre.toPoint()), kRed));
        QVERIFY(nearColor(image.pixel(QPoint(380, 20)), 0xffffffff));
    }
}

void TestExportFills::rasterFormatsShowFills_data()
{
    QTest::addColumn<int>("format");
    QTest::addColumn<QString>("file");
    QTest::newRow("png") << int(ExportFormat::PngSequence) << QStringLiteral("png");
    QTest::newRow("gif") << int(ExportFormat::Gif) << QStringLiteral("a.gif");
    QTest::newRow("mp4") << int(ExportFormat::Mp4) << QStringLiteral("a.mp4");
    QTest::newRow("webm") << int(ExportFormat::WebM) << QStringLiteral("a.webm");
    QTest::newRow("apng") << int(ExportFormat::Apng) << QStringLiteral("a.apng");
}

void TestExportFills::rasterFormatsShowFills()
{
    QFETCH(int, format);
    QFETCH(QString, file);
    if (ExportFormat(format) != ExportFormat::PngSequence && program("ffmpeg").isEmpty())
        QSKIP("ffmpeg not installed (bash .ci/setup installs it)");
    QTemporaryDir dir;
    ExportOptions o;
    o.format = ExportFormat(format);
    o.target = dir.filePath(file);
    const auto result = exportAnimation(filledSource(), o);
    QVERIFY(result);
    for (int frame = 0; frame < 2; ++frame) {
        const QImage image = ExportFormat(format) == ExportFormat::PngSequence
                                 ? QImage(result->files[frame])
                                 : decodeFrame(o.target, frame);
        QVERIFY2(!image.isNull(), qPrintable(QStringLiteral("frame %1").arg(frame)));
        const QPointF centre = QPointF(150, 150) + (frame == 1 ? kShift : QPointF());
        QVERIFY2(nearColor(image.pixel(centre.toPoint()), kRed),
                 qPrintable(QString::number(image.pixel(centre.toPoint()), 16)));
        QVERIFY(nearColor(image.pixel(QPoint(380, 20)), 0xffffffff));
        // The other frame's place is paper: the fill moved with the pose.
        const QPointF other = QPointF(150, 150) + (frame == 0 ? kShift : QPointF());
        QVERIFY(!nearColor(image.pixel(other.toPoint()), kRed));
    }
}

void TestExportFills::htmlShowsFillsInChromium()
{
    if (chromium().isEmpty())
        QSKIP("Chromium not installed (bash .ci/setup installs it)");
    QTemporaryDir dir;
    ExportOptions o;
    o.format = ExportFormat::Html;
    o.target = dir.filePath(QStringLiteral("fills.html"));
    o.loop = false;
    QVERIFY(exportAnimation(filledSource(), o));
    QUrl url = QUrl::fromLocalFile(o.target);
    url.setFragment(QStringLiteral("paused"));
    QTemporaryDir profile;
    const QString shot = dir.filePath(QStringLiteral("shot.png"));
    QProcess p;
    p.start(chromium(),
            {QStringLiteral("--headless"), QStringLiteral("--no-sandbox"),
             QStringLiteral("--disable-gpu"), QStringLiteral("--no-first-run"),
             QStringLiteral("--disable-background-networking"), QStringLiteral("--hide-scrollbars"),
             QStringLiteral("--force-device-scale-factor=1"),
             QStringLiteral("--user-data-dir=") + profile.path(),
             QStringLiteral("--window-size=600,440"), QStringLiteral("--virtual-time-budget=500"),
             QStringLiteral("--screenshot=") + shot, url.toString()});
    QVERIFY(p.waitForFinished(120000));
    const QImage image(shot);
    QVERIFY2(!image.isNull(), "Chromium made no screenshot");
    // The canvas sits at the top left, 1:1: the first frame's fill, the paper beside it.
    QVERIFY2(nearColor(image.pixel(150, 150), kRed),
             qPrintable(QString::number(image.pixel(150, 150), 16)));
    QVERIFY(nearColor(image.pixel(380, 20), 0xffffffff));
}

QTEST_MAIN(TestExportFills)
#include "tst_export_fills.moc"
