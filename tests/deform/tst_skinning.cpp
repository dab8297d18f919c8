// Skinning weights (harmonic, bone boundary conditions), linear blend skinning and the rigid
// (ARAP with bone pins) mode: bounds, partition of unity, locality, rest pose, bone turns,
// random poses, and what the rigid mode buys at a bent joint.
#include "grid_mesh.h"
#include "skin_test_support.h"

#include <finbook/deform/skeleton/linear_blend_skinning.h>
#include <finbook/deform/skeleton/rigid_skinning.h>
#include <finbook/deform/skeleton/skeleton.h>
#include <finbook/deform/skeleton/skinning_weights.h>
#include <finbook/geometry/embedding.h>
#include <finbook/geometry/object_mesh.h>

#include <QTest>

#include <cmath>
#include <random>

using namespace finbook::deform;
using finbook::geometry::ObjectMesh;

namespace {

// A shape meshed by geometry; the outline may run either way round.
ObjectMesh meshed(Eigen::MatrixX2d outline)
{
    double shoelace = 0.0;
    for (Eigen::Index i = 0, j = outline.rows() - 1; i < outline.rows(); j = i++)
        shoelace += outline(j, 0) * outline(i, 1) - outline(i, 0) * outline(j, 1);
    if (shoelace < 0.0)
        outline = outline.colwise().reverse().eval();
    auto mesh = finbook::geometry::buildObjectMesh(finbook::geometry::Region{{outline, {}}});
    if (!mesh)
        qFatal("meshing failed: %s", mesh.error().message.c_str());
    return *mesh;
}

// Two fingers 45 px wide and 150 px long over a palm, with a 10 px gap between them.
ObjectMesh twoFingers()
{
    return meshed(finbook::test::rows(
        {{0, 200}, {100, 200}, {100, 0}, {55, 0}, {55, 150}, {45, 150}, {45, 0}, {0, 0}}));
}

// Root in the palm, a bone to each finger's base and one up each finger.
Skeleton twoFingerSkeleton()
{
    Eigen::MatrixX2d joints =
        finbook::test::rows({{50, 175}, {22.5, 150}, {22.5, 10}, {77.5, 150}, {77.5, 10}});
    Eigen::VectorXi parent(5);
    parent << -1, 0, 1, 0, 3;
    return *makeSkeleton(joints, parent);
}

// A 300×40 limb along x with joints every `length` px on its midline.
ObjectMesh limb()
{
    return meshed(finbook::test::rows({{0, 0}, {0, 40}, {300, 40}, {300, 0}}));
}

Skeleton limbSkeleton(int bones)
{
    Eigen::MatrixX2d joints(bones + 1, 2);
    Eigen::VectorXi parent(bones + 1);
    for (int j = 0; j <= bones; ++j) {
        joints.row(j) << 10.0 + 280.0 * j / bones, 20.0;
        parent(j) = j - 1;
    }
    return *makeSkeleton(joints, parent);
}

std::shared_ptr<const SkinningWeights> weightsOf(const ObjectMesh &mesh, const Skeleton &skeleton)
{
    auto weights = computeSkinningWeights(mesh.V, mesh.F, skeleton);
    if (!weights)
        qFatal("weights failed: %s", weights.error().message.c_str());
    return *weights;
}

Eigen::MatrixX2d lbs(const Eigen::MatrixX2d &V, const SkinningWeights &weights,
                     const Skeleton &skeleton, const SkeletonPose &pose)
{
    Eigen::MatrixX2d U;
    skin(bindVertices(weights, V), *forwardKinematics(skeleton, pose), U);
    return U;
}

Eigen::MatrixX2d rigid(const RigidSkinning &rig, const Skeleton &skeleton, const SkeletonPose &pose)
{
    Eigen::MatrixX2d U;
    auto solved = rigidSkinSolve(rig, *forwardKinematics(skeleton, pose), U);
    if (!solved)
        qFatal("rigid solve failed: %s", solved.error().message.c_str());
    return U;
}

double area(const Eigen::MatrixX2d &U, const Eigen::MatrixX3i &F)
{
    double sum = 0.0;
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        const Eigen::RowVector2d a = U.row(F(t, 1)) - U.row(F(t, 0));
        const Eigen::RowVector2d b = U.row(F(t, 2)) - U.row(F(t, 0));
        sum += 0.5 * (a.x() * b.y() - a.y() * b.x());
    }
    return sum;
}

// Mean |length / rest − 1| over the triangle edges.
double edgeError(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F, const Eigen::MatrixX2d &U)
{
    double sum = 0.0;
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const int i = F(t, k), j = F(t, (k + 1) % 3);
            sum += std::abs((U.row(j) - U.row(i)).norm() / (V.row(j) - V.row(i)).norm() - 1.0);
        }
    }
    return sum / double(3 * F.rows());
}

void checkPartitionOfUnity(const SkinningWeights &w)
{
    QVERIFY(w.W.allFinite());
    QVERIFY(w.W.minCoeff() >= 0.0);
    QVERIFY(w.W.maxCoeff() <= 1.0);
    QVERIFY((w.W.rowwise().sum().array() - 1.0).abs().maxCoeff() <= 1e-9);
}

} // namespace

class TestSkinning : public QObject {
    Q_OBJECT

private slots:
    void weightsAreBoundedAndSumToOne();
    void everyBoneHoldsAVertex();
    void weightsStayInsideTheShape();
    void componentNoBoneReachesFollowsNearestBone();
    void chosenBonesAloneSkinTheMesh();
    void restPoseIsIdentity();
    void turningABoneTurnsItsTip();
    void boundPointsFollowTheirVertices();
    void randomPosesStayFinite();
    void rigidModeKeepsBentLimbBetterThanLbs();
    void invalidInputGivesTypedErrors();
    void cancellationStopsWeights();
    void realDataWeights();
};

void TestSkinning::weightsAreBoundedAndSumToOne()
{
    const ObjectMesh mesh = twoFingers();
    const auto w = weightsOf(mesh, twoFingerSkeleton());
    checkPartitionOfUnity(*w);
    QVERIFY(w->relativeResidual < 1e-10);
    QCOMPARE(w->W.col(0).maxCoeff(), 0.0); // the root has children: it is no handle
    // Harmonic, not piecewise constant: some vertices blend two bones.
    QVERIFY(((w->W.array() > 0.05) && (w->W.array() < 0.95)).rowwise().any().count() > 10);
}

void TestSkinning::everyBoneHoldsAVertex()
{
    // Bone 2 is far shorter than an edge and lies off every vertex.
    const auto g = finbook::test::gridMesh(6, 6, 60.0, 60.0);
    Eigen::MatrixX2d joints = finbook::test::rows({{5, 5}, {33, 33}, {33.5, 33.2}, {55, 55}});
    Eigen::VectorXi parent(4);
    parent << -1, 0, 1, 2;
    const Skeleton skeleton = *makeSkeleton(joints, parent);
    SkinningOptions options;
    options.reach = 0.1;
    auto w = computeSkinningWeights(g.V, g.F, skeleton, options);
    QVERIFY(w.hasValue());
    for (const int j : {1, 2, 3})
        QVERIFY((*w)->W.col(j).maxCoeff() == 1.0);
    QCOMPARE((*w)->active.size(), 3);
    checkPartitionOfUnity(**w);
}

void TestSkinning::weightsStayInsideTheShape()
{
    const ObjectMesh mesh = twoFingers();
    const auto w = weightsOf(mesh, twoFingerSkeleton());
    double harmonicLeak = 0.0, euclideanLeak = 0.0;
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
        if (!(mesh.V(v, 0) > 55.0 - 1e-9 && mesh.V(v, 1) < 75.0))
            continue; // upper half of the second finger
        harmonicLeak = std::max(harmonicLeak, w->W(v, 1) + w->W(v, 2));
        // Synfig-style inverse-square falloff from the bone segments, for comparison.
        double mine = 0.0, total = 0.0;
        const Eigen::Vector2d p = mesh.V.row(v).transpose();
        const double dA = std::abs(p.x() - 22.5), dB = std::abs(p.x() - 77.5);
        mine = 1.0 / (dA * dA + 1.0);
        total = mine + 1.0 / (dB * dB + 1.0);
        euclideanLeak = std::max(euclideanLeak, mine / total);
    }
    qInfo("first finger's weight in the second finger's upper half: harmonic %.2e, "
          "inverse-square distance %.3f",
          harmonicLeak, euclideanLeak);
    QVERIFY(harmonicLeak < 1e-3);
    QVERIFY(euclideanLeak > 0.2); // the comparison is meaningful: distance alone leaks
}

void TestSkinning::componentNoBoneReachesFollowsNearestBone()
{
    auto g = finbook::test::gridMesh(8, 4, 80.0, 40.0);
    const auto far = finbook::test::gridMesh(4, 4, 40.0, 40.0, 0.0, {200.0, 0.0});
    const int offset = finbook::test::appendMesh(g.V, g.F, far.V, far.F);
    const Skeleton skeleton = *makeSkeleton(finbook::test::rows({{5, 20}, {40, 20}, {75, 20}}),
                                            Eigen::Vector3i(-1, 0, 1));
    const auto w = *computeSkinningWeights(g.V, g.F, skeleton);
    checkPartitionOfUnity(*w);
    for (Eigen::Index v = offset; v < g.V.rows(); ++v)
        QCOMPARE(w->W(v, 2), 1.0);
    // Rigid mode pins it twice (ARAP can only translate a component with one pin) and so
    // turns it with its bone instead of leaving it behind.
    const auto pins = rigidSkinPins(*w, g.V, g.F);
    QVERIFY(pins.hasValue());
    QCOMPARE(((pins->array() >= offset)).count(), Eigen::Index(2));
    for (Eigen::Index v = 0; v < g.V.rows(); ++v)
        QVERIFY(w->owner(v) < 0 || (pins->array() == int(v)).any());
    const auto rig = *rigidSkinPrecompute(g.V, g.F, *w);
    SkeletonPose pose = restPose(skeleton);
    pose.angles(2) = 0.5;
    const Eigen::MatrixX2d U = rigid(*rig, skeleton, pose);
    const Eigen::MatrixX2d expected = lbs(g.V, *w, skeleton, pose);
    QVERIFY((U.bottomRows(far.V.rows()) - expected.bottomRows(far.V.rows())).cwiseAbs().maxCoeff() <
            1e-6);
}

void TestSkinning::chosenBonesAloneSkinTheMesh()
{
    // The hand's skeleton continues into an arm far below this object: only the hand's bones
    // may skin it, otherwise the arm's bones would grab the vertices nearest to them.
    const ObjectMesh mesh = twoFingers();
    const Skeleton hand = twoFingerSkeleton();
    Eigen::MatrixX2d joints(7, 2);
    joints << hand.joints, 50, 400, 50, 600;
    Eigen::VectorXi parent(7);
    parent << -1, 0, 1, 0, 3, 0, 5;
    const Skeleton skeleton = *makeSkeleton(joints, parent);
    const auto everything = *computeSkinningWeights(mesh.V, mesh.F, skeleton);
    QVERIFY(everything->W.col(6).maxCoeff() > 0.0);
    SkinningOptions options;
    options.bones = (Eigen::VectorXi(4) << 1, 2, 3, 4).finished();
    const auto chosen = *computeSkinningWeights(mesh.V, mesh.F, skeleton, options);
    checkPartitionOfUnity(*chosen);
    QCOMPARE(chosen->handles, options.bones);
    QCOMPARE(chosen->W.col(5).maxCoeff(), 0.0);
    QCOMPARE(chosen->W.col(6).maxCoeff(), 0.0);
    QVERIFY((chosen->W.leftCols(5) - weightsOf(mesh, hand)->W).cwiseAbs().maxCoeff() < 1e-12);
    options.bones = (Eigen::VectorXi(2) << 1, 9).finished();
    auto bad = computeSkinningWeights(mesh.V, mesh.F, skeleton, options);
    QVERIFY(!bad && bad.error().code == DeformErrorCode::InvalidIndex);
    options.bones = Eigen::VectorXi::Zero(1); // the root has children: no handle
    bad = computeSkinningWeights(mesh.V, mesh.F, skeleton, options);
    QVERIFY(!bad && bad.error().code == DeformErrorCode::InvalidSkeleton);
}

void TestSkinning::restPoseIsIdentity()
{
    const ObjectMesh mesh = twoFingers();
    const Skeleton skeleton = twoFingerSkeleton();
    const auto w = weightsOf(mesh, skeleton);
    QVERIFY((lbs(mesh.V, *w, skeleton, restPose(skeleton)) - mesh.V).cwiseAbs().maxCoeff() < 1e-9);
    const auto rig = *rigidSkinPrecompute(mesh.V, mesh.F, *w);
    QVERIFY((rigid(*rig, skeleton, restPose(skeleton)) - mesh.V).cwiseAbs().maxCoeff() < 1e-9);
}

void TestSkinning::turningABoneTurnsItsTip()
{
    const ObjectMesh mesh = limb();
    const Skeleton skeleton = limbSkeleton(3);
    const auto w = weightsOf(mesh, skeleton);
    const auto rig = *rigidSkinPrecompute(mesh.V, mesh.F, *w);
    const Eigen::Vector2d pivot = skeleton.joints.row(1).transpose();
    const Eigen::Vector2d tip = skeleton.joints.row(2).transpose();
    for (const double theta : {0.3, 1.0, -2.0}) {
        SkeletonPose pose = restPose(skeleton);
        pose.angles(2) = theta;
        const Eigen::MatrixX2d U = lbs(mesh.V, *w, skeleton, pose);
        const Eigen::MatrixX2d R = rigid(*rig, skeleton, pose);
        double worstLbs = 0.0, worstRigid = 0.0;
        int near = 0;
        for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
            const Eigen::Vector2d x = mesh.V.row(v).transpose();
            if ((x - tip).norm() > 10.0)
                continue;
            ++near;
            const auto turned = [&](const Eigen::MatrixX2d &P) {
                const Eigen::Vector2d a = x - pivot, b = P.row(v).transpose() - pivot;
                return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
            };
            worstLbs = std::max(worstLbs, std::abs(std::remainder(turned(U) - theta, 2 * M_PI)));
            worstRigid =
                std::max(worstRigid, std::abs(std::remainder(turned(R) - theta, 2 * M_PI)));
        }
        qInfo("θ = %.1f: %d points near the tip, worst turn error LBS %.2e rad, rigid %.2e rad",
              theta, near, worstLbs, worstRigid);
        QVERIFY(near > 5);
        QVERIFY(worstLbs < 1e-3);
        QVERIFY(worstRigid < 1e-3);
    }
}

void TestSkinning::boundPointsFollowTheirVertices()
{
    const ObjectMesh mesh = twoFingers();
    const Skeleton skeleton = twoFingerSkeleton();
    const auto w = weightsOf(mesh, skeleton);
    Eigen::MatrixX2d points;
    finbook::geometry::Embedding e = finbook::test::randomEmbedding(mesh.V, mesh.F, 500, points);
    points.row(0).setConstant(NAN); // an unlocatable point is bound where it was embedded
    const auto binding = bindPoints(*w, mesh.V, mesh.F, e, points);
    QVERIFY(binding.hasValue());
    SkeletonPose pose = restPose(skeleton);
    pose.angles << 0.2, -0.4, 0.3, 0.5, -0.6;
    pose.rootOffset << 12.0, -7.0;
    Eigen::MatrixX2d moved;
    QVERIFY(!skin(*binding, *forwardKinematics(skeleton, pose), moved));
    QVERIFY(moved.allFinite());
    // Skinning bound points and mapping the skinned mesh agree to within the blend's
    // non-linearity inside one small triangle.
    const Eigen::MatrixX2d viaMesh =
        finbook::geometry::applyEmbedding(e, lbs(mesh.V, *w, skeleton, pose), mesh.F);
    const double gap = (moved - viaMesh).rowwise().norm().maxCoeff();
    qInfo("bound points vs embedded skinned mesh: %.3f px", gap);
    QVERIFY(gap < 1.0);
    // And at rest they are exactly where they were.
    QVERIFY(!skin(*binding, *forwardKinematics(skeleton, restPose(skeleton)), moved));
    QVERIFY((moved.bottomRows(499) - points.bottomRows(499)).cwiseAbs().maxCoeff() < 1e-9);
}

void TestSkinning::randomPosesStayFinite()
{
    const ObjectMesh mesh = twoFingers();
    const Skeleton skeleton = twoFingerSkeleton();
    const auto w = weightsOf(mesh, skeleton);
    const auto rig = *rigidSkinPrecompute(mesh.V, mesh.F, *w);
    const SkinBinding binding = bindVertices(*w, mesh.V);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> angle(-10.0, 10.0), offset(-1e4, 1e4);
    PosedSkeleton posed;
    Eigen::MatrixX2d U, R;
    int nonFinite = 0, failed = 0;
    for (int k = 0; k < 10000; ++k) {
        SkeletonPose pose = restPose(skeleton);
        for (Eigen::Index j = 0; j < pose.angles.size(); ++j)
            pose.angles(j) = angle(random);
        pose.rootOffset << offset(random), offset(random);
        QVERIFY(!forwardKinematics(skeleton, pose, posed));
        QVERIFY(!skin(binding, posed, U));
        failed += rigidSkinSolve(*rig, posed, R).hasValue() ? 0 : 1;
        nonFinite += (U.allFinite() && R.allFinite()) ? 0 : 1;
    }
    QCOMPARE(failed, 0);
    QCOMPARE(nonFinite, 0);
}

void TestSkinning::rigidModeKeepsBentLimbBetterThanLbs()
{
    const ObjectMesh mesh = limb();
    const Skeleton skeleton = limbSkeleton(2);
    const auto w = weightsOf(mesh, skeleton);
    const auto rig = *rigidSkinPrecompute(mesh.V, mesh.F, *w);
    const double restArea = area(mesh.V, mesh.F);
    for (const double bend : {M_PI / 2, 2 * M_PI / 3}) {
        SkeletonPose pose = restPose(skeleton);
        pose.angles(2) = bend;
        const Eigen::MatrixX2d U = lbs(mesh.V, *w, skeleton, pose);
        const Eigen::MatrixX2d R = rigid(*rig, skeleton, pose);
        const double lbsArea = std::abs(area(U, mesh.F) / restArea - 1.0);
        const double rigidArea = std::abs(area(R, mesh.F) / restArea - 1.0);
        const double lbsEdges = edgeError(mesh.V, mesh.F, U);
        const double rigidEdges = edgeError(mesh.V, mesh.F, R);
        qInfo("bend %.0f°: area change LBS %.2f%%, rigid %.2f%%; mean edge-length error LBS "
              "%.2f%%, rigid %.2f%%",
              bend * 180 / M_PI, 100 * lbsArea, 100 * rigidArea, 100 * lbsEdges, 100 * rigidEdges);
        QVERIFY(rigidArea < 0.5 * lbsArea);
        QVERIFY(rigidEdges < 0.75 * lbsEdges);
    }
}

void TestSkinning::invalidInputGivesTypedErrors()
{
    const ObjectMesh mesh = twoFingers();
    const Skeleton skeleton = twoFingerSkeleton();
    SkinningOptions options;
    options.reach = -1.0;
    auto negative = computeSkinningWeights(mesh.V, mesh.F, skeleton, options);
    QVERIFY(!negative && negative.error().code == DeformErrorCode::InvalidSkeleton);
    Eigen::MatrixX2d bad = mesh.V;
    bad(3, 0) = NAN;
    auto nan = computeSkinningWeights(bad, mesh.F, skeleton);
    QVERIFY(!nan && nan.error().code == DeformErrorCode::NonFiniteInput);
    auto empty = computeSkinningWeights(mesh.V, Eigen::MatrixX3i(), skeleton);
    QVERIFY(!empty && empty.error().code == DeformErrorCode::EmptyMesh);
    const auto w = weightsOf(mesh, skeleton);
    finbook::geometry::Embedding e{Eigen::VectorXi::Constant(2, int(mesh.F.rows())),
                                   Eigen::MatrixX3d::Constant(2, 3, 1.0 / 3), 0, 0};
    auto outside = bindPoints(*w, mesh.V, mesh.F, e, Eigen::MatrixX2d::Zero(2, 2));
    QVERIFY(!outside && outside.error().code == DeformErrorCode::InvalidIndex);
    auto mismatch = bindPoints(*w, mesh.V, mesh.F, e, Eigen::MatrixX2d::Zero(3, 2));
    QVERIFY(!mismatch && mismatch.error().code == DeformErrorCode::SizeMismatch);
    // A pose of a smaller skeleton cannot drive these weights.
    const Skeleton small = limbSkeleton(1);
    Eigen::MatrixX2d U = Eigen::MatrixX2d::Constant(3, 2, 5.0);
    const auto smallPose = *forwardKinematics(small, restPose(small));
    auto refused = skin(bindVertices(*w, mesh.V), smallPose, U);
    QVERIFY(refused && refused->code == DeformErrorCode::SizeMismatch);
    QCOMPARE(U(0, 0), 5.0);
    const auto rig = *rigidSkinPrecompute(mesh.V, mesh.F, *w);
    QVERIFY(!rigidSkinSolve(*rig, smallPose, U).hasValue());
    auto otherMesh = rigidSkinPrecompute(limb().V, limb().F, *w);
    QVERIFY(!otherMesh && otherMesh.error().code == DeformErrorCode::SizeMismatch);
}

void TestSkinning::cancellationStopsWeights()
{
    const ObjectMesh mesh = twoFingers();
    auto result =
        computeSkinningWeights(mesh.V, mesh.F, twoFingerSkeleton(), {}, [] { return true; });
    QVERIFY(!result && result.error().code == DeformErrorCode::Cancelled);
}

void TestSkinning::realDataWeights()
{
    const QString dir = finbook::test::realDataDir();
    if (dir.isEmpty())
        QSKIP("FINBOOK_DATA_DIR not found: real-data skinning not checked");
    int files = 0;
    for (const QString &path : finbook::test::realDataFiles(dir)) {
        const auto mesh = finbook::test::meshDataFile(path);
        QVERIFY2(mesh.has_value(), qPrintable(path));
        const auto s = finbook::test::medialTreeSkeleton(mesh->V, mesh->F);
        const auto skeleton = makeSkeleton(s.joints, s.parent);
        QVERIFY2(skeleton.hasValue(), qPrintable(path));
        const auto w = computeSkinningWeights(mesh->V, mesh->F, *skeleton);
        QVERIFY2(w.hasValue(), qPrintable(path));
        checkPartitionOfUnity(**w);
        QCOMPARE((*w)->active.size(), (*w)->handles.size());
        // A random pose stays finite in both modes.
        SkeletonPose pose = restPose(*skeleton);
        pose.angles.setLinSpaced(-0.8, 0.8);
        const Eigen::MatrixX2d U = lbs(mesh->V, **w, *skeleton, pose);
        const auto rig = rigidSkinPrecompute(mesh->V, mesh->F, **w);
        QVERIFY2(rig.hasValue(), qPrintable(path));
        QVERIFY(U.allFinite() && rigid(**rig, *skeleton, pose).allFinite());
        ++files;
    }
    QVERIFY(files > 50);
}

QTEST_APPLESS_MAIN(TestSkinning)
#include "tst_skinning.moc"
