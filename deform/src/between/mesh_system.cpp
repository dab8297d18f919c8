#include "mesh_system.h"

#include <algorithm>
#include <cmath>

namespace finbook::deform::between::detail {
namespace {

// Index of entry (row, col) in a compressed row-major matrix with sorted columns.
int slotOf(const Eigen::SparseMatrix<double, Eigen::RowMajor> &m, int row, int col)
{
    const int *begin = m.innerIndexPtr() + m.outerIndexPtr()[row];
    const int *end = m.innerIndexPtr() + m.outerIndexPtr()[row + 1];
    const int *it = std::lower_bound(begin, end, col);
    return int(it - m.innerIndexPtr());
}

} // namespace

MeshSystem::MeshSystem(int n, const Eigen::MatrixX3i &F, const std::vector<bool> &eliminated,
                       const std::vector<std::array<int, 2>> &links)
{
    m_unknown.assign(std::size_t(n), -1);
    for (int v = 0; v < n; ++v)
        if (eliminated.empty() || !eliminated[std::size_t(v)])
            m_unknown[std::size_t(v)] = m_free++;

    // Upper pattern in unknown numbering, then the order the supernodal factor wants (as the
    // ARAP precompute's).
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(std::size_t(m_free) + std::size_t(F.rows()) * 3 + links.size());
    for (int u = 0; u < m_free; ++u)
        entries.emplace_back(u, u, 1.0);
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        for (int a = 0; a < 3; ++a) {
            const int i = m_unknown[std::size_t(F(t, a))],
                      j = m_unknown[std::size_t(F(t, (a + 1) % 3))];
            if (i >= 0 && j >= 0 && i != j)
                entries.emplace_back(std::min(i, j), std::max(i, j), 1.0);
        }
    }
    for (const auto &[a, b] : links) {
        const int i = m_unknown[std::size_t(a)], j = m_unknown[std::size_t(b)];
        if (i >= 0 && j >= 0 && i != j)
            entries.emplace_back(std::min(i, j), std::max(i, j), 1.0);
    }
    Eigen::SparseMatrix<double> upper(m_free, m_free);
    upper.setFromTriplets(entries.begin(), entries.end());
    const std::vector<int> order = supernodalOrder(upper);
    m_position.assign(std::size_t(m_free), 0);
    for (int k = 0; k < m_free; ++k)
        m_position[std::size_t(order[std::size_t(k)])] = k;

    std::vector<Eigen::Triplet<double>> full;
    full.reserve(entries.size() * 2);
    for (const auto &e : entries) {
        const int r = m_position[std::size_t(e.row())], c = m_position[std::size_t(e.col())];
        full.emplace_back(r, c, 0.0);
        if (r != c)
            full.emplace_back(c, r, 0.0);
    }
    m_matrix.resize(m_free, m_free);
    m_matrix.setFromTriplets(full.begin(), full.end());
    m_matrix.makeCompressed();
    m_symbolic = analyzeSupernodal(m_free, m_matrix.outerIndexPtr(), m_matrix.innerIndexPtr());

    m_diagonal.resize(std::size_t(m_free));
    for (int u = 0; u < m_free; ++u) {
        const int p = m_position[std::size_t(u)];
        m_diagonal[std::size_t(u)] = slotOf(m_matrix, p, p);
    }
    m_linkSlots.reserve(links.size());
    for (const auto &[a, b] : links) {
        const int i = m_unknown[std::size_t(a)], j = m_unknown[std::size_t(b)];
        const int pi = i >= 0 ? m_position[std::size_t(i)] : -1;
        const int pj = j >= 0 ? m_position[std::size_t(j)] : -1;
        const bool both = pi >= 0 && pj >= 0 && pi != pj;
        m_linkSlots.push_back(
            {pi >= 0 ? slotOf(m_matrix, pi, pi) : -1, pj >= 0 ? slotOf(m_matrix, pj, pj) : -1,
             both ? slotOf(m_matrix, pi, pj) : -1, both ? slotOf(m_matrix, pj, pi) : -1});
    }
    m_slots.assign(std::size_t(F.rows()) * 9, -1);
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) {
                const int i = m_unknown[std::size_t(F(t, a))], j = m_unknown[std::size_t(F(t, b))];
                if (i >= 0 && j >= 0)
                    m_slots[std::size_t(t) * 9 + std::size_t(a * 3 + b)] =
                        slotOf(m_matrix, m_position[std::size_t(i)], m_position[std::size_t(j)]);
            }
        }
    }
}

void MeshSystem::clear()
{
    std::fill(m_matrix.valuePtr(), m_matrix.valuePtr() + m_matrix.nonZeros(), 0.0);
}

void MeshSystem::addTriangleBlock(int t, const double beta[3], double w)
{
    const int *slot = m_slots.data() + std::size_t(t) * 9;
    double *values = m_matrix.valuePtr();
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            if (slot[a * 3 + b] >= 0)
                values[slot[a * 3 + b]] += w * beta[a] * beta[b];
}

void MeshSystem::addEntry(int t, int a, int b, double w)
{
    const int *slot = m_slots.data() + std::size_t(t) * 9;
    double *values = m_matrix.valuePtr();
    if (slot[a * 3 + b] >= 0)
        values[slot[a * 3 + b]] += w;
    if (a != b && slot[b * 3 + a] >= 0)
        values[slot[b * 3 + a]] += w;
}

void MeshSystem::addDiagonal(int v, double w)
{
    const int u = m_unknown[std::size_t(v)];
    if (u >= 0)
        m_matrix.valuePtr()[m_diagonal[std::size_t(u)]] += w;
}

void MeshSystem::addLink(int l, double w)
{
    const std::array<int, 4> &slot = m_linkSlots[std::size_t(l)];
    double *values = m_matrix.valuePtr();
    if (slot[2] < 0 && slot[0] >= 0 && slot[0] == slot[1])
        return; // both ends one unknown: the link holds nothing
    for (int k = 0; k < 4; ++k)
        if (slot[std::size_t(k)] >= 0)
            values[slot[std::size_t(k)]] += k < 2 ? w : -w;
}

bool MeshSystem::factorize()
{
    if (m_free == 0)
        return true;
    for (Eigen::Index k = 0; k < m_matrix.nonZeros(); ++k)
        if (!std::isfinite(m_matrix.valuePtr()[k]))
            return false;
    return m_factor.factorize(m_symbolic, m_matrix);
}

template <class Scalar> void MeshSystem::solveInPlace(Scalar *x, int columns) const
{
    std::vector<Scalar> y(std::size_t(m_free) * std::size_t(columns));
    for (int u = 0; u < m_free; ++u)
        for (int c = 0; c < columns; ++c)
            y[std::size_t(m_position[std::size_t(u)] * columns + c)] =
                x[std::size_t(u * columns + c)];
    if (m_free > 0)
        m_factor.solveInPlace(y.data(), columns);
    for (int u = 0; u < m_free; ++u)
        for (int c = 0; c < columns; ++c)
            x[std::size_t(u * columns + c)] =
                y[std::size_t(m_position[std::size_t(u)] * columns + c)];
}

template void MeshSystem::solveInPlace(double *, int) const;
template void MeshSystem::solveInPlace(std::complex<double> *, int) const;

} // namespace finbook::deform::between::detail
