// The refined method minimises the standard, cotangent-weighted ARAP energy (issue 26): its
// gradient vanishes at a stored pose (checked with a gradient computed here from each
// triangle's deformation gradient, independently of the solver's edge weights), the result
// does not depend on how the shape was triangulated, negative cotangent weights are handled,
// a stored pose has no flips the unrepaired optimum does not have and keeps the ones pins
// force (and says so), and rest pins still give the rest pose.
#include "arap_test_support.h"
#include "grid_mesh.h"

#include <finbook/deform/arap.h>

#include <QTest>

#include <Eigen/LU>

using namespace finbook::deform;
using finbook::test::GridMesh;
using finbook::test::precompute;
using finbook::test::solved;

namespace {

double maxRowDistance(const Eigen::MatrixX2d &A, const Eigen::MatrixX2d &B)
{
    return A.rows() == B.rows() ? (A - B).rowwise().norm().maxCoeff() : INFINITY;
}

// ∂E/∂U of E = Σ_t area_t ‖J_t − R_t‖² (R_t the closest rotation, held fixed: at the optimal
// rotation that is the whole gradient). J = D·S⁻¹ with S, D the rest and deformed edges
// 0→1, 0→2 as columns, so ∂E/∂D = 2·area·(J − R)·S⁻ᵀ.
Eigen::MatrixX2d cotangentGradient(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                   const Eigen::MatrixX2d &U)
{
    Eigen::MatrixX2d G = Eigen::MatrixX2d::Zero(V.rows(), 2);
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        Eigen::Matrix2d S, D;
        for (int k = 1; k < 3; ++k) {
            S.col(k - 1) = (V.row(F(t, k)) - V.row(F(t, 0))).transpose();
            D.col(k - 1) = (U.row(F(t, k)) - U.row(F(t, 0))).transpose();
        }
        const Eigen::Matrix2d J = D * S.inverse();
        const double angle = std::atan2(J(1, 0) - J(0, 1), J(0, 0) + J(1, 1));
        Eigen::Matrix2d R;
        R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
        const Eigen::Matrix2d dD = std::abs(S.determinant()) * (J - R) * S.inverse().transpose();
        G.row(F(t, 1)) += dD.col(0).transpose();
        G.row(F(t, 2)) += dD.col(1).transpose();
        G.row(F(t, 0)) -= (dD.col(0) + dD.col(1)).transpose();
    }
    return G;
}

// Gradient over the vertices that are not pinned.
double freeGradientNorm(const Eigen::MatrixX2d &G, const Eigen::VectorXi &b)
{
    Eigen::MatrixX2d free = G;
    for (Eigen::Index k = 0; k < b.size(); ++k)
        free.row(b(k)).setZero();
    return free.norm();
}

// Both end columns pinned: the left held, the right turned by `angle` about
// (4·(1 − squeeze), 0.5): the bar bent and pushed together.
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

// The same vertices as g with every cell split along its other diagonal.
Eigen::MatrixX3i otherDiagonals(const GridMesh &g)
{
    Eigen::MatrixX3i F(2 * g.columns * g.rows, 3);
    int t = 0;
    for (int r = 0; r < g.rows; ++r) {
        for (int c = 0; c < g.columns; ++c) {
            const int a = g.vertex(c, r), b = g.vertex(c + 1, r);
            const int d = g.vertex(c, r + 1), e = g.vertex(c + 1, r + 1);
            if ((r + c) % 2 != 0) {
                F.row(t++) << a, b, e;
                F.row(t++) << a, e, d;
            } else {
                F.row(t++) << a, b, d;
                F.row(t++) << b, e, d;
            }
        }
    }
    return F;
}

ArapOptions paperConverged() // the uniform-weight optimum, as far as 400 plain passes get
{
    ArapOptions o;
    o.method = ArapMethod::TwoStep;
    o.extraPasses = 400;
    return o;
}

} // namespace

class TestArapCotangent : public QObject {
    Q_OBJECT

private slots:
    void storedPoseIsStationaryForTheCotangentEnergy();
    void cocircularEdgesAreNotCountedNegative();
    void energyFormsAgree();
    void poseDoesNotDependOnTheTriangulation();
    void storedPoseAddsNoFlips();
    void foldsThePinsForceAreKeptAndReported();
    void restPinsGiveRestInEveryMode();
};

// On a jittered grid about half the cell diagonals have a negative cotangent weight (the two
// angles opposite them add up to more than 180°): the stored pose is still the minimum, to
// the tolerance it promises; the uniform optimum is not, so the test tells the energies apart.
void TestArapCotangent::storedPoseIsStationaryForTheCotangentEnergy()
{
    const GridMesh g = finbook::test::gridMesh(40, 10, 4.0, 1.0, 0.2);
    const Bend bend = bendEnds(g, 1.0, 0.1);
    const auto data = precompute(g.V, g.F, bend.b);
    const auto uniform = precompute(g.V, g.F, bend.b, paperConverged());
    QVERIFY(data && uniform);
    QVERIFY(data->negativeWeightEdges > 0);
    QCOMPARE(uniform->negativeWeightEdges, 0);
    Eigen::MatrixX2d start;
    QVERIFY(arapSimilarity(*data, bend.bc, start));
    const double scale = freeGradientNorm(cotangentGradient(g.V, g.F, start), bend.b);
    ArapSolveReport report;
    const Eigen::MatrixX2d stored = solved(*data, bend.bc, ArapStage::Final, &report);
    QVERIFY(report.converged);
    QCOMPARE(report.flippedTriangles, 0);
    const double atStored = freeGradientNorm(cotangentGradient(g.V, g.F, stored), bend.b);
    QVERIFY2(atStored <= 1e-4 * scale, qPrintable(QString::number(atStored / scale)));
    const Eigen::MatrixX2d other = solved(*uniform, bend.bc, ArapStage::Final);
    const double atUniform = freeGradientNorm(cotangentGradient(g.V, g.F, other), bend.b);
    QVERIFY2(atUniform > 1e-2 * scale, qPrintable(QString::number(atUniform / scale)));
    QVERIFY(arapCotangentEnergy(g.V, g.F, stored) < arapCotangentEnergy(g.V, g.F, other));
}

// A grid of squares, each cut by a diagonal, turned: the diagonals face two right angles, so
// their weight is 0 (cot 90° + cot 90°), computed as round-off of either sign. The CDT meshes
// the app builds have such edges (a horse's ~2k-vertex mesh has two), and they are not
// negative. Sheared cells make real negative weights, which are counted.
void TestArapCotangent::cocircularEdgesAreNotCountedNegative()
{
    GridMesh g = finbook::test::gridMesh(30, 10, 3.0, 1.0);
    const double turn = 0.37;
    Eigen::Matrix2d R;
    R << std::cos(turn), -std::sin(turn), std::sin(turn), std::cos(turn);
    g.V = (g.V * R.transpose()).eval();
    const Bend bend = bendEnds(g, 0.5, 0.0);
    const auto square = precompute(g.V, g.F, bend.b);
    QVERIFY(square);
    QCOMPARE(square->negativeWeightEdges, 0);
    Eigen::Matrix2d shear;
    shear << 1.0, 0.6, 0.0, 1.0;
    g.V = (g.V * shear.transpose()).eval();
    const auto sheared = precompute(g.V, g.F, bendEnds(g, 0.5, 0.0).b);
    QVERIFY(sheared);
    QVERIFY(sheared->negativeWeightEdges > 0);
}

// The energy the solver descends (edge form, cotangent weights) is the one measured from J:
// between two passes counts the energy can only fall, in both measures.
void TestArapCotangent::energyFormsAgree()
{
    const GridMesh g = finbook::test::gridMesh(24, 6, 4.0, 1.0, 0.2);
    const Bend bend = bendEnds(g, 0.9, 0.2);
    double previous = INFINITY;
    for (const int passes : {1, 2, 4, 8, 16}) {
        ArapOptions o;
        o.finalTolerance = 0.0;
        o.finalEnergyTolerance = 0.0;
        o.finalPassCap = passes;
        o.fixFlips = false;
        const auto data = precompute(g.V, g.F, bend.b, o);
        QVERIFY(data);
        const double energy =
            arapCotangentEnergy(g.V, g.F, solved(*data, bend.bc, ArapStage::Final));
        QVERIFY2(energy <= previous * (1.0 + 1e-12), qPrintable(QString::number(passes)));
        previous = energy;
    }
}

// Pins of both end columns moved by one affine map A (a stretch, then a turn): the affine
// map is the cotangent ARAP optimum for any triangulation (constant J − R, and the free top
// and bottom edges feel no traction), so both triangulations of the same jittered vertices
// give it. With uniform weights neither does.
void TestArapCotangent::poseDoesNotDependOnTheTriangulation()
{
    const GridMesh g = finbook::test::gridMesh(20, 5, 4.0, 1.0, 0.2);
    const Bend ends = bendEnds(g, 0.0, 0.0);
    Eigen::Matrix2d A;
    A << 1.3, 0.0, 0.0, 1.0;
    const double turn = 0.5;
    Eigen::Matrix2d R;
    R << std::cos(turn), -std::sin(turn), std::sin(turn), std::cos(turn);
    A = R * A;
    const Eigen::MatrixX2d expected = g.V * A.transpose();
    const Eigen::MatrixX2d bc = finbook::test::rowsOf(expected, ends.b);
    for (const Eigen::MatrixX3i &F : {g.F, otherDiagonals(g)}) {
        const auto data = precompute(g.V, F, ends.b);
        const auto uniform = precompute(g.V, F, ends.b, paperConverged());
        QVERIFY(data && uniform);
        const Eigen::MatrixX2d U = solved(*data, bc, ArapStage::Final);
        QVERIFY2(maxRowDistance(U, expected) <= 1e-5 * g.size(),
                 qPrintable(QString::number(maxRowDistance(U, expected))));
        const Eigen::MatrixX2d W = solved(*uniform, bc, ArapStage::Final);
        QVERIFY2(maxRowDistance(W, expected) > 1e-3 * g.size(),
                 qPrintable(QString::number(maxRowDistance(W, expected))));
    }
}

// A bent, pushed-together bar: the stored pose flips no triangle that the converged pose
// without flip repair keeps upright.
void TestArapCotangent::storedPoseAddsNoFlips()
{
    const GridMesh g = finbook::test::gridMesh(24, 6, 4.0, 1.0, 0.2);
    for (const double squeeze : {0.3, 0.5}) {
        const Bend bend = bendEnds(g, 1.5, squeeze);
        ArapOptions reference;
        reference.finalTolerance = 1e-11;
        reference.finalEnergyTolerance = 0.0;
        reference.finalPassCap = 20000;
        reference.fixFlips = false;
        const auto best = precompute(g.V, g.F, bend.b, reference);
        const auto data = precompute(g.V, g.F, bend.b);
        QVERIFY(best && data);
        const Eigen::MatrixX2d optimum = solved(*best, bend.bc, ArapStage::Final);
        ArapSolveReport report;
        const Eigen::MatrixX2d stored = solved(*data, bend.bc, ArapStage::Final, &report);
        QCOMPARE(report.flippedTriangles, arapFlippedTriangles(g.V, g.F, stored));
        for (Eigen::Index t = 0; t < g.F.rows(); ++t) {
            const Eigen::MatrixX3i one = g.F.row(t);
            if (arapFlippedTriangles(g.V, one, optimum) == 0)
                QCOMPARE(arapFlippedTriangles(g.V, one, stored), 0);
        }
        QVERIFY(arapCotangentEnergy(g.V, g.F, stored) <=
                1.001 * arapCotangentEnergy(g.V, g.F, optimum));
    }
}

// The two right end columns pinned upside down: the cells between them are turned over by
// the pins themselves, so the stored pose keeps folds, is still returned (finite, pins held)
// and reports them. (With only the end column pinned upside down the bar can twist without a
// flipped triangle: the injective finish of the flip repair finds such a pose, at 0.24 % more
// energy than the converged pose with its one fold.)
void TestArapCotangent::foldsThePinsForceAreKeptAndReported()
{
    const GridMesh g = finbook::test::gridMesh(24, 6, 4.0, 1.0, 0.2);
    Bend bend = bendEnds(g, 0.0, 0.0);
    const Eigen::Index ends = bend.b.size();
    bend.b.conservativeResize(ends + g.rows + 1);
    bend.bc.conservativeResize(ends + g.rows + 1, 2);
    for (int r = 0; r <= g.rows; ++r) {
        bend.b(ends + r) = g.vertex(g.columns - 1, r);
        bend.bc(ends + r, 0) = g.V(g.vertex(g.columns - 1, r), 0);
        bend.bc(ends + r, 1) = 1.0 - g.V(g.vertex(g.columns - 1, r), 1);
    }
    for (Eigen::Index k = 1; k < ends; k += 2)
        bend.bc(k, 1) = 1.0 - bend.bc(k, 1);
    const auto data = precompute(g.V, g.F, bend.b);
    QVERIFY(data);
    ArapSolveReport report;
    const Eigen::MatrixX2d stored = solved(*data, bend.bc, ArapStage::Final, &report);
    QVERIFY(stored.allFinite());
    QVERIFY(report.flippedTriangles > 0);
    QCOMPARE(report.flippedTriangles, arapFlippedTriangles(g.V, g.F, stored));
    QCOMPARE(finbook::test::rowsOf(stored, bend.b), bend.bc);
}

void TestArapCotangent::restPinsGiveRestInEveryMode()
{
    const GridMesh g = finbook::test::gridMesh(30, 10, 640.0, 200.0, 0.2);
    const Bend ends = bendEnds(g, 0.0, 0.0);
    for (const ArapMethod method : {ArapMethod::TwoStep, ArapMethod::Refined}) {
        ArapOptions o;
        o.method = method;
        const auto data = precompute(g.V, g.F, ends.b, o);
        QVERIFY(data);
        for (const ArapStage stage : {ArapStage::Drag, ArapStage::Final})
            QVERIFY(maxRowDistance(solved(*data, ends.bc, stage), g.V) <= 1e-9 * g.size());
    }
}

QTEST_APPLESS_MAIN(TestArapCotangent)
#include "tst_arap_cotangent.moc"
