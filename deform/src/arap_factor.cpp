#include "arap_solver.h"

#include <atomic>
#include <exception>
#include <latch>
#include <thread>

namespace finbook::deform::detail {
namespace {

DeformError cancelledError()
{
    return makeError(DeformErrorCode::Cancelled, "precompute was cancelled");
}

DeformError singularError()
{
    return makeError(DeformErrorCode::FactorizationFailed,
                     "the deformation system is numerically singular");
}

// Positive pivots do not make a factor accurate (a nearly singular matrix has them too), so
// solve for a known vector and check the answer is finite with a small residual.
template <class Factor, class Matrix>
bool probe(const Factor &factor, const Matrix &upper, double norm)
{
    using Vector = Eigen::Matrix<typename Matrix::Scalar, Eigen::Dynamic, 1>;
    const Vector known = Vector::LinSpaced(upper.rows(), 1.0, 2.0);
    const Vector rhs = upper.template selfadjointView<Eigen::Upper>() * known;
    const Vector x = factor.solve(rhs);
    const Vector residual = upper.template selfadjointView<Eigen::Upper>() * x - rhs;
    return x.allFinite() && relativeResidual(residual, norm, x, rhs) <= kResidualTolerance;
}

} // namespace

// Work shared by the two threads. The caller's cancellation callback is only ever polled on
// the calling thread; the helper watches `abort`.
struct ArapFactorization::Shared {
    explicit Shared(ArapPrecompute &data)
        : d(data)
    {}
    ArapPrecompute &d;
    std::latch stepOneFactored{1};
    std::latch assembled{1};    // the caller finished assembleArapSystems
    bool released = false;      // stepOneFactored was counted down (calling thread only)
    bool assembledSaid = false; // assembled was counted down (calling thread only)
    bool stepTwoOk = false;
    std::atomic<bool> stepOneOk{false};
    std::atomic<bool> abort{false};
    std::atomic<bool> inaccurate{false};
    CoarseBuilder coarse;
    std::atomic<bool> coarseReady{false};
    std::atomic<int> nextColumn{0};
    SupernodalCholesky<Complex> stepOne; // G00's factor, for the basis solves

    void sayAssembled()
    {
        if (!assembledSaid)
            assembled.count_down();
        assembledSaid = true;
    }

    // The drag pass count, and whether coarse rotations are wanted (the budget holds fewer
    // than kCoarseBelowPasses): then their clusters. On 55 drawings of about 2k vertices
    // (finbook-bench arap --quality) they took the median drag pose from 1.004× to 1.0001×
    // the converged energy and the worst from 6.2× to 1.5×. They need H00's factor and the
    // assembled triangles, not G00, so on large meshes the helper does them while the caller
    // factors G00; the columns are shared (coarseColumns) and finishDrag completes them on
    // the caller.
    void prepareDrag()
    {
        const double budgetPasses = chooseDragPasses(d);
        if (d.options.method == ArapMethod::Refined && budgetPasses < kCoarseBelowPasses &&
            coarse.prepare(d))
            coarseReady = true;
    }

    // Claims blocks of coarse columns until none is left (either thread; each block once).
    void coarseColumns(const std::function<bool()> &stop)
    {
        if (!coarseReady)
            return;
        std::vector<Complex> x;
        for (int k = nextColumn.fetch_add(kBlockWidth); k < coarse.count();
             k = nextColumn.fetch_add(kBlockWidth)) {
            if (abort || stop()) {
                abort = true;
                return;
            }
            coarse.columns(d, k, x);
        }
    }

    void finishDrag()
    {
        if (!coarseReady)
            return;
        coarse.finish(d);
        chooseDragPasses(d);
    }

    void release(bool ok)
    {
        stepOneOk = ok;
        released = true;
        stepOneFactored.count_down();
    }

    // LLᵀ of H00, the compressed L and reciprocal pivots of the back-substitution kernel,
    // and a probe through that kernel (x and y of a known vector at once).
    void factorStepTwo()
    {
        SupernodalCholesky<double> factor;
        stepTwoOk = factor.factorize(d.factorPattern, d.stepTwoMatrix);
        if (!stepTwoOk)
            return;
        // Swapped in: assigning Eigen 3.4's SparseMatrix copies it even from a temporary.
        Eigen::SparseMatrix<double> lower = factor.lowerMatrix();
        d.stepTwoLower.swap(lower);
        const auto &L = d.stepTwoLower;
        d.stepTwoPivotInverse.resize(L.cols());
        for (Eigen::Index j = 0; j < L.cols(); ++j) // the diagonal leads each column
            d.stepTwoPivotInverse(j) = 1.0 / L.valuePtr()[L.outerIndexPtr()[j]];
        const Eigen::Index n = L.cols();
        Eigen::VectorXcd known(n);
        known.real() = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
        known.imag() = Eigen::VectorXd::LinSpaced(n, 2.0, 1.0);
        const Eigen::VectorXcd rhs = d.stepTwoMatrix * known; // both halves are stored
        Eigen::VectorXcd x = rhs;
        arapStepTwoBacksubstitute(d, x);
        const Eigen::VectorXcd residual = d.stepTwoMatrix * x - rhs;
        stepTwoOk = x.allFinite() &&
                    relativeResidual(residual, d.stepTwoNorm, x, rhs) <= kResidualTolerance;
    }

    // Basis columns first, first + stride, …: M(:, c) = −G00⁻¹ G01(:, c), solved together
    // (one pass over the factor; each right-hand side has a pin's few neighbours, so the
    // forward pass hardly touches L) and each residual-checked (which also verifies the G00
    // factor, so it needs no probe then).
    void basisColumns(Eigen::Index first, Eigen::Index stride, const std::function<bool()> &stop)
    {
        std::vector<Eigen::Index> columns;
        for (Eigen::Index c = first; c < d.stepOneBasis.cols(); c += stride)
            columns.push_back(c);
        if (columns.empty())
            return;
        if (abort || inaccurate || stop()) {
            abort = true;
            return;
        }
        const auto k = Eigen::Index(columns.size());
        // Row by row, as the multi-column solve takes them.
        Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> block =
            Eigen::MatrixXcd::Zero(d.freeCount, k);
        for (Eigen::Index j = 0; j < k; ++j)
            block.col(j) = -Eigen::VectorXcd(d.stepOneCoupling.col(columns[std::size_t(j)]));
        const Eigen::MatrixXcd rhs = block;
        stepOne.solveInPlace(block.data(), int(k));
        for (Eigen::Index j = 0; j < k; ++j) {
            const Eigen::VectorXcd column = block.col(j);
            const Eigen::VectorXcd residual =
                d.stepOneMatrix.selfadjointView<Eigen::Upper>() * column - rhs.col(j);
            if (!column.allFinite() ||
                relativeResidual(residual, d.stepOneNorm, column, rhs.col(j)) > kResidualTolerance)
                inaccurate = true;
            d.stepOneBasis.col(columns[std::size_t(j)]) = column;
        }
    }
};

ArapFactorization::ArapFactorization(ArapPrecompute &d)
    : m_shared(std::make_unique<Shared>(d))
{
    if (d.freeCount < kParallelFreeVertices)
        return; // finish() does everything on the calling thread
    m_helper = std::thread([this] {
        Shared &s = *m_shared;
        try {
            s.factorStepTwo();
            s.assembled.wait();
            if (s.stepTwoOk && !s.abort) {
                s.prepareDrag();
                s.coarseColumns([] { return false; });
            }
            s.stepOneFactored.wait();
            if (s.stepTwoOk && s.stepOneOk && !s.abort)
                s.basisColumns(1, 2, [] { return false; });
        } catch (...) {
            s.abort = true;
            m_helperFailure = std::current_exception();
        }
    });
}

ArapFactorization::~ArapFactorization()
{
    if (!m_helper.joinable())
        return;
    m_shared->abort = true;
    m_shared->sayAssembled();
    if (!m_shared->released)
        m_shared->release(false);
    m_helper.join();
}

std::optional<DeformError> ArapFactorization::finish(const std::function<bool()> &cancelled)
{
    const std::function<bool()> stop = [&cancelled] { return cancelled && cancelled(); };
    Shared &s = *m_shared;
    s.sayAssembled();
    if (s.d.freeCount == 0) { // every vertex of every solved component is pinned
        chooseDragPasses(s.d);
        return std::nullopt;
    }
    const bool parallel = m_helper.joinable();
    if (!parallel) {
        s.factorStepTwo();
        if (s.stepTwoOk)
            s.prepareDrag();
        s.coarseColumns(stop);
    }
    const Eigen::Index handles = s.d.handleEntry.size();
    s.d.stepOneBasis.resize(s.d.freeCount, handles <= kMaxBasisHandles ? handles : 0);
    if (stop()) {
        s.abort = true;
        s.release(false);
    } else {
        // The factor reads lower columns: G00's are the conjugates of its upper rows.
        bool ok = s.stepOne.factorize(s.d.factorPattern,
                                      ArapPrecompute::ComplexMatrix(s.d.stepOneMatrix.adjoint()));
        // Drag events solve with G00 only when there is no basis: then they need the
        // compact factor, and there are no basis solves to verify it with.
        if (ok && s.d.stepOneBasis.cols() == 0) {
            s.d.stepOneFactor = ArapPrecompute::ComplexFactor(s.stepOne.lowerMatrix());
            ok = probe(s.d.stepOneFactor, s.d.stepOneMatrix, s.d.stepOneNorm);
        }
        s.release(ok);
        if (ok && (s.stepTwoOk || parallel))
            s.basisColumns(0, parallel ? 2 : 1, stop);
        if (parallel) // help with the coarse columns the helper has not claimed yet
            s.coarseColumns(stop);
    }
    if (parallel)
        m_helper.join();
    if (m_helperFailure)
        std::rethrow_exception(m_helperFailure);
    if (s.abort || stop())
        return cancelledError();
    if (!s.stepOneOk || !s.stepTwoOk)
        return singularError();
    if (s.inaccurate)
        return makeError(DeformErrorCode::SolveFailed,
                         "the similarity basis could not be computed accurately");
    s.finishDrag();
    return std::nullopt;
}

} // namespace finbook::deform::detail
