// traceAlphaOutline: the outline of a picture's opaque pixels, from anti-aliased alpha.
#include <finbook/geometry/picture/alpha_outline.h>
#include <finbook/geometry/polyline.h>
#include <finbook/geometry/region.h>
#include <finbook/geometry/simplicity.h>

#include <QtTest>

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

using namespace finbook::geometry;

namespace {

// An alpha picture: each pixel's coverage by `inside`, measured on 16 × 16 sub-samples, as an
// anti-aliasing painter would give it.
struct AlphaPicture {
    int width = 0, height = 0;
    std::vector<std::uint8_t> alpha;
    std::uint8_t &at(int x, int y) { return alpha[std::size_t(y) * std::size_t(width) + x]; }
};

AlphaPicture paint(int width, int height, const std::function<bool(double, double)> &inside)
{
    AlphaPicture p{width, height, std::vector<std::uint8_t>(std::size_t(width) * height, 0)};
    constexpr int kSub = 16;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            int covered = 0;
            for (int j = 0; j < kSub; ++j)
                for (int i = 0; i < kSub; ++i)
                    covered += inside(x + (i + 0.5) / kSub, y + (j + 0.5) / kSub);
            p.at(x, y) = std::uint8_t(std::lround(255.0 * covered / (kSub * kSub)));
        }
    }
    return p;
}

std::function<bool(double, double)> disc(double cx, double cy, double r)
{
    return [=](double x, double y) { return std::hypot(x - cx, y - cy) <= r; };
}

Region trace(const AlphaPicture &p, const AlphaOutlineOptions &options = {})
{
    const auto region = traceAlphaOutline(p.alpha.data(), p.width, p.height, p.width, 1, options);
    if (!region)
        qFatal("traceAlphaOutline failed: %s", region.error().message.c_str());
    return *region;
}

// The largest distance of a ring's vertices from the circle.
double offCircle(const Eigen::MatrixX2d &ring, double cx, double cy, double r)
{
    double worst = 0.0;
    for (Eigen::Index i = 0; i < ring.rows(); ++i)
        worst = std::max(worst, std::abs(std::hypot(ring(i, 0) - cx, ring(i, 1) - cy) - r));
    return worst;
}

} // namespace

class TestAlphaOutline : public QObject {
    Q_OBJECT
private slots:
    void discFollowsCircle();
    void ringGivesOuterAndHole();
    void twoBlobsGiveTwoPolygons();
    void emptyAndFullPictures();
    void specksAndPinholesDropped();
    void diagonalNeighboursAreValidRings();
    void thresholdChoosesTheEdge();
    void interleavedPixelsReadAlpha();
    void badInputRefused();
};

void TestAlphaOutline::discFollowsCircle()
{
    const double cx = 64.3, cy = 60.7, r = 40.0;
    const AlphaPicture p = paint(128, 128, disc(cx, cy, r));
    const Region simplified = trace(p);
    QCOMPARE(simplified.size(), std::size_t(1));
    QVERIFY(simplified[0].holes.empty());
    const double area = regionArea(simplified);
    QVERIFY2(std::abs(area - M_PI * r * r) < 0.01 * M_PI * r * r,
             qPrintable(QString::number(area)));
    QVERIFY(offCircle(simplified[0].outer, cx, cy, r) <= 0.5);
    QVERIFY(isSimple(simplified));
    // Far fewer vertices than crossings, yet on the circle.
    AlphaOutlineOptions exact;
    exact.simplify = 0.0;
    const Region raw = trace(p, exact);
    QVERIFY(simplified[0].outer.rows() < raw[0].outer.rows() / 3);
    // Every traced crossing lies within the tolerance of the simplified outline.
    const Eigen::MatrixX2d &kept = simplified[0].outer;
    for (Eigen::Index i = 0; i < raw[0].outer.rows(); ++i) {
        double nearest = 1e9;
        for (Eigen::Index j = 0; j < kept.rows(); ++j) {
            const Eigen::RowVector2d a = kept.row(j), ab = kept.row((j + 1) % kept.rows()) - a;
            const Eigen::RowVector2d q = raw[0].outer.row(i);
            const double t = std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
            nearest = std::min(nearest, (q - (a + t * ab)).norm());
        }
        QVERIFY(nearest <= 0.5 + 1e-9);
    }
    // Interpolated crossings follow the anti-aliased edge to a fraction of a pixel (the
    // crossings of a pixel grid without interpolation are off by up to half a pixel).
    QVERIFY2(offCircle(raw[0].outer, cx, cy, r) < 0.15,
             qPrintable(QString::number(offCircle(raw[0].outer, cx, cy, r))));
    QVERIFY(std::abs(regionArea(raw) - M_PI * r * r) < 0.002 * M_PI * r * r);
}

void TestAlphaOutline::ringGivesOuterAndHole()
{
    const double cx = 50.5, cy = 49.2;
    const AlphaPicture p = paint(100, 100, [&](double x, double y) {
        const double d = std::hypot(x - cx, y - cy);
        return d <= 40.0 && d >= 18.0;
    });
    const Region region = trace(p);
    QCOMPARE(region.size(), std::size_t(1));
    QCOMPARE(region[0].holes.size(), std::size_t(1));
    QVERIFY(signedArea(region[0].outer) > 0.0);
    QVERIFY(signedArea(region[0].holes[0]) < 0.0);
    QVERIFY(offCircle(region[0].outer, cx, cy, 40.0) <= 0.5);
    QVERIFY(offCircle(region[0].holes[0], cx, cy, 18.0) <= 0.5);
    const double expected = M_PI * (40.0 * 40.0 - 18.0 * 18.0);
    QVERIFY(std::abs(regionArea(region) - expected) < 0.01 * expected);
    QVERIFY(regionContains(region, cx + 30.0, cy));
    QVERIFY(!regionContains(region, cx, cy));
    QVERIFY(isSimple(region));
}

void TestAlphaOutline::twoBlobsGiveTwoPolygons()
{
    const auto a = disc(20, 20, 12), b = disc(60, 30, 8);
    const AlphaPicture p = paint(80, 50, [&](double x, double y) { return a(x, y) || b(x, y); });
    const Region region = trace(p);
    QCOMPARE(region.size(), std::size_t(2));
    // Simplification keeps vertices on the traced outline and moves chords at most 0.5 px off
    // it, inward on convex parts: the area may shrink by up to half the perimeter.
    const double expected = M_PI * (12.0 * 12.0 + 8.0 * 8.0);
    const double perimeter = 2.0 * M_PI * (12.0 + 8.0);
    QVERIFY(regionArea(region) <= expected + 0.01 * expected);
    QVERIFY(regionArea(region) >= expected - 0.01 * expected - 0.5 * perimeter);
    AlphaOutlineOptions exact;
    exact.simplify = 0.0;
    QVERIFY(std::abs(regionArea(trace(p, exact)) - expected) < 0.01 * expected);
    for (const Polygon &polygon : region) {
        QVERIFY(polygon.holes.empty());
        QVERIFY(signedArea(polygon.outer) > 0.0);
    }
    QVERIFY(regionContains(region, 20, 20) && regionContains(region, 60, 30));
    QVERIFY(!regionContains(region, 40, 25));
}

void TestAlphaOutline::emptyAndFullPictures()
{
    AlphaPicture empty{40, 30, std::vector<std::uint8_t>(40 * 30, 0)};
    QVERIFY(trace(empty).empty());
    QVERIFY(traceAlphaOutline(nullptr, 0, 0, 0).hasValue()); // no pixels: no outline
    QVERIFY(traceAlphaOutline(nullptr, 0, 0, 0)->empty());

    AlphaPicture full{40, 30, std::vector<std::uint8_t>(40 * 30, 255)};
    const Region region = trace(full);
    QCOMPARE(region.size(), std::size_t(1));
    QVERIFY(region[0].holes.empty());
    // The rectangle with its four corners cut by half a pixel along the diagonal (exactly so
    // before simplification, which may slant an edge by up to 0.5 px).
    QVERIFY(regionArea(region) < 40.0 * 30.0);
    QVERIFY(regionArea(region) > 40.0 * 30.0 - 0.5 * 140.0);
    AlphaOutlineOptions exact;
    exact.simplify = 0.0;
    const Region rectangle = trace(full, exact);
    QVERIFY(std::abs(regionArea(rectangle) - (40.0 * 30.0 - 4 * 0.125)) < 1e-9);
    QCOMPARE(rectangle[0].outer.col(0).minCoeff(), 0.0);
    QCOMPARE(rectangle[0].outer.col(0).maxCoeff(), 40.0);
    QCOMPARE(rectangle[0].outer.col(1).minCoeff(), 0.0);
    QCOMPARE(rectangle[0].outer.col(1).maxCoeff(), 30.0);
}

void TestAlphaOutline::specksAndPinholesDropped()
{
    const AlphaPicture clean = paint(60, 60, disc(30, 30, 20));
    AlphaPicture p = clean;
    p.at(2, 2) = 255; // a one-pixel speck outside the disc
    p.at(30, 30) = 0; // a one-pixel pinhole inside it
    const Region region = trace(p);
    QCOMPARE(region.size(), std::size_t(1));
    QVERIFY(region[0].holes.empty());
    QVERIFY(!regionContains(region, 2.5, 2.5));
    // With no minimum area both show: a speck is a diamond of ½ px², a pinhole a hole.
    AlphaOutlineOptions keepAll;
    keepAll.minArea = 0.0;
    const Region all = trace(p, keepAll);
    QCOMPARE(all.size(), std::size_t(2));
    std::size_t holes = 0;
    for (const Polygon &polygon : all)
        holes += polygon.holes.size();
    QCOMPARE(holes, std::size_t(1));
    QVERIFY(std::abs(regionArea(all) - regionArea(region)) < 1.01);
    // Without them the disc is traced exactly as it is without the speck and the pinhole.
    QCOMPARE(regionArea(region), regionArea(trace(clean)));
}

void TestAlphaOutline::diagonalNeighboursAreValidRings()
{
    // Two opaque squares meeting at one corner: a saddle cell between them. Rings stay valid
    // and the area is the squares' (less the cut corners) wherever the saddle goes.
    AlphaPicture p{20, 20, std::vector<std::uint8_t>(400, 0)};
    for (int y = 4; y < 10; ++y)
        for (int x = 4; x < 10; ++x) {
            p.at(x, y) = 255;
            p.at(x + 6, y + 6) = 255;
        }
    AlphaOutlineOptions exact;
    exact.simplify = 0.0;
    const Region region = trace(p, exact);
    QVERIFY(!region.empty());
    QVERIFY(isSimple(region, Touching::AllowedAtPoints));
    const double area = regionArea(region);
    QVERIFY2(area > 72.0 - 2.0 && area < 72.0 + 0.5, qPrintable(QString::number(area)));
    QVERIFY(regionContains(region, 5, 5) && regionContains(region, 14, 14));
    QVERIFY(!regionContains(region, 14, 5) && !regionContains(region, 5, 14));
    QCOMPARE(region.size(), std::size_t(2)); // the saddle's centre (alpha 127.5) is outside

    // The two pixels beside the corner just below the threshold: the saddle's centre is inside
    // and joins the squares into one polygon.
    p.at(10, 9) = 200;
    p.at(9, 10) = 200;
    exact.threshold = 210;
    const Region joined = trace(p, exact);
    QCOMPARE(joined.size(), std::size_t(1));
    QVERIFY(joined[0].holes.empty());
    QVERIFY(signedArea(joined[0].outer) > 0.0);
    QVERIFY(isSimple(joined, Touching::AllowedAtPoints));
}

void TestAlphaOutline::thresholdChoosesTheEdge()
{
    // A horizontal ramp: alpha rises by 2 per pixel from the left. The edge lies where the
    // ramp passes the threshold, between the pixels on either side of it.
    AlphaPicture p{128, 8, std::vector<std::uint8_t>(128 * 8, 0)};
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 128; ++x)
            p.at(x, y) = std::uint8_t(2 * x);
    for (const int threshold : {40, 128, 200}) {
        AlphaOutlineOptions options;
        options.threshold = threshold;
        const Region region = trace(p, options);
        QCOMPARE(region.size(), std::size_t(1));
        const double left = region[0].outer.col(0).minCoeff();
        // Centres x + 0.5 have alpha 2x; alpha reaches threshold − ½ at x = (threshold − ½) / 2.
        QVERIFY2(std::abs(left - ((threshold - 0.5) / 2.0 + 0.5)) < 1e-9,
                 qPrintable(QString::number(left)));
    }
}

void TestAlphaOutline::interleavedPixelsReadAlpha()
{
    const AlphaPicture p = paint(50, 40, disc(25, 20, 15));
    // 32-bit pixels with 3 bytes of noise around the alpha byte, rows padded to 256 bytes.
    std::vector<std::uint8_t> pixels(256 * 40, 0xA5);
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 50; ++x)
            pixels[std::size_t(y) * 256 + std::size_t(x) * 4 + 3] =
                p.alpha[std::size_t(y) * 50 + x];
    const auto interleaved = traceAlphaOutline(pixels.data() + 3, 50, 40, 256, 4);
    QVERIFY(interleaved.hasValue());
    const Region plain = trace(p);
    QCOMPARE(interleaved->size(), plain.size());
    QVERIFY(((*interleaved)[0].outer - plain[0].outer).cwiseAbs().maxCoeff() == 0.0);
}

void TestAlphaOutline::badInputRefused()
{
    std::vector<std::uint8_t> a(100, 255);
    QVERIFY(!traceAlphaOutline(nullptr, 10, 10, 10));
    QVERIFY(!traceAlphaOutline(a.data(), 10, 10, 5)); // rows overlap
    QVERIFY(!traceAlphaOutline(a.data(), -1, 10, 10));
    QVERIFY(!traceAlphaOutline(a.data(), 10, 10, 10, 0));
    AlphaOutlineOptions bad;
    bad.threshold = 0; // everything, the padding too, would be inside
    QCOMPARE(traceAlphaOutline(a.data(), 10, 10, 10, 1, bad).error().code,
             GeometryErrorCode::InvalidOptions);
    bad = {};
    bad.simplify = std::numeric_limits<double>::quiet_NaN();
    QVERIFY(!traceAlphaOutline(a.data(), 10, 10, 10, 1, bad));
    // Noise: a checkerboard's every pixel is a ring; a limit refuses it instead of tracing.
    std::vector<std::uint8_t> noise(200 * 200);
    for (int i = 0; i < 200 * 200; ++i)
        noise[std::size_t(i)] = ((i % 200) + (i / 200)) % 2 ? 255 : 0;
    AlphaOutlineOptions limited;
    limited.maxOutlinePoints = 10000;
    const auto refused = traceAlphaOutline(noise.data(), 200, 200, 200, 1, limited);
    QVERIFY(!refused);
    QCOMPARE(refused.error().code, GeometryErrorCode::TooManyPoints);
    QVERIFY(!refused.error().message.empty());
}

QTEST_APPLESS_MAIN(TestAlphaOutline)
#include "tst_alpha_outline.moc"
