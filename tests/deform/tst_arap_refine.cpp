// Refined ARAP poses (issues 13, 26) and following components (issue 15): drag and stored
// poses are pure functions of pins and precompute, a stored pose is converged (energies here
// are the cotangent ARAP energy the refined method minimises), rigid pin motions
// stay rigid in every mode, flipped triangles the optimum does not have are repaired, an
// unpinned component follows the nearest pinned one, and degenerate pins never give NaN.
#include "arap_test_support.h"
#include "grid_mesh.h"

#include <finbook/deform/arap.h>

#include <QTest>

#include <cstring>
#include <thread>

using namespace finbook::deform;
using finbook::test::GridMesh;
using finbook::test::precompute;
using finbook::test::solved;

namespace {

struct Mode {
    ArapMethod method;
    ArapStage stage;
};

bool sameBits(const Eigen::MatrixX2d &A, const Eigen::MatrixX2d &B)
{
    return A.rows() == B.rows() && A.size() > 0 &&
           std::memcmp(A.data(), B.data(), sizeof(double) * std::size_t(A.size())) == 0;
}

double maxRowDistance(const Eigen::MatrixX2d &A, const Eigen::MatrixX2d &B)
{
    return A.rows() == B.rows() ? (A - B).rowwise().norm().maxCoeff() : INFINITY;
}

// Both end columns of a bar pinned: the left held, the right turned by `angle` about the
// point (4·(1 − squeeze), 0.5), i.e. the bar bent and pushed together.
struct Bend {
    Eigen::VectorXi b;
    Eigen::MatrixX2d bc;
};

Bend bendEnds(const GridMesh &g, double angle, double squeeze)
{
    Bend bend;
    bend.b.resize(2 * (g.rows + 1));
    for (int r = 0; r <= g.rows; ++r) {
        bend.b(2 * r) = g.vertex(0, r);
        bend.b(2 * r + 1) = g.vertex(g.columns, r);
    }
    bend.bc = finbook::test::rowsOf(g.V, bend.b);
    const Eigen::RowVector2d end(4.0, 0.5), pivot(4.0 * (1.0 - squeeze), 0.5);
    Eigen::Matrix2d R;
    R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    for (Eigen::Index k = 1; k < bend.b.size(); k += 2)
        bend.bc.row(k) = pivot + (bend.bc.row(k) - end) * R.transpose();
    return bend;
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

// Body: a 4:1 bar with both ends pinned; leg: a separate small grid under its right end.
struct BodyAndLeg {
    Eigen::MatrixX2d V;
    Eigen::MatrixX3i F;
    GridMesh body, leg;
    int legOffset = 0;
};

BodyAndLeg bodyAndLeg()
{
    BodyAndLeg s;
    s.body = finbook::test::gridMesh(24, 6, 4.0, 1.0, 0.2);
    s.leg = finbook::test::gridMesh(3, 6, 0.3, 1.0, 0.2, Eigen::Vector2d(3.5, -1.2));
    s.V = s.body.V;
    s.F = s.body.F;
    s.legOffset = finbook::test::appendMesh(s.V, s.F, s.leg.V, s.leg.F);
    return s;
}

// Best rigid fit (rotation angle) of Q onto P, both n×2 about their centroids.
double fittedAngle(const Eigen::MatrixX2d &P, const Eigen::MatrixX2d &Q)
{
    const Eigen::MatrixX2d p = P.rowwise() - P.colwise().mean();
    const Eigen::MatrixX2d q = Q.rowwise() - Q.colwise().mean();
    double a = 0.0, b = 0.0;
    for (Eigen::Index i = 0; i < p.rows(); ++i) {
        a += p(i, 0) * q(i, 0) + p(i, 1) * q(i, 1);
        b += p(i, 0) * q(i, 1) - p(i, 1) * q(i, 0);
    }
    return std::atan2(b, a);
}

// Largest change of any pairwise vertex distance: 0 for a rigid motion.
double distanceDistortion(const Eigen::MatrixX2d &P, const Eigen::MatrixX2d &Q)
{
    double worst = 0.0;
    for (Eigen::Index i = 0; i < P.rows(); ++i)
        for (Eigen::Index j = i + 1; j < P.rows(); ++j)
            worst = std::max(worst,
                             std::abs((P.row(i) - P.row(j)).norm() - (Q.row(i) - Q.row(j)).norm()));
    return worst;
}

} // namespace

class TestArapRefine : public QObject {
    Q_OBJECT

private slots:
    void poseIsDeterministic();
    void storedPoseIsConverged();
    void dragPoseImprovesOnTheTwoSteps();
    void rigidMotionIsRigidInEveryMode_data();
    void rigidMotionIsRigidInEveryMode();
    void flipRepairUnfoldsWhatTheOptimumDoesNot();
    void unpinnedComponentFollowsNearestPinned();
    void followingComponentPicksTheNearestOne();
    void degeneratePinsNeverGiveNaN_data();
    void degeneratePinsNeverGiveNaN();
    void dragPassesComeFromMeshSize();
    void largeMeshDragStartsFromCoarseRotations();
    void finalSolveCanBeCancelled();
    void twoStepMethodIsTheOldSolve();
};

// Same pins + same precompute → the same bits: after other solves on this thread (scratch
// reuse), on another thread, and from a second precompute of the same input (reopening).
void TestArapRefine::poseIsDeterministic()
{
    const GridMesh g = finbook::test::gridMesh(32, 8, 4.0, 1.0, 0.2);
    const Bend bend = bendEnds(g, 1.0, 0.1);
    const auto data = precompute(g.V, g.F, bend.b);
    const auto again = precompute(g.V, g.F, bend.b);
    QVERIFY(data && again);
    for (const ArapStage stage : {ArapStage::Drag, ArapStage::Final}) {
        const Eigen::MatrixX2d first = solved(*data, bend.bc, stage);
        QVERIFY(first.allFinite());
        Eigen::MatrixX2d other = bend.bc;
        other.row(1) += Eigen::RowVector2d(0.3, -0.2);
        QVERIFY(solved(*data, other, stage).allFinite()); // something else in between
        QVERIFY(sameBits(solved(*data, bend.bc, stage), first));
        QVERIFY(sameBits(solved(*again, bend.bc, stage), first));
        Eigen::MatrixX2d fromThread;
        std::thread([&] { fromThread = solved(*data, bend.bc, stage); }).join();
        QVERIFY(sameBits(fromThread, first));
    }
}

// The stored pose meets the tolerance it promises and sits at the converged energy.
void TestArapRefine::storedPoseIsConverged()
{
    const GridMesh g = finbook::test::gridMesh(40, 10, 4.0, 1.0, 0.2);
    const Bend bend = bendEnds(g, 1.0, 0.0);
    const auto data = precompute(g.V, g.F, bend.b);
    const auto reference = precompute(g.V, g.F, bend.b, convergedReference());
    QVERIFY(data && reference);
    ArapSolveReport report;
    const Eigen::MatrixX2d stored = solved(*data, bend.bc, ArapStage::Final, &report);
    QVERIFY(report.converged);
    QVERIFY(report.passes < data->options.finalPassCap);
    const Eigen::MatrixX2d best = solved(*reference, bend.bc, ArapStage::Final);
    const double energy = arapCotangentEnergy(g.V, g.F, stored),
                 optimum = arapCotangentEnergy(g.V, g.F, best);
    QVERIFY2(energy <= 1.001 * optimum, qPrintable(QString::number(energy / optimum)));
    QVERIFY(maxRowDistance(stored, best) <= 1e-3 * g.size());
    // The two steps alone are far from it, so the test can tell the modes apart.
    ArapOptions paper;
    paper.method = ArapMethod::TwoStep;
    const auto exact = precompute(g.V, g.F, bend.b, paper);
    QVERIFY(exact);
    QVERIFY(arapCotangentEnergy(g.V, g.F, solved(*exact, bend.bc, ArapStage::Final)) >
            1.2 * optimum);
}

void TestArapRefine::dragPoseImprovesOnTheTwoSteps()
{
    const GridMesh g = finbook::test::gridMesh(40, 10, 4.0, 1.0, 0.2);
    const Bend bend = bendEnds(g, 1.0, 0.0);
    const auto data = precompute(g.V, g.F, bend.b);
    ArapOptions paper;
    paper.method = ArapMethod::TwoStep;
    const auto exact = precompute(g.V, g.F, bend.b, paper);
    QVERIFY(data && exact);
    QVERIFY(data->dragPasses >= data->options.minDragPasses);
    ArapSolveReport report;
    const double drag =
        arapCotangentEnergy(g.V, g.F, solved(*data, bend.bc, ArapStage::Drag, &report));
    QVERIFY(report.passes >= data->dragPasses);
    const double twoSteps = arapCotangentEnergy(g.V, g.F, solved(*exact, bend.bc, ArapStage::Drag));
    const double stored = arapCotangentEnergy(g.V, g.F, solved(*data, bend.bc, ArapStage::Final));
    QVERIFY(drag < twoSteps);
    QVERIFY(stored <= drag * 1.001); // both near the optimum here: 24 drag passes at this size
}

void TestArapRefine::rigidMotionIsRigidInEveryMode_data()
{
    QTest::addColumn<int>("method");
    QTest::addColumn<int>("stage");
    QTest::newRow("two steps") << int(ArapMethod::TwoStep) << int(ArapStage::Final);
    QTest::newRow("refined, drag") << int(ArapMethod::Refined) << int(ArapStage::Drag);
    QTest::newRow("refined, final") << int(ArapMethod::Refined) << int(ArapStage::Final);
}

// Pins moved by one rigid motion move everything by it: the solved body, and the unpinned
// leg that follows it.
void TestArapRefine::rigidMotionIsRigidInEveryMode()
{
    QFETCH(int, method);
    QFETCH(int, stage);
    const BodyAndLeg s = bodyAndLeg();
    const Bend bend = bendEnds(s.body, 0.0, 0.0); // the end columns, at rest
    ArapOptions options;
    options.method = ArapMethod(method);
    const auto data = precompute(s.V, s.F, bend.b, options);
    QVERIFY(data);
    for (const double angle : {0.0, 0.7, -2.9}) {
        const Eigen::MatrixX2d expected =
            finbook::test::rigidlyMoved(s.V, angle, Eigen::Vector2d(120.0, -35.0));
        const Eigen::MatrixX2d U =
            solved(*data, finbook::test::rowsOf(expected, bend.b), ArapStage(stage));
        QVERIFY2(maxRowDistance(U, expected) <= 1e-9 * 130.0,
                 qPrintable(QString::number(maxRowDistance(U, expected))));
    }
}

// A bent, pushed-together bar whose 3-pass drag pose folds two triangles that the converged
// pose does not: the repair must unfold them (and the test fails with fixFlips off).
void TestArapRefine::flipRepairUnfoldsWhatTheOptimumDoesNot()
{
    const GridMesh g = finbook::test::gridMesh(24, 6, 4.0, 1.0, 0.2);
    const Bend bend = bendEnds(g, 1.5, 0.5);
    const auto reference = precompute(g.V, g.F, bend.b, convergedReference());
    QVERIFY(reference);
    const Eigen::MatrixX2d best = solved(*reference, bend.bc, ArapStage::Final);
    QCOMPARE(arapFlippedTriangles(g.V, g.F, best), 0);

    ArapOptions options;
    options.maxDragPasses = 3;
    options.fixFlips = false;
    const auto unfixed = precompute(g.V, g.F, bend.b, options);
    options.fixFlips = true;
    const auto fixed = precompute(g.V, g.F, bend.b, options);
    QVERIFY(unfixed && fixed);
    ArapSolveReport report;
    const Eigen::MatrixX2d folded = solved(*unfixed, bend.bc, ArapStage::Drag, &report);
    QVERIFY(arapFlippedTriangles(g.V, g.F, folded) > 0); // what the repair is for
    QCOMPARE(report.flippedTriangles, arapFlippedTriangles(g.V, g.F, folded));

    const Eigen::MatrixX2d repaired = solved(*fixed, bend.bc, ArapStage::Drag, &report);
    QVERIFY(repaired.allFinite());
    QCOMPARE(arapFlippedTriangles(g.V, g.F, repaired), 0);
    QCOMPARE(report.flippedTriangles, 0);
    QVERIFY(report.repairedTriangles > 0);
    QCOMPARE(finbook::test::rowsOf(repaired, bend.b), bend.bc); // pins still hold
}

void TestArapRefine::unpinnedComponentFollowsNearestPinned()
{
    const BodyAndLeg s = bodyAndLeg();
    const Bend bend = bendEnds(s.body, 1.2, 0.2);
    const auto data = precompute(s.V, s.F, bend.b);
    QVERIFY(data);
    const Eigen::MatrixX2d U = solved(*data, bend.bc, ArapStage::Final);
    QVERIFY(U.allFinite());
    const Eigen::MatrixX2d legRest = s.V.middleRows(s.legOffset, s.leg.V.rows());
    const Eigen::MatrixX2d leg = U.middleRows(s.legOffset, s.leg.V.rows());
    QVERIFY(maxRowDistance(leg, legRest) > 0.5);       // it moved...
    QVERIFY(distanceDistortion(legRest, leg) <= 1e-9); // ...rigidly
    // It turned with the part of the body it hangs under (bottom rows above the leg), not
    // with the held left end.
    std::vector<int> nearVertices;
    for (Eigen::Index v = 0; v < s.body.V.rows(); ++v)
        if (s.V(v, 0) >= 3.3 && s.V(v, 0) <= 4.0 && s.V(v, 1) <= 0.35)
            nearVertices.push_back(int(v));
    const Eigen::VectorXi end =
        Eigen::Map<const Eigen::VectorXi>(nearVertices.data(), Eigen::Index(nearVertices.size()));
    const double bodyTurn =
        fittedAngle(finbook::test::rowsOf(s.V, end), finbook::test::rowsOf(U, end));
    QVERIFY(std::abs(bodyTurn) > 0.5);
    QVERIFY2(std::abs(fittedAngle(legRest, leg) - bodyTurn) < 0.15,
             qPrintable(QString("%1 vs %2").arg(fittedAngle(legRest, leg)).arg(bodyTurn)));
    // It stays attached: its distance to the body's nearest vertex is kept.
    double restGap = INFINITY, gap = INFINITY;
    for (Eigen::Index i = 0; i < legRest.rows(); ++i)
        for (Eigen::Index v = 0; v < s.body.V.rows(); ++v) {
            restGap = std::min(restGap, (legRest.row(i) - s.V.row(v)).norm());
            gap = std::min(gap, (leg.row(i) - U.row(v)).norm());
        }
    QVERIFY(std::abs(gap - restGap) <= 0.25 * restGap);

    ArapOptions still; // the previous behaviour stays available
    still.followNearestComponent = false;
    const auto atRest = precompute(s.V, s.F, bend.b, still);
    QVERIFY(atRest);
    QCOMPARE(
        Eigen::MatrixX2d(
            solved(*atRest, bend.bc, ArapStage::Final).middleRows(s.legOffset, legRest.rows())),
        legRest);
}

// Two pinned components: the unpinned one follows the nearer, here one that only translates
// (a single pin) while the farther one rotates.
void TestArapRefine::followingComponentPicksTheNearestOne()
{
    const GridMesh near = finbook::test::gridMesh(4, 4, 1.0, 1.0, 0.1, Eigen::Vector2d(0.0, 0.0));
    const GridMesh far = finbook::test::gridMesh(8, 4, 2.0, 1.0, 0.1, Eigen::Vector2d(6.0, 0.0));
    const GridMesh free = finbook::test::gridMesh(3, 3, 0.6, 0.6, 0.1, Eigen::Vector2d(1.5, 0.2));
    Eigen::MatrixX2d V = near.V;
    Eigen::MatrixX3i F = near.F;
    const int farOffset = finbook::test::appendMesh(V, F, far.V, far.F);
    const int freeOffset = finbook::test::appendMesh(V, F, free.V, free.F);
    Eigen::VectorXi b(3);
    b << near.vertex(2, 2), farOffset + far.vertex(0, 0), farOffset + far.vertex(far.columns, 0);
    Eigen::MatrixX2d bc = finbook::test::rowsOf(V, b);
    bc.row(0) += Eigen::RowVector2d(0.4, 0.3);
    bc.row(2) += Eigen::RowVector2d(-0.5, 1.5); // swings the far component
    const auto data = precompute(V, F, b);
    QVERIFY(data);
    const Eigen::MatrixX2d U = solved(*data, bc, ArapStage::Drag);
    const Eigen::MatrixX2d expected =
        V.middleRows(freeOffset, free.V.rows()).rowwise() + Eigen::RowVector2d(0.4, 0.3);
    QVERIFY(maxRowDistance(U.middleRows(freeOffset, free.V.rows()), expected) <= 1e-12);
}

void TestArapRefine::degeneratePinsNeverGiveNaN_data()
{
    QTest::addColumn<int>("method");
    QTest::addColumn<int>("stage");
    QTest::newRow("two steps") << int(ArapMethod::TwoStep) << int(ArapStage::Drag);
    QTest::newRow("refined, drag") << int(ArapMethod::Refined) << int(ArapStage::Drag);
    QTest::newRow("refined, final") << int(ArapMethod::Refined) << int(ArapStage::Final);
}

void TestArapRefine::degeneratePinsNeverGiveNaN()
{
    QFETCH(int, method);
    QFETCH(int, stage);
    const BodyAndLeg s = bodyAndLeg();
    ArapOptions options;
    options.method = ArapMethod(method);
    const GridMesh &g = s.body;
    Eigen::VectorXi one(1), two(2), three(3);
    one << g.vertex(3, 3);
    two << g.vertex(0, 0), g.vertex(g.columns, g.rows);
    three << g.vertex(0, 0), g.vertex(g.columns, g.rows), g.vertex(12, 3);
    for (const Eigen::VectorXi &b : {one, two, three}) {
        const auto data = precompute(s.V, s.F, b, options);
        QVERIFY(data);
        Eigen::MatrixX2d onOneSpot(b.size(), 2), twoOnOneSpot = finbook::test::rowsOf(s.V, b);
        onOneSpot.rowwise() = Eigen::RowVector2d(1.5, 0.25);
        twoOnOneSpot.topRows(std::min<Eigen::Index>(2, b.size())).rowwise() =
            Eigen::RowVector2d(2.0, 0.5);
        for (const Eigen::MatrixX2d &bc : {onOneSpot, twoOnOneSpot}) {
            ArapSolveReport report;
            const Eigen::MatrixX2d U = solved(*data, bc, ArapStage(stage), &report);
            QCOMPARE(U.rows(), s.V.rows());
            QVERIFY(U.allFinite());
            QVERIFY(std::isfinite(report.relativeResidual));
        }
    }
}

// The drag pass count depends on the mesh, not on a clock: fewer passes for a larger mesh,
// the same count for the same input.
void TestArapRefine::dragPassesComeFromMeshSize()
{
    const GridMesh small = finbook::test::gridMesh(20, 5, 4.0, 1.0, 0.2);
    const GridMesh large = finbook::test::gridMesh(200, 50, 4.0, 1.0, 0.2);
    const auto a = precompute(small.V, small.F, bendEnds(small, 0.5, 0.0).b);
    const auto a2 = precompute(small.V, small.F, bendEnds(small, 0.5, 0.0).b);
    const auto c = precompute(large.V, large.F, bendEnds(large, 0.5, 0.0).b);
    QVERIFY(a && a2 && c);
    QCOMPARE(a->dragPasses, a2->dragPasses);
    QVERIFY(a->dragPasses > c->dragPasses);
    // With coarse rotations (large meshes) the coarse start's global step is one of them.
    QVERIFY(c->dragPasses + (c->triangleCluster.size() > 0 ? 1 : 0) >= c->options.minDragPasses);
    QVERIFY(a->dragPasses <= a->options.maxDragPasses);
    QVERIFY(c->estimatedPassMs > a->estimatedPassMs);
    // Coarse rotations wherever the budget holds fewer than 128 passes: not on the 126-vertex
    // bar, but already at about 2k vertices, where thin drawings need them; their reduced
    // iterations are counted by the same model (200 to 400).
    const GridMesh medium = finbook::test::gridMesh(80, 20, 4.0, 1.0, 0.2);
    const auto b = precompute(medium.V, medium.F, bendEnds(medium, 0.5, 0.0).b);
    QVERIFY(b);
    QCOMPARE(a->triangleCluster.size(), Eigen::Index(0));
    QCOMPARE(b->triangleCluster.size(), medium.F.rows());
    for (const auto *data : {b.get(), c.get()})
        QVERIFY2(data->coarseIterations >= 200 && data->coarseIterations <= 400,
                 qPrintable(QString::number(data->coarseIterations)));
}

// Where the budget holds only a few passes (here 10k vertices), the drag pose starts from the
// clustered rotations: far closer to the optimum than as many passes from step 1 (the
// paper's method with that many extra passes), still a pure function of the pins, and exact
// for a rigid motion of the pins.
void TestArapRefine::largeMeshDragStartsFromCoarseRotations()
{
    const GridMesh g = finbook::test::gridMesh(200, 50, 4.0, 1.0, 0.2);
    const Bend bend = bendEnds(g, 1.0, 0.0);
    ArapOptions fewPasses; // the budget of a larger mesh (8 ms holds more passes here)
    fewPasses.dragBudgetMs = 4.0;
    const auto data = precompute(g.V, g.F, bend.b, fewPasses);
    const auto again = precompute(g.V, g.F, bend.b, fewPasses);
    const auto reference = precompute(g.V, g.F, bend.b, convergedReference());
    QVERIFY(data && again && reference);
    QVERIFY(data->triangleCluster.size() == g.F.rows());
    QVERIFY(data->coarseCoupling.rows() >= 8);
    ArapOptions paper;
    paper.method = ArapMethod::TwoStep;
    paper.extraPasses = data->dragPasses; // one more global solve than the drag's fine passes
    const auto plain = precompute(g.V, g.F, bend.b, paper);
    QVERIFY(plain);
    const double optimum =
        arapCotangentEnergy(g.V, g.F, solved(*reference, bend.bc, ArapStage::Final));
    const Eigen::MatrixX2d drag = solved(*data, bend.bc, ArapStage::Drag);
    const double dragRatio = arapCotangentEnergy(g.V, g.F, drag) / optimum;
    const double plainRatio =
        arapCotangentEnergy(g.V, g.F, solved(*plain, bend.bc, ArapStage::Drag)) / optimum;
    QVERIFY2(dragRatio <= 1.2 && plainRatio > 1.3,
             qPrintable(QStringLiteral("%1 %2").arg(dragRatio).arg(plainRatio)));
    QCOMPARE(finbook::test::rowsOf(drag, bend.b), bend.bc);
    QVERIFY(sameBits(solved(*again, bend.bc, ArapStage::Drag), drag));
    Eigen::MatrixX2d fromThread;
    std::thread([&] { fromThread = solved(*data, bend.bc, ArapStage::Drag); }).join();
    QVERIFY(sameBits(fromThread, drag));

    const Bend rest = bendEnds(g, 0.0, 0.0);
    for (const double angle : {0.7, -2.9}) {
        const Eigen::MatrixX2d expected =
            finbook::test::rigidlyMoved(g.V, angle, Eigen::Vector2d(120.0, -35.0));
        const Eigen::MatrixX2d U =
            solved(*data, finbook::test::rowsOf(expected, rest.b), ArapStage::Drag);
        QVERIFY2(maxRowDistance(U, expected) <= 1e-9 * 130.0,
                 qPrintable(QString::number(maxRowDistance(U, expected))));
    }
    // Every pin on one spot collapses every cluster: finite, and the pins still hold.
    const Eigen::MatrixX2d onePoint = Eigen::MatrixX2d::Constant(bend.b.size(), 2, 0.5);
    const Eigen::MatrixX2d collapsed = solved(*data, onePoint, ArapStage::Drag);
    QVERIFY(collapsed.allFinite() && collapsed.rows() == g.V.rows());
    QCOMPARE(finbook::test::rowsOf(collapsed, bend.b), onePoint);
}

void TestArapRefine::finalSolveCanBeCancelled()
{
    const GridMesh g = finbook::test::gridMesh(40, 10, 4.0, 1.0, 0.2);
    const Bend bend = bendEnds(g, 1.0, 0.0);
    const auto data = precompute(g.V, g.F, bend.b);
    QVERIFY(data);
    Eigen::MatrixX2d U;
    int polls = 0;
    auto result = arapSolve(*data, bend.bc, U, ArapStage::Final, [&] { return ++polls > 3; });
    QVERIFY(!result);
    QCOMPARE(result.error().code, DeformErrorCode::Cancelled);
    QVERIFY(arapSolve(*data, bend.bc, U, ArapStage::Final, [] { return false; }));
}

// The Rigidity setting's "paper" choice through the stage API is exactly the three-argument
// solve the model calls today, for both stages.
void TestArapRefine::twoStepMethodIsTheOldSolve()
{
    const GridMesh g = finbook::test::gridMesh(32, 8, 4.0, 1.0, 0.2);
    const Bend bend = bendEnds(g, 0.8, 0.1);
    ArapOptions paper;
    paper.method = ArapMethod::TwoStep;
    paper.extraPasses = 2;
    const auto data = precompute(g.V, g.F, bend.b, paper);
    QVERIFY(data);
    Eigen::MatrixX2d old;
    auto report = arapSolve(*data, bend.bc, old);
    QVERIFY(report);
    QCOMPARE(report->passes, 3);
    QVERIFY(sameBits(solved(*data, bend.bc, ArapStage::Drag), old));
    QVERIFY(sameBits(solved(*data, bend.bc, ArapStage::Final), old));
}

QTEST_APPLESS_MAIN(TestArapRefine)
#include "tst_arap_refine.moc"
