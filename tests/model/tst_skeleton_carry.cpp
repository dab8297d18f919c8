// Hand edits surviving a rebuild (issue 21): carryHandEdits keeps moved joints and locks of
// the old skeleton where the rebuilt one still has a joint of the same kind close by.
#include "stroke_support.h"

#include <finbook/model/skeleton/skeleton_carry.h>
#include <finbook/model/skeleton/skeleton_commands.h>

#include <QLineF>
#include <QTest>

using namespace finbook;
using namespace finbook::model;

namespace {

// An arm drawn with parallel strokes, its forearm `reach` px long, plus `extra` strokes.
StrokeGroup arm(double reach, const std::vector<std::pair<QPointF, QPointF>> &extra = {})
{
    StrokeGroup g;
    g.id = 1;
    Id id = 2;
    for (int k = 0; k <= 6; ++k) {
        const double o = 5.0 * k;
        g.strokes.push_back({id++, testing::lineStroke({100, 100 + o}, {330, 100 + o}, 60, 6.0f)});
        g.strokes.push_back(
            {id++, testing::lineStroke({300 + o, 100}, {300 + o, 100 + reach}, 60, 6.0f)});
    }
    for (const auto &[a, b] : extra)
        g.strokes.push_back({id++, testing::lineStroke(a, b, 30, 6.0f)});
    return g;
}

int tipNear(const SkeletonRig &rig, QPointF p)
{
    int best = -1;
    for (std::size_t j = 0; j < rig.joints.size(); ++j) {
        if (best < 0 ||
            QLineF(rig.joints[j], p).length() < QLineF(rig.joints[std::size_t(best)], p).length())
            best = int(j);
    }
    return best;
}

} // namespace

class TestSkeletonCarry : public QObject {
    Q_OBJECT
private slots:
    void movedJointAndLockSurviveARebuild();
    void jointsTheDrawingMovedTakeTheirNewPlace();
    void invalidInputGivesTheRebuiltSkeleton();
};

void TestSkeletonCarry::movedJointAndLockSurviveARebuild()
{
    const auto built = buildSkeletonRig(arm(230));
    QVERIFY(built);
    // By hand: the hand's tip moved 6 px, the root locked.
    SkeletonRig edited = *built;
    const int tip = tipNear(edited, {315, 330});
    const QPointF moved = edited.joints[std::size_t(tip)] + QPointF(6, -4);
    edited.joints[std::size_t(tip)] = moved;
    edited = edited.withLock(edited.root, true);
    // A stroke added at the other end (the shoulder drawn a little thicker).
    const auto rebuilt = buildSkeletonRig(arm(230, {{{100, 98}, {180, 98}}}), edited.settings,
                                          edited.joints[std::size_t(edited.root)]);
    QVERIFY(rebuilt);
    const int newTip = tipNear(*rebuilt, moved);
    QVERIFY(QLineF(rebuilt->joints[std::size_t(newTip)], moved).length() > 1.0);
    const SkeletonRig carried = carryHandEdits(edited, *rebuilt);
    QVERIFY(carried.isValid());
    QCOMPARE(carried.joints[std::size_t(newTip)], moved);
    QVERIFY(carried.isLocked(carried.root));
    QCOMPARE(carried.parent, rebuilt->parent);
}

void TestSkeletonCarry::jointsTheDrawingMovedTakeTheirNewPlace()
{
    const auto built = buildSkeletonRig(arm(230));
    QVERIFY(built);
    // The forearm drawn 150 px longer: its tip goes with it.
    const auto rebuilt =
        buildSkeletonRig(arm(380), built->settings, built->joints[std::size_t(built->root)]);
    QVERIFY(rebuilt);
    const SkeletonRig carried = carryHandEdits(*built, *rebuilt);
    const int tip = tipNear(carried, {315, 480});
    QVERIFY(carried.joints[std::size_t(tip)].y() > 420.0);
}

void TestSkeletonCarry::invalidInputGivesTheRebuiltSkeleton()
{
    const auto rebuilt = buildSkeletonRig(arm(230));
    QVERIFY(rebuilt);
    QCOMPARE(carryHandEdits(SkeletonRig{}, *rebuilt), *rebuilt);
    SkeletonRig broken = *rebuilt;
    broken.parent[0] = 5;
    QCOMPARE(carryHandEdits(broken, *rebuilt), *rebuilt);
}

QTEST_GUILESS_MAIN(TestSkeletonCarry)
#include "tst_skeleton_carry.moc"
