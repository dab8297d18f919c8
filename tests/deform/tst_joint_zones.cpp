// Joint zones (issue 21): the flesh around a joint where bones meet is held by no bone, in the
// weights' boundary (SkinningOptions::jointFree) or in the rigid mode's pins only
// (withJointZones).
#include "arm_mesh.h"
#include "grid_mesh.h"

#include <finbook/deform/skeleton/linear_blend_skinning.h>
#include <finbook/deform/skeleton/rigid_skinning.h>
#include <finbook/deform/skeleton/skeleton.h>
#include <finbook/deform/skeleton/skinning_weights.h>

#include <QTest>

#include <cmath>

using namespace finbook::deform;
using finbook::test::Arm;
using finbook::test::gridMesh;

class TestJointZones : public QObject {
    Q_OBJECT
private slots:
    void zonesFreeTheElbowOnly();
    void pinsOnlyKeepTheWeights();
    void everyBoneStillHoldsAVertex();
    void badRadiiAreTypedErrors();
};

void TestJointZones::zonesFreeTheElbowOnly()
{
    const Arm arm;
    SkinningOptions options;
    options.jointRadius = arm.radius;
    options.jointFree = 1.0;
    const auto plain = computeSkinningWeights(arm.mesh.V, arm.mesh.F, arm.skeleton);
    const auto zoned = computeSkinningWeights(arm.mesh.V, arm.mesh.F, arm.skeleton, options);
    QVERIFY(plain && zoned);
    int freed = 0;
    for (Eigen::Index v = 0; v < arm.mesh.V.rows(); ++v) {
        if (arm.elbowDistance(v) < 20.0)
            QCOMPARE((*zoned)->owner(v), -1);
        else
            QCOMPARE((*zoned)->owner(v), (*plain)->owner(v));
        freed += (*plain)->owner(v) >= 0 && (*zoned)->owner(v) < 0 ? 1 : 0;
    }
    QVERIFY(freed > 0);
    // Still a partition of unity in [0, 1].
    QVERIFY(((*zoned)->W.rowwise().sum().array() - 1.0).abs().maxCoeff() < 1e-9);
    QVERIFY((*zoned)->W.minCoeff() >= -1e-12 && (*zoned)->W.maxCoeff() <= 1.0 + 1e-12);
}

void TestJointZones::pinsOnlyKeepTheWeights()
{
    const Arm arm;
    const auto plain = computeSkinningWeights(arm.mesh.V, arm.mesh.F, arm.skeleton);
    QVERIFY(plain);
    const SkinningWeights pins = withJointZones(**plain, arm.mesh.V, arm.skeleton, arm.radius);
    QVERIFY(pins.W == (*plain)->W);
    const auto plainPins = rigidSkinPins(**plain, arm.mesh.V, arm.mesh.F);
    const auto zonedPins = rigidSkinPins(pins, arm.mesh.V, arm.mesh.F);
    QVERIFY(plainPins && zonedPins);
    QVERIFY(zonedPins->size() < plainPins->size());
    for (const int v : *zonedPins)
        QVERIFY(arm.elbowDistance(v) >= 20.0);
    // Bent 60° at the elbow, the rigid mode keeps the forearm rigid and flips nothing.
    const auto rigid = rigidSkinPrecompute(arm.mesh.V, arm.mesh.F, pins);
    QVERIFY(rigid);
    SkeletonPose pose = restPose(arm.skeleton);
    pose.angles(2) = M_PI / 3;
    const auto posed = forwardKinematics(arm.skeleton, pose);
    Eigen::MatrixX2d U = arm.mesh.V;
    QVERIFY(rigidSkinSolve(**rigid, *posed, U));
    for (Eigen::Index t = 0; t < arm.mesh.F.rows(); ++t) {
        auto area = [&](const Eigen::MatrixX2d &P) {
            const Eigen::RowVector2d a = P.row(arm.mesh.F(t, 1)) - P.row(arm.mesh.F(t, 0));
            const Eigen::RowVector2d b = P.row(arm.mesh.F(t, 2)) - P.row(arm.mesh.F(t, 0));
            return a.x() * b.y() - a.y() * b.x();
        };
        QVERIFY(area(arm.mesh.V) * area(U) > 0.0);
    }
}

void TestJointZones::everyBoneStillHoldsAVertex()
{
    // Zones so large they cover the whole arm: each bone keeps one vertex.
    const Arm arm;
    const auto plain = computeSkinningWeights(arm.mesh.V, arm.mesh.F, arm.skeleton);
    QVERIFY(plain);
    const SkinningWeights pins =
        withJointZones(**plain, arm.mesh.V, arm.skeleton, arm.radius, 100.0);
    for (const int bone : {1, 2})
        QCOMPARE(int((pins.owner.array() == bone).count()), 1);
    SkinningOptions options;
    options.jointRadius = arm.radius;
    options.jointFree = 100.0;
    const auto zoned = computeSkinningWeights(arm.mesh.V, arm.mesh.F, arm.skeleton, options);
    QVERIFY(zoned);
    for (const int bone : {1, 2})
        QVERIFY((*zoned)->owner.cwiseEqual(bone).count() >= 1);
}

void TestJointZones::badRadiiAreTypedErrors()
{
    const Arm arm;
    SkinningOptions options;
    options.jointFree = 1.0;
    options.jointRadius = Eigen::VectorXd::Constant(2, 10.0); // J = 3
    QCOMPARE(computeSkinningWeights(arm.mesh.V, arm.mesh.F, arm.skeleton, options).error().code,
             DeformErrorCode::InvalidSkeleton);
    options.jointRadius = Eigen::Vector3d(1.0, NAN, 1.0);
    QCOMPARE(computeSkinningWeights(arm.mesh.V, arm.mesh.F, arm.skeleton, options).error().code,
             DeformErrorCode::InvalidSkeleton);
    options.jointRadius = arm.radius;
    options.jointFree = -1.0;
    QCOMPARE(computeSkinningWeights(arm.mesh.V, arm.mesh.F, arm.skeleton, options).error().code,
             DeformErrorCode::InvalidSkeleton);
}

QTEST_APPLESS_MAIN(TestJointZones)
#include "tst_joint_zones.moc"
