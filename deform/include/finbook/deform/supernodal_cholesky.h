// Sparse Cholesky A = L Lᴴ for Hermitian positive definite matrices already in a
// fill-reducing order (the ARAP precompute assembles its systems pre-permuted), computed by
// supernodes: columns of L with the same structure below their diagonal block are factored
// together as one dense block, so almost all the arithmetic runs in Eigen's dense kernels.
// Eigen's SimplicialLDLT touches one entry at a time and spent about 300 ms on the complex
// ARAP system of a 100k-vertex mesh; most of the factorization time is in the few large
// separator blocks of such meshes, where dense products are many times faster.
//
// The symbolic analysis depends only on the pattern and is shared: the ARAP step-1 and
// step-2 systems have the same pattern, so they are analysed once and factored twice.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <complex>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <vector>

namespace finbook::deform {

// Supernode partition and row structures of L for one pattern. Supernode s holds columns
// first[s] … first[s + 1] − 1; its rows (ascending, its own columns first) are
// rows[rowStart[s]] … rows[rowStart[s + 1] − 1]; its values are a column-major block of
// (row count) × (column count) at valueStart[s].
struct SupernodalSymbolic {
    int n = 0;
    std::vector<int> first;
    std::vector<int> superOf; // per column: its supernode
    std::vector<std::int64_t> rowStart;
    std::vector<int> rows;
    std::vector<std::int64_t> valueStart;
    std::int64_t factorEntries = 0; // nonzeros of L, diagonal included (as a simplicial L)
    int maxRows = 0;                // of any supernode
    std::int64_t maxUpdate = 0;     // entries of the largest update one supernode sends
};

// Elimination tree of the upper-triangular pattern (compressed columns, column j holding
// rows i ≤ j; other entries are ignored): parent per column, −1 at roots.
std::vector<int> eliminationTree(int n, const int *outer, const int *inner);

// A postorder of that forest: post[k] is the k-th column visited, children in ascending
// order before their parent. Renumbering by it keeps the fill of L and makes every chain of
// single children contiguous, which is what lets columns form supernodes.
std::vector<int> postorder(const std::vector<int> &parent);

// The elimination order for a symmetric pattern that analyzeSupernodal wants: AMD (the fill),
// then a postorder of the elimination tree of the AMD-permuted pattern (the same fill, with
// the chains of columns that become supernodes made contiguous). `upper`: the upper triangle
// (values ignored). order[k] is the column eliminated k-th.
std::vector<int> supernodalOrder(const Eigen::SparseMatrix<double> &upper);

// Analyses the upper-triangular pattern of a matrix whose elimination tree is postordered:
// compressed columns (outer[j + 1] ends column j, so an Eigen matrix must be compressed
// first), column j holding rows i ≤ j; entries below the diagonal are ignored.
std::shared_ptr<const SupernodalSymbolic> analyzeSupernodal(int n, const int *outer,
                                                            const int *inner);

// The copies of the numeric factorization (see src/supernodal/numeric.h). Automatic takes
// the widest the CPU runs, capped by the environment variable FINBOOK_SUPERNODAL_ISA
// (baseline or avx2) to measure or rule out a wider one.
enum class SupernodalIsa { Automatic, Baseline, Avx2, Avx512 };
bool supernodalIsaAvailable(SupernodalIsa isa); // built in and supported by this CPU
// What Automatic is here: "avx512", "avx2" or "baseline" (SSE2 on x86-64).
const char *supernodalInstructionSet();

// A⁻¹ b through factor.solveInPlace (the solve() of both factor classes).
template <class Factor, class RhsScalar>
Eigen::Matrix<RhsScalar, Eigen::Dynamic, 1>
solvedCopy(const Factor &factor, const Eigen::Matrix<RhsScalar, Eigen::Dynamic, 1> &b)
{
    Eigen::Matrix<RhsScalar, Eigen::Dynamic, 1> x = b;
    factor.solveInPlace(x.data());
    return x;
}

namespace detail {
// Storage for a numeric factor's blocks (tens of megabytes on large meshes): on Linux, blocks
// of 4 MB and more are aligned to and marked for transparent huge pages, so that first touching
// them takes one page fault per 2 MB instead of per 4 kB (see supernodal_cholesky.cpp).
void *allocateFactorStorage(std::size_t bytes);
void releaseFactorStorage(void *p, std::size_t bytes) noexcept;

template <class T> struct FactorAllocator {
    using value_type = T;
    FactorAllocator() = default;
    template <class U> FactorAllocator(const FactorAllocator<U> &) {}
    T *allocate(std::size_t count)
    {
        return static_cast<T *>(allocateFactorStorage(count * sizeof(T)));
    }
    void deallocate(T *p, std::size_t count) noexcept
    {
        releaseFactorStorage(p, count * sizeof(T));
    }
    template <class U> bool operator==(const FactorAllocator<U> &) const { return true; }
};
} // namespace detail

template <class Scalar> class SupernodalCholesky {
public:
    using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;

    // Numeric factorization of A, given by the entries on and below the diagonal of each
    // column of `lower` (compressed columns; entries above the diagonal are skipped, so a
    // matrix holding both halves may be passed as is). False when A is not numerically
    // positive definite (a pivot ≤ 0 or not finite). An unavailable isa runs the baseline.
    bool factorize(std::shared_ptr<const SupernodalSymbolic> symbolic,
                   const Eigen::SparseMatrix<Scalar> &lower,
                   SupernodalIsa isa = SupernodalIsa::Automatic);
    // The same for a real symmetric A stored by rows, both halves (its rows are its columns):
    // passed to the overload above it would first be converted to compressed columns, a
    // sorting pass over the whole matrix. A member template, so that the complex factor's
    // explicit instantiation does not instantiate it (clang 14 ignores the constraint there).
    template <class Real>
    requires std::is_same_v<Real, double> && std::is_same_v<Scalar, double>
    bool factorize(std::shared_ptr<const SupernodalSymbolic> symbolic,
                   const Eigen::SparseMatrix<Real, Eigen::RowMajor> &symmetric,
                   SupernodalIsa isa = SupernodalIsa::Automatic)
    {
        return factorize(std::move(symbolic), symmetric.outerIndexPtr(), symmetric.innerIndexPtr(),
                         symmetric.innerNonZeroPtr(), symmetric.valuePtr(), isa);
    }
    bool ok() const { return m_ok; }

    // x ← A⁻¹ x for the n entries at x (n of the symbolic). Rhs may be real or complex (a real
    // factor with a complex right-hand side solves for its real and imaginary parts at once).
    // Allocates nothing.
    template <class RhsScalar> void solveInPlace(RhsScalar *x) const { solveInPlace(x, 1); }
    // The same for `columns` right-hand sides stored row by row (x[i·columns + c]), in one
    // pass over L. Columns of L whose entries of x are all zero when the forward pass
    // reaches them are skipped there: a right-hand side with a few entries (a basis column
    // of a pin) only travels up the elimination tree from them.
    template <class RhsScalar> void solveInPlace(RhsScalar *x, int columns) const;
    template <class RhsScalar>
    Eigen::Matrix<RhsScalar, Eigen::Dynamic, 1>
    solve(const Eigen::Matrix<RhsScalar, Eigen::Dynamic, 1> &b) const
    {
        return solvedCopy(*this, b);
    }

    // L as compressed columns, the diagonal first in each column, structural zeros of the
    // supernodes left out (the layout SimplicialLLT's matrixL() has).
    Eigen::SparseMatrix<Scalar> lowerMatrix() const;

private:
    // Column j of A's lower half: inner[outer[j] …) (the first nonZeros[j] of them when
    // nonZeros is not null), entries above the diagonal skipped.
    bool factorize(std::shared_ptr<const SupernodalSymbolic> symbolic, const int *outer,
                   const int *inner, const int *nonZeros, const Scalar *values, SupernodalIsa isa);

    std::shared_ptr<const SupernodalSymbolic> m_symbolic;
    std::vector<Scalar, detail::FactorAllocator<Scalar>> m_values;
    bool m_ok = false;
};

// A Cholesky factor L (A = L Lᴴ) kept as compressed columns, the diagonal first in each:
// what repeated solves use. The supernodes' dense blocks are the fast layout to factor in,
// but they store the zeros of relaxed merges (about 35–45 % more entries on meshes), and a
// solve streams every stored entry: at 20k vertices a supernodal solve took 1.9 ms where
// this one takes about as long as Eigen's simplicial solve (1.1 ms).
template <class Scalar> class CholeskyFactor {
public:
    // Eigen 3.4's SparseMatrix has no move constructor or move assignment: std::move copies
    // it (at 100k vertices the step-1 factor's 4.6M entries, twice, took 95 ms of a
    // precompute). Moves here swap.
    CholeskyFactor() = default;
    explicit CholeskyFactor(Eigen::SparseMatrix<Scalar> lower) { m_lower.swap(lower); }
    CholeskyFactor(const CholeskyFactor &) = default;
    CholeskyFactor &operator=(const CholeskyFactor &) = default;
    CholeskyFactor(CholeskyFactor &&other) noexcept { m_lower.swap(other.m_lower); }
    CholeskyFactor &operator=(CholeskyFactor &&other) noexcept
    {
        m_lower.swap(other.m_lower);
        return *this;
    }
    ~CholeskyFactor() = default;
    const Eigen::SparseMatrix<Scalar> &lower() const { return m_lower; }
    Eigen::Index rows() const { return m_lower.rows(); }

    // x ← A⁻¹ x for `columns` right-hand sides stored row by row (x[i·columns + c]), real or
    // complex (a real factor solves a complex right-hand side's two parts at once), in one
    // pass over L each way. The forward pass skips columns of L whose entries of x are all
    // zero, so a right-hand side with a few entries (a pin's basis column) costs little
    // there. Allocates nothing.
    template <class RhsScalar> void solveInPlace(RhsScalar *x, int columns = 1) const;
    template <class RhsScalar>
    Eigen::Matrix<RhsScalar, Eigen::Dynamic, 1>
    solve(const Eigen::Matrix<RhsScalar, Eigen::Dynamic, 1> &b) const
    {
        return solvedCopy(*this, b);
    }

private:
    Eigen::SparseMatrix<Scalar> m_lower;
};

extern template class SupernodalCholesky<double>;
extern template class SupernodalCholesky<std::complex<double>>;
extern template class CholeskyFactor<double>;
extern template class CholeskyFactor<std::complex<double>>;

} // namespace finbook::deform
