// Warm-started drag events (issue 26): each event of a drag continues from the pose the one
// before returned (arapSolveFrom), so along a drag the pose stays near the converged one where
// a cold event's few passes on a large mesh cannot reach it; the stored pose stays a pure
// function of the pins whatever the drag did, and bad or degenerate starts never give NaN.
#include "arap_test_support.h"
#include "grid_mesh.h"

#include <finbook/deform/arap.h>

#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <vector>

using namespace finbook::deform;
using finbook::test::GridMesh;
using finbook::test::precompute;
using finbook::test::solved;

namespace {

bool sameBits(const Eigen::MatrixX2d &A, const Eigen::MatrixX2d &B)
{
    return A.rows() == B.rows() && A.size() > 0 &&
           std::memcmp(A.data(), B.data(), sizeof(double) * std::size_t(A.size())) == 0;
}

// Both end columns of a bar pinned, the right end turned by `angle` about the left end's
// middle: a bend.
struct Bend {
    Eigen::VectorXi b;
    Eigen::MatrixX2d bc;
};

Bend bendEnds(const GridMesh &g, double angle)
{
    Bend bend;
    bend.b.resize(2 * (g.rows + 1));
    for (int r = 0; r <= g.rows; ++r) {
        bend.b(2 * r) = g.vertex(0, r);
        bend.b(2 * r + 1) = g.vertex(g.columns, r);
    }
    bend.bc = finbook::test::rowsOf(g.V, bend.b);
    const Eigen::RowVector2d pivot(0.0, 0.5);
    Eigen::Matrix2d R;
    R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    for (Eigen::Index k = 1; k < bend.b.size(); k += 2)
        bend.bc.row(k) = pivot + (bend.bc.row(k) - pivot) * R.transpose();
    return bend;
}

// The vertices within `fraction` of the bar's length from either end pinned, the right band
// turned by `angle` about the left band's centroid.
Bend bendBands(const GridMesh &g, double fraction, double angle)
{
    const double low = g.V.col(0).minCoeff(), high = g.V.col(0).maxCoeff();
    std::vector<int> left, right;
    for (Eigen::Index v = 0; v < g.V.rows(); ++v) {
        if (g.V(v, 0) <= low + fraction * (high - low))
            left.push_back(int(v));
        else if (g.V(v, 0) >= high - fraction * (high - low))
            right.push_back(int(v));
    }
    Bend bend;
    bend.b.resize(Eigen::Index(left.size() + right.size()));
    std::copy(left.begin(), left.end(), bend.b.begin());
    std::copy(right.begin(), right.end(), bend.b.begin() + Eigen::Index(left.size()));
    bend.bc = finbook::test::rowsOf(g.V, bend.b);
    const Eigen::RowVector2d pivot = bend.bc.topRows(Eigen::Index(left.size())).colwise().mean();
    Eigen::Matrix2d R;
    R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    for (Eigen::Index k = Eigen::Index(left.size()); k < bend.b.size(); ++k)
        bend.bc.row(k) = pivot + (bend.bc.row(k) - pivot) * R.transpose();
    return bend;
}

// The bend `bendAt(t)` reached in `events` warm events from the rest pose (t = 1/events … 1);
// the last event's pose.
Eigen::MatrixX2d warmDrag(const ArapPrecompute &d, const Eigen::MatrixX2d &rest,
                          const std::function<Bend(double)> &bendAt, int events,
                          ArapSolveReport *report = nullptr)
{
    Eigen::MatrixX2d U = rest;
    for (int e = 1; e <= events; ++e) {
        const Eigen::MatrixX2d start = U;
        auto result = arapSolveFrom(d, bendAt(double(e) / events).bc, start, U);
        if (!result) {
            qWarning("solve failed: %s", result.error().message.c_str());
            return {};
        }
        if (report)
            *report = *result;
    }
    return U;
}

// The same for bendEnds(g, ·) up to `angle`.
Eigen::MatrixX2d warmDrag(const ArapPrecompute &d, const GridMesh &g, double angle, int events,
                          ArapSolveReport *report = nullptr)
{
    return warmDrag(
        d, g.V, [&](double t) { return bendEnds(g, angle * t); }, events, report);
}

ArapOptions convergedReference()
{
    ArapOptions o;
    o.finalTolerance = 1e-11;
    o.finalEnergyTolerance = 0.0;
    o.finalPassCap = 20000;
    o.fixFlips = false;
    return o;
}

// The end bands (6 % of the length) of `g` pinned and the right one turned `degrees` in a steady
// drag of 30 events with `passes` passes each: the drag ends without a flipped triangle (the
// converged pose has none), near the optimum, and repeats bit for bit.
void checkBandedDragUnfolds(const GridMesh &g, double degrees, int passes)
{
    const double angle = degrees * M_PI / 180.0;
    const Bend bend = bendBands(g, 0.06, angle);
    ArapOptions few;
    few.maxDragPasses = passes;
    const auto data = precompute(g.V, g.F, bend.b, few);
    const auto reference = precompute(g.V, g.F, bend.b, convergedReference());
    QVERIFY(data && reference);
    QCOMPARE(data->warmDragPasses, passes);
    const Eigen::MatrixX2d optimum = solved(*reference, bend.bc, ArapStage::Final);
    QCOMPARE(arapFlippedTriangles(g.V, g.F, optimum), 0);
    const auto drag = [&] {
        return warmDrag(
            *data, g.V, [&](double t) { return bendBands(g, 0.06, angle * t); }, 30);
    };
    const Eigen::MatrixX2d U = drag();
    QVERIFY(U.rows() == g.V.rows());
    QCOMPARE(arapFlippedTriangles(g.V, g.F, U), 0);
    const double ratio = arapCotangentEnergy(g.V, g.F, U) / arapCotangentEnergy(g.V, g.F, optimum);
    QVERIFY2(ratio <= 1.01, qPrintable(QString::number(ratio)));
    QVERIFY(sameBits(drag(), U));
}

} // namespace

class TestArapDrag : public QObject {
    Q_OBJECT

private slots:
    void warmDragIsCloserThanColdEvents();
    void storedPoseIgnoresTheDragPath();
    void warmStartKeepsRigidMotionsRigid();
    void badStartsFallBackToTheColdEvent();
    void degenerateDragsStayFinite();
    void steadyDragOfAThinStripKeepsUp();
    void steadyDragWithTwoPassesFollowsTheArc();
    void dragsRepeatBitForBit();
    void dragLeavesNoFoldTheOptimumHasNot();
    void lastEventsFoldsOpenWithTwoMorePasses();
    void coldEventsStartFromACoarserMesh();
};

// 10k vertices: the budget holds a few passes, so a cold event starts from the clustered
// rotations and stays above the optimum; after a drag of 20 events the warm pose is at
// least as close, the pins hold, more passes fit an event than a cold one runs, and events
// that keep the targets converge to the optimum.
void TestArapDrag::warmDragIsCloserThanColdEvents()
{
    const GridMesh g = finbook::test::gridMesh(200, 50, 4.0, 1.0, 0.2);
    const double angle = 1.0;
    const Bend bend = bendEnds(g, angle);
    const auto data = precompute(g.V, g.F, bend.b);
    const auto reference = precompute(g.V, g.F, bend.b, convergedReference());
    QVERIFY(data && reference);
    QVERIFY(data->warmDragPasses > data->dragPasses);
    const double optimum =
        arapCotangentEnergy(g.V, g.F, solved(*reference, bend.bc, ArapStage::Final));
    const double cold =
        arapCotangentEnergy(g.V, g.F, solved(*data, bend.bc, ArapStage::Drag)) / optimum;
    ArapSolveReport report;
    const Eigen::MatrixX2d U = warmDrag(*data, g, angle, 20, &report);
    QVERIFY(U.rows() == g.V.rows());
    const double warm = arapCotangentEnergy(g.V, g.F, U) / optimum;
    QVERIFY2(warm <= cold, qPrintable(QStringLiteral("warm %1, cold %2").arg(warm).arg(cold)));
    QVERIFY(report.passes >= data->warmDragPasses);
    QCOMPARE(finbook::test::rowsOf(U, bend.b), bend.bc);
    // The mouse held still: events at the same targets converge (here from 1.095× in 20).
    Eigen::MatrixX2d still = U;
    for (int e = 0; e < 20; ++e) {
        const Eigen::MatrixX2d start = still;
        QVERIFY(arapSolveFrom(*data, bend.bc, start, still));
    }
    const double settled = arapCotangentEnergy(g.V, g.F, still) / optimum;
    QVERIFY2(settled <= 1.01, qPrintable(QString::number(settled)));
}

// The stored (Final) pose after any drag is the same bits as without one: fast, slow, and a
// drag that went far past the target and came back.
void TestArapDrag::storedPoseIgnoresTheDragPath()
{
    const GridMesh g = finbook::test::gridMesh(40, 10, 4.0, 1.0, 0.2);
    const Bend bend = bendEnds(g, 0.8);
    const auto data = precompute(g.V, g.F, bend.b);
    QVERIFY(data);
    const Eigen::MatrixX2d direct = solved(*data, bend.bc, ArapStage::Final);
    for (const int events : {1, 3, 25}) {
        QVERIFY(warmDrag(*data, g, 0.8, events).rows() == g.V.rows());
        QVERIFY(sameBits(solved(*data, bend.bc, ArapStage::Final), direct));
    }
    Eigen::MatrixX2d U = warmDrag(*data, g, 2.5, 10);
    for (int e = 0; e < 5; ++e) {
        const Eigen::MatrixX2d start = U;
        QVERIFY(arapSolveFrom(*data, bendEnds(g, 2.5 - 1.7 * (e + 1) / 5).bc, start, U));
    }
    QVERIFY(sameBits(solved(*data, bend.bc, ArapStage::Final), direct));
}

// All pins moved by one rigid motion, event by event: every warm pose is that motion of the
// rest shape (the start's correction by step 1 is rigid, and so is every pass from there).
void TestArapDrag::warmStartKeepsRigidMotionsRigid()
{
    const GridMesh g = finbook::test::gridMesh(60, 15, 4.0, 1.0, 0.2);
    const Bend rest = bendEnds(g, 0.0);
    const auto data = precompute(g.V, g.F, rest.b);
    QVERIFY(data);
    Eigen::MatrixX2d U = g.V;
    for (int e = 1; e <= 8; ++e) {
        const Eigen::MatrixX2d expected =
            finbook::test::rigidlyMoved(g.V, 0.4 * e, Eigen::Vector2d(15.0 * e, -4.0 * e));
        const Eigen::MatrixX2d start = U;
        QVERIFY(arapSolveFrom(*data, finbook::test::rowsOf(expected, rest.b), start, U));
        const double error = (U - expected).rowwise().norm().maxCoeff();
        QVERIFY2(error <= 1e-9 * 130.0, qPrintable(QString::number(error)));
    }
}

// A start of the wrong size, with NaN or beyond the coordinate range is not used: the event
// is the cold one, bit for bit; with the paper's method the start is ignored.
void TestArapDrag::badStartsFallBackToTheColdEvent()
{
    const GridMesh g = finbook::test::gridMesh(40, 10, 4.0, 1.0, 0.2);
    const Bend bend = bendEnds(g, 0.8);
    const auto data = precompute(g.V, g.F, bend.b);
    ArapOptions paper;
    paper.method = ArapMethod::TwoStep;
    paper.extraPasses = 1;
    const auto exact = precompute(g.V, g.F, bend.b, paper);
    QVERIFY(data && exact);
    const Eigen::MatrixX2d cold = solved(*data, bend.bc, ArapStage::Drag);
    Eigen::MatrixX2d withNaN = g.V, huge = g.V;
    withNaN(3, 1) = std::numeric_limits<double>::quiet_NaN();
    huge(5, 0) = 1e200;
    for (const Eigen::MatrixX2d &start :
         {Eigen::MatrixX2d(g.V.topRows(10)), Eigen::MatrixX2d(), withNaN, huge}) {
        Eigen::MatrixX2d U;
        QVERIFY(arapSolveFrom(*data, bend.bc, start, U));
        QVERIFY(sameBits(U, cold));
    }
    Eigen::MatrixX2d U;
    QVERIFY(arapSolveFrom(*exact, bend.bc, g.V, U));
    QVERIFY(sameBits(U, solved(*exact, bend.bc, ArapStage::Drag)));
    // Bad targets are reported as by arapSolve.
    Eigen::MatrixX2d badTargets = bend.bc;
    badTargets(0, 0) = std::numeric_limits<double>::infinity();
    const auto result = arapSolveFrom(*data, badTargets, g.V, U);
    QVERIFY(!result);
    QCOMPARE(result.error().code, DeformErrorCode::NonFiniteInput);
}

// Pins dragged onto one point collapse the pose; dragging on from there (the start is a
// point), and back out again, stays finite with the pins where they were put.
void TestArapDrag::degenerateDragsStayFinite()
{
    for (const int columns : {40, 200}) { // plain passes; coarse rotations
        const GridMesh g = finbook::test::gridMesh(columns, columns / 4, 4.0, 1.0, 0.2);
        const Bend bend = bendEnds(g, 0.8);
        const auto data = precompute(g.V, g.F, bend.b);
        QVERIFY(data);
        Eigen::MatrixX2d U = g.V;
        const Eigen::MatrixX2d onePoint = Eigen::MatrixX2d::Constant(bend.b.size(), 2, 0.5);
        const Eigen::MatrixX2d onLine = [&] {
            Eigen::MatrixX2d m = bend.bc;
            m.col(1).setConstant(0.5);
            return m;
        }();
        for (const Eigen::MatrixX2d &bc :
             {onePoint, onePoint, onLine, bend.bc, onePoint, bend.bc}) {
            const Eigen::MatrixX2d start = U;
            QVERIFY(arapSolveFrom(*data, bc, start, U));
            QVERIFY(U.allFinite() && U.rows() == g.V.rows());
            QCOMPARE(finbook::test::rowsOf(U, bend.b), bc);
        }
        // Starting from a pose collapsed to one point.
        const Eigen::MatrixX2d point = Eigen::MatrixX2d::Constant(g.V.rows(), 2, 0.5);
        QVERIFY(arapSolveFrom(*data, bend.bc, point, U));
        QVERIFY(U.allFinite());
    }
}

// A thin 20:1 strip with the few passes per event a large mesh gets (maxDragPasses 3), bent
// by 1 rad in a steady drag of 30 events: each event continues the last one's correction
// (momentum), so the pose keeps up with the pins: the last event's energy stays near the
// converged one (measured 1.0005×; without momentum the pose lagged at 1.11×) and no
// triangle is flipped where the converged pose has none.
void TestArapDrag::steadyDragOfAThinStripKeepsUp()
{
    const GridMesh g = finbook::test::gridMesh(160, 6, 20.0, 1.0, 0.2);
    const double angle = 1.0;
    const Bend bend = bendEnds(g, angle);
    ArapOptions few;
    few.minDragPasses = 2;
    few.maxDragPasses = 3;
    const auto data = precompute(g.V, g.F, bend.b, few);
    const auto reference = precompute(g.V, g.F, bend.b, convergedReference());
    QVERIFY(data && reference);
    QCOMPARE(data->warmDragPasses, 3);
    const Eigen::MatrixX2d optimum = solved(*reference, bend.bc, ArapStage::Final);
    const Eigen::MatrixX2d U = warmDrag(*data, g, angle, 30);
    QVERIFY(U.rows() == g.V.rows());
    const double ratio = arapCotangentEnergy(g.V, g.F, U) / arapCotangentEnergy(g.V, g.F, optimum);
    QVERIFY2(ratio <= 1.02, qPrintable(QString::number(ratio)));
    QCOMPARE(arapFlippedTriangles(g.V, g.F, optimum), 0);
    QCOMPARE(arapFlippedTriangles(g.V, g.F, U), 0);
}

// The same strip with two passes per event: the correction an event needs grows along the
// arc the pins turn on, and the start follows that growth (acceleration): the drag ends at
// 1.0016× the converged energy, where momentum alone left 1.0039×.
void TestArapDrag::steadyDragWithTwoPassesFollowsTheArc()
{
    const GridMesh g = finbook::test::gridMesh(160, 6, 20.0, 1.0, 0.2);
    const double angle = 1.0;
    const Bend bend = bendEnds(g, angle);
    ArapOptions two;
    two.minDragPasses = 2;
    two.maxDragPasses = 2;
    const auto data = precompute(g.V, g.F, bend.b, two);
    const auto reference = precompute(g.V, g.F, bend.b, convergedReference());
    QVERIFY(data && reference);
    QCOMPARE(data->warmDragPasses, 2);
    const Eigen::MatrixX2d optimum = solved(*reference, bend.bc, ArapStage::Final);
    const Eigen::MatrixX2d U = warmDrag(*data, g, angle, 30);
    QVERIFY(U.rows() == g.V.rows());
    const double ratio = arapCotangentEnergy(g.V, g.F, U) / arapCotangentEnergy(g.V, g.F, optimum);
    QVERIFY2(ratio <= 1.0025, qPrintable(QString::number(ratio)));
    QVERIFY(sameBits(warmDrag(*data, g, angle, 30), U));
}

// Momentum continues only the drag whose last pose is the start: a drag repeated from the
// rest pose gives the same poses bit for bit, event by event.
void TestArapDrag::dragsRepeatBitForBit()
{
    const GridMesh g = finbook::test::gridMesh(80, 4, 10.0, 1.0, 0.2);
    const Bend bend = bendEnds(g, 1.0);
    ArapOptions few;
    few.maxDragPasses = 3;
    const auto data = precompute(g.V, g.F, bend.b, few);
    QVERIFY(data);
    const Eigen::MatrixX2d first = warmDrag(*data, g, 1.0, 30);
    const Eigen::MatrixX2d second = warmDrag(*data, g, 1.0, 30);
    QVERIFY(sameBits(first, second));
    // The momentum carried: the same drag with each event's start a fresh copy of a pose
    // that is not the last one returned (one event back) differs.
    Eigen::MatrixX2d U = g.V;
    for (int e = 1; e <= 30; ++e) {
        const Eigen::MatrixX2d start = U;
        QVERIFY(arapSolveFrom(*data, bendEnds(g, 1.0 * e / 30).bc, start, U));
        Eigen::MatrixX2d other; // breaks the continuation
        QVERIFY(arapSolveFrom(*data, bend.bc, g.V, other));
    }
    QVERIFY(!sameBits(U, first));
}

// A 2:1 bar whose end bands (6 % of its length) are pinned, the right one turned 60° in a
// steady drag of 30 events with the few passes of a large mesh (8): the drag squeezes the
// triangles next to the left band, and local relaxation left two of them folded where the
// converged pose has none (a local minimum the drag walked into). The restart of the region
// from its neighbour means opens them; the pose stays near the optimum and the drag repeats.
void TestArapDrag::dragLeavesNoFoldTheOptimumHasNot()
{
    checkBandedDragUnfolds(finbook::test::gridMesh(40, 20, 2.0, 1.0), 60.0, 8);
}

// A 4:1 bar whose end bands are pinned, the right one turned 75° in 30 events with the five
// passes per event of a large mesh: the last events squeeze two triangles next to a band over
// where the converged pose keeps them upright, local relaxation cannot open them, and one
// extra pass did not either (the drag ended with both folded). Two extra passes, with the count
// allowed to stall for one, open them.
void TestArapDrag::lastEventsFoldsOpenWithTwoMorePasses()
{
    checkBandedDragUnfolds(finbook::test::gridMesh(60, 15, 4.0, 1.0), 75.0, 5);
}

// A 20k-vertex 4:1 bar (the size of `finbook-bench arap`'s): a cold drag event, which has room
// for one or two fine passes, starts from the same shape solved on a coarser mesh. With its
// ends pinned as 6 % bands and turned 60° it lands much closer to the optimum than the
// clustered start alone (1.05× against 1.12× the converged energy), the pins hold
// exactly, and the stored pose is unchanged by it. Single pinned vertices (the app's pins), two
// at each end, get the same start. A jump event (undo, a flick) is such a cold event.
void TestArapDrag::coldEventsStartFromACoarserMesh()
{
    const GridMesh g = finbook::test::gridMesh(280, 70, 4.0, 1.0, 0.1);
    const double angle = 60.0 * M_PI / 180.0;
    ArapOptions single;
    single.twoLevelVertices = 0;
    for (const bool bands : {true, false}) {
        const auto bent = [&](double turn) {
            Bend bend = bands ? bendBands(g, 0.06, turn) : bendEnds(g, turn);
            if (!bands) { // two vertices of each end column, a quarter from its ends
                const int r1 = g.rows / 4, r2 = 3 * g.rows / 4;
                Eigen::VectorXi chosen(4), b(4);
                chosen << 2 * r1, 2 * r2, 2 * r1 + 1, 2 * r2 + 1;
                for (int k = 0; k < 4; ++k)
                    b(k) = bend.b(chosen(k));
                const Eigen::MatrixX2d bc = finbook::test::rowsOf(bend.bc, chosen);
                bend.b = b;
                bend.bc = bc;
            }
            return bend;
        };
        const Bend bend = bent(angle);
        const auto twoLevel = precompute(g.V, g.F, bend.b);
        const auto oneLevel = precompute(g.V, g.F, bend.b, single);
        const auto reference = precompute(g.V, g.F, bend.b, convergedReference());
        QVERIFY(twoLevel && oneLevel && reference);
        QVERIFY(twoLevel->coarseLevel);
        QVERIFY(!oneLevel->coarseLevel);
        QVERIFY(twoLevel->coarseLevel->rest.size() < g.V.rows() / 4);
        const double optimum =
            arapCotangentEnergy(g.V, g.F, solved(*reference, bend.bc, ArapStage::Final));
        const Eigen::MatrixX2d U = solved(*twoLevel, bend.bc, ArapStage::Drag);
        QVERIFY(U.allFinite());
        QCOMPARE(finbook::test::rowsOf(U, bend.b), bend.bc);
        const double coarse = arapCotangentEnergy(g.V, g.F, U) / optimum;
        const double clustered =
            arapCotangentEnergy(g.V, g.F, solved(*oneLevel, bend.bc, ArapStage::Drag)) / optimum;
        QVERIFY2(coarse <= 1.06 && coarse < clustered - 0.05,
                 qPrintable(QStringLiteral("bands %1: two levels %2, clustered start %3")
                                .arg(bands)
                                .arg(coarse)
                                .arg(clustered)));
        const Eigen::MatrixX2d stored = solved(*twoLevel, bend.bc, ArapStage::Final);
        QVERIFY(sameBits(stored, solved(*oneLevel, bend.bc, ArapStage::Final)));
        // A jump is that cold event, whatever the start: the whole bend in one event from the
        // rest pose, from the pose of a bend 15° short of it (where the warm start is good too),
        // and its undo back from the bent pose.
        Eigen::MatrixX2d jumped;
        QVERIFY(arapSolveFrom(*twoLevel, bend.bc, g.V, jumped));
        QVERIFY(sameBits(jumped, U));
        const Eigen::MatrixX2d shorter =
            solved(*twoLevel, bent(angle - 15.0 * M_PI / 180.0).bc, ArapStage::Drag);
        QVERIFY(arapSolveFrom(*twoLevel, bend.bc, shorter, jumped));
        QVERIFY(sameBits(jumped, U));
        const Eigen::MatrixX2d rest = finbook::test::rowsOf(g.V, bend.b);
        Eigen::MatrixX2d undone;
        QVERIFY(arapSolveFrom(*twoLevel, rest, jumped, undone));
        QVERIFY(sameBits(undone, solved(*twoLevel, rest, ArapStage::Drag)));
        QVERIFY((undone - g.V).cwiseAbs().maxCoeff() <= 1e-9);
    }
}

QTEST_APPLESS_MAIN(TestArapDrag)
#include "tst_arap_drag.moc"
