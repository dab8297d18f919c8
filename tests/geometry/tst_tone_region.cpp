// Tone regions traced as contours (shade/tone_region.h): they stay inside the region they
// are clipped to, the set and its complement cover the region, and a terminator on a disc
// lit from the side is a smooth curve, not the zigzag of a coarse mesh's contour.
#include "geometry_test_support.h"

#include <finbook/geometry/inflate/inflation.h>
#include <finbook/geometry/shade/shading.h>
#include <finbook/geometry/shade/tone_region.h>

#include <QtTest>

#include <cmath>
#include <limits>

using namespace finbook::geometry;
using namespace finbook::test;

namespace {

constexpr double kRadius = 100.0;

Inflation disc(int targetVertices = 600)
{
    MeshOptions options;
    options.targetVertices = targetVertices;
    auto result = inflateRegion(Region{Polygon{circle(128, kRadius), {}}}, options);
    if (!result)
        qFatal("inflateRegion failed: %s", result.error().message.c_str());
    return std::move(*result);
}

// Largest turn (degrees) between consecutive edges at ring vertices farther than `margin`
// inside the disc (the contour itself, not where it meets the outline).
double worstTurn(const Pieces &rings, double margin)
{
    double worst = 0.0;
    for (int k = 0; k < rings.count(); ++k) {
        const int begin = rings.starts[std::size_t(k)], end = rings.starts[std::size_t(k) + 1];
        const int n = end - begin;
        for (int i = 0; i < n; ++i) {
            const Eigen::Vector2d &a = rings.points[std::size_t(begin + (i + n - 1) % n)];
            const Eigen::Vector2d &p = rings.points[std::size_t(begin + i)];
            const Eigen::Vector2d &b = rings.points[std::size_t(begin + (i + 1) % n)];
            if (p.norm() > kRadius - margin || (p - a).norm() < 1e-9 || (b - p).norm() < 1e-9)
                continue;
            const Eigen::Vector2d u = (p - a).normalized(), v = (b - p).normalized();
            const double turn = std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
            worst = std::max(worst, std::abs(turn) * 180.0 / M_PI);
        }
    }
    return worst;
}

Eigen::VectorXd litFromTheSide(const Inflation &shape)
{
    return diffuseTerm(shape.normal, lightDirection(0.0, 20.0));
}

} // namespace

class TestToneRegion : public QObject {
    Q_OBJECT
private slots:
    void meshEdgesPairTheTwoSides();
    void tonesStayInsideTheirRegion();
    void toneAndItsComplementCoverTheRegion();
    void terminatorIsASmoothCurve();
    void badInputGivesNothing();
};

void TestToneRegion::meshEdgesPairTheTwoSides()
{
    Eigen::MatrixX3i F(2, 3);
    F << 0, 1, 2, 0, 2, 3;
    const MeshEdges edges = meshEdges(F);
    QCOMPARE(edges.edgeCount, 5);
    QCOMPARE(edges.neighbour(0, 2), 1); // edge 2 → 0 of the first is 0 → 2 of the second
    QCOMPARE(edges.neighbour(1, 0), 0);
    QCOMPARE(edges.edge(0, 2), edges.edge(1, 0));
    QCOMPARE(edges.neighbour(0, 0), -1);
}

void TestToneRegion::tonesStayInsideTheirRegion()
{
    // The mesh is posed by another map than the fill's outline: here the region is the disc
    // moved 6 px right and shrunk by 5 px, so an unclipped tone would spill past its left side.
    const Inflation shape = disc();
    const Eigen::MatrixX2d region = circle(96, kRadius - 5.0, {6.0, 0.0});
    const Eigen::VectorXd lit = litFromTheSide(shape);
    const MeshEdges edges = meshEdges(shape.F);
    const Pieces shadow = toneRegion(shape.V, shape.F, edges, -lit, -0.3, {region});
    QVERIFY(shadow.count() >= 1);
    int outside = 0;
    for (const Eigen::Vector2d &p : shadow.points)
        outside += (p - Eigen::Vector2d(6.0, 0.0)).norm() > kRadius - 5.0 + 0.02 ? 1 : 0;
    QCOMPARE(outside, 0); // the region is convex: corners inside → the tone inside
    const Pieces raw = toneRegion(shape.V, shape.F, edges, -lit, -0.3, {});
    int spilled = 0;
    for (const Eigen::Vector2d &p : raw.points)
        spilled += (p - Eigen::Vector2d(6.0, 0.0)).norm() > kRadius - 5.0 + 0.02 ? 1 : 0;
    QVERIFY(spilled > 0); // without the clip it would spill (the test can fail)
    QVERIFY(ringsArea(shadow) < ringsArea(raw));
}

void TestToneRegion::toneAndItsComplementCoverTheRegion()
{
    const Inflation shape = disc();
    const Eigen::MatrixX2d region = circle(128, kRadius);
    Pieces whole;
    for (Eigen::Index i = 0; i < region.rows(); ++i)
        whole.points.emplace_back(region(i, 0), region(i, 1));
    whole.starts.push_back(int(region.rows()));
    const double area = ringsArea(whole);
    const Eigen::VectorXd lit = litFromTheSide(shape);
    const MeshEdges edges = meshEdges(shape.F);
    for (double t : {0.1, 0.3, 0.55, 0.8}) {
        const double dark = ringsArea(toneRegion(shape.V, shape.F, edges, -lit, -t, {region}));
        const double light = ringsArea(toneRegion(shape.V, shape.F, edges, lit, t, {region}));
        qInfo("t = %.2f: shadow %.0f + light %.0f = %.0f px² of %.0f", t, dark, light, dark + light,
              area);
        QVERIFY(dark > 0.0 && light > 0.0);
        QVERIFY2(std::abs(dark + light - area) < 0.002 * area, qPrintable(QString::number(t)));
    }
    // Below every value the tone is the whole region, above every value nothing.
    const double all = ringsArea(toneRegion(shape.V, shape.F, edges, lit, -1.0, {region}));
    QVERIFY(std::abs(all - area) < 0.002 * area);
    QCOMPARE(toneRegion(shape.V, shape.F, edges, lit, 2.0, {region}).count(), 0);
}

void TestToneRegion::terminatorIsASmoothCurve()
{
    // A coarse mesh (as the shading uses) lit from the right and low: the shadow's edge is
    // the projection of a circle on the hemisphere, an elliptic arc that meets the outline
    // tangentially (it turns sharply only there, so the turn is read 15 px inside).
    const Inflation shape = disc(300);
    const Eigen::VectorXd lit = litFromTheSide(shape);
    const MeshEdges edges = meshEdges(shape.F);
    const Eigen::MatrixX2d region = circle(128, kRadius);
    ToneOptions raw;
    raw.smoothingSteps = 0;
    const Pieces before = toneRegion(shape.V, shape.F, edges, -lit, -0.3, {region}, raw);
    const Pieces after = toneRegion(shape.V, shape.F, edges, -lit, -0.3, {region});
    const double turnBefore = worstTurn(before, 15.0), turnAfter = worstTurn(after, 15.0);
    // The analytic terminator: n · l = 0.3 with n = (x, y, h) / R, h = √(R² − x² − y²).
    const Eigen::Vector3d light = lightDirection(0.0, 20.0);
    double off = 0.0;
    int onContour = 0;
    for (const Eigen::Vector2d &p : after.points) {
        if (p.norm() > kRadius - 15.0)
            continue;
        const double h = std::sqrt(kRadius * kRadius - p.squaredNorm());
        off = std::max(off, std::abs((p.x() * light.x() + h * light.z()) / kRadius - 0.3));
        ++onContour;
    }
    qInfo("terminator: %d contour points, worst turn %.1f° raw, %.1f° smoothed, max |n·l − 0.3| "
          "%.3f",
          onContour, turnBefore, turnAfter, off);
    QVERIFY(onContour > 10);
    QVERIFY(turnAfter < 8.0);
    QVERIFY(turnAfter <= turnBefore);
    QVERIFY(off < 0.02);
}

void TestToneRegion::badInputGivesNothing()
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Eigen::MatrixX2d V(3, 2);
    V << 0, 0, 10, 0, 0, 10;
    Eigen::MatrixX3i F(1, 3);
    F << 0, 1, 2;
    const MeshEdges edges = meshEdges(F);
    Eigen::VectorXd value(3);
    value << 1.0, nan, 1.0;
    QCOMPARE(toneRegion(V, F, edges, value, 0.5, {}).count(), 0);
    QCOMPARE(toneRegion(V, F, MeshEdges{}, Eigen::VectorXd::Ones(3), 0.5, {}).count(), 0);
    const Pieces whole = toneRegion(V, F, edges, Eigen::VectorXd::Ones(3), 0.5, {});
    QCOMPARE(whole.count(), 1);
    QVERIFY(std::abs(ringsArea(whole) - 50.0) < 1e-9);
}

QTEST_APPLESS_MAIN(TestToneRegion)
#include "tst_tone_region.moc"
