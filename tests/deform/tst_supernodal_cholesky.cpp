// The supernodal Cholesky the ARAP precompute factors its two systems with: the same L as
// Eigen's simplicial factorization in the same order (pattern and values), solves to
// rounding, refusal of matrices that are not positive definite, and every instruction-set
// copy of the numeric factorization agreeing with the baseline.
#include "grid_mesh.h"

#include <finbook/deform/supernodal_cholesky.h>

#include <QTest>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <complex>
#include <random>

using finbook::deform::SupernodalCholesky;
using finbook::deform::SupernodalIsa;
using Complex = std::complex<double>;

namespace {

template <class Scalar> using Sparse = Eigen::SparseMatrix<Scalar>;

// A symmetric pattern from a mesh (vertices sharing a triangle) or random edges, in an AMD
// order followed by an elimination-tree postorder (what the ARAP precompute does).
std::vector<std::pair<int, int>> gridEdges(int vertices)
{
    const auto g = finbook::test::gridMeshWithVertices(vertices, 100.0, 0.1);
    std::vector<std::pair<int, int>> edges;
    for (Eigen::Index t = 0; t < g.F.rows(); ++t) {
        for (int k = 0; k < 3; ++k)
            edges.emplace_back(g.F(t, k), g.F(t, (k + 1) % 3));
    }
    return edges;
}

std::vector<std::pair<int, int>> randomEdges(int n, int count, std::mt19937 &random)
{
    std::uniform_int_distribution<int> vertex(0, n - 1);
    std::vector<std::pair<int, int>> edges;
    for (int k = 0; k < count; ++k) {
        const int i = vertex(random), j = vertex(random);
        if (i != j)
            edges.emplace_back(i, j);
    }
    return edges;
}

int vertexCount(const std::vector<std::pair<int, int>> &edges)
{
    int n = 0;
    for (const auto &[i, j] : edges)
        n = std::max({n, i + 1, j + 1});
    return n;
}

// Hermitian, strictly diagonally dominant (so positive definite): −w on an edge (with a
// random phase when complex), row sums of |w| plus a shift on the diagonal. Both halves.
template <class Scalar>
Sparse<Scalar> hermitian(int n, const std::vector<std::pair<int, int>> &edges, std::mt19937 &random)
{
    std::uniform_real_distribution<double> weight(0.5, 2.0), phase(-3.0, 3.0);
    std::vector<Eigen::Triplet<Scalar>> entries;
    Eigen::VectorXd diagonal = Eigen::VectorXd::Constant(n, 0.01);
    for (const auto &[i, j] : edges) {
        const double w = weight(random);
        Scalar value(-w);
        if constexpr (!std::is_same_v<Scalar, double>)
            value = std::polar(-w, phase(random));
        entries.emplace_back(i, j, value);
        entries.emplace_back(j, i, Eigen::numext::conj(value));
        diagonal(i) += w;
        diagonal(j) += w;
    }
    for (int i = 0; i < n; ++i)
        entries.emplace_back(i, i, Scalar(diagonal(i)));
    Sparse<Scalar> A(n, n);
    A.setFromTriplets(entries.begin(), entries.end());
    return A;
}

// AMD, then the postorder of the elimination tree; A permuted by both (both halves).
template <class Scalar> Sparse<Scalar> ordered(const Sparse<Scalar> &A)
{
    const int n = int(A.rows());
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> amd;
    Eigen::AMDOrdering<int>()(A, amd);
    Sparse<Scalar> B(n, n);
    B = A.twistedBy(amd.inverse());
    B.makeCompressed();
    const std::vector<int> post = finbook::deform::postorder(
        finbook::deform::eliminationTree(n, B.outerIndexPtr(), B.innerIndexPtr()));
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse(n);
    for (int k = 0; k < n; ++k)
        inverse.indices()(k) = post[std::size_t(k)];
    Sparse<Scalar> C(n, n);
    C = B.twistedBy(inverse.inverse());
    C.makeCompressed();
    return Sparse<Scalar>(Eigen::SparseMatrix<Scalar, Eigen::RowMajor>(C)); // sorted rows
}

template <class Scalar>
std::shared_ptr<const finbook::deform::SupernodalSymbolic> analyze(const Sparse<Scalar> &A)
{
    Sparse<Scalar> compressed = A; // the analysis reads compressed columns
    compressed.makeCompressed();
    return finbook::deform::analyzeSupernodal(int(compressed.rows()), compressed.outerIndexPtr(),
                                              compressed.innerIndexPtr());
}

// L from supernodes against Eigen's SimplicialLLT in the same (natural) order: the same
// pattern entry by entry, values to rounding; solves to a small residual.
template <class Scalar> void compareWithSimplicial(const Sparse<Scalar> &A, const char *what)
{
    const auto symbolic = analyze(A);
    SupernodalCholesky<Scalar> factor;
    QVERIFY2(factor.factorize(symbolic, A), what);
    Eigen::SimplicialLLT<Sparse<Scalar>, Eigen::Lower, Eigen::NaturalOrdering<int>> reference(A);
    QCOMPARE(reference.info(), Eigen::Success);
    const Sparse<Scalar> expected = reference.matrixL();
    const Sparse<Scalar> L = factor.lowerMatrix();
    QCOMPARE(L.nonZeros(), expected.nonZeros());
    QCOMPARE(std::int64_t(L.nonZeros()), symbolic->factorEntries);
    const double scale = expected.coeffs().cwiseAbs().maxCoeff();
    for (int j = 0; j < L.cols(); ++j) {
        QCOMPARE(L.outerIndexPtr()[j + 1] - L.outerIndexPtr()[j],
                 expected.outerIndexPtr()[j + 1] - expected.outerIndexPtr()[j]);
        for (int p = L.outerIndexPtr()[j], q = expected.outerIndexPtr()[j];
             p < L.outerIndexPtr()[j + 1]; ++p, ++q) {
            QCOMPARE(L.innerIndexPtr()[p], expected.innerIndexPtr()[q]);
            QVERIFY2(std::abs(L.valuePtr()[p] - expected.valuePtr()[q]) <= 1e-12 * scale, what);
        }
        QCOMPARE(L.innerIndexPtr()[L.outerIndexPtr()[j]], j); // the diagonal leads
    }
    using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
    const Vector known = Vector::Random(A.rows());
    const Vector b = A * known;
    const Vector x = factor.solve(b);
    QVERIFY2((x - known).norm() <= 1e-9 * known.norm(), what);
    QVERIFY2((A * x - b).norm() <= 1e-12 * b.norm(), what);
}

} // namespace

class TestSupernodalCholesky : public QObject {
    Q_OBJECT

private slots:
    void matchesSimplicialOnMeshes()
    {
        std::mt19937 random(7);
        for (const int vertices : {9, 200, 2000, 12000}) {
            const auto edges = gridEdges(vertices);
            const int n = vertexCount(edges);
            compareWithSimplicial(ordered(hermitian<double>(n, edges, random)), "real grid");
            compareWithSimplicial(ordered(hermitian<Complex>(n, edges, random)), "complex grid");
        }
    }

    void matchesSimplicialOnIrregularPatterns()
    {
        std::mt19937 random(11);
        for (int round = 0; round < 40; ++round) {
            const int n = 1 + int(random() % 400);
            const int count = int(random() % std::uint32_t(6 * n + 1));
            auto edges = randomEdges(n, count, random);
            // Isolated vertices and several components included: no edge touches n − 1.
            const auto A = hermitian<double>(n, edges, random);
            compareWithSimplicial(ordered(A), "random real");
            compareWithSimplicial(ordered(hermitian<Complex>(n, edges, random)), "random complex");
            compareWithSimplicial(A, "unordered real"); // no postorder: smaller supernodes
        }
        // A chain (one supernode after relaxation) and a star (many children of one column).
        std::vector<std::pair<int, int>> chain, star;
        for (int i = 0; i + 1 < 300; ++i) {
            chain.emplace_back(i, i + 1);
            star.emplace_back(i, 299);
        }
        compareWithSimplicial(hermitian<Complex>(300, chain, random), "chain");
        compareWithSimplicial(hermitian<double>(300, star, random), "star");
    }

    void postorderKeepsFillAndOrder()
    {
        std::mt19937 random(3);
        const auto edges = randomEdges(500, 1500, random);
        const auto A = hermitian<double>(500, edges, random);
        const auto parent =
            finbook::deform::eliminationTree(500, A.outerIndexPtr(), A.innerIndexPtr());
        const auto post = finbook::deform::postorder(parent);
        QCOMPARE(int(post.size()), 500);
        std::vector<int> at(500, -1);
        for (int k = 0; k < 500; ++k)
            at[std::size_t(post[std::size_t(k)])] = k;
        for (int j = 0; j < 500; ++j) {
            QVERIFY(at[std::size_t(j)] >= 0); // a permutation
            if (parent[std::size_t(j)] >= 0)  // parents after their children
                QVERIFY(at[std::size_t(parent[std::size_t(j)])] > at[std::size_t(j)]);
        }
        Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse(500);
        for (int k = 0; k < 500; ++k)
            inverse.indices()(k) = post[std::size_t(k)];
        Sparse<double> B(500, 500);
        B = A.twistedBy(inverse.inverse());
        B.makeCompressed();
        QCOMPARE(analyze(B)->factorEntries, analyze(A)->factorEntries);
    }

    void refusesWhatIsNotPositiveDefinite()
    {
        std::mt19937 random(5);
        const auto edges = gridEdges(400);
        const int n = vertexCount(edges);
        Sparse<double> A = ordered(hermitian<double>(n, edges, random));
        const auto symbolic = analyze(A);
        SupernodalCholesky<double> factor;
        QVERIFY(factor.factorize(symbolic, A));
        Sparse<double> indefinite = A;
        indefinite.coeffRef(n / 2, n / 2) = -1.0; // a negative pivot in the middle
        QVERIFY(!factor.factorize(symbolic, indefinite));
        QVERIFY(!factor.ok());
        // Without its diagonal shift A is a graph Laplacian (singular); a little less on one
        // diagonal entry makes it indefinite with every pivot but the last positive.
        Sparse<double> barelyIndefinite = A;
        for (int k = 0; k < n; ++k)
            barelyIndefinite.coeffRef(k, k) -= 0.01;
        barelyIndefinite.coeffRef(n - 1, n - 1) -= 1e-3;
        QVERIFY(!factor.factorize(symbolic, barelyIndefinite));
        Sparse<double> notFinite = A;
        notFinite.coeffRef(3, 3) = std::numeric_limits<double>::quiet_NaN();
        QVERIFY(!factor.factorize(symbolic, notFinite));
        Sparse<Complex> complexIndefinite = ordered(hermitian<Complex>(n, edges, random));
        complexIndefinite.coeffRef(0, 0) = Complex(-2.0, 0.0);
        SupernodalCholesky<Complex> complexFactor;
        QVERIFY(!complexFactor.factorize(analyze(complexIndefinite), complexIndefinite));
    }

    // Several right-hand sides at once (row by row), some with only a few entries (the
    // forward pass skips what stays zero), through the supernodes and the compact factor:
    // each column as its own solve gives, to rounding.
    void blocksOfRightHandSides()
    {
        std::mt19937 random(13);
        const auto edges = gridEdges(3000);
        const int n = vertexCount(edges);
        const auto A = ordered(hermitian<Complex>(n, edges, random));
        SupernodalCholesky<Complex> factor;
        QVERIFY(factor.factorize(analyze(A), A));
        const finbook::deform::CholeskyFactor<Complex> compact(factor.lowerMatrix());
        QCOMPARE(compact.rows(), Eigen::Index(n));
        constexpr int k = 5;
        Eigen::Matrix<Complex, Eigen::Dynamic, k, Eigen::RowMajor> block =
            Eigen::Matrix<Complex, Eigen::Dynamic, k, Eigen::RowMajor>::Zero(n, k);
        block.col(0) = Eigen::VectorXcd::Random(n);
        for (int c = 1; c < k; ++c) { // a pin's neighbourhood: a handful of entries
            for (int e = 0; e < 6; ++e)
                block(int(random() % std::uint32_t(n)), c) = Complex(1.0 + e, -0.5 * c);
        }
        const Eigen::MatrixXcd rhs = block;
        auto viaSupernodes = block, viaCompact = block;
        factor.solveInPlace(viaSupernodes.data(), k);
        compact.solveInPlace(viaCompact.data(), k);
        for (int c = 0; c < k; ++c) {
            const Eigen::VectorXcd single = factor.solve(Eigen::VectorXcd(rhs.col(c)));
            const double scale = single.norm();
            QVERIFY((Eigen::VectorXcd(viaSupernodes.col(c)) - single).norm() <= 1e-12 * scale);
            QVERIFY((Eigen::VectorXcd(viaCompact.col(c)) - single).norm() <= 1e-12 * scale);
            QVERIFY((A * single - Eigen::VectorXcd(rhs.col(c))).norm() <=
                    1e-12 * rhs.col(c).norm());
        }
        // A real factor with a complex right-hand side solves both parts at once.
        const auto R = ordered(hermitian<double>(n, edges, random));
        SupernodalCholesky<double> real;
        QVERIFY(real.factorize(analyze(R), R));
        const Eigen::VectorXcd b = Eigen::VectorXcd::Random(n);
        const Eigen::VectorXcd x = real.solve(b);
        QVERIFY((R * Eigen::VectorXd(x.real()) - Eigen::VectorXd(b.real())).norm() <=
                1e-12 * b.real().norm());
        QVERIFY((R * Eigen::VectorXd(x.imag()) - Eigen::VectorXd(b.imag())).norm() <=
                1e-12 * b.imag().norm());
    }

    // A real symmetric matrix stored by rows (H00 as the ARAP precompute keeps it) is factored
    // as it is, to the same L bit for bit as from compressed columns; the system is large
    // enough (60k unknowns, a factor over 4 MB) for the block storage's huge-page path.
    // A moved compact factor keeps the entries without copying them.
    void rowMajorSymmetricAndMoves()
    {
        std::mt19937 random(17);
        const auto edges = gridEdges(60000);
        const int n = vertexCount(edges);
        const auto A = ordered(hermitian<double>(n, edges, random));
        const Eigen::SparseMatrix<double, Eigen::RowMajor> rows(A);
        SupernodalCholesky<double> byColumns, byRows;
        QVERIFY(byColumns.factorize(analyze(A), A));
        QVERIFY(byRows.factorize(analyze(A), rows));
        const Sparse<double> L = byColumns.lowerMatrix(), M = byRows.lowerMatrix();
        QVERIFY2(L.nonZeros() > 524288, QByteArray::number(qint64(L.nonZeros())));
        QCOMPARE(M.nonZeros(), L.nonZeros());
        QVERIFY(std::equal(L.innerIndexPtr(), L.innerIndexPtr() + L.nonZeros(), M.innerIndexPtr()));
        QVERIFY(std::equal(L.valuePtr(), L.valuePtr() + L.nonZeros(), M.valuePtr()));

        finbook::deform::CholeskyFactor<double> first(byRows.lowerMatrix());
        const double *values = first.lower().valuePtr();
        finbook::deform::CholeskyFactor<double> second(std::move(first));
        QCOMPARE(second.lower().valuePtr(), values);
        finbook::deform::CholeskyFactor<double> third;
        third = std::move(second);
        QCOMPARE(third.lower().valuePtr(), values);
        const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
        const Eigen::VectorXd x = third.solve(b);
        QVERIFY((A * x - b).norm() <= 1e-12 * b.norm());
    }

    void emptyAndSingle()
    {
        const Sparse<double> empty(0, 0);
        SupernodalCholesky<double> factor;
        QVERIFY(factor.factorize(analyze(empty), empty));
        QCOMPARE(factor.lowerMatrix().nonZeros(), Eigen::Index(0));
        Sparse<double> one(1, 1);
        one.insert(0, 0) = 4.0;
        QVERIFY(factor.factorize(analyze(one), one));
        const Eigen::VectorXd x = factor.solve(Eigen::VectorXd(Eigen::VectorXd::Constant(1, 2.0)));
        QCOMPARE(x(0), 0.5);
    }

    // Every copy this CPU runs agrees with the baseline to rounding (FMA changes the last
    // bits, nothing more), on the real and the complex system of a mesh.
    void instructionSetsAgree()
    {
        qInfo("automatic: %s", finbook::deform::supernodalInstructionSet());
        std::mt19937 random(9);
        const auto edges = gridEdges(20000);
        const int n = vertexCount(edges);
        const auto real = ordered(hermitian<double>(n, edges, random));
        const auto complex = ordered(hermitian<Complex>(n, edges, random));
        const auto symbolic = analyze(real);
        SupernodalCholesky<double> baseReal;
        SupernodalCholesky<Complex> baseComplex;
        QVERIFY(baseReal.factorize(symbolic, real, SupernodalIsa::Baseline));
        QVERIFY(baseComplex.factorize(symbolic, complex, SupernodalIsa::Baseline));
        const Eigen::VectorXcd b = Eigen::VectorXcd::Random(n);
        const Eigen::VectorXcd xReal = baseReal.solve(b), xComplex = baseComplex.solve(b);
        int compared = 0;
        for (const SupernodalIsa isa : {SupernodalIsa::Avx2, SupernodalIsa::Avx512}) {
            if (!finbook::deform::supernodalIsaAvailable(isa))
                continue;
            ++compared;
            SupernodalCholesky<double> otherReal;
            SupernodalCholesky<Complex> otherComplex;
            QVERIFY(otherReal.factorize(symbolic, real, isa));
            QVERIFY(otherComplex.factorize(symbolic, complex, isa));
            QVERIFY((otherReal.solve(b) - xReal).norm() <= 1e-10 * xReal.norm());
            QVERIFY((otherComplex.solve(b) - xComplex).norm() <= 1e-10 * xComplex.norm());
            const Sparse<double> L = otherReal.lowerMatrix(), L0 = baseReal.lowerMatrix();
            QCOMPARE(L.nonZeros(), L0.nonZeros());
            QVERIFY((L - L0).norm() <= 1e-12 * L0.norm());
        }
        qInfo("wider copies compared with the baseline: %d", compared);
    }
};

QTEST_APPLESS_MAIN(TestSupernodalCholesky)
#include "tst_supernodal_cholesky.moc"
