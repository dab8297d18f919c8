#include "harmonic_internal.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace finbook::deform::detail {
namespace {

// Cotangent weights are scale-free; cocircular quadrilaterals (an isosceles trapezoid in a
// patched lattice triangle) give exactly 0 up to this much rounding.
constexpr double kNegligibleWeight = 1e-12;

// Position of `target` in v's neighbour list (it is there: both come from the same triangle).
int slotOf(const VertexAdjacency &a, int v, int target)
{
    int p = a.start[std::size_t(v)];
    while (a.neighbour[std::size_t(p)] != target)
        ++p;
    return p;
}

// Per adjacency entry: the cotangent weight of that edge, ½ cot of the angle opposite it in
// each of its (one or two) triangles.
std::vector<double> edgeWeights(const geometry::CageMesh &mesh, const VertexAdjacency &a)
{
    std::vector<double> weight(a.neighbour.size(), 0.0);
    const Eigen::MatrixX2d &V = mesh.V;
    for (Eigen::Index t = 0; t < mesh.F.rows(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const int o = mesh.F(t, k), i = mesh.F(t, (k + 1) % 3), j = mesh.F(t, (k + 2) % 3);
            const Eigen::Vector2d u = V.row(i) - V.row(o), w = V.row(j) - V.row(o);
            const double half = 0.5 * u.dot(w) / std::abs(u.x() * w.y() - u.y() * w.x());
            weight[std::size_t(slotOf(a, i, j))] += half;
            weight[std::size_t(slotOf(a, j, i))] += half;
        }
    }
    return weight;
}

} // namespace

void renumberInterior(geometry::CageMesh &mesh, VertexAdjacency &adjacency,
                      const std::vector<int> &order)
{
    const Eigen::Index n = mesh.V.rows(), nb = mesh.boundaryCount;
    std::vector<int> renumbered(static_cast<std::size_t>(n), 0);
    std::iota(renumbered.begin(), renumbered.begin() + nb, 0);
    for (std::size_t k = 0; k < order.size(); ++k)
        renumbered[std::size_t(order[k])] = int(nb) + int(k);
    Eigen::MatrixX2d V(n, 2);
    for (Eigen::Index v = 0; v < n; ++v)
        V.row(renumbered[std::size_t(v)]) = mesh.V.row(v);
    mesh.V = std::move(V);
    for (Eigen::Index i = 0; i < mesh.F.size(); ++i)
        mesh.F.data()[i] = renumbered[std::size_t(mesh.F.data()[i])];
    VertexAdjacency a;
    a.start.resize(std::size_t(n) + 1);
    a.neighbour.resize(adjacency.neighbour.size());
    a.start[0] = 0;
    for (Eigen::Index v = 0; v < n; ++v) {
        const int old = v < nb ? int(v) : order[std::size_t(v - nb)];
        const int begin = adjacency.start[std::size_t(old)],
                  end = adjacency.start[std::size_t(old) + 1];
        for (int p = begin; p < end; ++p)
            a.neighbour[std::size_t(a.start[std::size_t(v)] + p - begin)] =
                renumbered[std::size_t(adjacency.neighbour[std::size_t(p)])];
        a.start[std::size_t(v) + 1] = a.start[std::size_t(v)] + end - begin;
    }
    adjacency = std::move(a);
}

HarmonicSystem assembleHarmonicSystem(const geometry::CageMesh &mesh,
                                      const VertexAdjacency &adjacency, SupernodeTree tree,
                                      CageRowMatrix &W)
{
    HarmonicSystem s;
    s.tree = std::move(tree);
    const Eigen::Index n = mesh.V.rows(), nb = mesh.boundaryCount, ni = n - nb;
    const Eigen::Index c = mesh.cornerCount;
    const std::vector<double> weight = edgeWeights(mesh, adjacency);
    W = CageRowMatrix::Zero(n, c);
    for (Eigen::Index v = 0; v < nb; ++v) {
        W(v, mesh.boundaryEdge(v)) += 1.0 - mesh.boundaryParameter(v);
        W(v, (mesh.boundaryEdge(v) + 1) % c) += mesh.boundaryParameter(v);
    }

    // Column k of the lower triangle (interior vertex nb + k) holds the diagonal (Σ w over all
    // neighbours, boundary ones included), then the later-eliminated neighbours (−w).
    s.A.resize(ni, ni);
    int *outer = s.A.outerIndexPtr();
    std::vector<std::pair<int, double>> column;
    std::vector<int> rows;
    std::vector<double> values;
    rows.reserve(adjacency.neighbour.size() / 2 + std::size_t(ni));
    values.reserve(rows.capacity());
    for (Eigen::Index k = 0; k < ni; ++k) {
        const Eigen::Index v = nb + k;
        outer[k] = int(rows.size());
        column.clear();
        double diagonal = 0.0, rowSum = 0.0;
        for (int p = adjacency.start[std::size_t(v)]; p < adjacency.start[std::size_t(v) + 1];
             ++p) {
            const int u = adjacency.neighbour[std::size_t(p)];
            const double w = weight[std::size_t(p)];
            diagonal += w;
            if (u < nb) { // boundary neighbour: its hat values move to the right-hand side
                W.row(v) += w * W.row(u);
                s.negativeWeights += w < -kNegligibleWeight ? 1 : 0;
                continue;
            }
            rowSum += std::abs(w);
            if (u > v) {
                s.negativeWeights += w < -kNegligibleWeight ? 1 : 0;
                column.emplace_back(int(u - nb), -w);
            }
        }
        std::sort(column.begin(), column.end());
        rows.push_back(int(k));
        values.push_back(diagonal);
        for (const auto &[row, value] : column) {
            rows.push_back(row);
            values.push_back(value);
        }
        s.normA = std::max(s.normA, rowSum + std::abs(diagonal));
    }
    outer[ni] = int(rows.size());
    s.A.resizeNonZeros(Eigen::Index(rows.size()));
    std::copy(rows.begin(), rows.end(), s.A.innerIndexPtr());
    std::copy(values.begin(), values.end(), s.A.valuePtr());
    return s;
}

} // namespace finbook::deform::detail
