// Wide pens (issue 25, item 6): a 200-pixel pen scribbling 20,000 points over a 1920 x 1080
// frame took 97 s, QPainter filling the outlines of 20,000 overlapping capsules. Such strokes
// are now rasterized as a coverage mask whose work is bounded by the frame; it must look like
// the outline fill, and ordinary wide strokes must keep the outline fill.
#include "../../model/src/capsule_coverage.h"
#include "../../model/src/render_wide_pen.h"
#include "engine_device.h"

#include <finbook/model/render.h>

#include <QPaintEngine>
#include <QPainterPath>
#include <QtTest>

using namespace finbook::model;

namespace {
// Counts what QPainter's engine is handed: outline vertices and image pixels.
class CountingEngine : public QPaintEngine {
public:
    CountingEngine()
        : QPaintEngine(QPaintEngine::AllFeatures)
    {}
    bool begin(QPaintDevice *) override { return true; }
    bool end() override { return true; }
    void updateState(const QPaintEngineState &) override {}
    void drawPixmap(const QRectF &, const QPixmap &, const QRectF &) override {}
    void drawImage(const QRectF &, const QImage &image, const QRectF &,
                   Qt::ImageConversionFlags) override
    {
        imagePixels += qint64(image.width()) * image.height();
    }
    void drawPolygon(const QPointF *, int count, PolygonDrawMode) override
    {
        outlineVertices += count;
    }
    void drawPath(const QPainterPath &path) override { outlineVertices += path.elementCount(); }
    Type type() const override { return QPaintEngine::User; }

    qint64 outlineVertices = 0;
    qint64 imagePixels = 0;
};

using CountingDevice = engine_test::EngineDevice<CountingEngine>;

// `count` points spread at random over w × h (a fixed sequence), pressures in [minPressure, 1].
std::vector<StrokePoint> scribble(int count, int w, int h, float minPressure = 1.0f)
{
    std::vector<StrokePoint> points;
    quint32 seed = 12345;
    const auto next = [&seed](int range) {
        seed = seed * 1664525u + 1013904223u;
        return float((seed >> 8) % quint32(range));
    };
    for (int i = 0; i < count; ++i) {
        const float x = next(w), y = next(h);
        points.push_back({x, y, minPressure + (1.0f - minPressure) * next(1000) / 999.0f});
    }
    return points;
}

std::vector<WideSegment> segmentsOf(const std::vector<StrokePoint> &points, float width)
{
    std::vector<WideSegment> segments;
    for (std::size_t i = 1; i < points.size(); ++i)
        segments.push_back({QPointF(points[i - 1].x, points[i - 1].y),
                            QPointF(points[i].x, points[i].y), width * points[i].pressure});
    return segments;
}

// The segments filled on a white image through `transform`, by the given fill.
QImage filled(const std::vector<WideSegment> &segments, QSize size, const QTransform &transform,
              WidePenFill fill, const QRect &clip = {})
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    if (!clip.isNull())
        painter.setClipRect(clip);
    painter.setTransform(transform);
    painter.setBrush(QColor(20, 40, 200));
    const qreal scale = std::sqrt(std::abs(transform.determinant()));
    const QRectF visible = transform.inverted().mapRect(QRectF(QPointF(0, 0), QSizeF(size)));
    const WidePenWork work = fillWideSegments(painter, segments, visible, scale, fill);
    if (work.used != fill)
        return {};
    return image;
}

struct Difference {
    int worst = 0;
    double farShare = 0;     // share of pixels differing by more than 48 of 255
    double farEdgeShare = 0; // the same pixels' share of the edge pixels (partly inked in a)
};

Difference compare(const QImage &a, const QImage &b)
{
    Difference d;
    qint64 far = 0, edge = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            const int diff = std::max({std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                                       std::abs(qBlue(p) - qBlue(q))});
            d.worst = std::max(d.worst, diff);
            far += diff > 48;
            edge += p != qRgb(255, 255, 255) && p != qRgb(20, 40, 200); // neither paper nor ink
        }
    d.farShare = double(far) / (qint64(a.width()) * a.height());
    d.farEdgeShare = double(far) / std::max<qint64>(1, edge);
    return d;
}
} // namespace

class TestWidePenFill : public QObject {
    Q_OBJECT
private slots:
    void coverageLooksLikeTheOutlineFill_data();
    void coverageLooksLikeTheOutlineFill();
    void ordinaryWideStrokesKeepTheOutlineFill();
    void scribbleOverTheFrameCostsWhatTheFrameHolds();
    void narrowPenScribbleIsBoundedToo();
    void coverageOfOneCapsuleIsItsArea();
};

void TestWidePenFill::coverageLooksLikeTheOutlineFill_data()
{
    QTest::addColumn<float>("width");
    QTest::addColumn<int>("points");
    QTest::addColumn<float>("minPressure");
    QTest::addColumn<QTransform>("transform");
    QTest::addColumn<QRect>("clip");
    QTest::newRow("200 px pen, 12 points") << 200.0f << 12 << 1.0f << QTransform() << QRect();
    QTest::newRow("60 px pen with pressure, 40 points")
        << 60.0f << 40 << 0.2f << QTransform() << QRect();
    QTest::newRow("scaled 2.5 and moved, pressure")
        << 50.0f << 30 << 0.3f << QTransform::fromTranslate(-90, -40).scale(2.5, 2.5) << QRect();
    QTest::newRow("rotated, clipped")
        << 80.0f << 20 << 1.0f << QTransform().translate(200, 20).rotate(30)
        << QRect(50, 60, 250, 150);
    QTest::newRow("10 px pen, 60 points") << 10.0f << 60 << 1.0f << QTransform() << QRect();
    QTest::newRow("2,000 px pen") << 2000.0f << 10 << 1.0f << QTransform() << QRect();
}

// The mask is sampled 4 x 4 per pixel where QPainter computes areas: the two differ at edges
// only, by a few grey levels, in under 1 % of the pixels by more than 48 of 255, never
// ink against paper. (Where several capsules' edges share a pixel QPainter adds up their
// areas and overstates the union by up to half a pixel; the mask samples the union itself.)
void TestWidePenFill::coverageLooksLikeTheOutlineFill()
{
    QFETCH(float, width);
    QFETCH(int, points);
    QFETCH(float, minPressure);
    QFETCH(QTransform, transform);
    QFETCH(QRect, clip);
    const QSize size(400, 300);
    const auto segments = segmentsOf(scribble(points, 400, 300, minPressure), width);
    const QImage outline = filled(segments, size, transform, WidePenFill::Outline, clip);
    const QImage coverage = filled(segments, size, transform, WidePenFill::Coverage, clip);
    QVERIFY(!outline.isNull() && !coverage.isNull());
    const Difference d = compare(outline, coverage);
    qInfo("worst difference %d of 255; by more than 48: %.3f %% of pixels, %.2f %% of edge pixels",
          d.worst, 100 * d.farShare, 100 * d.farEdgeShare);
    QVERIFY2(d.farShare <= 0.01, qPrintable(QString::number(d.farShare)));
    QVERIFY2(d.worst <= 160, qPrintable(QString::number(d.worst)));
}

// The coverage mask is for strokes whose outline fill would cost much more than the frame: a
// 60-pixel pen drawing an ordinary line keeps QPainter's fill (and so its look, exactly).
void TestWidePenFill::ordinaryWideStrokesKeepTheOutlineFill()
{
    std::vector<StrokePoint> line;
    for (int i = 0; i < 600; ++i) // a wavy line across the frame, 3 px between samples
        line.push_back({float(20 + 3 * (i % 600)), float(540 + 200 * std::sin(i / 40.0)), 1.0f});
    QImage image(1920, 1080, QImage::Format_ARGB32_Premultiplied);
    QPainter painter(&image);
    const WidePenWork work =
        fillWideSegments(painter, segmentsOf(line, 60), QRectF(0, 0, 1920, 1080), 1.0);
    QCOMPARE(int(work.used), int(WidePenFill::Outline));
    QVERIFY(work.outlineVertices > 0);
}

// The worst case: 20,000 random points, 200-pixel pen, 1920 x 1080. QPainter is
// handed one image of the frame's size, no outline, and the mask's work stays within a few
// times the frame's samples (it used to be handed ~1.8 million outline vertices).
void TestWidePenFill::scribbleOverTheFrameCostsWhatTheFrameHolds()
{
    const QSize size(1920, 1080);
    const std::vector<StrokePoint> points = scribble(20000, 1920, 1080);
    CountingDevice device(size);
    {
        QPainter painter(&device);
        painter.setRenderHint(QPainter::Antialiasing);
        paintStroke(painter, points, 0xff000000, 200);
    }
    const qint64 pixels = qint64(size.width()) * size.height();
    QCOMPARE(device.engine().outlineVertices, 0);
    QCOMPARE(device.engine().imagePixels, pixels);

    std::vector<Capsule> capsules;
    for (const WideSegment &s : segmentsOf(points, 200))
        capsules.push_back({s.a.x(), s.a.y(), s.b.x(), s.b.y(), s.width / 2});
    std::vector<std::uint8_t> alpha;
    const CoverageWork work = capsuleCoverage(capsules, size.width(), size.height(), alpha);
    const qint64 samples = pixels * kCoverageSamples * kCoverageSamples;
    qInfo("%lld spans, %lld samples for %lld frame samples", qint64(work.spans),
          qint64(work.samples), samples);
    QVERIFY(work.samples <= samples);
    QVERIFY2(work.total() <= 2 * samples, qPrintable(QString::number(work.total())));
    // Ten times the points cost no more than twice as much: the frame is full long before.
    capsules.reserve(capsules.size() * 10);
    for (std::size_t i = 0, n = capsules.size(); i < 9 * n; ++i)
        capsules.push_back(capsules[i % n]);
    const CoverageWork more = capsuleCoverage(capsules, size.width(), size.height(), alpha);
    QVERIFY2(more.total() <= 2 * work.total(), qPrintable(QString::number(more.total())));
}

// A 10-pixel pen scribbling 20,000 points crowds the rows just as much (265 s a frame through
// QPainter's stroker): it takes the mask too, while an ordinary 10-pixel line does not.
void TestWidePenFill::narrowPenScribbleIsBoundedToo()
{
    const QSize size(1920, 1080);
    CountingDevice scribbled(size);
    {
        QPainter painter(&scribbled);
        paintStroke(painter, scribble(20000, 1920, 1080), 0xff000000, 10);
    }
    QCOMPARE(scribbled.engine().outlineVertices, 0);
    QCOMPARE(scribbled.engine().imagePixels, qint64(size.width()) * size.height());

    std::vector<StrokePoint> line;
    for (int i = 0; i < 2000; ++i)
        line.push_back({float(20 + i * 0.9f), float(540 + 300 * std::sin(i / 40.0)), 0.8f});
    CountingDevice drawn(size);
    {
        QPainter painter(&drawn);
        paintStroke(painter, line, 0xff000000, 10);
    }
    QVERIFY(drawn.engine().outlineVertices > 0);
    QCOMPARE(drawn.engine().imagePixels, 0);
}

// One capsule's mask adds up to its area (a 30 x 100 rectangle and a disk of radius 15), to
// within its edge's rounding, wherever its centre line lies, on the grid or far off it.
void TestWidePenFill::coverageOfOneCapsuleIsItsArea()
{
    std::vector<std::uint8_t> alpha;
    const auto area = [&alpha] {
        double sum = 0;
        for (std::uint8_t a : alpha)
            sum += a / 255.0;
        return sum;
    };
    const double expected = 30 * 100 + M_PI * 15 * 15;
    const Capsule inside{50, 60, 150, 60, 15};
    capsuleCoverage(std::span(&inside, 1), 200, 120, alpha);
    QVERIFY2(std::abs(area() - expected) < 0.01 * expected, qPrintable(QString::number(area())));
    // Centre line entirely above the grid: only the lower 5 rows of the band show.
    const Capsule above{-1e6, -10, 1e6, -10, 15};
    capsuleCoverage(std::span(&above, 1), 200, 120, alpha);
    QVERIFY2(std::abs(area() - 5 * 200) < 4, qPrintable(QString::number(area())));
    // Non-finite and empty capsules are skipped.
    const Capsule broken[] = {{NAN, 0, 10, 10, 5}, {0, 0, 10, 10, 0}, {0, 0, INFINITY, 0, 3}};
    const CoverageWork none = capsuleCoverage(broken, 200, 120, alpha);
    QCOMPARE(area(), 0.0);
    QCOMPARE(none.spans, 0);
}

QTEST_GUILESS_MAIN(TestWidePenFill)
#include "tst_wide_pen_fill.moc"
