// The automatic skeleton as a rig an animator accepts as it comes (issue 21): clean-up by
// default, joints where limbs leave the body and bend, the root at the thickest part, loose
// pieces joined. Each test compares with RealSkel's refinement alone (animatorRig off), so it
// fails if the rig's step it checks does nothing.
#include "skeleton_test_support.h"

#include <finbook/geometry/polyline.h>
#include <finbook/geometry/silhouette.h>
#include <finbook/geometry/skeleton/raw_skeleton.h>
#include <finbook/geometry/skeleton/skeleton_connect.h>
#include <finbook/geometry/skeleton/skeleton_refine.h>

#include <QtTest>

#include <array>
#include <cmath>

using namespace finbook::geometry;
using namespace finbook::test;

namespace {

Region shapeOf(const std::vector<StrokeInput> &strokes)
{
    const auto region = silhouette(strokes);
    if (!region)
        qFatal("silhouette failed: %s", region.error().message.c_str());
    return *region;
}

Skeleton rigOf(const Region &region, bool animator = true)
{
    RefineOptions options;
    options.animatorRig = animator;
    const auto s = skeletonize(region, {}, options);
    if (!s)
        qFatal("skeletonize failed: %s", s.error().message.c_str());
    return *s;
}

int kindCount(const Skeleton &s, JointKind kind)
{
    const std::vector<JointKind> kinds = jointKinds(s);
    return int(std::count(kinds.begin(), kinds.end(), kind));
}

// Joints from a tip up to (not including) the first junction or root: the limb's chain.
std::vector<int> limbChain(const Skeleton &s, int tip)
{
    const Eigen::VectorXi degree = jointDegrees(s);
    std::vector<int> chain{tip};
    while (s.parent(chain.back()) >= 0 && degree(s.parent(chain.back())) == 2)
        chain.push_back(s.parent(chain.back()));
    return chain;
}

int tipNearest(const Skeleton &s, const Eigen::RowVector2d &p)
{
    const Eigen::VectorXi degree = jointDegrees(s);
    int best = -1;
    for (int j = 0; j < s.jointCount(); ++j) {
        if (degree(j) == 1 &&
            (best < 0 || (s.joints.row(j) - p).norm() < (s.joints.row(best) - p).norm()))
            best = j;
    }
    return best;
}

// A body (a disk of radius 80) with three arms 24 px wide reaching 260 px from its centre.
Region threeArmedBody()
{
    std::vector<StrokeInput> strokes{{rows({{0, 0}}), 156.0}};
    for (int k = 0; k < 3; ++k) {
        const double a = 2.0 * M_PI * k / 3 + 0.3;
        strokes.push_back({rows({{0, 0}, {250 * std::cos(a), 250 * std::sin(a)}}), 20.0});
    }
    return shapeOf(strokes);
}

} // namespace

class TestAnimatorRig : public QObject {
    Q_OBJECT
private slots:
    void drawnRectangleHasOneBone();
    void plusSignHasFourLimbsFromOneJunction();
    void limbBaseJointSitsWhereWidthDrops();
    void limbBaseBelowALongChest();
    void rootIsAtThickestPart();
    void bentArmGetsAnElbow();
    void longStraightArmGetsAMiddleJoint();
    void loosePiecesHangFromNearestBone();
    void legsDrawnApartHangFromTheBodyTheyMeet();
    void ellipseBodyHoldsItsLegs();
    void crossOfTwoObjectsJoins();
    void prongBesideALongerBranchGoes();
    void stripOfABrokenLoopLeavesTheBodyWhereItNarrows();
    void tailFusedWithTheRumpLeavesTheBodyBelowIt();
};

void TestAnimatorRig::drawnRectangleHasOneBone()
{
    // A rectangle drawn as one closed stroke with a 4 px pen, corners a little rounded and
    // uneven as a hand makes them: the silhouette fills it, its corners leave spurs.
    const Region shape = shapeOf({{rows({{0, 2},
                                         {3, 0},
                                         {150, -1},
                                         {204, 1},
                                         {206, 5},
                                         {205, 60},
                                         {201, 64},
                                         {90, 62},
                                         {2, 63},
                                         {-1, 58},
                                         {0, 2}}),
                                   4.0}});
    const Skeleton s = rigOf(shape);
    QVERIFY(isValidSkeleton(s));
    QCOMPARE(boneCount(s), 1);
    QVERIFY(s.limbBase.empty()); // no limb leaves a body
    QVERIFY(bonesInside(s, shape) >= 0.99);
    // Without the clean-up the corner spurs stay.
    QVERIFY(boneCount(rigOf(shape, false)) > 1);
}

void TestAnimatorRig::plusSignHasFourLimbsFromOneJunction()
{
    const Region shape = regionOf(plusSign(40, 120));
    const Skeleton s = rigOf(shape);
    QVERIFY(isValidSkeleton(s));
    QCOMPARE(kindCount(s, JointKind::Junction), 1);
    QCOMPARE(kindCount(s, JointKind::Terminal), 4);
    const Eigen::VectorXi degree = jointDegrees(s);
    int junction = -1;
    for (int j = 0; j < s.jointCount(); ++j)
        junction = degree(j) >= 3 ? j : junction;
    QVERIFY(s.joints.row(junction).norm() < 2.0);
    QCOMPARE(s.root, junction); // the thickest place
    for (int j = 0; j < s.jointCount(); ++j) {
        if (degree(j) != 1)
            continue;
        const std::vector<int> chain = limbChain(s, j);
        QCOMPARE(s.parent(chain.back()), junction);
    }
}

void TestAnimatorRig::limbBaseJointSitsWhereWidthDrops()
{
    const Region shape = threeArmedBody();
    const Skeleton s = rigOf(shape), plain = rigOf(shape, false);
    QVERIFY(bonesInside(s, shape) >= 0.99);
    QCOMPARE(kindCount(s, JointKind::Terminal), 3);
    for (int k = 0; k < 3; ++k) {
        const double a = 2.0 * M_PI * k / 3 + 0.3;
        const Eigen::RowVector2d tipAt(260 * std::cos(a), 260 * std::sin(a));
        const int tip = tipNearest(s, tipAt);
        const std::vector<int> chain = limbChain(s, tip);
        // The joint nearest the junction on the limb is its base: where the arm (radius 12)
        // leaves the body (radius 80), not at the body's centre.
        const double base = s.joints.row(chain.back()).norm();
        QVERIFY2(base > 60.0 && base < 110.0, qPrintable(QString::number(base)));
        QVERIFY(s.radius(chain.back()) < 0.5 * s.radius(s.parent(chain.back())));
        // It is marked as the base (IK turns the arm there), and nothing else on the arm is.
        QCOMPARE(s.limbBase.size(), std::size_t(s.jointCount()));
        for (const int j : chain)
            QCOMPARE(bool(s.limbBase[std::size_t(j)]), j == chain.back());
        // RealSkel alone turns the arm about the centre: one bone from there.
        const std::vector<int> plainChain = limbChain(plain, tipNearest(plain, tipAt));
        QVERIFY(plain.joints.row(plainChain.back()).norm() < 60.0 ||
                plain.joints.row(plainChain.back()).norm() > 110.0);
    }
}

void TestAnimatorRig::limbBaseBelowALongChest()
{
    // A horse's foreleg: the junction of back, neck and chest sits high, the chest (radius 60)
    // runs 180 px down from it and the leg (radius 12) only then leaves the body. The leg's
    // base belongs at the bottom of the chest, not one body radius below the junction.
    const Region shape = shapeOf({{rows({{0, 0}, {300, 0}}), 120.0},
                                  {rows({{0, 0}, {-80, -200}}), 80.0},
                                  {rows({{0, 0}, {0, 180}}), 120.0},
                                  {rows({{0, 180}, {0, 430}}), 24.0}});
    const Skeleton s = rigOf(shape);
    QVERIFY(bonesInside(s, shape) >= 0.99);
    const std::vector<int> chain = limbChain(s, tipNearest(s, Eigen::RowVector2d(0, 440)));
    const double baseY = s.joints(chain.back(), 1);
    QVERIFY2(baseY > 150.0 && baseY < 260.0, qPrintable(QString::number(baseY)));
    QVERIFY(s.limbBase.at(std::size_t(chain.back())));
}

void TestAnimatorRig::rootIsAtThickestPart()
{
    // A long bent tail on a small body: the centre of mass lies out by the tail's bend, the
    // thickest part is the body.
    const Region shape =
        shapeOf({{rows({{0, 0}}), 100.0}, {rows({{0, 0}, {400, 0}, {400, -400}}), 40.0}});
    const Skeleton s = rigOf(shape);
    QCOMPARE(s.radius(s.root), s.radius.maxCoeff());
    QVERIFY(s.joints.row(s.root).norm() < 40.0);
    const Skeleton plain = rigOf(shape, false);
    QVERIFY(plain.joints.row(plain.root).norm() > 100.0);
}

void TestAnimatorRig::bentArmGetsAnElbow()
{
    // An L-shaped arm (upper arm right, forearm down) on a body.
    const Region shape =
        shapeOf({{rows({{0, 0}}), 150.0}, {rows({{0, 0}, {230, 0}, {230, 200}}), 28.0}});
    const Skeleton s = rigOf(shape);
    QVERIFY(bonesInside(s, shape) >= 0.99);
    const std::vector<int> chain = limbChain(s, tipNearest(s, {230, 214}));
    QVERIFY(chain.size() >= 3); // tip, elbow, base
    bool elbow = false;
    for (int j : chain)
        elbow = elbow || (s.joints.row(j) - Eigen::RowVector2d(230, 0)).norm() < 30.0;
    QVERIFY(elbow);
}

void TestAnimatorRig::longStraightArmGetsAMiddleJoint()
{
    const Region shape = shapeOf({{rows({{0, 0}}), 150.0}, {rows({{0, 0}, {400, 0}}), 24.0}});
    const Skeleton s = rigOf(shape);
    const std::vector<int> chain = limbChain(s, tipNearest(s, {412, 0}));
    // Tip, a middle joint, the base where the arm leaves the body.
    QVERIFY2(chain.size() >= 3, qPrintable(QString::number(chain.size())));
    bool middle = false;
    for (std::size_t k = 1; k + 1 < chain.size(); ++k)
        middle = middle || (s.joints(chain[k], 0) > 170.0 && s.joints(chain[k], 0) < 330.0);
    QVERIFY(middle);
    const std::vector<int> plainChain =
        limbChain(rigOf(shape, false), tipNearest(rigOf(shape, false), {412, 0}));
    QCOMPARE(int(plainChain.size()), 1);
}

void TestAnimatorRig::loosePiecesHangFromNearestBone()
{
    // A body with a head drawn apart from it (20 px gap): one object, two polygons.
    const Region shape = shapeOf({{rows({{0, 0}, {0, 200}}), 60.0}, {rows({{0, -80}}), 50.0}});
    QCOMPARE(int(shape.size()), 2);
    const Skeleton s = rigOf(shape);
    QVERIFY(isValidSkeleton(s));
    QCOMPARE(int((s.parent.array() < 0).count()), 1); // one tree
    const Skeleton plain = rigOf(shape, false);
    QCOMPARE(int((plain.parent.array() < 0).count()), 2);
    // The same head drawn 300 px away (a second figure) is not hung across open air: it
    // keeps a tree of its own, and no bone leaves the shape.
    const Region apart = shapeOf({{rows({{0, 0}, {0, 200}}), 60.0}, {rows({{0, -330}}), 50.0}});
    QCOMPARE(int(apart.size()), 2);
    const Skeleton two = rigOf(apart);
    QVERIFY(isValidSkeleton(two));
    QCOMPARE(int((two.parent.array() < 0).count()), 2);
    for (int j = 0; j < two.jointCount(); ++j)
        if (two.parent(j) >= 0)
            QVERIFY(std::abs(two.joints(j, 1) - two.joints(two.parent(j), 1)) < 250.0);
}

void TestAnimatorRig::legsDrawnApartHangFromTheBodyTheyMeet()
{
    // A cow drawn as a thick body with four legs as lines under it, each stopping 20 px short
    // of the belly; the front two legs 50 px apart, nearer each other than the body's bone
    // (80 px above them). Each leg hangs from the body where it meets it, never from the leg
    // beside it by a bone through the air between them.
    const std::array<double, 4> legs{40.0, 90.0, 210.0, 260.0};
    std::vector<StrokeInput> strokes{{rows({{0, 0}, {300, 0}}), 160.0}};
    for (double x : legs)
        strokes.push_back({rows({{x, 106}, {x, 250}}), 12.0});
    const Region shape = shapeOf(strokes);
    QCOMPARE(int(shape.size()), 5);
    const Skeleton s = rigOf(shape);
    QVERIFY(isValidSkeleton(s));
    QCOMPARE(int((s.parent.array() < 0).count()), 1); // one tree
    for (int j = 0; j < s.jointCount(); ++j) {
        const int p = s.parent(j);
        if (p < 0)
            continue;
        // Below the belly (y > 80), a bone runs down one leg only.
        if (s.joints(j, 1) > 84.0 && s.joints(p, 1) > 84.0)
            QVERIFY2(std::abs(s.joints(j, 0) - s.joints(p, 0)) < 15.0,
                     qPrintable(QStringLiteral("bone %1-%2 from x %3 to %4")
                                    .arg(p)
                                    .arg(j)
                                    .arg(s.joints(p, 0))
                                    .arg(s.joints(j, 0))));
    }
    // Out of the shape: the four gaps the bridges cross, not a bone along the belly.
    double bonePx = 0.0;
    for (int j = 0; j < s.jointCount(); ++j)
        if (s.parent(j) >= 0)
            bonePx += (s.joints.row(j) - s.joints.row(s.parent(j))).norm();
    const double air = (1.0 - bonesInside(s, shape)) * bonePx;
    QVERIFY2(air < 4 * 20.0 + 10.0, qPrintable(QString::number(air)));
}

void TestAnimatorRig::ellipseBodyHoldsItsLegs()
{
    // A cow drawn with the pen: its body an ellipse (500 × 234 px), a round head beyond its
    // front, four legs as lines under it, the outer two under the body's curved ends (about
    // 70 px below it, the inner two 30 px). The body's medial axis has joints only at its ends,
    // where the inscribed radius is b²/a = 55 px, less than half the middle's 117: measured at
    // its joints, the outer legs lay further from the body than its "widest radius" and kept
    // trees of their own.
    const auto ring = [](double cx, double cy, double rx, double ry, double start) {
        Eigen::MatrixX2d out(61, 2);
        for (int i = 0; i <= 60; ++i) {
            const double t = start + 2.0 * M_PI * i / 60;
            out.row(i) << cx + rx * std::cos(t), cy + ry * std::sin(t);
        }
        return out;
    };
    std::vector<StrokeInput> strokes{{ring(0, 0, 250, 117, 0.0), 3.0},
                                     {ring(308, -100, 70, 67, 2.5), 3.0}};
    for (double x : {-183.0, -67.0, 100.0, 217.0})
        strokes.push_back({rows({{x, 145}, {x, 338}}), 3.0});
    const Region shape = shapeOf(strokes);
    QCOMPARE(int(shape.size()), 6);
    const Skeleton s = rigOf(shape);
    QVERIFY(isValidSkeleton(s));
    QCOMPARE(int((s.parent.array() < 0).count()), 1); // every leg hangs from the body
}

void TestAnimatorRig::crossOfTwoObjectsJoins()
{
    // Two bars drawn as separate objects, crossing as an X.
    const std::vector<Skeleton> parts{rigOf(regionOf(bar(300, 30, M_PI / 4))),
                                      rigOf(regionOf(bar(300, 30, -M_PI / 4)))};
    const std::vector<PartJoin> joins = findJoins(parts, 0);
    QCOMPARE(int(joins.size()), 1);
    const auto character = assembleCharacter(parts, joins, 0);
    QVERIFY(character.hasValue());
    QCOMPARE(int((character->skeleton.parent.array() < 0).count()), 1);
    QCOMPARE(character->joins.front().kind, JoinKind::BoneSplit);
    const int joint = character->joins.front().joint;
    QVERIFY(character->skeleton.joints.row(joint).norm() < 10.0); // where they cross
}

QTEST_APPLESS_MAIN(TestAnimatorRig)
void TestAnimatorRig::prongBesideALongerBranchGoes()
{
    // A horse's tail as the straight skeleton saw it: the tail (60 px wide, hanging from the
    // rump) splits at the rump into two branches 20 px apart, one to the tail's end and a
    // shorter one to a notch at its corner, inside the longer one's width all the way. The
    // animator's rig keeps one chain down the tail; a second prong there is a limb whose turn
    // drags the tail with it.
    RawSkeleton raw;
    raw.contour = regionOf(rows(
        {{0, 0}, {300, 0}, {300, 330}, {254, 330}, {254, 300}, {240, 300}, {240, 100}, {0, 100}}));
    const std::vector<std::array<double, 3>> nodes{
        {50, 50, 50},   {150, 50, 50},  {270, 60, 30}, // body, the junction at the rump
        {280, 120, 20}, {280, 200, 20}, {281, 290, 19}, {283, 328, 2}, // down the tail
        {262, 130, 18}, {262, 220, 18}, {262, 296, 4}};                // the prong to the notch
    raw.nodes.resize(Eigen::Index(nodes.size()), 2);
    raw.radius.resize(raw.nodes.rows());
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        raw.nodes.row(Eigen::Index(i)) << nodes[i][0], nodes[i][1];
        raw.radius(Eigen::Index(i)) = nodes[i][2];
    }
    raw.clearance = raw.radius;
    raw.polygon = Eigen::VectorXi::Zero(raw.nodes.rows());
    raw.edges.resize(9, 2);
    raw.edges << 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 2, 7, 7, 8, 8, 9;
    raw.polygonVertices = raw.contour.front().outer.rows();
    raw.centroid << 150, 100;

    const auto tips = [](const Skeleton &s) { return kindCount(s, JointKind::Terminal); };
    RefineOptions options;
    options.animatorRig = true;
    const auto rig = refineSkeleton(raw, options);
    QVERIFY(rig && isValidSkeleton(*rig));
    QCOMPARE(tips(*rig), 2); // the body's end and the tail's
    const int tail = tipNearest(*rig, Eigen::RowVector2d(283, 328));
    QVERIFY((rig->joints.row(tail) - Eigen::RowVector2d(283, 328)).norm() < 1.0);
    QVERIFY(tipNearest(*rig, Eigen::RowVector2d(262, 296)) == tail);

    // Spread apart (the notch's prong turned 30° away from the tail), it is a limb of its own.
    RawSkeleton apart = raw;
    for (const Eigen::Index k : {7, 8, 9}) {
        const Eigen::Vector2d from = apart.nodes.row(k).transpose() - Eigen::Vector2d(270, 60);
        const double a = -M_PI / 6.0;
        apart.nodes.row(k) = (Eigen::Vector2d(270, 60) +
                              Eigen::Vector2d(std::cos(a) * from.x() - std::sin(a) * from.y(),
                                              std::sin(a) * from.x() + std::cos(a) * from.y()))
                                 .transpose();
        apart.clearance(k) = apart.radius(k) = 0.5 * raw.radius(k);
    }
    const auto spread = refineSkeleton(apart, options);
    QVERIFY(spread && isValidSkeleton(*spread));
    QCOMPARE(tips(*spread), 3);
    // RealSkel's refinement alone keeps the prong: the step above does something.
    options.animatorRig = false;
    const auto plain = refineSkeleton(raw, options);
    QVERIFY(plain && isValidSkeleton(*plain));
    QCOMPARE(tips(*plain), 3);
}

void TestAnimatorRig::stripOfABrokenLoopLeavesTheBodyWhereItNarrows()
{
    // A guitar: a body (radius 100), a neck of two strips 28 px wide round a slot, a head. The
    // skeleton is a tree, so the loop round the slot is broken at one end of a strip: that
    // strip ends in a tip, and its branch runs from the head's junction down the other strip,
    // through the body and out again. The strip is a limb of the body: its base is where it
    // leaves the body, not the body's centre (turning there swings the body with it).
    Region shape = shapeOf({{rows({{0, 0}}), 200.0},
                            {rows({{0, 0}, {420, 0}}), 80.0},
                            {rows({{450, 0}}), 120.0},
                            {rows({{450, -120}, {450, 120}}), 30.0},
                            {rows({{450, 0}, {580, 0}}), 30.0}});
    QCOMPARE(shape.size(), std::size_t(1));
    // The upper strip narrows towards the head (30 to 26 px), so the loop breaks there.
    shape[0].holes.push_back(rows({{60, -10}, {60, 10}, {380, 14}, {380, -10}}));
    const Skeleton s = rigOf(shape);
    QVERIFY(isValidSkeleton(s));
    QVERIFY(bonesInside(s, shape) >= 0.99);
    QVERIFY(s.joints.row(s.root).norm() < 40.0); // the body's centre
    const Eigen::VectorXi degree = jointDegrees(s);
    int strips = 0;
    for (int t = 0; t < s.jointCount(); ++t) {
        const Eigen::RowVector2d p = s.joints.row(t);
        if (degree(t) != 1 || p.x() < 100 || p.x() > 420 || std::abs(p.y()) < 12)
            continue;
        ++strips; // the loop's broken end
        // Up the parent links to the first joint marked as a limb base.
        int base = s.parent(t);
        while (base >= 0 && !(base < int(s.limbBase.size()) && s.limbBase[std::size_t(base)]))
            base = s.parent(base);
        QVERIFY2(base >= 0, "the strip has no base");
        const double x = s.joints(base, 0);
        QVERIFY2(x > 50.0 && x < 150.0, qPrintable(QString::number(x))); // the disk's edge: 96
        QVERIFY(std::abs(s.joints(base, 1)) > 12.0); // on the strip's side of the slot
    }
    QCOMPARE(strips, 1);
}

void TestAnimatorRig::tailFusedWithTheRumpLeavesTheBodyBelowIt()
{
    // A horse's tail (y down): it rises from the rump's top corner and hangs down the rump's
    // back, one with it on its inner side down to a slit at y = 150 where the body's back
    // parts from it. Its width is a tail's (radius 15) from the corner on, but it leaves the
    // body only where its inner side is outline too: a base at the corner turns the rump's
    // back with the tail (no cut there separates the two).
    const Region shape{Polygon{rows({{0, 0},
                                     {290, 0},
                                     {320, 10},
                                     {340, 30},
                                     {350, 60},
                                     {350, 400},
                                     {335, 410},
                                     {320, 400},
                                     {318, 150},
                                     {315, 190},
                                     {315, 300},
                                     {0, 300}}),
                               {}}};
    QVERIFY(signedArea(shape[0].outer) > 0.0);
    const Skeleton s = rigOf(shape);
    QVERIFY(isValidSkeleton(s));
    QVERIFY(bonesInside(s, shape) >= 0.99);
    // Up the parent links from the tail's tip to the first joint marked as a limb base.
    int base = s.parent(tipNearest(s, Eigen::RowVector2d(335, 410)));
    while (base >= 0 && !(base < int(s.limbBase.size()) && s.limbBase[std::size_t(base)]))
        base = s.parent(base);
    QVERIFY2(base >= 0, "the tail has no base");
    const Eigen::RowVector2d at = s.joints.row(base);
    QVERIFY2(at.y() > 120.0 && at.y() < 250.0 && at.x() > 318.0,
             qPrintable(QStringLiteral("%1, %2").arg(at.x()).arg(at.y())));
}

#include "tst_animator_rig.moc"
