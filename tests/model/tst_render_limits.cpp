// Rendering costs what the canvas shows: a point millions of pixels away is clipped before
// QPainter strokes it, one stroke referenced thousands of times is painted once, a huge
// canvas exports band by band (its memory is measured in app/tst_limits).
#include "engine_device.h"
#include "tst_file_sample.h"

#include <finbook/model/export/export_plan.h>
#include <finbook/model/export/exporter.h>
#include <finbook/model/render.h>

#include <QPaintEngine>
#include <QPainterPath>
#include <QTemporaryDir>

using namespace finbook::model;
using namespace file_test;

namespace {
// A paint device that records what QPainter hands its engine, in logical coordinates.
class RecordingEngine : public QPaintEngine {
public:
    RecordingEngine()
        : QPaintEngine(QPaintEngine::AllFeatures)
    {}
    bool begin(QPaintDevice *) override { return true; }
    bool end() override { return true; }
    void updateState(const QPaintEngineState &) override {}
    void drawPixmap(const QRectF &, const QPixmap &, const QRectF &) override {}
    void drawPolygon(const QPointF *points, int count, PolygonDrawMode) override
    {
        ++calls;
        for (int i = 0; i < count; ++i)
            note(points[i]);
        pointsDrawn += count;
    }
    void drawEllipse(const QRectF &r) override
    {
        ++calls;
        note(r.topLeft());
        note(r.bottomRight());
    }
    void drawPath(const QPainterPath &path) override
    {
        ++calls;
        note(path.boundingRect().topLeft());
        note(path.boundingRect().bottomRight());
    }
    // QRectF::united ignores empty rectangles, so the extent is kept by hand.
    void note(const QPointF &p)
    {
        extent =
            !any ? QRectF(p, p)
                 : QRectF(
                       QPointF(std::min(extent.left(), p.x()), std::min(extent.top(), p.y())),
                       QPointF(std::max(extent.right(), p.x()), std::max(extent.bottom(), p.y())));
        any = true;
    }
    Type type() const override { return QPaintEngine::User; }

    bool any = false;
    int calls = 0;
    qint64 pointsDrawn = 0;
    QRectF extent;
};

using RecordingDevice = engine_test::EngineDevice<RecordingEngine>;

Frame frameWith(std::vector<StrokeDataPtr> strokes)
{
    Frame frame;
    frame.id = 1;
    StrokeGroup g;
    g.id = 2;
    Id next = 3;
    for (StrokeDataPtr &s : strokes)
        g.strokes.push_back({next++, std::move(s)});
    frame.groups.push_back(std::move(g));
    return frame;
}

StrokeDataPtr strokeOf(std::vector<StrokePoint> points, QRgb color = 0xff000000, float width = 3)
{
    auto data = std::make_shared<StrokeData>();
    data->points = std::move(points);
    data->color = color;
    data->width = width;
    return data;
}

DocumentSettings canvas(int w, int h)
{
    DocumentSettings s;
    s.canvasSize = QSize(w, h);
    return s;
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

} // namespace

class TestRenderLimits : public QObject {
    Q_OBJECT
private slots:
    void farPointIsClipped();
    void clippingKeepsWhatIsVisible();
    void nonFiniteValuesAreSkipped();
    void repeatedStrokeIsPaintedOnce();
    void repeatedTranslucentStrokeKeepsItsLook();
    void bandsMatchTheWholeImage();
    void exportedPngMatchesRender();
};

void TestRenderLimits::farPointIsClipped()
{
    // The 641-byte file: one point at y = -2.6e6 took 12 s to export.
    const Frame frame = frameWith(
        {strokeOf({{100, 100, 1}, {100, -2.6e6f, 1}, {300, 200, 0.5f}, {-1e30f, 1e30f, 1}})});
    RecordingDevice device(QSize(640, 360));
    {
        QPainter painter(&device);
        paintFrame(painter, frame, canvas(640, 360));
    }
    const QRectF reach = QRectF(0, 0, 640, 360).adjusted(-10, -10, 10, 10);
    QVERIFY2(reach.contains(device.engine().extent),
             qPrintable(QStringLiteral("drawn as far as %1,%2 %3x%4")
                            .arg(device.engine().extent.x())
                            .arg(device.engine().extent.y())
                            .arg(device.engine().extent.width())
                            .arg(device.engine().extent.height())));
    QVERIFY(device.engine().pointsDrawn > 0); // the visible parts are still drawn
}

void TestRenderLimits::clippingKeepsWhatIsVisible()
{
    // A segment leaving the canvas looks the same as the same segment ending just outside.
    const QRgb ink = 0xff203040;
    const Frame far = frameWith({strokeOf({{20, 50, 1}, {20, -2.6e6f, 1}}, ink, 6)});
    const Frame near = frameWith({strokeOf({{20, 50, 1}, {20, -40, 1}}, ink, 6)});
    const DocumentSettings settings = canvas(100, 100);
    QCOMPARE(maxChannelDifference(renderFrame(far, settings, QSize(100, 100)),
                                  renderFrame(near, settings, QSize(100, 100))),
             0);
    // Zoomed in (a quarter of the canvas magnified), the same holds.
    QImage a(200, 200, QImage::Format_ARGB32_Premultiplied), b = a;
    a.fill(Qt::white);
    b.fill(Qt::white);
    for (auto [image, frame] : {std::pair{&a, &far}, std::pair{&b, &near}}) {
        QPainter painter(image);
        painter.scale(4, 4);
        painter.translate(-5, -10);
        paintFrame(painter, *frame, settings);
    }
    QCOMPARE(maxChannelDifference(a, b), 0);
}

void TestRenderLimits::nonFiniteValuesAreSkipped()
{
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Frame frame = frameWith({strokeOf({{10, 10, 1}, {nan, 5, 1}, {20, 20, nan}, {inf, 3, 1}}),
                                   strokeOf({{30, 30, 1}, {40, 40, 1}}, 0xff000000, nan),
                                   strokeOf({{50, 50, 1}, {60, 60, 1}}, 0xff000000, 0.0f),
                                   strokeOf({{70, 70, inf}})});
    const QImage image = renderFrame(frame, canvas(100, 100), QSize(100, 100));
    QVERIFY(!image.isNull());
    RecordingDevice device(QSize(100, 100));
    {
        QPainter painter(&device);
        paintFrame(painter, frame, canvas(100, 100));
    }
    const QRectF e = device.engine().extent;
    QVERIFY(std::isfinite(e.x()) && std::isfinite(e.y()) && std::isfinite(e.width()) &&
            std::isfinite(e.height()));
}

void TestRenderLimits::repeatedStrokeIsPaintedOnce()
{
    std::vector<StrokePoint> points;
    for (int i = 0; i < 500; ++i)
        points.push_back({float(i % 600), float((i * 37) % 300), 1.0f});
    const StrokeDataPtr shared = strokeOf(points);
    const Frame frame = frameWith(std::vector<StrokeDataPtr>(2000, shared));
    RecordingDevice device(QSize(640, 360));
    {
        QPainter painter(&device);
        RenderOptions strokesOnly;
        strokesOnly.paintBackground = false;
        paintFrame(painter, frame, canvas(640, 360), strokesOnly);
    }
    QCOMPARE(device.engine().calls, 1); // one polyline, not 2,000
    QCOMPARE(paintList(frame).size(), std::size_t(1));
    QCOMPARE(paintList(frame).front().coats, 2000);
}

void TestRenderLimits::repeatedTranslucentStrokeKeepsItsLook()
{
    const StrokeDataPtr stroke = strokeOf({{10, 50, 1}, {90, 50, 1}}, 0x60ff0000, 12);
    const StrokeDataPtr other = strokeOf({{50, 10, 1}, {50, 90, 1}}, 0xff0000ff, 4);
    const Frame frame = frameWith({stroke, other, stroke, stroke});
    const QImage merged = renderFrame(frame, canvas(100, 100), QSize(100, 100));
    // What three separate coats look like, painted one by one.
    QImage coats(100, 100, QImage::Format_ARGB32_Premultiplied);
    coats.fill(Qt::white);
    {
        QPainter painter(&coats);
        painter.setRenderHint(QPainter::Antialiasing);
        paintStroke(painter, other->points, other->color, other->width);
        for (int i = 0; i < 3; ++i)
            paintStroke(painter, stroke->points, stroke->color, stroke->width);
    }
    // Inside the red stroke, away from the blue one, the colours agree within rounding.
    for (int x : {20, 30, 70, 80}) {
        const QColor a = merged.pixelColor(x, 50), b = coats.pixelColor(x, 50);
        QVERIFY2(std::abs(a.red() - b.red()) <= 2 && std::abs(a.green() - b.green()) <= 2 &&
                     std::abs(a.blue() - b.blue()) <= 2,
                 qPrintable(QStringLiteral("x=%1: %2 vs %3").arg(x).arg(a.name(), b.name())));
    }
    // The red stroke now lies over the blue one where they cross: its last reference is last.
    QVERIFY(merged.pixelColor(50, 50).red() > merged.pixelColor(50, 30).red());
}

void TestRenderLimits::bandsMatchTheWholeImage()
{
    Document doc;
    buildSample(doc);
    const QSize size(640, 360);
    for (const Frame &frame : doc.frames()) {
        const QImage whole = renderFrame(frame, doc.settings(), size);
        QImage stitched(size, QImage::Format_ARGB32_Premultiplied);
        QPainter painter(&stitched);
        painter.setCompositionMode(QPainter::CompositionMode_Source);
        for (int top = 0; top < size.height(); top += 37)
            painter.drawImage(0, top,
                              renderFrameBand(frame, doc.settings(), size, top,
                                              std::min(37, size.height() - top)));
        painter.end();
        QVERIFY(maxChannelDifference(whole, stitched) <= 1);
    }
}

void TestRenderLimits::exportedPngMatchesRender()
{
    Document doc;
    buildSample(doc);
    ExportSource source = exportSource(doc);
    source.settings.canvasSize = QSize(4200, 1100); // more than one band
    QVERIFY(qint64(4200) * 1100 > kExportBandPixels);
    QTemporaryDir dir;
    ExportOptions options;
    options.target = dir.filePath(QStringLiteral("png"));
    options.firstFrame = options.lastFrame = 0;
    options.transparent = true; // straight alpha through the band conversion too
    const auto result = exportAnimation(source, options);
    QVERIFY2(result, result ? "" : qPrintable(result.error().message));
    const QImage decoded(result->files.first(), "PNG");
    QCOMPARE(decoded.size(), source.settings.canvasSize);
    auto plan = planExport(source, options);
    QVERIFY(plan);
    const QImage rendered = renderExportFrame(source.frames[0], source.settings, *plan);
    QVERIFY(maxChannelDifference(decoded, rendered) <= 1);
}

QTEST_GUILESS_MAIN(TestRenderLimits)
#include "tst_render_limits.moc"
