// Shading from inflation (shade/shading.h, shade/pose.h): the light's side is the bright
// side, a posed limb is shaded as the same limb drawn in that pose, the tone pieces cover
// exactly the super-level set, and degenerate input stays finite.
#include "geometry_test_support.h"
#include "inflate_test_support.h"

#include <finbook/geometry/inflate/inflation.h>
#include <finbook/geometry/object_mesh.h>
#include <finbook/geometry/shade/pose.h>
#include <finbook/geometry/shade/shading.h>

#include <QtTest>

#include <cmath>
#include <limits>

using namespace finbook::geometry;
using namespace finbook::test;

namespace {

Inflation inflated(const Region &region)
{
    auto result = inflateRegion(region);
    if (!result)
        qFatal("inflateRegion failed: %s", result.error().message.c_str());
    return std::move(*result);
}

Eigen::Matrix2d rotation(double angle)
{
    Eigen::Matrix2d r;
    r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    return r;
}

double piecesArea(const Pieces &pieces)
{
    double area = 0.0;
    for (int k = 0; k < pieces.count(); ++k)
        for (int i = pieces.starts[std::size_t(k)]; i < pieces.starts[std::size_t(k) + 1]; ++i) {
            const int j =
                i + 1 < pieces.starts[std::size_t(k) + 1] ? i + 1 : pieces.starts[std::size_t(k)];
            const Eigen::Vector2d &a = pieces.points[std::size_t(i)];
            const Eigen::Vector2d &b = pieces.points[std::size_t(j)];
            area += 0.5 * (a.x() * b.y() - a.y() * b.x());
        }
    return area;
}

// The limb of the pose tests: a capsule along x, 240 px long, 60 px wide, as a mesh.
Inflation limb()
{
    return inflated(Region{Polygon{capsuleRing(120.0, 30.0, 24), {}}});
}

// Controls as a drawing gives them: the limb's outline sampled every few px.
Eigen::MatrixX2d outlineControls()
{
    const Eigen::MatrixX2d ring = capsuleRing(120.0, 30.0, 24);
    std::vector<Eigen::Vector2d> points;
    for (Eigen::Index i = 0; i < ring.rows(); ++i) {
        const Eigen::Vector2d a = ring.row(i), b = ring.row((i + 1) % ring.rows());
        const int steps = std::max(1, int(std::ceil((b - a).norm() / 4.0)));
        for (int s = 0; s < steps; ++s)
            points.push_back(a + (b - a) * double(s) / steps);
    }
    Eigen::MatrixX2d controls(Eigen::Index(points.size()), 2);
    for (std::size_t i = 0; i < points.size(); ++i)
        controls.row(Eigen::Index(i)) = points[i].transpose();
    return controls;
}

} // namespace

class TestShading : public QObject {
    Q_OBJECT
private slots:
    void lightDirectionIsUnitAndOnTheNamedSide();
    void discLitFromTheLeftIsBrighterOnItsLeft();
    void rimLightsTheOutlineAwayFromTheLight();
    void rigidPoseMovesAndTurnsExactly();
    void posedLimbShadesAsTheLimbDrawnInThatPose();
    void bentLimbKeepsItsShadingAwayFromTheJoint();
    void piecesCoverTheSuperLevelSet();
    void degenerateInputStaysFinite();
};

void TestShading::lightDirectionIsUnitAndOnTheNamedSide()
{
    const Eigen::Vector3d left = lightDirection(180.0, 0.0);
    QVERIFY(std::abs(left.norm() - 1.0) < 1e-12);
    QVERIFY(left.x() < -0.999);
    const Eigen::Vector3d above = lightDirection(90.0, 30.0);
    QVERIFY(above.y() < -0.8); // canvas y points down: from above is −y
    QVERIFY(above.z() > 0.49 && above.z() < 0.51);
    const Eigen::Vector3d fallback = lightDirection(std::numeric_limits<double>::quiet_NaN(), 0.0);
    QVERIFY(fallback.allFinite());
    QVERIFY(std::abs(fallback.norm() - 1.0) < 1e-12);
}

void TestShading::discLitFromTheLeftIsBrighterOnItsLeft()
{
    const Inflation disc = inflated(Region{Polygon{circle(96, 100.0), {}}});
    const Eigen::VectorXd lit = diffuseTerm(disc.normal, lightDirection(180.0, 30.0));
    double left = 0.0, right = 0.0;
    int nLeft = 0, nRight = 0;
    for (Eigen::Index i = 0; i < disc.V.rows(); ++i) {
        if (disc.V(i, 0) < -20.0) {
            left += lit(i);
            ++nLeft;
        } else if (disc.V(i, 0) > 20.0) {
            right += lit(i);
            ++nRight;
        }
    }
    QVERIFY(nLeft > 50 && nRight > 50);
    qInfo("disc lit from the left: mean %.3f on the left, %.3f on the right", left / nLeft,
          right / nRight);
    QVERIFY(left / nLeft > right / nRight + 0.3);
    // The brightest vertex faces the light: left of the centre, on the horizontal axis.
    Eigen::Index brightest = 0;
    lit.maxCoeff(&brightest);
    QVERIFY(disc.V(brightest, 0) < -30.0);
    QVERIFY(std::abs(disc.V(brightest, 1)) < 20.0);
}

void TestShading::rimLightsTheOutlineAwayFromTheLight()
{
    const Inflation disc = inflated(Region{Polygon{circle(96, 100.0), {}}});
    const Eigen::VectorXd rim = rimTerm(disc.normal, lightDirection(180.0, 30.0));
    QVERIFY(rim.allFinite() && rim.minCoeff() >= 0.0 && rim.maxCoeff() <= 1.0);
    for (Eigen::Index i = 0; i < disc.V.rows(); ++i) {
        if (!disc.outline(i))
            continue;
        if (disc.V(i, 0) > 90.0) // far side from a light on the left
            QVERIFY(rim(i) > 0.9);
        if (disc.V(i, 0) < -50.0)
            QCOMPARE(rim(i), 0.0);
    }
    Eigen::Index top = 0;
    disc.height.maxCoeff(&top);
    QVERIFY(rim(top) < 0.05);
}

void TestShading::rigidPoseMovesAndTurnsExactly()
{
    const Inflation rest = limb();
    const Eigen::MatrixX2d controls = outlineControls();
    const PoseWeights weights = poseWeights(rest.V, controls);
    // At rest: identity.
    const PosedPoints same = applyPose(weights, controls);
    QVERIFY((same.V - rest.V).cwiseAbs().maxCoeff() < 1e-9);
    QVERIFY(same.angle.cwiseAbs().maxCoeff() < 1e-12);
    // A rotation by 70° and a move: every point and every angle exactly.
    const double angle = 70.0 * M_PI / 180.0;
    const Eigen::Matrix2d r = rotation(angle);
    const Eigen::RowVector2d move(300.0, -40.0);
    const Eigen::MatrixX2d shown = (controls * r.transpose()).rowwise() + move;
    const PosedPoints posed = applyPose(weights, shown);
    const Eigen::MatrixX2d expected = (rest.V * r.transpose()).rowwise() + move;
    QVERIFY((posed.V - expected).cwiseAbs().maxCoeff() < 1e-8);
    QVERIFY((posed.angle.array() - angle).abs().maxCoeff() < 1e-9);
}

void TestShading::posedLimbShadesAsTheLimbDrawnInThatPose()
{
    const Inflation rest = limb();
    const Eigen::MatrixX2d controls = outlineControls();
    const double angle = -50.0 * M_PI / 180.0;
    const Eigen::Matrix2d r = rotation(angle);
    const Eigen::RowVector2d move(80.0, 200.0);
    const PosedPoints posed =
        applyPose(poseWeights(rest.V, controls), (controls * r.transpose()).rowwise() + move);
    // The same limb drawn in that pose: its own inflation, lit by the same screen light.
    const auto drawn = inflateMesh((rest.V * r.transpose()).rowwise() + move, rest.F);
    QVERIFY(drawn.hasValue());
    for (double azimuth : {0.0, 135.0, 200.0}) {
        const Eigen::Vector3d light = lightDirection(azimuth, 40.0);
        const Eigen::VectorXd a = diffuseTerm(rotateNormals(rest.normal, posed.angle), light);
        const Eigen::VectorXd b = diffuseTerm(drawn->normal, light);
        const double worst = (a - b).cwiseAbs().maxCoeff();
        qInfo("light %.0f°: max |posed − drawn| = %.2e", azimuth, worst);
        QVERIFY(worst < 1e-3);
    }
}

void TestShading::bentLimbKeepsItsShadingAwayFromTheJoint()
{
    // The right half of the limb turns 60° about its middle (an elbow), the turn spread over
    // the 80 px around it; the limb drawn bent is the rest mesh moved that way, inflated as it
    // is (its own outline, its own medial balls).
    const Inflation rest = limb();
    const Eigen::MatrixX2d controls = outlineControls();
    const double full = 60.0 * M_PI / 180.0;
    const auto bend = [&](const Eigen::MatrixX2d &points) {
        Eigen::MatrixX2d out = points;
        for (Eigen::Index i = 0; i < points.rows(); ++i) {
            const double t = std::clamp((points(i, 0) + 40.0) / 80.0, 0.0, 1.0);
            out.row(i) =
                (rotation(full * t * t * (3.0 - 2.0 * t)) * points.row(i).transpose()).transpose();
        }
        return out;
    };
    const PosedPoints posed = applyPose(poseWeights(rest.V, controls), bend(controls));
    const auto drawn = inflateMesh(bend(rest.V), rest.F);
    QVERIFY(drawn.hasValue());
    const Eigen::Vector3d light = lightDirection(135.0, 40.0);
    const Eigen::VectorXd a = diffuseTerm(rotateNormals(rest.normal, posed.angle), light);
    const Eigen::VectorXd b = diffuseTerm(drawn->normal, light);
    double worst = 0.0;
    int compared = 0;
    for (Eigen::Index i = 0; i < rest.V.rows(); ++i) {
        if (std::abs(rest.V(i, 0)) < 70.0) // where the elbow turns, and its width around it
            continue;
        worst = std::max(worst, std::abs(a(i) - b(i)));
        QVERIFY((posed.V.row(i) - bend(rest.V.row(i))).norm() < 0.5);
        ++compared;
    }
    qInfo("bent limb: %d vertices away from the joint, max |posed − drawn| = %.3f", compared,
          worst);
    QVERIFY(compared > 100);
    QVERIFY(worst < 0.05);
    // At the elbow itself the drawn limb's balls see the bend (the inner side is pinched), the
    // posed one keeps the straight limb's: close, not equal.
    const double mean = (a - b).cwiseAbs().mean();
    qInfo("bent limb: mean |posed − drawn| over all vertices = %.3f", mean);
    QVERIFY(mean < 0.05);
}

void TestShading::piecesCoverTheSuperLevelSet()
{
    // A 100 px square in two triangles, value = x / 100: the set x ≥ t has area 100·(100 − 100t).
    Eigen::MatrixX2d V(4, 2);
    V << 0, 0, 100, 0, 100, 100, 0, 100;
    Eigen::MatrixX3i F(2, 3);
    F << 0, 1, 2, 0, 2, 3;
    const Eigen::VectorXd value = V.col(0) / 100.0;
    for (double t : {-1.0, 0.0, 0.25, 0.5, 0.9, 1.0, 2.0}) {
        const Pieces pieces = superLevelPieces(V, F, value, t);
        const double expected = 100.0 * 100.0 * std::clamp(1.0 - t, 0.0, 1.0);
        QVERIFY2(std::abs(piecesArea(pieces) - expected) < 1e-9, qPrintable(QString::number(t)));
        for (int k = 0; k < pieces.count(); ++k) {
            const int size = pieces.starts[std::size_t(k) + 1] - pieces.starts[std::size_t(k)];
            QVERIFY(size >= 3 && size <= 4);
        }
    }
}

void TestShading::degenerateInputStaysFinite()
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Eigen::MatrixX2d points(3, 2);
    points << 0, 0, 10, 0, nan, 5;
    // No control at all: points stay where they are.
    const PosedPoints none =
        applyPose(poseWeights(points, Eigen::MatrixX2d(0, 2)), Eigen::MatrixX2d(0, 2));
    QVERIFY(none.V.topRows(2).isApprox(points.topRows(2)));
    QVERIFY(none.V.allFinite() && none.angle.allFinite());
    // One control, repeated controls, a NaN control and a NaN posed control.
    Eigen::MatrixX2d controls(4, 2);
    controls << 5, 5, 5, 5, nan, 0, 5, 5;
    Eigen::MatrixX2d shown = controls;
    shown.row(0) << 8, 9;
    shown.row(1) << nan, nan;
    const PosedPoints posed = applyPose(poseWeights(points, controls), shown);
    QVERIFY(posed.V.allFinite() && posed.angle.allFinite());
    // Controls so far away that the squared distance overflows: the points stay put.
    Eigen::MatrixX2d far(2, 2);
    far << 1e200, 0, 0, -1e200;
    const PosedPoints away = applyPose(poseWeights(points, far), far * 0.5);
    QVERIFY(away.V.topRows(2).isApprox(points.topRows(2)));
    QVERIFY(away.V.allFinite() && away.angle.allFinite());
    // Pieces skip triangles with a NaN corner or a bad index.
    Eigen::MatrixX3i F(2, 3);
    F << 0, 1, 2, 0, 1, 7;
    QCOMPARE(superLevelPieces(points, F, Eigen::VectorXd::Ones(3), 0.5).count(), 0);
}

QTEST_APPLESS_MAIN(TestShading)
#include "tst_shading.moc"
