// Skeletons, forward kinematics and inverse kinematics: rest pose, bone turns, reachability,
// unreachable targets (no NaN, continuity), locks, and bad input.
#include <finbook/deform/skeleton/inverse_kinematics.h>
#include <finbook/deform/skeleton/skeleton.h>

#include <QTest>

#include <cmath>
#include <random>

using namespace finbook::deform;

namespace {

// A chain of `bones` bones of the given length along +x from (100, 50), with a slight zigzag
// so that no bend is exactly straight.
Skeleton chain(int bones, double length = 40.0)
{
    Eigen::MatrixX2d joints(bones + 1, 2);
    Eigen::VectorXi parent(bones + 1);
    for (int j = 0; j <= bones; ++j) {
        joints.row(j) << 100.0 + length * j, 50.0 + (j % 2 == 0 ? 0.0 : 3.0);
        parent(j) = j - 1;
    }
    return *makeSkeleton(joints, parent);
}

// A small character: root (hips), spine to chest, two arms of two bones from the chest, one
// leg of two bones from the hips, and a head.
Skeleton character()
{
    Eigen::MatrixX2d joints(9, 2);
    joints << 200, 300, 200, 200, 150, 210, 110, 260, 250, 210, 290, 260, 195, 380, 190, 460, 200,
        160;
    Eigen::VectorXi parent(9);
    parent << -1, 0, 1, 2, 1, 4, 0, 6, 1;
    return *makeSkeleton(joints, parent);
}

Eigen::MatrixX2d posedJoints(const Skeleton &s, const SkeletonPose &pose)
{
    auto posed = forwardKinematics(s, pose);
    return posed ? posed->joints : Eigen::MatrixX2d();
}

double boneLength(const Eigen::MatrixX2d &joints, const Skeleton &s, int j)
{
    return (joints.row(j) - joints.row(s.parent(j))).norm();
}

double reach(const Skeleton &s, const Eigen::VectorXi &chainBones)
{
    double sum = 0.0;
    for (const int b : chainBones)
        sum += boneLength(s.joints, s, b);
    return sum;
}

} // namespace

class TestKinematics : public QObject {
    Q_OBJECT

private slots:
    void invalidSkeletonsAreRefused();
    void restPoseGivesRestJoints();
    void turningABoneTurnsItsSubtree();
    void randomPosesKeepBonesAndStayFinite();
    void ikReachesReachableTargets_data();
    void ikReachesReachableTargets();
    void twoBoneIkKeepsItsBendSide();
    void unreachableTargetsStretchTowardsCursor();
    void ikIsContinuousInTheTarget();
    void locksAreRespected();
    void limbsTurnAtTheirBase();
    void oneBoneLimbsTurnAtTheirMarkedBase();
    void rootDragTranslates();
    void rotateBoneFollowsTheCursor();
    void badDragInputGivesTypedErrors();
};

void TestKinematics::invalidSkeletonsAreRefused()
{
    const auto code = [](const Eigen::MatrixX2d &joints, const Eigen::VectorXi &parent) {
        auto s = makeSkeleton(joints, parent);
        return s ? std::optional<DeformErrorCode>() : s.error().code;
    };
    const Eigen::MatrixX2d three = Eigen::MatrixX2d::Random(3, 2);
    QCOMPARE(code(Eigen::MatrixX2d(0, 2), Eigen::VectorXi()), DeformErrorCode::InvalidSkeleton);
    QCOMPARE(code(three, Eigen::Vector2i(-1, 0)), DeformErrorCode::InvalidSkeleton);
    QCOMPARE(code(three, Eigen::Vector3i(-1, 0, 3)), DeformErrorCode::InvalidSkeleton);
    QCOMPARE(code(three, Eigen::Vector3i(-1, 1, 1)), DeformErrorCode::InvalidSkeleton);
    QCOMPARE(code(three, Eigen::Vector3i(2, 0, 1)), DeformErrorCode::InvalidSkeleton); // cycle
    QCOMPARE(code(three, Eigen::Vector3i(-2, 0, 1)), DeformErrorCode::InvalidSkeleton);
    Eigen::MatrixX2d bad = three;
    bad(1, 1) = NAN;
    QCOMPARE(code(bad, Eigen::Vector3i(-1, 0, 1)), DeformErrorCode::NonFiniteInput);
    bad(1, 1) = 1e200;
    QCOMPARE(code(bad, Eigen::Vector3i(-1, 0, 1)), DeformErrorCode::CoordinateOutOfRange);
    // A forest with children listed before parents is fine.
    auto forest = makeSkeleton(Eigen::MatrixX2d::Random(4, 2), Eigen::Vector4i(2, -1, -1, 1));
    QVERIFY(forest.hasValue());
    for (Eigen::Index k = 0; k < 4; ++k) {
        const int j = forest->order(k), p = forest->parent(j);
        for (Eigen::Index before = k; p >= 0 && before < 4; ++before)
            QVERIFY(forest->order(before) != p);
    }
}

void TestKinematics::restPoseGivesRestJoints()
{
    const Skeleton s = character();
    const auto posed = forwardKinematics(s, restPose(s));
    QVERIFY(posed.hasValue());
    QVERIFY((posed->joints - s.joints).cwiseAbs().maxCoeff() < 1e-9);
    for (const BoneTransform &T : posed->transforms) {
        QVERIFY((T.leftCols<2>() - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff() < 1e-15);
        QVERIFY(T.col(2).cwiseAbs().maxCoeff() < 1e-9);
    }
}

void TestKinematics::turningABoneTurnsItsSubtree()
{
    const Skeleton s = character();
    SkeletonPose pose = restPose(s);
    const double theta = 0.7;
    pose.angles(2) = theta; // the left upper arm, about the chest (joint 1)
    const Eigen::MatrixX2d P = posedJoints(s, pose);
    const Eigen::Vector2d pivot = s.joints.row(1).transpose();
    Eigen::Matrix2d R;
    R << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
    for (const int j : {2, 3}) // the arm turns about the chest
        QVERIFY(
            (P.row(j).transpose() - (pivot + R * (s.joints.row(j).transpose() - pivot))).norm() <
            1e-9);
    for (const int j : {0, 1, 4, 5, 6, 7, 8}) // nothing else moves
        QVERIFY((P.row(j) - s.joints.row(j)).norm() < 1e-9);
    // The bone's transform is that rotation about the pivot, also for points off the bone.
    const auto posed = *forwardKinematics(s, pose);
    const Eigen::Vector2d x(170.0, 240.0);
    QVERIFY((transformPoint(posed.transforms[3], x) - (pivot + R * (x - pivot))).norm() < 1e-9);
    // A root's angle turns the whole tree about the root.
    pose = restPose(s);
    pose.angles(0) = -1.1;
    const Eigen::MatrixX2d Q = posedJoints(s, pose);
    R << std::cos(-1.1), -std::sin(-1.1), std::sin(-1.1), std::cos(-1.1);
    const Eigen::Vector2d root = s.joints.row(0).transpose();
    for (int j = 0; j < 9; ++j)
        QVERIFY((Q.row(j).transpose() - (root + R * (s.joints.row(j).transpose() - root))).norm() <
                1e-9);
}

void TestKinematics::randomPosesKeepBonesAndStayFinite()
{
    const Skeleton s = character();
    std::mt19937 random(3);
    std::uniform_real_distribution<double> angle(-50.0, 50.0), offset(-1e5, 1e5);
    PosedSkeleton posed;
    double worst = 0.0;
    for (int k = 0; k < 10000; ++k) {
        SkeletonPose pose = restPose(s);
        for (Eigen::Index j = 0; j < pose.angles.size(); ++j)
            pose.angles(j) = angle(random);
        pose.rootOffset << offset(random), offset(random);
        QVERIFY(!forwardKinematics(s, pose, posed));
        QVERIFY(posed.joints.allFinite());
        for (int j = 1; j < 9; ++j)
            worst = std::max(worst,
                             std::abs(boneLength(posed.joints, s, j) - boneLength(s.joints, s, j)));
        // Bone transforms map the rest bone onto the posed bone.
        for (int j = 1; j < 9; ++j)
            worst = std::max(worst, (transformPoint(posed.transforms[std::size_t(j)],
                                                    s.joints.row(s.parent(j)).transpose()) -
                                     posed.joints.row(s.parent(j)).transpose())
                                        .norm());
    }
    QVERIFY(worst < 1e-6);
}

void TestKinematics::ikReachesReachableTargets_data()
{
    QTest::addColumn<int>("bones");
    QTest::newRow("one bone") << 1;
    QTest::newRow("two bones") << 2;
    QTest::newRow("three bones") << 3;
    QTest::newRow("six bones") << 6;
}

void TestKinematics::ikReachesReachableTargets()
{
    QFETCH(int, bones);
    const Skeleton s = chain(bones);
    std::mt19937 random(bones);
    std::uniform_real_distribution<double> angle(-1.2, 1.2);
    double worst = 0.0;
    for (int k = 0; k < 200; ++k) {
        // A target some pose of the chain reaches is reachable by construction.
        SkeletonPose goal = restPose(s);
        for (int j = 1; j <= bones; ++j)
            goal.angles(j) = angle(random);
        const Eigen::Vector2d target = posedJoints(s, goal).row(bones).transpose();
        SkeletonPose start = restPose(s);
        for (int j = 1; j <= bones; ++j)
            start.angles(j) = 0.3 * angle(random);
        const auto result = solveIk(s, start, bones, target);
        QVERIFY(result.hasValue());
        QCOMPARE(result->chain.size(), bones);
        const Eigen::MatrixX2d P = posedJoints(s, result->pose);
        const double miss = (P.row(bones).transpose() - target).norm();
        QCOMPARE(miss, result->distance);
        worst = std::max(worst, miss);
        QVERIFY((P.row(0) - s.joints.row(0)).norm() < 1e-9); // the pivot stays
    }
    qInfo("%d bones: worst miss %.2e px over 200 reachable targets", bones, worst);
    QVERIFY(worst < 0.5);
}

void TestKinematics::twoBoneIkKeepsItsBendSide()
{
    const Skeleton s = chain(2);
    for (const double side : {1.0, -1.0}) {
        SkeletonPose start = restPose(s);
        start.angles(2) = 0.5 * side;
        const auto sideOf = [&](const SkeletonPose &pose) {
            const Eigen::MatrixX2d P = posedJoints(s, pose);
            const Eigen::RowVector2d a = P.row(1) - P.row(0), b = P.row(2) - P.row(1);
            return a.x() * b.y() - a.y() * b.x();
        };
        const double before = sideOf(start);
        for (const Eigen::Vector2d &target :
             {Eigen::Vector2d(150, 90), Eigen::Vector2d(130, 20), Eigen::Vector2d(60, 60)}) {
            const auto result = solveIk(s, start, 2, target);
            QVERIFY(result.hasValue() && result->distance < 1e-6);
            QVERIFY(sideOf(result->pose) * before > 0.0);
        }
    }
}

void TestKinematics::unreachableTargetsStretchTowardsCursor()
{
    for (const int bones : {1, 2, 4}) {
        const Skeleton s = chain(bones);
        const double length = reach(s, ikChain(s, bones, {}));
        const Eigen::Vector2d pivot = s.joints.row(0).transpose();
        for (const Eigen::Vector2d &target :
             {Eigen::Vector2d(900, 50), Eigen::Vector2d(-300, -800), Eigen::Vector2d(100, 1e9)}) {
            const auto result = solveIk(s, restPose(s), bones, target);
            QVERIFY(result.hasValue());
            const Eigen::MatrixX2d P = posedJoints(s, result->pose);
            QVERIFY(P.allFinite());
            // Straight towards the target: the end sits on the ray at full length.
            const Eigen::Vector2d expected = pivot + length * (target - pivot).normalized();
            QVERIFY2((P.row(bones).transpose() - expected).norm() < 1e-3,
                     qPrintable(QString::number((P.row(bones).transpose() - expected).norm())));
        }
    }
}

void TestKinematics::ikIsContinuousInTheTarget()
{
    // The target sweeps along a line past the pivot, across the boundary of the reachable disc
    // and out again. Continuity: the largest joint jump between consecutive targets shrinks
    // with the step (near full extension joints move like √(step · length), the one place
    // where they move faster than the target), and stays small in absolute terms.
    for (const int bones : {1, 2, 3, 5}) {
        const Skeleton s = chain(bones);
        SkeletonPose start = restPose(s);
        for (int j = 1; j <= bones; ++j)
            start.angles(j) = 0.2;
        const double length = reach(s, ikChain(s, bones, {}));
        const Eigen::Vector2d pivot = s.joints.row(0).transpose();
        const auto worstJump = [&](double step) -> double {
            Eigen::MatrixX2d previous;
            double worst = 0.0;
            const int steps = int(std::ceil(2.6 * length / step));
            for (int k = 0; k <= steps; ++k) {
                const Eigen::Vector2d target =
                    pivot + Eigen::Vector2d(-1.3 * length + k * step, 0.35 * length);
                const auto result = solveIk(s, start, bones, target);
                if (!result)
                    return INFINITY;
                const Eigen::MatrixX2d P = posedJoints(s, result->pose);
                if (!P.allFinite())
                    return INFINITY;
                if (previous.size() > 0)
                    worst = std::max(worst, (P - previous).rowwise().norm().maxCoeff());
                previous = P;
            }
            return worst;
        };
        const double coarse = worstJump(0.05), fine = worstJump(0.0125);
        qInfo("%d bones: largest joint jump %.3f px for target steps of 0.05 px, %.3f px for "
              "0.0125 px",
              bones, coarse, fine);
        QVERIFY(coarse < 3.0 * std::sqrt(0.05 * length) + 0.1);
        QVERIFY(fine < 0.7 * coarse);
    }
}

void TestKinematics::locksAreRespected()
{
    const Skeleton s = character();
    std::vector<bool> locked(9, false);
    // Hand (3) of the left arm: chain = forearm, upper arm (which starts at the chest, a
    // branch point, so the spine stays).
    QCOMPARE(ikChain(s, 3, locked), Eigen::Vector2i(3, 2));
    QCOMPARE(ikChain(s, 3, locked, 1), Eigen::VectorXi::Constant(1, 3));
    QCOMPARE(ikChain(s, 9, locked).size(), Eigen::Index(0));
    QCOMPARE(ikChain(s, 3, std::vector<bool>(4, false)).size(), Eigen::Index(0));
    // Along an unbranched chain a lock stops the chain below it.
    const Skeleton tail = chain(5);
    std::vector<bool> tailLocks(6, false);
    QCOMPARE(ikChain(tail, 5, tailLocks), (Eigen::VectorXi(5) << 5, 4, 3, 2, 1).finished());
    tailLocks[2] = true;
    QCOMPARE(ikChain(tail, 5, tailLocks), Eigen::Vector3i(5, 4, 3));
    // Locking the other hand keeps the chest (and so the spine) still.
    locked[5] = true;
    QCOMPARE(ikChain(s, 3, locked), Eigen::Vector2i(3, 2));
    const Eigen::MatrixX2d rest = s.joints;
    auto result = solveIk(s, restPose(s), 3, Eigen::Vector2d(150, 120), locked);
    QVERIFY(result.hasValue());
    Eigen::MatrixX2d P = posedJoints(s, result->pose);
    for (const int j : {0, 1, 4, 5, 6, 7, 8})
        QVERIFY((P.row(j) - rest.row(j)).norm() < 1e-9);
    QVERIFY(result->distance < 0.5); // still reachable with two bones
    // Locking the elbow leaves only the forearm.
    locked.assign(9, false);
    locked[2] = true;
    QCOMPARE(ikChain(s, 3, locked), Eigen::VectorXi::Constant(1, 3));
    result = solveIk(s, restPose(s), 3, Eigen::Vector2d(0, 0), locked);
    P = posedJoints(s, result->pose);
    QVERIFY((P.row(2) - rest.row(2)).norm() < 1e-9);
    // A locked joint does not follow the cursor at all.
    locked[3] = true;
    result = solveIk(s, restPose(s), 3, Eigen::Vector2d(0, 0), locked);
    QVERIFY(result.hasValue() && result->chain.size() == 0);
    QVERIFY((posedJoints(s, result->pose) - rest).cwiseAbs().maxCoeff() < 1e-9);
    // With a lock anywhere, dragging the root moves nothing.
    result = solveIk(s, restPose(s), 0, Eigen::Vector2d(0, 0), locked);
    QVERIFY((posedJoints(s, result->pose) - rest).cwiseAbs().maxCoeff() < 1e-9);
}

// An automatic rig's arm: the body's centre (a branch point: the arm, the head and the legs
// leave it), a bone inside the body to the shoulder, then the upper arm and the forearm.
// Dragging the hand turns the arm at the shoulder; the shoulder and the body stay.
void TestKinematics::limbsTurnAtTheirBase()
{
    Eigen::MatrixX2d joints(6, 2);
    joints << 300, 300, 380, 280, 460, 260, 540, 240, 300, 180, 300, 420;
    Eigen::VectorXi parent(6);
    parent << -1, 0, 1, 2, 0, 0;
    const Skeleton s = *makeSkeleton(joints, parent);
    const std::vector<bool> none(6, false);
    QCOMPARE(ikChain(s, 3, none), Eigen::Vector2i(3, 2));
    // The elbow alone has one bone below the branch point: it takes the inner bone too.
    QCOMPARE(ikChain(s, 2, none), Eigen::Vector2i(2, 1));
    QCOMPARE(ikChain(s, 4, none), Eigen::VectorXi::Constant(1, 4));

    const auto result = solveIk(s, restPose(s), 3, Eigen::Vector2d(420, 160));
    QVERIFY(result.hasValue());
    const Eigen::MatrixX2d P = posedJoints(s, result->pose);
    for (const int j : {0, 1, 4, 5})
        QVERIFY((P.row(j) - s.joints.row(j)).norm() < 1e-9);
    QVERIFY(result->distance < 0.5);
    QVERIFY(std::abs(boneLength(P, s, 2) - boneLength(s.joints, s, 2)) < 1e-9);
    QVERIFY(std::abs(boneLength(P, s, 3) - boneLength(s.joints, s, 3)) < 1e-9);
}

// An automatic rig's foreleg: from the chest (a branch point) a bone inside the body to the
// top of the leg, where the width drops (the limb base), then one bone to the paw. Without the
// mark the paw's chain takes the bone into the body too, and the drag swings the chest; with
// it the leg turns at its base, and dragging the base itself still turns the inner bone.
void TestKinematics::oneBoneLimbsTurnAtTheirMarkedBase()
{
    Eigen::MatrixX2d joints(5, 2);
    joints << 300, 300, 340, 360, 340, 460, 200, 300, 400, 300;
    Eigen::VectorXi parent(5);
    parent << -1, 0, 1, 0, 0;
    const Skeleton s = *makeSkeleton(joints, parent);
    const std::vector<bool> none(5, false);
    std::vector<bool> bases(5, false);
    bases[1] = true;
    QCOMPARE(ikChain(s, 2, none), Eigen::Vector2i(2, 1));
    QCOMPARE(ikChain(s, 2, none, 0, bases), Eigen::VectorXi::Constant(1, 2));
    QCOMPARE(ikChain(s, 1, none, 0, bases), Eigen::VectorXi::Constant(1, 1));

    const Eigen::Vector2d target(440, 380);
    const auto unmarked = solveIk(s, restPose(s), 2, target);
    QVERIFY(unmarked.hasValue());
    QVERIFY((posedJoints(s, unmarked->pose).row(1) - s.joints.row(1)).norm() > 1.0);
    IkOptions options;
    options.limbBase = bases;
    const auto marked = solveIk(s, restPose(s), 2, target, {}, options);
    QVERIFY(marked.hasValue());
    const Eigen::MatrixX2d P = posedJoints(s, marked->pose);
    for (const int j : {0, 1, 3, 4})
        QVERIFY((P.row(j) - s.joints.row(j)).norm() < 1e-9);
    // The paw points from the base at the cursor, the leg its own length.
    const Eigen::Vector2d base = s.joints.row(1).transpose(), paw = P.row(2).transpose();
    QVERIFY(std::abs((paw - base).norm() - 100.0) < 1e-9);
    QVERIFY(std::abs((paw - base).normalized().dot((target - base).normalized()) - 1.0) < 1e-12);
    // Dragging the base turns the bone into the body about the chest.
    const auto shoulder = solveIk(s, restPose(s), 1, Eigen::Vector2d(360, 340), {}, options);
    QVERIFY(shoulder.hasValue());
    QCOMPARE(shoulder->chain, Eigen::VectorXi::Constant(1, 1));
    QVERIFY(std::abs(shoulder->pose.angles(1)) > 0.1);
    options.limbBase.resize(3);
    QCOMPARE(solveIk(s, restPose(s), 2, target, {}, options).error().code,
             DeformErrorCode::SizeMismatch);
    QCOMPARE(ikChain(s, 2, none, 0, std::vector<bool>(3)).size(), Eigen::Index(0));
}

void TestKinematics::rootDragTranslates()
{
    const Skeleton s = character();
    SkeletonPose start = restPose(s);
    start.angles(2) = 0.4;
    const auto result = solveIk(s, start, 0, Eigen::Vector2d(260, 330));
    QVERIFY(result.hasValue());
    QVERIFY(result->distance < 1e-9);
    const Eigen::MatrixX2d before = posedJoints(s, start), after = posedJoints(s, result->pose);
    QVERIFY(((after - before).rowwise() - Eigen::RowVector2d(60, 30)).cwiseAbs().maxCoeff() < 1e-9);
}

void TestKinematics::rotateBoneFollowsTheCursor()
{
    const Skeleton s = character();
    const Eigen::Vector2d pivot = s.joints.row(6).transpose(); // the shin turns about the knee
    const Eigen::Vector2d grabbed = s.joints.row(7).transpose();
    const Eigen::Vector2d cursor = pivot + Eigen::Vector2d(80, 0);
    const auto pose = rotateBone(s, restPose(s), 7, grabbed, cursor);
    QVERIFY(pose.hasValue());
    const Eigen::MatrixX2d P = posedJoints(s, *pose);
    const Eigen::Vector2d foot = P.row(7).transpose();
    QVERIFY(std::abs((foot - pivot).normalized().dot(Eigen::Vector2d(1, 0)) - 1.0) < 1e-12);
    // Grabbing the pivot itself turns nothing.
    const auto none = rotateBone(s, restPose(s), 7, pivot, cursor);
    QVERIFY(none.hasValue() && none->angles.cwiseAbs().maxCoeff() == 0.0);
}

void TestKinematics::badDragInputGivesTypedErrors()
{
    const Skeleton s = character();
    const SkeletonPose rest = restPose(s);
    QCOMPARE(solveIk(s, rest, 9, {0, 0}).error().code, DeformErrorCode::InvalidIndex);
    QCOMPARE(solveIk(s, rest, -1, {0, 0}).error().code, DeformErrorCode::InvalidIndex);
    QCOMPARE(solveIk(s, rest, 3, {NAN, 0}).error().code, DeformErrorCode::NonFiniteInput);
    QCOMPARE(solveIk(s, rest, 3, {1e300, 0}).error().code, DeformErrorCode::CoordinateOutOfRange);
    QCOMPARE(solveIk(s, rest, 3, {0, 0}, std::vector<bool>(3)).error().code,
             DeformErrorCode::SizeMismatch);
    SkeletonPose bad = rest;
    bad.angles(4) = INFINITY;
    QCOMPARE(solveIk(s, bad, 3, {0, 0}).error().code, DeformErrorCode::NonFiniteInput);
    bad.angles.resize(3);
    QCOMPARE(forwardKinematics(s, bad).error().code, DeformErrorCode::SizeMismatch);
    QCOMPARE(rotateBone(s, rest, 12, {0, 0}, {1, 1}).error().code, DeformErrorCode::InvalidIndex);
    QCOMPARE(rotateBone(s, rest, 2, {NAN, 0}, {1, 1}).error().code,
             DeformErrorCode::NonFiniteInput);
    // Targets on the pivot or on a joint are defined, finite poses.
    for (const Eigen::Vector2d &target : {Eigen::Vector2d(s.joints.row(1).transpose()),
                                          Eigen::Vector2d(s.joints.row(2).transpose())}) {
        for (const int joint : {2, 3, 5, 7}) {
            const auto result = solveIk(s, rest, joint, target);
            QVERIFY(result.hasValue() && result->pose.angles.allFinite());
        }
    }
}

QTEST_APPLESS_MAIN(TestKinematics)
#include "tst_kinematics.moc"
