#include "supernodal/numeric.h"

#include <finbook/deform/supernodal_cholesky.h>

#include <Eigen/OrderingMethods>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace finbook::deform {
namespace {

// Relaxed amalgamation (the rule CHOLMOD uses by default): a supernode is merged with its
// parent when the merged block stays small, or when the explicit zeros the merge stores stay
// a small share of it. Tiny supernodes cost more in loop and call overhead than the zeros
// cost in arithmetic; the zeros stay exact zeros and lowerMatrix() leaves them out.
bool mergeAllowed(std::int64_t columns, std::int64_t zeros, std::int64_t total)
{
    const double share = total > 0 ? double(zeros) / double(total) : 0.0;
    if (columns <= 4)
        return true;
    if (columns <= 16)
        return share < 0.8;
    if (columns <= 48)
        return share < 0.1;
    return share < 0.05;
}

// Entries of a column-major block of `rows` × `columns` whose first `columns` rows are its
// diagonal block, lower trapezoid only.
std::int64_t trapezoid(std::int64_t rows, std::int64_t columns)
{
    return columns * rows - columns * (columns - 1) / 2;
}

} // namespace

namespace detail {

namespace {
constexpr std::size_t kHugePage = std::size_t(2) << 20;
constexpr std::size_t kHugeFrom = std::size_t(4) << 20;
} // namespace

void *allocateFactorStorage(std::size_t bytes)
{
#if defined(__linux__)
    if (bytes >= kHugeFrom) {
        const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
        if (void *p = std::aligned_alloc(kHugePage, rounded)) {
            madvise(p, rounded, MADV_HUGEPAGE); // advice only: ignored where unsupported
            return p;
        }
        throw std::bad_alloc();
    }
#endif
    if (void *p = std::malloc(bytes > 0 ? bytes : 1))
        return p;
    throw std::bad_alloc();
}

void releaseFactorStorage(void *p, std::size_t) noexcept
{
    std::free(p);
}

} // namespace detail

std::vector<int> eliminationTree(int n, const int *outer, const int *inner)
{
    std::vector<int> parent(std::size_t(n), -1), ancestor(std::size_t(n), -1);
    for (int j = 0; j < n; ++j) {
        for (int p = outer[j]; p < outer[j + 1]; ++p) {
            for (int i = inner[p]; i != -1 && i < j;) { // climb with path compression
                const int next = ancestor[std::size_t(i)];
                ancestor[std::size_t(i)] = j;
                if (next == -1)
                    parent[std::size_t(i)] = j;
                i = next;
            }
        }
    }
    return parent;
}

std::vector<int> supernodalOrder(const Eigen::SparseMatrix<double> &upper)
{
    const int n = int(upper.rows());
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
    Eigen::AMDOrdering<int>()(upper.selfadjointView<Eigen::Upper>(), inverse);
    Eigen::SparseMatrix<double> permuted(n, n);
    permuted = upper.selfadjointView<Eigen::Upper>().twistedBy(inverse.inverse());
    permuted.makeCompressed();
    const std::vector<int> post =
        postorder(eliminationTree(n, permuted.outerIndexPtr(), permuted.innerIndexPtr()));
    std::vector<int> order(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) // inverse.indices()(k): the column at AMD position k
        order[std::size_t(k)] = inverse.indices()(post[std::size_t(k)]);
    return order;
}

std::vector<int> postorder(const std::vector<int> &parent)
{
    const int n = int(parent.size());
    std::vector<int> head(std::size_t(n), -1), next(std::size_t(n), -1), post, stack;
    post.reserve(std::size_t(n));
    for (int j = n - 1; j >= 0; --j) { // children lists in ascending order
        if (parent[std::size_t(j)] >= 0) {
            next[std::size_t(j)] = head[std::size_t(parent[std::size_t(j)])];
            head[std::size_t(parent[std::size_t(j)])] = j;
        }
    }
    for (int root = 0; root < n; ++root) {
        if (parent[std::size_t(root)] >= 0)
            continue;
        stack.push_back(root);
        while (!stack.empty()) {
            const int j = stack.back();
            const int child = head[std::size_t(j)];
            if (child == -1) {
                stack.pop_back();
                post.push_back(j);
            } else {
                head[std::size_t(j)] = next[std::size_t(child)];
                stack.push_back(child);
            }
        }
    }
    return post;
}

std::shared_ptr<const SupernodalSymbolic> analyzeSupernodal(int n, const int *outer,
                                                            const int *inner)
{
    auto s = std::make_shared<SupernodalSymbolic>();
    s->n = n;
    const std::vector<int> parent = eliminationTree(n, outer, inner);
    // Column counts of L below the diagonal: row k of L is the union of the etree paths
    // from the entries of column k of the upper triangle up to k.
    std::vector<int> below(std::size_t(n), 0), flag(std::size_t(n), -1),
        children(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
        flag[std::size_t(k)] = k;
        for (int p = outer[k]; p < outer[k + 1]; ++p) {
            for (int i = inner[p]; i < k && flag[std::size_t(i)] != k; i = parent[std::size_t(i)]) {
                flag[std::size_t(i)] = k;
                ++below[std::size_t(i)];
            }
        }
        if (parent[std::size_t(k)] >= 0)
            ++children[std::size_t(parent[std::size_t(k)])];
    }
    for (int j = 0; j < n; ++j)
        s->factorEntries += below[std::size_t(j)] + 1;

    // Fundamental supernodes, then relaxed merges of a supernode into the one right after
    // it when that is its parent (in a postorder, a parent's last child comes right before).
    // Tracked per supernode: its columns, rows (of its first column) and true entries.
    std::vector<int> first;
    std::vector<std::int64_t> rowCount, entries;
    for (int j = 0; j < n; ++j) {
        const bool continues = j > 0 && parent[std::size_t(j - 1)] == j &&
                               children[std::size_t(j)] == 1 &&
                               below[std::size_t(j - 1)] == below[std::size_t(j)] + 1;
        if (continues) {
            entries.back() += below[std::size_t(j)] + 1;
            continue;
        }
        first.push_back(j);
        rowCount.push_back(below[std::size_t(j)] + 1);
        entries.push_back(below[std::size_t(j)] + 1);
    }
    first.push_back(n);
    std::vector<int> merged{0};
    std::int64_t mergedEntries = entries.empty() ? 0 : entries[0];
    for (std::size_t t = 1; t + 1 < first.size(); ++t) {
        const int lastColumn = first[t] - 1;
        const std::int64_t columns = first[t + 1] - merged.back();
        const std::int64_t width = first[t] - merged.back();
        const std::int64_t rowsTogether = width + rowCount[t];
        const std::int64_t total = trapezoid(rowsTogether, columns);
        const std::int64_t trueEntries = mergedEntries + entries[t];
        if (parent[std::size_t(lastColumn)] == first[t] &&
            mergeAllowed(columns, total - trueEntries, total)) {
            mergedEntries = trueEntries;
            continue;
        }
        merged.push_back(first[t]);
        mergedEntries = entries[t];
    }
    if (n > 0)
        merged.push_back(n);
    else
        merged.assign(1, 0);
    s->first = std::move(merged);
    const int count = int(s->first.size()) - 1;
    s->superOf.resize(std::size_t(n));
    for (int t = 0; t < count; ++t)
        std::fill(s->superOf.begin() + s->first[std::size_t(t)],
                  s->superOf.begin() + s->first[std::size_t(t) + 1], t);

    // Row structures: a supernode's columns, the rows below it in its columns of A, and the
    // rows below it of its child supernodes. Lower entries of A are read as the upper
    // triangle's rows, so build that transpose's pattern first.
    std::vector<int> rowStartOfUpper(std::size_t(n) + 1, 0), upperRows;
    for (int j = 0; j < n; ++j) {
        for (int p = outer[j]; p < outer[j + 1]; ++p) {
            if (inner[p] < j)
                ++rowStartOfUpper[std::size_t(inner[p]) + 1];
        }
    }
    for (int i = 0; i < n; ++i)
        rowStartOfUpper[std::size_t(i) + 1] += rowStartOfUpper[std::size_t(i)];
    upperRows.resize(std::size_t(rowStartOfUpper[std::size_t(n)]));
    {
        std::vector<int> fill(rowStartOfUpper.begin(), rowStartOfUpper.end() - 1);
        for (int j = 0; j < n; ++j) {
            for (int p = outer[j]; p < outer[j + 1]; ++p) {
                if (inner[p] < j)
                    upperRows[std::size_t(fill[std::size_t(inner[p])]++)] = j;
            }
        }
    }
    std::vector<int> childHead(std::size_t(count), -1), childNext(std::size_t(count), -1);
    for (int t = count - 1; t >= 0; --t) {
        const int up = parent[std::size_t(s->first[std::size_t(t) + 1] - 1)];
        if (up >= 0) {
            const int p = s->superOf[std::size_t(up)];
            childNext[std::size_t(t)] = childHead[std::size_t(p)];
            childHead[std::size_t(p)] = t;
        }
    }
    s->rowStart.assign(std::size_t(count) + 1, 0);
    s->valueStart.assign(std::size_t(count) + 1, 0);
    std::vector<int> mark(std::size_t(n), -1), gathered;
    for (int t = 0; t < count; ++t) {
        const int f = s->first[std::size_t(t)], l = s->first[std::size_t(t) + 1] - 1;
        gathered.clear();
        const auto add = [&](int row) {
            if (row > l && mark[std::size_t(row)] != t) {
                mark[std::size_t(row)] = t;
                gathered.push_back(row);
            }
        };
        for (int j = f; j <= l; ++j) {
            for (int p = rowStartOfUpper[std::size_t(j)]; p < rowStartOfUpper[std::size_t(j) + 1];
                 ++p)
                add(upperRows[std::size_t(p)]);
        }
        for (int c = childHead[std::size_t(t)]; c >= 0; c = childNext[std::size_t(c)]) {
            for (std::int64_t p = s->rowStart[std::size_t(c)]; p < s->rowStart[std::size_t(c) + 1];
                 ++p)
                add(s->rows[std::size_t(p)]);
        }
        std::sort(gathered.begin(), gathered.end());
        for (int j = f; j <= l; ++j)
            s->rows.push_back(j);
        s->rows.insert(s->rows.end(), gathered.begin(), gathered.end());
        const std::int64_t m = std::int64_t(l - f + 1) + std::int64_t(gathered.size());
        s->rowStart[std::size_t(t) + 1] = s->rowStart[std::size_t(t)] + m;
        s->maxRows = std::max(s->maxRows, int(m));
        // An update this supernode sends has at most (rows below its columns)² entries.
        const std::int64_t offDiagonalRows = m - (l - f + 1);
        s->maxUpdate = std::max(s->maxUpdate, offDiagonalRows * offDiagonalRows);
        s->valueStart[std::size_t(t) + 1] = s->valueStart[std::size_t(t)] + m * (l - f + 1);
    }
    return s;
}

namespace {

SupernodalIsa widestSupported()
{
#if defined(FINBOOK_SUPERNODAL_X86)
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
        __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
        return SupernodalIsa::Avx512;
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
        return SupernodalIsa::Avx2;
#endif
    return SupernodalIsa::Baseline;
}

SupernodalIsa automaticIsa()
{
    static const SupernodalIsa isa = [] {
        const SupernodalIsa widest = widestSupported();
        const char *cap = std::getenv("FINBOOK_SUPERNODAL_ISA");
        if (cap && std::strcmp(cap, "baseline") == 0)
            return SupernodalIsa::Baseline;
        if (cap && std::strcmp(cap, "avx2") == 0 && widest == SupernodalIsa::Avx512)
            return SupernodalIsa::Avx2;
        return widest;
    }();
    return isa;
}

} // namespace

bool supernodalIsaAvailable(SupernodalIsa isa)
{
    static const SupernodalIsa widest = widestSupported();
    switch (isa) {
    case SupernodalIsa::Automatic:
    case SupernodalIsa::Baseline:
        return true;
    case SupernodalIsa::Avx2:
        return widest == SupernodalIsa::Avx2 || widest == SupernodalIsa::Avx512;
    case SupernodalIsa::Avx512:
        return widest == SupernodalIsa::Avx512;
    }
    return false;
}

const char *supernodalInstructionSet()
{
    switch (automaticIsa()) {
    case SupernodalIsa::Avx512:
        return "avx512";
    case SupernodalIsa::Avx2:
        return "avx2";
    default:
        return "baseline";
    }
}

template <class Scalar>
bool SupernodalCholesky<Scalar>::factorize(std::shared_ptr<const SupernodalSymbolic> symbolic,
                                           const Eigen::SparseMatrix<Scalar> &lower,
                                           SupernodalIsa isa)
{
    return factorize(std::move(symbolic), lower.outerIndexPtr(), lower.innerIndexPtr(),
                     lower.innerNonZeroPtr(), lower.valuePtr(), isa);
}

template <class Scalar>
bool SupernodalCholesky<Scalar>::factorize(std::shared_ptr<const SupernodalSymbolic> symbolic,
                                           const int *outer, const int *inner, const int *nonZeros,
                                           const Scalar *values, SupernodalIsa isa)
{
    m_symbolic = std::move(symbolic);
    m_ok = false;
    const SupernodalSymbolic &s = *m_symbolic;
    const int count = int(s.first.size()) - 1;
    m_values.assign(std::size_t(s.valueStart.back()), Scalar(0));
    supernodal::Pattern pattern;
    pattern.n = s.n;
    pattern.count = count;
    pattern.first = s.first.data();
    pattern.superOf = s.superOf.data();
    pattern.rowStart = s.rowStart.data();
    pattern.rows = s.rows.data();
    pattern.valueStart = s.valueStart.data();
    supernodal::Lower<Scalar> a;
    a.outer = outer;
    a.inner = inner;
    a.nonZeros = nonZeros;
    a.values = values;
    std::vector<int> ints(std::size_t(s.n) + 3 * std::size_t(count) + std::size_t(s.maxRows));
    std::vector<Scalar> update(std::size_t(s.maxUpdate));
    supernodal::Scratch scratch;
    scratch.map = ints.data();
    scratch.head = scratch.map + s.n;
    scratch.link = scratch.head + count;
    scratch.position = scratch.link + count;
    scratch.relative = scratch.position + count;
    scratch.update = update.data();
    if (isa == SupernodalIsa::Automatic)
        isa = automaticIsa();
    else if (!supernodalIsaAvailable(isa))
        isa = SupernodalIsa::Baseline;
    switch (isa) {
#if defined(FINBOOK_SUPERNODAL_X86)
    case SupernodalIsa::Avx512:
        m_ok = supernodal::avx512::factorize(pattern, a, m_values.data(), scratch);
        break;
    case SupernodalIsa::Avx2:
        m_ok = supernodal::avx2::factorize(pattern, a, m_values.data(), scratch);
        break;
#endif
    default:
        m_ok = supernodal::baseline::factorize(pattern, a, m_values.data(), scratch);
        break;
    }
    return m_ok;
}

namespace {

// One column of L: its diagonal entry first, then the rows below it that are stored.
template <class Scalar> struct Column {
    const int *rows;
    const Scalar *values;
    int count;
};

// x ← (L Lᴴ)⁻¹ x for right-hand sides stored row by row, L given column by column (both
// layouts of L solve through this). Fixed > 0 fixes the column count at compile time: one
// right-hand side, the step-1 solve of a drag event with many pins, must not pay for loops
// over a run-time count. The forward pass skips columns of L where x is still all zero.
template <int Fixed, class Scalar, class RhsScalar, class ColumnOf>
void solveByColumns(int n, const ColumnOf &columnOf, RhsScalar *y, int runtimeColumns)
{
    using Eigen::numext::conj;
    using Eigen::numext::real;
    const int columns = Fixed > 0 ? Fixed : runtimeColumns;
    for (int j = 0; j < n; ++j) { // L y = b
        RhsScalar *yj = y + std::ptrdiff_t(j) * columns;
        bool zero = true;
        for (int c = 0; c < columns; ++c)
            zero = zero && yj[c] == RhsScalar(0);
        if (zero)
            continue;
        const Column<Scalar> column = columnOf(j);
        const double pivotInverse = 1.0 / real(column.values[0]);
        for (int c = 0; c < columns; ++c)
            yj[c] *= pivotInverse;
        for (int p = 1; p < column.count; ++p) {
            RhsScalar *target = y + std::ptrdiff_t(column.rows[p]) * columns;
            const Scalar v = column.values[p];
            for (int c = 0; c < columns; ++c)
                target[c] -= v * yj[c];
        }
    }
    for (int j = n - 1; j >= 0; --j) { // Lᴴ x = y
        RhsScalar *yj = y + std::ptrdiff_t(j) * columns;
        const Column<Scalar> column = columnOf(j);
        for (int p = 1; p < column.count; ++p) {
            const RhsScalar *source = y + std::ptrdiff_t(column.rows[p]) * columns;
            const Scalar v = conj(column.values[p]);
            for (int c = 0; c < columns; ++c)
                yj[c] -= v * source[c];
        }
        const double pivotInverse = 1.0 / real(column.values[0]);
        for (int c = 0; c < columns; ++c)
            yj[c] *= pivotInverse;
    }
}

template <class Scalar, class RhsScalar, class ColumnOf>
void solveByColumns(int n, const ColumnOf &columnOf, RhsScalar *y, int columns)
{
    if (columns == 1)
        solveByColumns<1, Scalar>(n, columnOf, y, 1);
    else
        solveByColumns<0, Scalar>(n, columnOf, y, columns);
}

} // namespace

template <class Scalar>
template <class RhsScalar>
void SupernodalCholesky<Scalar>::solveInPlace(RhsScalar *y, int columns) const
{
    const SupernodalSymbolic &s = *m_symbolic;
    const auto columnOf = [&s, this](int j) {
        const auto t = std::size_t(s.superOf[std::size_t(j)]);
        const int k = j - s.first[t];
        const int m = int(s.rowStart[t + 1] - s.rowStart[t]);
        return Column<Scalar>{s.rows.data() + s.rowStart[t] + k,
                              m_values.data() + s.valueStart[t] + std::ptrdiff_t(k) * m + k, m - k};
    };
    solveByColumns<Scalar>(s.n, columnOf, y, columns);
}

template <class Scalar> Eigen::SparseMatrix<Scalar> SupernodalCholesky<Scalar>::lowerMatrix() const
{
    const SupernodalSymbolic &s = *m_symbolic;
    const int count = int(s.first.size()) - 1;
    // Written straight into the compressed arrays (through insertBack this took 20–30 ms at
    // 3M entries). Zeros stored by relaxed merges are left out: structurally zero entries
    // stay exact zeros through the factorization, so at most factorEntries remain.
    Eigen::SparseMatrix<Scalar> L(s.n, s.n);
    L.resizeNonZeros(Eigen::Index(s.factorEntries));
    int *outer = L.outerIndexPtr();
    int *inner = L.innerIndexPtr();
    Scalar *values = L.valuePtr();
    int next = 0;
    outer[0] = 0;
    for (int t = 0; t < count; ++t) {
        const int f = s.first[std::size_t(t)];
        const int w = s.first[std::size_t(t) + 1] - f;
        const int *rs = s.rows.data() + s.rowStart[std::size_t(t)];
        const int m = int(s.rowStart[std::size_t(t) + 1] - s.rowStart[std::size_t(t)]);
        const Scalar *block = m_values.data() + s.valueStart[std::size_t(t)];
        for (int k = 0; k < w; ++k) {
            const Scalar *column = block + std::ptrdiff_t(k) * m;
            inner[next] = f + k;
            values[next++] = column[k];
            for (int r = k + 1; r < m; ++r) {
                if (column[r] != Scalar(0)) {
                    inner[next] = rs[r];
                    values[next++] = column[r];
                }
            }
            outer[f + k + 1] = next;
        }
    }
    L.resizeNonZeros(next);
    return L;
}

template <class Scalar>
template <class RhsScalar>
void CholeskyFactor<Scalar>::solveInPlace(RhsScalar *x, int columns) const
{
    const int *start = m_lower.outerIndexPtr();
    const auto columnOf = [this, start](int j) {
        return Column<Scalar>{m_lower.innerIndexPtr() + start[j], m_lower.valuePtr() + start[j],
                              start[j + 1] - start[j]};
    };
    solveByColumns<Scalar>(int(m_lower.cols()), columnOf, x, columns);
}

template class CholeskyFactor<double>;
template class CholeskyFactor<std::complex<double>>;
template void CholeskyFactor<double>::solveInPlace(double *, int) const;
template void CholeskyFactor<double>::solveInPlace(std::complex<double> *, int) const;
template void CholeskyFactor<std::complex<double>>::solveInPlace(std::complex<double> *, int) const;

template class SupernodalCholesky<double>;
template class SupernodalCholesky<std::complex<double>>;
template void SupernodalCholesky<double>::solveInPlace(double *, int) const;
template void SupernodalCholesky<double>::solveInPlace(std::complex<double> *, int) const;
template void SupernodalCholesky<std::complex<double>>::solveInPlace(std::complex<double> *,
                                                                     int) const;

} // namespace finbook::deform
