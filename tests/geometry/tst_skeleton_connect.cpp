// Joining parts into a character skeleton (bone split, joint connect, cylinder–ball test,
// detach and reattach as data) and hand edits of a skeleton as pure functions.
#include "skeleton_test_support.h"

#include <finbook/geometry/skeleton/skeleton.h>
#include <finbook/geometry/skeleton/skeleton_connect.h>
#include <finbook/geometry/skeleton/skeleton_edit.h>
#include <finbook/geometry/skeleton/skeleton_refine.h>

#include <QtTest>

#include <cmath>
#include <limits>

using namespace finbook::geometry;
using namespace finbook::test;

namespace {

Skeleton skeletonOf(const Eigen::MatrixX2d &outer)
{
    const auto s = skeletonize(regionOf(outer));
    if (!s)
        qFatal("skeletonize failed: %s", s.error().message.c_str());
    return *s;
}

Character assembled(const std::vector<Skeleton> &parts, const std::vector<PartJoin> &joins,
                    int rootPart)
{
    const auto c = assembleCharacter(parts, joins, rootPart);
    if (!c)
        qFatal("assembleCharacter failed: %s", c.error().message.c_str());
    return *c;
}

// A torso (upright bar) and an arm (a bar whose left end lies inside the torso).
std::vector<Skeleton> torsoAndArm(double armY)
{
    return {skeletonOf(bar(60, 240, 0.0, {0, 0})), skeletonOf(bar(160, 24, 0.05, {90, armY}))};
}

// Joints of `part` in a character.
int jointsOf(const Skeleton &s, int part)
{
    return int((s.part.array() == part).count());
}

} // namespace

class TestSkeletonConnect : public QObject {
    Q_OBJECT
private slots:
    void crossingPartsJoinByOneBoneSplit();
    void armOnTorsoSplitsTheTorsoBone();
    void armAtTorsoEndConnectsToTheJoint();
    void partsApartStayApart();
    void detachAndReattachAreData();
    void characterRootIsChosen();
    void badJoinsAreTypedErrors();
    void moveJoint();
    void insertJoint();
    void deleteJoint();
    void deleteRootPromotesAChild();
    void setRootKeepsTheBones();
    void badEditsAreTypedErrors();
};

void TestSkeletonConnect::crossingPartsJoinByOneBoneSplit()
{
    // An X: two bars crossing at (100, 100).
    const std::vector<Skeleton> parts{skeletonOf(bar(220, 30, 0.3, {100, 100})),
                                      skeletonOf(bar(200, 26, -0.9, {100, 100}))};
    QCOMPARE(boneCount(parts[0]), 1);
    QCOMPARE(boneCount(parts[1]), 1);
    const std::vector<PartJoin> joins = findJoins(parts, 0);
    QCOMPARE(int(joins.size()), 1);
    QCOMPARE(joins[0].child, 1);
    QCOMPARE(joins[0].parent, 0);
    const Character x = assembled(parts, joins, 0);
    QVERIFY(isValidSkeleton(x.skeleton));
    QCOMPARE(int(x.joins.size()), 1);
    QCOMPARE(x.joins[0].kind, JoinKind::BoneSplit);
    // One junction where the bars cross, four tips, four bones, one tree.
    QCOMPARE(countKind(x.skeleton, JointKind::Junction), 1);
    QCOMPARE(countKind(x.skeleton, JointKind::Terminal), 4);
    QCOMPARE(boneCount(x.skeleton), 4);
    QCOMPARE(jointDegrees(x.skeleton)(x.joins[0].joint), 4);
    QVERIFY((x.skeleton.joints.row(x.joins[0].joint) - Eigen::RowVector2d(100, 100)).norm() < 1.0);
    QCOMPARE(x.skeleton.part(x.skeleton.root), 0);
}

void TestSkeletonConnect::armOnTorsoSplitsTheTorsoBone()
{
    const std::vector<Skeleton> parts = torsoAndArm(-40);
    const auto join = findJoin(1, parts[1], 0, parts[0]);
    QVERIFY(join.has_value());
    const Character c = assembled(parts, {*join}, 0);
    QCOMPARE(c.joins[0].kind, JoinKind::BoneSplit);
    // The torso's bone is split (one more torso joint), the arm hangs from the new joint.
    QCOMPARE(jointsOf(c.skeleton, 0), parts[0].jointCount() + 1);
    QCOMPARE(boneCount(c.skeleton), boneCount(parts[0]) + 1 + boneCount(parts[1]) + 1);
    const int split = c.joins[0].joint;
    QCOMPARE(c.skeleton.part(split), 0);
    QVERIFY(std::abs(c.skeleton.joints(split, 1) - join->parentAt.y()) < 1e-9);
    // Cylinder–ball: the attach point lies within the torso bone's radius.
    QVERIFY((join->childAt - join->parentAt).norm() <= c.skeleton.radius(split));
    QVERIFY(isValidSkeleton(c.skeleton));
    QCOMPARE(int((c.skeleton.parent.array() < 0).count()), 1);
}

void TestSkeletonConnect::armAtTorsoEndConnectsToTheJoint()
{
    // The arm's end lies at the upper end of the torso's bone: joint connect.
    const std::vector<Skeleton> parts = torsoAndArm(-88);
    const auto join = findJoin(1, parts[1], 0, parts[0]);
    QVERIFY(join.has_value());
    const Character c = assembled(parts, {*join}, 0);
    QCOMPARE(c.joins[0].kind, JoinKind::JointConnect);
    QCOMPARE(jointsOf(c.skeleton, 0), parts[0].jointCount());
    QCOMPARE(boneCount(c.skeleton), boneCount(parts[0]) + boneCount(parts[1]) + 1);
}

void TestSkeletonConnect::partsApartStayApart()
{
    const std::vector<Skeleton> parts{skeletonOf(bar(100, 20, 0.0, {0, 0})),
                                      skeletonOf(bar(100, 20, 0.0, {0, 300}))};
    QVERIFY(!findJoin(1, parts[1], 0, parts[0]).has_value());
    QVERIFY(findJoins(parts, 0).empty());
    const Character c = assembled(parts, {}, 1);
    QCOMPARE(int((c.skeleton.parent.array() < 0).count()), 2);
    QCOMPARE(c.skeleton.part(c.skeleton.root), 1);
}

void TestSkeletonConnect::detachAndReattachAreData()
{
    const std::vector<Skeleton> parts = torsoAndArm(-40);
    const std::vector<PartJoin> joins = findJoins(parts, 0);
    QCOMPARE(int(joins.size()), 1);
    // Detached: the arm is its own tree again, the torso as it was.
    const Character detached = assembled(parts, {}, 0);
    QCOMPARE(boneCount(detached.skeleton), boneCount(parts[0]) + boneCount(parts[1]));
    QCOMPARE(int((detached.skeleton.parent.array() < 0).count()), 2);
    // Reattached by dragging the arm's root onto the torso lower down.
    const Eigen::Vector2d root = parts[1].joints.row(parts[1].root).transpose();
    const PartJoin dragged{1, 0, root, Eigen::Vector2d(3, 50)};
    const Character lower = assembled(parts, {dragged}, 0);
    QCOMPARE(lower.joins[0].kind, JoinKind::BoneSplit);
    QVERIFY(std::abs(lower.skeleton.joints(lower.joins[0].joint, 1) - 50.0) < 1.0);
    // The same joins give the same character (a pure function).
    QVERIFY(identical(assembled(parts, {dragged}, 0).skeleton, lower.skeleton));
}

void TestSkeletonConnect::characterRootIsChosen()
{
    const std::vector<Skeleton> parts = torsoAndArm(-40);
    const std::vector<PartJoin> joins = findJoins(parts, 1); // the arm is the root part
    QCOMPARE(int(joins.size()), 1);
    QCOMPARE(joins[0].child, 0);
    const Character c = assembled(parts, joins, 1);
    QCOMPARE(c.skeleton.part(c.skeleton.root), 1);
    QCOMPARE(int((c.skeleton.parent.array() < 0).count()), 1);
}

void TestSkeletonConnect::badJoinsAreTypedErrors()
{
    const std::vector<Skeleton> parts = torsoAndArm(-40);
    const PartJoin armOnTorso = *findJoin(1, parts[1], 0, parts[0]);
    const PartJoin torsoOnArm{0, 1, armOnTorso.parentAt, armOnTorso.childAt};
    QCOMPARE(assembleCharacter(parts, {armOnTorso, torsoOnArm}, 0).error().code,
             GeometryErrorCode::InvalidIndex);
    QCOMPARE(assembleCharacter(parts, {torsoOnArm}, 0).error().code,
             GeometryErrorCode::InvalidIndex); // the root part cannot hang
    QCOMPARE(assembleCharacter(parts, {armOnTorso}, 5).error().code,
             GeometryErrorCode::InvalidIndex);
    PartJoin nan = armOnTorso;
    nan.parentAt.x() = std::numeric_limits<double>::quiet_NaN();
    QCOMPARE(assembleCharacter(parts, {nan}, 0).error().code, GeometryErrorCode::InvalidOptions);
    PartJoin missing = armOnTorso;
    missing.parent = 7;
    QCOMPARE(assembleCharacter(parts, {missing}, 0).error().code, GeometryErrorCode::InvalidIndex);
}

void TestSkeletonConnect::moveJoint()
{
    const Skeleton s = skeletonOf(plusSign(40, 120));
    const auto moved = finbook::geometry::moveJoint(s, 2, {5, 7});
    QVERIFY(moved.hasValue());
    QCOMPARE(moved->joint, 2);
    QVERIFY(moved->skeleton.joints.row(2) == Eigen::RowVector2d(5, 7));
    QVERIFY(moved->skeleton.parent == s.parent);
    QVERIFY(moved->skeleton.radius == s.radius);
    QVERIFY(isValidSkeleton(moved->skeleton));
}

void TestSkeletonConnect::insertJoint()
{
    const Skeleton s = skeletonOf(plusSign(40, 120));
    const int bone = 3, parent = s.parent(bone);
    const auto edit = finbook::geometry::insertJoint(s, bone, 0.25);
    QVERIFY(edit.hasValue());
    const Skeleton &t = edit->skeleton;
    QVERIFY(isValidSkeleton(t));
    QCOMPARE(t.jointCount(), s.jointCount() + 1);
    QCOMPARE(boneCount(t), boneCount(s) + 1);
    const int added = edit->joint;
    QVERIFY(
        (t.joints.row(added) - (0.75 * s.joints.row(parent) + 0.25 * s.joints.row(bone))).norm() <
        1e-12);
    QCOMPARE(t.parent(added), edit->newIndex(parent));
    QCOMPARE(t.parent(edit->newIndex(bone)), added);
    for (int j = 0; j < s.jointCount(); ++j)
        QVERIFY(t.joints.row(edit->newIndex(j)) == s.joints.row(j));
}

void TestSkeletonConnect::deleteJoint()
{
    const Skeleton s = skeletonOf(plusSign(40, 120));
    const auto inserted = finbook::geometry::insertJoint(s, 1, 0.5);
    const auto removed = finbook::geometry::deleteJoint(inserted->skeleton, inserted->joint);
    QVERIFY(removed.hasValue());
    QVERIFY(isValidSkeleton(removed->skeleton));
    QCOMPARE(removed->newIndex(inserted->joint), -1);
    QVERIFY(boneSet(removed->skeleton) == boneSet(s)); // insert then delete restores the bones
    // Deleting a tip removes its bone.
    const auto tip = finbook::geometry::deleteJoint(s, 1);
    QCOMPARE(boneCount(tip->skeleton), boneCount(s) - 1);
}

void TestSkeletonConnect::deleteRootPromotesAChild()
{
    const Skeleton s = skeletonOf(plusSign(40, 120)); // root: the centre, four children
    QCOMPARE(jointDegrees(s)(s.root), 4);
    const auto edit = finbook::geometry::deleteJoint(s, s.root);
    QVERIFY(edit.hasValue());
    const Skeleton &t = edit->skeleton;
    QVERIFY(isValidSkeleton(t));
    QCOMPARE(t.jointCount(), 4);
    QCOMPARE(boneCount(t), 3); // one tree: the other tips hang from the first child
    QCOMPARE(t.root, edit->newIndex(jointChildren(s)[std::size_t(s.root)].front()));
    const auto last = finbook::geometry::deleteJoint(skeletonOf(bar(30, 30)), 0);
    QCOMPARE(last.error().code, GeometryErrorCode::InvalidIndex); // the only joint stays
}

void TestSkeletonConnect::setRootKeepsTheBones()
{
    const Skeleton s = skeletonOf(plusSign(40, 120));
    for (int j = 0; j < s.jointCount(); ++j) {
        const auto edit = setRoot(s, j);
        QVERIFY(edit.hasValue());
        QVERIFY(isValidSkeleton(edit->skeleton));
        QCOMPARE(edit->skeleton.root, edit->joint);
        QVERIFY(edit->skeleton.joints.row(edit->joint) == s.joints.row(j));
        QVERIFY(boneSet(edit->skeleton) == boneSet(s));
    }
}

void TestSkeletonConnect::badEditsAreTypedErrors()
{
    const Skeleton s = skeletonOf(plusSign(40, 120));
    QCOMPARE(finbook::geometry::moveJoint(s, 9, {0, 0}).error().code,
             GeometryErrorCode::InvalidIndex);
    QCOMPARE(finbook::geometry::moveJoint(s, 0, {std::nan(""), 0}).error().code,
             GeometryErrorCode::InvalidOptions);
    QCOMPARE(finbook::geometry::insertJoint(s, s.root, 0.5).error().code,
             GeometryErrorCode::InvalidIndex);
    QCOMPARE(finbook::geometry::insertJoint(s, 1, 1.0).error().code,
             GeometryErrorCode::InvalidOptions);
    QCOMPARE(finbook::geometry::deleteJoint(s, -1).error().code, GeometryErrorCode::InvalidIndex);
    QCOMPARE(setRoot(s, 5).error().code, GeometryErrorCode::InvalidIndex);
}

QTEST_APPLESS_MAIN(TestSkeletonConnect)
#include "tst_skeleton_connect.moc"
