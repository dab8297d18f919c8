// Silhouettes of stroke groups: coverage with margin, gap closing, filled outlines, lobes,
// holes, orientation.
#include "geometry_test_support.h"

#include <finbook/geometry/polyline.h>
#include <finbook/geometry/silhouette.h>
#include <finbook/geometry/simplicity.h>

#include <QtTest>

#include <cmath>
#include <limits>

using namespace finbook::geometry;

namespace {

Eigen::MatrixX2d arc(int n, double r, Eigen::RowVector2d c, double from = 0.0, double to = 2 * M_PI)
{
    Eigen::MatrixX2d points(n, 2);
    for (int i = 0; i < n; ++i) {
        const double t = from + (to - from) * i / (n - 1);
        points.row(i) = c + r * Eigen::RowVector2d(std::cos(t), std::sin(t));
    }
    return points;
}

Eigen::MatrixX2d line(Eigen::RowVector2d a, Eigen::RowVector2d b, int n = 20)
{
    Eigen::MatrixX2d points(n, 2);
    for (int i = 0; i < n; ++i)
        points.row(i) = a + (b - a) * double(i) / (n - 1);
    return points;
}

// Even-odd point-in-region over all rings.
bool inside(const Region &region, const Eigen::RowVector2d &p)
{
    bool in = false;
    for (const Eigen::MatrixX2d &ring : regionRings(region))
        in ^= finbook::test::insideRing(ring, p);
    return in;
}

double distanceToBoundary(const Region &region, const Eigen::RowVector2d &p)
{
    double best = std::numeric_limits<double>::max();
    for (const Eigen::MatrixX2d &ring : regionRings(region))
        for (Eigen::Index i = 0; i < ring.rows(); ++i) {
            const Eigen::RowVector2d a = ring.row(i), ab = ring.row((i + 1) % ring.rows()) - a;
            const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
            best = std::min(best, (p - (a + t * ab)).norm());
        }
    return best;
}

void checkRegion(const Region &region)
{
    QVERIFY(!region.empty());
    QVERIFY(isSimple(region, Touching::AllowedAtPoints));
    for (const Polygon &polygon : region) {
        QVERIFY(polygon.outer.allFinite());
        QVERIFY(signedArea(polygon.outer) > 0.0);
        for (const Eigen::MatrixX2d &hole : polygon.holes)
            QVERIFY(signedArea(hole) < 0.0);
    }
}

// Every stroke point inside, with the clearance silhouette.h promises.
void checkCoverage(const Region &region, const std::vector<StrokeInput> &strokes,
                   const SilhouetteOptions &options)
{
    for (const StrokeInput &s : strokes)
        for (Eigen::Index i = 0; i < s.points.rows(); ++i) {
            if (!s.points.row(i).allFinite())
                continue;
            QVERIFY(inside(region, s.points.row(i)));
            const double radius = 0.5 * s.width + options.margin;
            const double clearance = distanceToBoundary(region, s.points.row(i));
            QVERIFY(clearance > radius - 0.2 - options.simplifyTolerance);
            QVERIFY(clearance > 0.7 * radius);
        }
}

std::size_t holeCount(const Region &region)
{
    std::size_t holes = 0;
    for (const Polygon &p : region)
        holes += p.holes.size();
    return holes;
}

} // namespace

class TestSilhouette : public QObject {
    Q_OBJECT
private slots:
    void singleStrokeIsABand();
    void dotIsADisk();
    void closedOutlineIsFilled();
    void nearlyClosedOutlineIsFilled();
    void concentricRingFilledByDefault();
    void concentricRingKeepsHoleOnRequest();
    void smallGapIsBridged();
    void partsDrawnApartStayLobes();
    void selfCrossingAndRepeatedPoints();
    void marginAndGapScaleTheArea();
    void regionContainsItsInside();
};

void TestSilhouette::singleStrokeIsABand()
{
    const std::vector<StrokeInput> strokes{{line({0, 0}, {200, 0}), 4.0}};
    const SilhouetteOptions options;
    const auto region = silhouette(strokes, options);
    QVERIFY(region.hasValue());
    checkRegion(*region);
    checkCoverage(*region, strokes, options);
    const double r = 2.0 + options.margin;
    const double expected = 200.0 * 2 * r + M_PI * r * r;
    QVERIFY(std::abs(regionArea(*region) - expected) < 0.02 * expected);
}

void TestSilhouette::dotIsADisk()
{
    const std::vector<StrokeInput> strokes{{Eigen::RowVector2d(50, 60), 6.0}};
    const auto region = silhouette(strokes);
    QVERIFY(region.hasValue());
    checkRegion(*region);
    checkCoverage(*region, strokes, {});
    const double r = 3.0 + SilhouetteOptions{}.margin;
    // An inscribed polygon: simplification trades a little area of tiny dots for fewer vertices.
    QVERIFY(regionArea(*region) <= M_PI * r * r);
    QVERIFY(regionArea(*region) > 0.85 * M_PI * r * r);
}

void TestSilhouette::closedOutlineIsFilled()
{
    // A circle drawn as one stroke: the artist means the disk, not a ring.
    const std::vector<StrokeInput> strokes{{arc(200, 150.0, {400, 300}), 3.0}};
    const auto region = silhouette(strokes);
    QVERIFY(region.hasValue());
    checkRegion(*region);
    QCOMPARE(region->size(), std::size_t(1));
    QCOMPARE(holeCount(*region), std::size_t(0));
    QVERIFY(inside(*region, Eigen::RowVector2d(400, 300)));
    const double outer = 150.0 + 1.5 + SilhouetteOptions{}.margin;
    QVERIFY(std::abs(regionArea(*region) - M_PI * outer * outer) < 0.01 * M_PI * outer * outer);
}

void TestSilhouette::nearlyClosedOutlineIsFilled()
{
    // The end stops 6 px short of the start, within the default gap: still a filled shape.
    const double gapAngle = 6.0 / 150.0;
    const std::vector<StrokeInput> strokes{{arc(200, 150.0, {400, 300}, gapAngle, 2 * M_PI), 1.0}};
    const auto region = silhouette(strokes);
    QVERIFY(region.hasValue());
    QCOMPARE(holeCount(*region), std::size_t(0));
    QVERIFY(inside(*region, Eigen::RowVector2d(400, 300)));
}

void TestSilhouette::concentricRingFilledByDefault()
{
    // A thick ring drawn as concentric circles 5 px apart around a 200 px wide opening.
    std::vector<StrokeInput> strokes;
    for (double r = 100.0; r <= 160.0; r += 5.0)
        strokes.push_back({arc(240, r, {0, 0}), 3.0});
    const auto region = silhouette(strokes);
    QVERIFY(region.hasValue());
    checkRegion(*region);
    QCOMPARE(holeCount(*region), std::size_t(0));
    QVERIFY(inside(*region, Eigen::RowVector2d(0, 0)));
}

void TestSilhouette::concentricRingKeepsHoleOnRequest()
{
    std::vector<StrokeInput> strokes;
    for (double r = 100.0; r <= 160.0; r += 5.0)
        strokes.push_back({arc(240, r, {0, 0}), 3.0});
    SilhouetteOptions options;
    options.holes = HoleMode::KeepHoles;
    const auto region = silhouette(strokes, options);
    QVERIFY(region.hasValue());
    checkRegion(*region);
    checkCoverage(*region, strokes, options);
    // The 5 px gaps between the circles are closed, the 200 px opening stays a hole.
    QCOMPARE(region->size(), std::size_t(1));
    QCOMPARE(holeCount(*region), std::size_t(1));
    QVERIFY(!inside(*region, Eigen::RowVector2d(0, 0)));
    QVERIFY(inside(*region, Eigen::RowVector2d(132.5, 0)));
    const double rIn = 100.0 - 1.5 - options.margin, rOut = 160.0 + 1.5 + options.margin;
    const double expected = M_PI * (rOut * rOut - rIn * rIn);
    QVERIFY(std::abs(regionArea(*region) - expected) < 0.02 * expected);
}

void TestSilhouette::smallGapIsBridged()
{
    // Two strokes whose pen edges are 5 px apart (< default gap 8): one lobe, and the space
    // between them is filled.
    const std::vector<StrokeInput> strokes{{line({0, 0}, {100, 0}), 3.0},
                                           {line({0, 8 + 3 + 4}, {100, 15}), 3.0}};
    const auto region = silhouette(strokes);
    QVERIFY(region.hasValue());
    QCOMPARE(region->size(), std::size_t(1));
    QVERIFY(inside(*region, Eigen::RowVector2d(50, 7.5)));
}

void TestSilhouette::partsDrawnApartStayLobes()
{
    const std::vector<StrokeInput> strokes{{arc(60, 40.0, {0, 0}), 3.0},
                                           {arc(60, 40.0, {200, 0}), 3.0},
                                           {line({400, -50}, {400, 50}), 3.0}};
    const auto region = silhouette(strokes);
    QVERIFY(region.hasValue());
    checkRegion(*region);
    QCOMPARE(region->size(), std::size_t(3));
    QVERIFY(!inside(*region, Eigen::RowVector2d(100, 0))); // no hull between lobes
    checkCoverage(*region, strokes, {});
}

void TestSilhouette::selfCrossingAndRepeatedPoints()
{
    // A figure eight drawn twice over, every point repeated three times.
    const Eigen::MatrixX2d eight = arc(300, 80.0, {0, 0}, 0, 4 * M_PI);
    Eigen::MatrixX2d figure(eight.rows() * 3, 2);
    for (Eigen::Index i = 0; i < eight.rows(); ++i) {
        const double t = 4 * M_PI * double(i) / double(eight.rows() - 1);
        const Eigen::RowVector2d p(80 * std::sin(t), 80 * std::sin(t) * std::cos(t));
        figure.row(3 * i) = figure.row(3 * i + 1) = figure.row(3 * i + 2) = p;
    }
    const std::vector<StrokeInput> strokes{{figure, 2.0}};
    const auto region = silhouette(strokes);
    QVERIFY(region.hasValue());
    checkRegion(*region);
    checkCoverage(*region, strokes, {});
    QVERIFY(inside(*region, Eigen::RowVector2d(40, 0))); // both loops filled
    QVERIFY(inside(*region, Eigen::RowVector2d(-40, 0)));
}

void TestSilhouette::marginAndGapScaleTheArea()
{
    const std::vector<StrokeInput> strokes{{line({0, 0}, {300, 100}), 2.0}};
    SilhouetteOptions thin, wide;
    thin.margin = 1.0;
    wide.margin = 6.0;
    const auto a = silhouette(strokes, thin), b = silhouette(strokes, wide);
    QVERIFY(a.hasValue() && b.hasValue());
    QVERIFY(regionArea(*b) > regionArea(*a) * 2.0);
    checkCoverage(*a, strokes, thin);
    checkCoverage(*b, strokes, wide);
    // Translation changes nothing but the position.
    std::vector<StrokeInput> moved = strokes;
    moved[0].points.rowwise() += Eigen::RowVector2d(-5000.25, 12345.5);
    const auto c = silhouette(moved, thin);
    QVERIFY(c.hasValue());
    QVERIFY(std::abs(regionArea(*c) - regionArea(*a)) < 1e-3 * regionArea(*a));
}

// regionContains agrees with the tests' own even-odd check everywhere on a grid, over a filled
// outline and over concentric rings that keep their hole; empty and flat regions hold nothing.
void TestSilhouette::regionContainsItsInside()
{
    const std::vector<StrokeInput> outline{{finbook::test::circle(96, 100, {0, 0}), 3.0}};
    const auto filled = silhouette(outline, SilhouetteOptions());
    QVERIFY(filled.hasValue());
    QVERIFY(regionContains(*filled, 0, 0));
    QVERIFY(!regionContains(*filled, 130, 0));

    std::vector<StrokeInput> rings;
    for (double r = 100.0; r <= 160.0; r += 5.0)
        rings.push_back({arc(240, r, {0, 0}), 3.0});
    SilhouetteOptions keepHoles;
    keepHoles.holes = HoleMode::KeepHoles;
    const auto annulus = silhouette(rings, keepHoles);
    QVERIFY(annulus.hasValue());
    QCOMPARE(holeCount(*annulus), std::size_t(1));
    QVERIFY(!regionContains(*annulus, 0, 0));    // the hole
    QVERIFY(regionContains(*annulus, 132.5, 0)); // the band

    int in = 0;
    for (const Region *region : {&*filled, &*annulus})
        for (double x = -180.5; x < 180; x += 7.0)
            for (double y = -180.5; y < 180; y += 7.0) {
                const bool expected = inside(*region, Eigen::RowVector2d(x, y));
                QCOMPARE(regionContains(*region, x, y), expected);
                in += expected;
            }
    QVERIFY(in > 500); // the grid did sample the insides

    QVERIFY(!regionContains(Region(), 0, 0));
    Polygon flat;
    flat.outer.resize(2, 2);
    flat.outer << 0, 0, 10, 0;
    QVERIFY(!regionContains(Region{flat}, 5, 0));
}

QTEST_APPLESS_MAIN(TestSilhouette)
#include "tst_silhouette.moc"
