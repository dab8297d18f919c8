// Polyline and ring utilities: resampling, Douglas–Peucker, orientation, simplicity, repair.
#include "geometry_test_support.h"

#include <finbook/geometry/polygon_repair.h>
#include <finbook/geometry/polyline.h>
#include <finbook/geometry/simplicity.h>

#include <QtTest>

#include <cmath>
#include <limits>

using namespace finbook::geometry;

namespace {

using namespace finbook::test;

double distanceToPolyline(const Eigen::RowVector2d &p, const Eigen::MatrixX2d &line)
{
    double best = std::numeric_limits<double>::max();
    for (Eigen::Index i = 0; i + 1 < line.rows(); ++i) {
        const Eigen::RowVector2d a = line.row(i), ab = line.row(i + 1) - a;
        const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
        best = std::min(best, (p - (a + t * ab)).norm());
    }
    return best;
}

} // namespace

class TestPolyline : public QObject {
    Q_OBJECT
private slots:
    void cleanDropsNonFiniteAndRepeats();
    void resampleIsUniformAndKeepsEnds();
    void resampleClosedRing();
    void resampleDegenerateInputUnchanged();
    void douglasPeuckerStaysWithinTolerance();
    void douglasPeuckerRingKeepsThreePoints();
    void signedAreaFollowsConvention();
    void orientedFlipsOnlyWhenNeeded();
    void simplicityDetectsCrossingsAndTouches();
    void simplicityOfManyVertexRing();
    void repairBowtieGivesSimpleLobes();
    void repairKeepsHoleAndOrientation();
};

void TestPolyline::cleanDropsNonFiniteAndRepeats()
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Eigen::MatrixX2d in = rows({{0, 0}, {0, 0}, {nan, 1}, {1, 0}, {1, 0}, {1, 1}, {0, 0}});
    QCOMPARE(cleanPolyline(in).rows(), Eigen::Index(4));
    const Eigen::MatrixX2d ring = cleanPolyline(in, 0.0, true);
    QCOMPARE(ring.rows(), Eigen::Index(3)); // the closing repeat of (0,0) goes too
    QVERIFY(ring.allFinite());
}

void TestPolyline::resampleIsUniformAndKeepsEnds()
{
    const Eigen::MatrixX2d line = rows({{0, 0}, {10, 0}, {10, 7.3}});
    const Eigen::MatrixX2d out = resample(line, 1.0);
    QCOMPARE(out.rows(), Eigen::Index(std::round(17.3) + 1));
    QVERIFY((out.row(0) - line.row(0)).norm() == 0.0);
    QVERIFY((out.row(out.rows() - 1) - line.row(2)).norm() == 0.0);
    // Consecutive samples are one arc-length step apart along the path (chords ≤ step).
    const double step = polylineLength(line) / double(out.rows() - 1);
    for (Eigen::Index i = 0; i + 1 < out.rows(); ++i)
        QVERIFY((out.row(i + 1) - out.row(i)).norm() <= step + 1e-12);
    QVERIFY(std::abs(polylineLength(out) - polylineLength(line)) < 0.2);
}

void TestPolyline::resampleClosedRing()
{
    const Eigen::MatrixX2d out = resample(circle(7, 50.0), 5.0, true);
    QVERIFY(std::abs(double(out.rows()) - polylineLength(circle(7, 50.0), true) / 5.0) <= 1.0);
    QVERIFY(isSimple(out));
}

void TestPolyline::resampleDegenerateInputUnchanged()
{
    const Eigen::MatrixX2d dot = rows({{3, 4}});
    QCOMPARE(resample(dot, 1.0), dot);
    const Eigen::MatrixX2d same = rows({{3, 4}, {3, 4}});
    QCOMPARE(resample(same, 1.0), same);
    QCOMPARE(resample(rows({{0, 0}, {1, 1}}), 0.0), rows({{0, 0}, {1, 1}}));
}

void TestPolyline::douglasPeuckerStaysWithinTolerance()
{
    Eigen::MatrixX2d wave(400, 2);
    for (int i = 0; i < 400; ++i)
        wave.row(i) << i, 20.0 * std::sin(i * 0.05) + 0.3 * std::sin(i * 1.7);
    for (double tolerance : {0.1, 1.0, 5.0}) {
        const Eigen::MatrixX2d kept = douglasPeucker(wave, tolerance);
        QVERIFY(kept.rows() < wave.rows());
        QCOMPARE(kept.row(0), wave.row(0));
        QCOMPARE(kept.row(kept.rows() - 1), wave.row(wave.rows() - 1));
        for (Eigen::Index i = 0; i < wave.rows(); ++i)
            QVERIFY(distanceToPolyline(wave.row(i), kept) <= tolerance + 1e-9);
    }
    QCOMPARE(douglasPeucker(rows({{0, 0}, {1, 0}, {2, 0}, {3, 0}}), 0.01).rows(), Eigen::Index(2));
}

void TestPolyline::douglasPeuckerRingKeepsThreePoints()
{
    const Eigen::MatrixX2d kept = douglasPeucker(circle(200, 100.0), 1000.0, true);
    QVERIFY(kept.rows() >= 3);
    const Eigen::MatrixX2d fine = douglasPeucker(circle(200, 100.0), 0.5, true);
    QVERIFY(fine.rows() < 200 && fine.rows() > 8);
    QVERIFY(isSimple(fine));
}

void TestPolyline::signedAreaFollowsConvention()
{
    // Shoelace on the coordinates as given: (0,0) → (1,0) → (1,1) is positive.
    const Eigen::MatrixX2d square = rows({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
    QCOMPARE(signedArea(square), 4.0);
    QVERIFY(isCounterClockwise(square));
    QCOMPARE(signedArea(square.colwise().reverse()), -4.0);
    // Far from the origin the area keeps its precision.
    const Eigen::MatrixX2d far = square.rowwise() + Eigen::RowVector2d(1e6, -1e6);
    QCOMPARE(signedArea(far), 4.0);
    QCOMPARE(signedArea(rows({{0, 0}, {1, 1}})), 0.0);
}

void TestPolyline::orientedFlipsOnlyWhenNeeded()
{
    const Eigen::MatrixX2d ring = circle(12, 3.0);
    QCOMPARE(oriented(ring, true), ring);
    QVERIFY(signedArea(oriented(ring, false)) < 0.0);
    QCOMPARE(oriented(oriented(ring, false), true).rows(), ring.rows());
}

void TestPolyline::simplicityDetectsCrossingsAndTouches()
{
    QVERIFY(isSimple(rows({{0, 0}, {4, 0}, {4, 4}, {0, 4}})));
    QVERIFY(!isSimple(rows({{0, 0}, {4, 4}, {4, 0}, {0, 4}})));         // bowtie
    QVERIFY(!isSimple(rows({{0, 0}, {4, 0}, {4, 0}, {4, 4}})));         // repeated vertex
    QVERIFY(!isSimple(rows({{0, 0}, {4, 0}, {2, 0}})));                 // flat
    QVERIFY(!isSimple(rows({{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}))); // vertex on an edge
    QVERIFY(!isSimple(rows({{0, 0}, {1, 1}})));                         // too few points
    // Two rings: apart, nested, touching, crossing.
    const Eigen::MatrixX2d a = rows({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
    QVERIFY(isSimple(std::vector<Eigen::MatrixX2d>{a, a.array() + 10.0}));
    QVERIFY(isSimple(std::vector<Eigen::MatrixX2d>{a, (a.array() * 0.5 + 1.0).matrix()}));
    QVERIFY(!isSimple(std::vector<Eigen::MatrixX2d>{a, (a.rowwise() + Eigen::RowVector2d(4, 0))}));
    QVERIFY(!isSimple(std::vector<Eigen::MatrixX2d>{a, a.array() + 2.0}));
    // Meeting at a corner: a pinch, allowed only on request; crossing never.
    const std::vector<Eigen::MatrixX2d> pinch{a, a.array() + 4.0};
    QVERIFY(!isSimple(pinch));
    QVERIFY(isSimple(pinch, Touching::AllowedAtPoints));
    QVERIFY(
        !isSimple(std::vector<Eigen::MatrixX2d>{a, a.array() + 2.0}, Touching::AllowedAtPoints));
    const std::vector<Eigen::MatrixX2d> sharedEdge{a, a.rowwise() + Eigen::RowVector2d(4, 1)};
    QVERIFY(!isSimple(sharedEdge, Touching::AllowedAtPoints));
}

void TestPolyline::simplicityOfManyVertexRing()
{
    Eigen::MatrixX2d ring = circle(20000, 500.0);
    QVERIFY(isSimple(ring));
    ring.row(10000) = 1.2 * ring.row(0); // a spike through the far side
    QVERIFY(!isSimple(ring));
}

void TestPolyline::repairBowtieGivesSimpleLobes()
{
    const auto region = repairRings({rows({{0, 0}, {40, 40}, {40, 0}, {0, 40}})},
                                    RepairOptions{FillRule::EvenOdd, 0.0, 0.0});
    QVERIFY(region.hasValue());
    QCOMPARE(region->size(), std::size_t(2));
    // The two triangles meet at the crossing point: a pinch, which meshing accepts.
    QVERIFY(isSimple(*region, Touching::AllowedAtPoints));
    QVERIFY(std::abs(regionArea(*region) - 800.0) < 1.0);
    for (const Polygon &p : *region)
        QVERIFY(signedArea(p.outer) > 0.0);
}

void TestPolyline::repairKeepsHoleAndOrientation()
{
    // Outer clockwise in the file's sense and hole with the same orientation: even-odd does
    // not care, the result is normalised.
    const Eigen::MatrixX2d outer = circle(64, 100.0).colwise().reverse();
    const Eigen::MatrixX2d hole = circle(32, 30.0).colwise().reverse();
    const auto region = repairRegion(Region{Polygon{outer, {hole}}});
    QVERIFY(region.hasValue());
    QCOMPARE(region->size(), std::size_t(1));
    QCOMPARE((*region)[0].holes.size(), std::size_t(1));
    QVERIFY(signedArea((*region)[0].outer) > 0.0);
    QVERIFY(signedArea((*region)[0].holes[0]) < 0.0);
    const double expected = std::abs(signedArea(outer)) - std::abs(signedArea(hole));
    QVERIFY(std::abs(regionArea(*region) - expected) < 0.01 * expected);
}

QTEST_APPLESS_MAIN(TestPolyline)
#include "tst_polyline.moc"
