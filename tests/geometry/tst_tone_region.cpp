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

// Non-zero winding of the rings around p.
bool covers(const Pieces &rings, const Eigen::Vector2d &p)
{
    int w = 0;
    for (int k = 0; k < rings.count(); ++k) {
        const int begin = rings.starts[std::size_t(k)], end = rings.starts[std::size_t(k) + 1];
        for (int i = begin, j = end - 1; i < end; j = i++) {
            const Eigen::Vector2d &a = rings.points[std::size_t(j)];
            const Eigen::Vector2d &b = rings.points[std::size_t(i)];
            const double side = (b - a).x() * (p - a).y() - (p - a).x() * (b - a).y();
            if (a.y() <= p.y() && b.y() > p.y() && side > 0.0)
                ++w;
            else if (a.y() > p.y() && b.y() <= p.y() && side < 0.0)
                --w;
        }
    }
    return w != 0;
}

// A concave outline: `points` spikes between radii r0 and r1 around c.
Eigen::MatrixX2d star(int points, double r0, double r1, Eigen::RowVector2d c)
{
    Eigen::MatrixX2d ring(2 * points, 2);
    for (int i = 0; i < 2 * points; ++i) {
        const double a = M_PI * i / points + 0.1, r = i % 2 ? r0 : r1;
        ring.row(i) = c + r * Eigen::RowVector2d(std::cos(a), std::sin(a));
    }
    return ring;
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
    void directCutEqualsClipper();
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

void TestToneRegion::directCutEqualsClipper()
{
    // A fill of one ring is cut by tracing where the outlines cross (shade/ring_clip.h); the
    // same clip with a second, far ring goes through Clipper. Both must draw the same tone:
    // a moved and shrunk disc, a star crossing the tone many times, a small disc inside the
    // tone (the clip's own ring is the cut), for shadows and lights at several levels.
    const Inflation shape = disc();
    const MeshEdges edges = meshEdges(shape.F);
    const Eigen::VectorXd lit = diffuseTerm(shape.normal, lightDirection(30.0, 35.0));
    const Eigen::MatrixX2d far = circle(8, 3.0, {900.0, 900.0});
    const std::vector<Eigen::MatrixX2d> clips = {circle(96, kRadius - 5.0, {6.0, 0.0}),
                                                 star(9, 55.0, 104.0, {-3.0, 2.0}),
                                                 circle(40, 12.0, {-50.0, -30.0})};
    int compared = 0;
    for (const Eigen::MatrixX2d &clip : clips)
        for (double t : {0.2, 0.45, 0.7})
            for (const double sign : {-1.0, 1.0}) {
                const Pieces direct =
                    toneRegion(shape.V, shape.F, edges, sign * lit, sign * t, {clip});
                const Pieces clipper =
                    toneRegion(shape.V, shape.F, edges, sign * lit, sign * t, {clip, far});
                const double a = ringsArea(direct), b = ringsArea(clipper);
                QVERIFY2(std::abs(a - b) < 1e-3 * std::abs(b) + 0.5,
                         qPrintable(QStringLiteral("%1 vs %2 px²").arg(a).arg(b)));
                int differ = 0;
                for (double y = -110.0; y < 110.0; y += 1.0)
                    for (double x = -110.0; x < 110.0; x += 1.0) {
                        const Eigen::Vector2d p(x + 0.37, y + 0.61);
                        differ += covers(direct, p) != covers(clipper, p) ? 1 : 0;
                    }
                QVERIFY2(differ <= 2, qPrintable(QString::number(differ)));
                compared += b > 1.0 ? 1 : 0;
            }
    QVERIFY(compared >= 12); // most cases have a tone to compare
}

QTEST_APPLESS_MAIN(TestToneRegion)
#include "tst_tone_region.moc"
