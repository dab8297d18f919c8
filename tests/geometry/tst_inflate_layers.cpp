// Layers of one object (inflate/layers.h): two overlapping discs drawn as two strokes, the
// second over the first, inflate as two domes, each the hemisphere of its own disc, not one
// blob and not the planar map's pieces inflated one by one.
#include "geometry_test_support.h"

#include <finbook/geometry/inflate/inflation.h>
#include <finbook/geometry/inflate/layers.h>
#include <finbook/geometry/regions.h>

#include <QtTest>

#include <cmath>

using namespace finbook::geometry;
using namespace finbook::test;

namespace {

// Body: a disc of radius 100 at the origin; arm: a disc of radius 60 at (110, 0), drawn later.
const Eigen::Vector2d kBody(0.0, 0.0), kArm(110.0, 0.0);
constexpr double kBodyRadius = 100.0, kArmRadius = 60.0;

StrokeInput closedStroke(const Eigen::Vector2d &centre, double radius)
{
    Eigen::MatrixX2d ring = circle(160, radius, centre.transpose());
    StrokeInput s;
    s.points.resize(ring.rows() + 1, 2);
    s.points << ring, ring.row(0);
    s.width = 2.0;
    return s;
}

// Worst |h − √(R² − |p − c|²)| / R over the mesh vertices of `inflation` inside `face`
// (farther than 8 px from its outline, where the pen's width and the mesh's steps show).
double worstAgainstDisc(const Inflation &inflation, const Face &face, const Eigen::Vector2d &c,
                        double radius, int &samples)
{
    double worst = 0.0;
    samples = 0;
    const Region own{face.polygon};
    for (Eigen::Index i = 0; i < inflation.V.rows(); ++i) {
        const Eigen::Vector2d p = inflation.V.row(i).transpose();
        if (!regionContains(own, p.x(), p.y()) || (p - c).norm() > radius - 8.0)
            continue;
        bool nearOther = false; // keep off the other disc's outline too
        for (const auto &[centre, r] : {std::pair{kBody, kBodyRadius}, std::pair{kArm, kArmRadius}})
            nearOther = nearOther || std::abs((p - centre).norm() - r) < 8.0;
        if (nearOther)
            continue;
        const double expected = std::sqrt(radius * radius - (p - c).squaredNorm());
        worst = std::max(worst, std::abs(inflation.height(i) - expected) / radius);
        ++samples;
    }
    return worst;
}

} // namespace

class TestInflateLayers : public QObject {
    Q_OBJECT
private slots:
    void overlappingDiscsInflateAsTwoDomes();
    void aFaceNoSingleStrokeClosesIsItsOwnLayer();
};

void TestInflateLayers::overlappingDiscsInflateAsTwoDomes()
{
    const std::vector<StrokeInput> strokes{closedStroke(kBody, kBodyRadius),
                                           closedStroke(kArm, kArmRadius)};
    RegionsOptions options;
    options.closeGap = 0.0;
    const auto regions = computeRegions(strokes, options);
    QVERIFY(regions.hasValue());
    QCOMPARE(regions->faces.size(), std::size_t(3)); // body only, arm over body, arm beside
    const std::vector<Layer> layers = strokeLayers(strokes, regions->closeGap);
    QCOMPARE(layers.size(), std::size_t(2));
    int checked = 0;
    for (int f = 0; f < 3; ++f) {
        const Face &face = regions->faces[std::size_t(f)];
        const bool inArm = (face.seed - kArm).norm() < kArmRadius;
        const Eigen::Vector2d centre = inArm ? kArm : kBody;
        const double radius = inArm ? kArmRadius : kBodyRadius;
        QCOMPARE(faceLayer(layers, *regions, f), inArm ? 1 : 0); // the arm lies on top
        const auto layered = inflateRegion(layerRegion(layers, *regions, f));
        QVERIFY(layered.hasValue());
        int samples = 0;
        const double worst = worstAgainstDisc(*layered, face, centre, radius, samples);
        // The face inflated by itself: its own outline is the other disc's too.
        const auto alone = inflateRegion(Region{face.polygon});
        QVERIFY(alone.hasValue());
        int aloneSamples = 0;
        const double aloneWorst = worstAgainstDisc(*alone, face, centre, radius, aloneSamples);
        qInfo("face %d (%s): %d vertices, worst |h − analytic| %.1f%% of R as a layer, %.1f%% "
              "inflated alone",
              f, inArm ? "arm" : "body", samples, 100.0 * worst, 100.0 * aloneWorst);
        QVERIFY(samples > 20);
        QVERIFY(worst < 0.04);
        if (face.area < M_PI * kArmRadius * kArmRadius * 0.9) // the pieces the other cuts
            QVERIFY(aloneWorst > 0.1);
        ++checked;
    }
    QCOMPARE(checked, 3);
}

void TestInflateLayers::aFaceNoSingleStrokeClosesIsItsOwnLayer()
{
    // A square drawn as two open strokes (two L shapes): no stroke closes anything alone.
    StrokeInput a, b;
    a.points = rows({{0, 0}, {100, 0}, {100, 100}});
    b.points = rows({{100, 100}, {0, 100}, {0, 0}});
    const std::vector<StrokeInput> strokes{a, b};
    RegionsOptions options;
    options.closeGap = 0.0;
    const auto regions = computeRegions(strokes, options);
    QVERIFY(regions.hasValue());
    QCOMPARE(regions->faces.size(), std::size_t(1));
    const std::vector<Layer> layers = strokeLayers(strokes, regions->closeGap);
    QVERIFY(layers.empty());
    QCOMPARE(faceLayer(layers, *regions, 0), -1);
    QVERIFY(std::abs(regionArea(layerRegion(layers, *regions, 0)) - regions->faces[0].area) < 1e-6);
    QVERIFY(layerRegion(layers, *regions, 5).empty());
}

QTEST_APPLESS_MAIN(TestInflateLayers)
#include "tst_inflate_layers.moc"
