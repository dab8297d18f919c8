// Invariants of the ARAP deformer (Igarashi et al. 2005): rigid motions, rest pose, what
// step 2 buys over step 1, extra passes, per-component pin rules and coincident pins.
#include "grid_mesh.h"

#include <finbook/deform/arap.h>
#include <finbook/deform/nearest_vertex.h>

#include <QTest>

#include <atomic>
#include <cmath>
#include <thread>

using namespace finbook::deform;
using finbook::test::GridMesh;

namespace {

// These tests are about the paper's method (the three-argument solve, uniform weights, as
// Deform → Rigidity → As in the Paper precomputes it); the refined method's are in
// tst_arap_refine and tst_arap_cotangent.
std::shared_ptr<const ArapPrecompute> precompute(const Eigen::MatrixX2d &V,
                                                 const Eigen::MatrixX3i &F,
                                                 const Eigen::VectorXi &b, ArapOptions options = {})
{
    options.method = ArapMethod::TwoStep;
    auto result = arapPrecompute(V, F, b, options);
    if (!result)
        qWarning("precompute failed: %s", result.error().message.c_str());
    return result ? *result : nullptr;
}

Eigen::MatrixX2d solved(const ArapPrecompute &data, const Eigen::MatrixX2d &bc)
{
    Eigen::MatrixX2d U;
    auto result = arapSolve(data, bc, U);
    if (!result)
        qWarning("solve failed: %s", result.error().message.c_str());
    return result ? U : Eigen::MatrixX2d();
}

double maxRowDistance(const Eigen::MatrixX2d &A, const Eigen::MatrixX2d &B)
{
    return A.rows() == B.rows() ? (A - B).rowwise().norm().maxCoeff() : INFINITY;
}

// Mean |length/rest − 1| over the triangle edges.
double edgeLengthError(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                       const Eigen::MatrixX2d &U)
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

// Pins at the four corners plus `extra` spread over the interior.
Eigen::VectorXi spreadPins(const GridMesh &g, int extra)
{
    Eigen::VectorXi b(4 + extra);
    b << g.vertex(0, 0), g.vertex(g.columns, 0), g.vertex(0, g.rows), g.vertex(g.columns, g.rows),
        Eigen::VectorXi::Zero(extra);
    for (int k = 0; k < extra; ++k)
        b(4 + k) = g.vertex(1 + (7 * k) % (g.columns - 1), 1 + (3 * k) % (g.rows - 1));
    return b;
}

} // namespace

class TestArap : public QObject {
    Q_OBJECT

private slots:
    void rigidMotionOfPinsMovesMeshRigidly_data();
    void rigidMotionOfPinsMovesMeshRigidly();
    void restPinsGiveRestPose();
    void pinsAreInterpolated();
    void stepTwoRestoresEdgeLengths();
    void extraPassesDoNotIncreaseEnergy();
    void zeroPinsGiveRestPose();
    void onePinTranslates();
    void repeatedPinLastEntryWins();
    void pinsDraggedOntoOnePointStayFinite();
    void componentsFollowTheirOwnPins();
    void cancellationReturnsCancelled();
    void concurrentSolvesAgree();
    void solveRejectsBadTargets();
    void nearestVertexSnaps();
};

void TestArap::rigidMotionOfPinsMovesMeshRigidly_data()
{
    QTest::addColumn<double>("scale");
    QTest::addColumn<int>("extraPins");
    QTest::addColumn<int>("extraPasses");
    QTest::newRow("unit, 2 pins") << 1.0 << -2 << 0;
    QTest::newRow("unit, 4 pins") << 1.0 << 0 << 0;
    QTest::newRow("unit, 4 pins, 3 passes") << 1.0 << 0 << 3;
    QTest::newRow("pixels, 4 pins") << 800.0 << 0 << 0;
    QTest::newRow("pixels, 12 pins, 1 pass") << 800.0 << 8 << 1;
    QTest::newRow("pixels, 40 pins (no basis)") << 800.0 << 36 << 0;
}

void TestArap::rigidMotionOfPinsMovesMeshRigidly()
{
    QFETCH(double, scale);
    QFETCH(int, extraPins);
    QFETCH(int, extraPasses);
    const GridMesh g = finbook::test::gridMesh(24, 18, scale, 0.75 * scale, 0.2,
                                               Eigen::Vector2d(0.3 * scale, -0.1 * scale));
    const Eigen::VectorXi b = spreadPins(g, std::max(0, extraPins)).head(4 + extraPins);
    const auto data = precompute(g.V, g.F, b, ArapOptions{extraPasses});
    QVERIFY(data);
    const Eigen::Vector2d shift(0.37 * scale, -1.3 * scale);
    for (const double angle : {0.0, 0.4, -2.5, 3.1}) {
        const Eigen::MatrixX2d expected = finbook::test::rigidlyMoved(g.V, angle, shift);
        const Eigen::MatrixX2d bc = finbook::test::rowsOf(expected, b);
        QVERIFY(maxRowDistance(solved(*data, bc), expected) <= 1e-9 * g.size());
        Eigen::MatrixX2d U;
        QVERIFY(arapSimilarity(*data, bc, U));
        QVERIFY(maxRowDistance(U, expected) <= 1e-9 * g.size());
    }
}

void TestArap::restPinsGiveRestPose()
{
    const GridMesh g = finbook::test::gridMesh(30, 10, 640.0, 200.0, 0.2);
    const Eigen::VectorXi b = spreadPins(g, 3);
    const auto data = precompute(g.V, g.F, b, ArapOptions{2});
    QVERIFY(data);
    QVERIFY(maxRowDistance(solved(*data, finbook::test::rowsOf(g.V, b)), g.V) <= 1e-9 * g.size());
}

void TestArap::pinsAreInterpolated()
{
    const GridMesh g = finbook::test::gridMesh(20, 20, 1.0, 1.0, 0.2);
    const Eigen::VectorXi b = spreadPins(g, 2);
    const auto data = precompute(g.V, g.F, b);
    QVERIFY(data);
    Eigen::MatrixX2d bc = finbook::test::rowsOf(g.V, b);
    bc.row(1) += Eigen::RowVector2d(0.3, 0.4);
    bc.row(4) += Eigen::RowVector2d(-0.1, 0.2);
    const Eigen::MatrixX2d U = solved(*data, bc);
    QCOMPARE(U.rows(), g.V.rows());
    QVERIFY(U.allFinite());
    QCOMPARE(finbook::test::rowsOf(U, b), bc);
}

// Pulling two pins apart scales the similarity solution up; step 2 must undo most of that.
void TestArap::stepTwoRestoresEdgeLengths()
{
    const GridMesh g = finbook::test::gridMesh(40, 8, 5.0, 1.0, 0.15);
    Eigen::VectorXi b(2);
    b << g.vertex(0, g.rows / 2), g.vertex(g.columns, g.rows / 2);
    const auto data = precompute(g.V, g.F, b);
    QVERIFY(data);
    Eigen::MatrixX2d bc = finbook::test::rowsOf(g.V, b);
    bc.row(1).x() += 2.5;
    Eigen::MatrixX2d similar;
    QVERIFY(arapSimilarity(*data, bc, similar));
    const Eigen::MatrixX2d U = solved(*data, bc);
    QVERIFY(U.allFinite());
    QVERIFY(edgeLengthError(g.V, g.F, U) < 0.5 * edgeLengthError(g.V, g.F, similar));
    QVERIFY(arapEnergy(g.V, g.F, U) < arapEnergy(g.V, g.F, similar));
}

void TestArap::extraPassesDoNotIncreaseEnergy()
{
    const GridMesh g = finbook::test::gridMesh(30, 12, 3.0, 1.0, 0.2);
    const Eigen::VectorXi b = spreadPins(g, 0);
    Eigen::MatrixX2d bc = finbook::test::rowsOf(g.V, b);
    // Bend: the right-hand corners (entries 1 and 3) swing up and inwards.
    bc.row(1) = Eigen::RowVector2d(2.2, -0.2);
    bc.row(3) = Eigen::RowVector2d(1.4, 0.6);
    double previous = INFINITY;
    for (int passes = 0; passes <= 6; ++passes) {
        const auto data = precompute(g.V, g.F, b, ArapOptions{passes});
        QVERIFY(data);
        const double energy = arapEnergy(g.V, g.F, solved(*data, bc));
        QVERIFY2(energy <= previous * (1.0 + 1e-12), qPrintable(QString::number(passes)));
        previous = energy;
    }
}

void TestArap::zeroPinsGiveRestPose()
{
    const GridMesh g = finbook::test::gridMesh(5, 4, 1.0, 1.0, 0.2);
    const auto data = precompute(g.V, g.F, Eigen::VectorXi());
    QVERIFY(data);
    QCOMPARE(solved(*data, Eigen::MatrixX2d(0, 2)), g.V);
}

void TestArap::onePinTranslates()
{
    const GridMesh g = finbook::test::gridMesh(9, 7, 300.0, 200.0, 0.2);
    Eigen::VectorXi b(3);
    b << 17, 17, 17; // one vertex, pinned three times: still one pin
    const auto data = precompute(g.V, g.F, b);
    QVERIFY(data);
    Eigen::MatrixX2d bc = finbook::test::rowsOf(g.V, b);
    bc.row(2) += Eigen::RowVector2d(40.0, -25.0);
    const Eigen::MatrixX2d expected = g.V.rowwise() + Eigen::RowVector2d(40.0, -25.0);
    QVERIFY(maxRowDistance(solved(*data, bc), expected) <= 1e-12 * g.size());
}

void TestArap::repeatedPinLastEntryWins()
{
    const GridMesh g = finbook::test::gridMesh(12, 12, 1.0, 1.0, 0.2);
    Eigen::VectorXi repeated(3), distinct(2);
    repeated << 5, 150, 5;
    distinct << 150, 5;
    Eigen::MatrixX2d repeatedTargets(3, 2), distinctTargets(2, 2);
    repeatedTargets << 9.0, 9.0, 0.5, 1.5, 0.1, -0.2;
    distinctTargets << 0.5, 1.5, 0.1, -0.2;
    const auto a = precompute(g.V, g.F, repeated), b = precompute(g.V, g.F, distinct);
    QVERIFY(a && b);
    QVERIFY(maxRowDistance(solved(*a, repeatedTargets), solved(*b, distinctTargets)) <= 1e-12);
}

void TestArap::pinsDraggedOntoOnePointStayFinite()
{
    const GridMesh g = finbook::test::gridMesh(15, 10, 150.0, 100.0, 0.2);
    Eigen::VectorXi b(3);
    b << g.vertex(0, 0), g.vertex(g.columns, g.rows), g.vertex(7, 5);
    const auto data = precompute(g.V, g.F, b, ArapOptions{2});
    QVERIFY(data);
    Eigen::MatrixX2d all(3, 2), two(3, 2);
    all << 50.0, 60.0, 50.0, 60.0, 50.0, 60.0;
    two << 50.0, 60.0, 50.0, 60.0, 75.0, 50.0;
    for (const Eigen::MatrixX2d &bc : {all, two}) {
        Eigen::MatrixX2d similar;
        QVERIFY(arapSimilarity(*data, bc, similar));
        QVERIFY(similar.allFinite());
        const Eigen::MatrixX2d U = solved(*data, bc);
        QVERIFY(U.allFinite());
        QCOMPARE(finbook::test::rowsOf(U, b), bc);
    }
}

void TestArap::componentsFollowTheirOwnPins()
{
    // Components: A without pins (not following), B with one pinned vertex (twice), C with
    // three pins, and a vertex in no triangle that is pinned on its own.
    const GridMesh a = finbook::test::gridMesh(6, 4, 1.0, 1.0, 0.2);
    const GridMesh c = finbook::test::gridMesh(10, 6, 2.0, 1.0, 0.2, Eigen::Vector2d(0.0, 3.0));
    Eigen::MatrixX2d V = a.V;
    Eigen::MatrixX3i F = a.F;
    const int offsetB =
        finbook::test::appendMesh(V, F, a.V.rowwise() + Eigen::RowVector2d(2, 0), a.F);
    const int offsetC = finbook::test::appendMesh(V, F, c.V, c.F);
    V.conservativeResize(V.rows() + 1, 2);
    V.row(V.rows() - 1) << -4.0, -4.0;
    Eigen::VectorXi bC = spreadPins(c, 0).head(3);
    Eigen::VectorXi b(6);
    b << offsetB + 9, bC.array() + offsetC, offsetB + 9, int(V.rows() - 1);
    Eigen::MatrixX2d bc = finbook::test::rowsOf(V, b);
    bc.row(0) << 100.0, 100.0; // overridden by the repeated entry below
    bc.row(4) += Eigen::RowVector2d(0.5, -0.25);
    bc.row(2) += Eigen::RowVector2d(0.7, 0.4);
    bc.row(5) += Eigen::RowVector2d(1.0, 1.0);
    ArapOptions atRest; // A stays at rest when it does not follow (see tst_arap_refine)
    atRest.followNearestComponent = false;
    const auto data = precompute(V, F, b, atRest);
    QVERIFY(data);
    const Eigen::MatrixX2d U = solved(*data, bc);
    QCOMPARE(U.topRows(a.V.rows()), a.V);
    const Eigen::MatrixX2d movedB =
        V.middleRows(offsetB, a.V.rows()).rowwise() + Eigen::RowVector2d(0.5, -0.25);
    QVERIFY(maxRowDistance(U.middleRows(offsetB, a.V.rows()), movedB) <= 1e-12);
    QCOMPARE(Eigen::RowVector2d(U.row(V.rows() - 1)), Eigen::RowVector2d(-3.0, -3.0));
    // The solved component deforms exactly as it would on its own.
    const auto alone = precompute(c.V, c.F, bC);
    QVERIFY(alone);
    const Eigen::MatrixX2d expected = solved(*alone, bc.middleRows(1, 3));
    QVERIFY(maxRowDistance(U.middleRows(offsetC, c.V.rows()), expected) <= 1e-12 * c.size());
}

void TestArap::cancellationReturnsCancelled()
{
    const GridMesh g = finbook::test::gridMesh(20, 20, 1.0, 1.0, 0.2);
    const Eigen::VectorXi b = spreadPins(g, 4);
    auto immediately = arapPrecompute(g.V, g.F, b, {}, [] { return true; });
    QVERIFY(!immediately);
    QCOMPARE(immediately.error().code, DeformErrorCode::Cancelled);
    // Cancelling after the k-th poll hits every phase, including the basis solves.
    int cancelledRuns = 0;
    for (int allowed = 1;; ++allowed) {
        std::atomic<int> polls{0};
        auto result = arapPrecompute(g.V, g.F, b, {}, [&] { return ++polls > allowed; });
        if (result)
            break;
        QCOMPARE(result.error().code, DeformErrorCode::Cancelled);
        ++cancelledRuns;
    }
    // Four phases poll before the factorization; more polls mean the basis solves poll too.
    QVERIFY(cancelledRuns > 4);
}

// The precompute is shared between the GUI thread and workers; solves keep their scratch per
// thread, so concurrent solves must give exactly what sequential ones give.
void TestArap::concurrentSolvesAgree()
{
    const GridMesh g = finbook::test::gridMesh(90, 90, 1.0, 1.0, 0.2); // parallel precompute
    const Eigen::VectorXi b = spreadPins(g, 2);
    const auto data = precompute(g.V, g.F, b, ArapOptions{1});
    QVERIFY(data);
    std::vector<Eigen::MatrixX2d> targets, expected, results(8);
    for (int k = 0; k < 8; ++k) {
        targets.push_back(finbook::test::rowsOf(g.V, b));
        targets.back().row(k % b.size()) += Eigen::RowVector2d(0.05 * k, -0.03 * k);
        expected.push_back(solved(*data, targets.back()));
    }
    std::thread other([&] {
        for (int k = 0; k < 8; k += 2)
            results[k] = solved(*data, targets[k]);
    });
    for (int k = 1; k < 8; k += 2)
        results[k] = solved(*data, targets[k]);
    other.join();
    for (int k = 0; k < 8; ++k)
        QCOMPARE(results[k], expected[k]);
}

void TestArap::solveRejectsBadTargets()
{
    const GridMesh g = finbook::test::gridMesh(4, 4, 1.0, 1.0);
    Eigen::VectorXi b(2);
    b << 0, 24;
    const auto data = precompute(g.V, g.F, b);
    QVERIFY(data);
    Eigen::MatrixX2d U;
    auto wrongCount = arapSolve(*data, Eigen::MatrixX2d::Zero(3, 2), U);
    QVERIFY(!wrongCount);
    QCOMPARE(wrongCount.error().code, DeformErrorCode::SizeMismatch);
    Eigen::MatrixX2d bc = finbook::test::rowsOf(g.V, b);
    bc(1, 0) = NAN;
    auto notFinite = arapSolve(*data, bc, U);
    QVERIFY(!notFinite);
    QCOMPARE(notFinite.error().code, DeformErrorCode::NonFiniteInput);
}

void TestArap::nearestVertexSnaps()
{
    const GridMesh g = finbook::test::gridMesh(4, 4, 4.0, 4.0);
    QCOMPARE(nearestVertex(g.V, Eigen::Vector2d(2.1, 2.9)), g.vertex(2, 3));
    QCOMPARE(nearestVertex(g.V, Eigen::Vector2d(-10.0, 100.0)), g.vertex(0, 4));
    QCOMPARE(nearestVertex(Eigen::MatrixX2d(0, 2), Eigen::Vector2d::Zero()), -1);
}

QTEST_APPLESS_MAIN(TestArap)
#include "tst_arap.moc"
