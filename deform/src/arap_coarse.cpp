// Coarse rotations: a better first iterate for drag poses of large meshes and thin drawings
// (wherever the budget holds fewer than kCoarseBelowPasses). Local/global passes remove
// short-wavelength error in a few passes but the long, smooth part of a bend's rotation field
// only slowly (at 20k vertices two passes from step 1 left 1.5× the converged energy; on thin
// 2k-vertex quickdraw drawings 49 passes left up to 4.6×).
// Grouping the triangles into K compact clusters with one rotation each gives a K-dimensional
// ARAP problem: the global step is linear in the rotations, so every cluster's covariance
// Σ conj(r)·p at the global solution is S = C·R + E·q with C (K×K) and E (K×handles) fixed
// at precompute time (one step-2 back-substitution per cluster). Its local/global iteration
// costs K² per pass, so it runs (nearly) to convergence from the solution of its convex
// relaxation; one fine global step with the cluster rotations then starts the fine passes
// from a pose whose long-wavelength error is gone.
// Everything is sequential and a function of the handles only (no state across events).
#include "arap_solver.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace finbook::deform::detail {
namespace {

// Clusters aimed for (grid cells; splitting and merging make it 12–20 on a bar, more on thin
// drawings): each costs one back-substitution at precompute time (7 ms at 100k vertices). On
// the 20k bar with two fine passes 8 left 1.15×, 16 1.13×, 24–48 1.13× the converged energy.
constexpr int kTargetClusters = 16;
// Pieces smaller than this fraction of the average cluster join a neighbour.
constexpr double kSmallPiece = 0.25;
// The change of every cluster rotation below which the reduced iterations stop early: a rigid
// motion of the pins must come out rigid to round-off (the relaxed start gives it at once);
// a bend runs all d.coarseIterations, about 0.1 ms at 16 clusters, 1 ms at 95 (200 of them).
constexpr double kCoarseTolerance = 1e-13;
// More clusters than this (many separately pinned parts, very thin strokes) would make the K²
// iterations cost more than the passes they save (95 clusters took 1 ms per event on a 16k
// octopus): such meshes start from step 1.
constexpr int kMaxClusters = 128;

int findRoot(std::vector<int> &parent, int i)
{
    while (parent[std::size_t(i)] != i) {
        parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
        i = parent[std::size_t(i)];
    }
    return i;
}

void unite(std::vector<int> &parent, int a, int b)
{
    a = findRoot(parent, a);
    b = findRoot(parent, b);
    if (a != b)
        parent[std::size_t(std::max(a, b))] = std::min(a, b); // smallest index leads
}

// Grid cells over the rest centroids, split into pieces connected through shared vertices;
// small pieces join a neighbouring piece. Returns the cluster per triangle and sets `count`.
Eigen::VectorXi clusterTriangles(const ArapPrecompute &d, int &count)
{
    const Eigen::Index m = d.triangles.rows();
    std::vector<Complex> centroid(static_cast<std::size_t>(m));
    for (Eigen::Index t = 0; t < m; ++t)
        centroid[std::size_t(t)] =
            (d.rest(d.triangles(t, 0)) + d.rest(d.triangles(t, 1)) + d.rest(d.triangles(t, 2))) /
            3.0;
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (const Complex c : centroid) {
        x0 = std::min(x0, c.real());
        x1 = std::max(x1, c.real());
        y0 = std::min(y0, c.imag());
        y1 = std::max(y1, c.imag());
    }
    // Cells sized by the mesh's own area, not its bounding box: a drawing of thin strokes
    // gets proportionally smaller cells, so fewer clusters straddle a joint that the pose
    // bends (on 20k-vertex quickdraw meshes bounding-box cells left 5–50× the converged
    // energy where these leave 1.8–11×).
    double area = 0.0;
    for (Eigen::Index t = 0; t < m; ++t)
        area += 0.5 * std::abs(d.restDoubleArea(t));
    const double cell =
        std::max({std::sqrt(std::max(area, 1e-300) / kTargetClusters), (x1 - x0) / kTargetClusters,
                  (y1 - y0) / kTargetClusters, 1e-300});
    const int columns = int((x1 - x0) / cell) + 1;
    std::vector<int> cellOf(static_cast<std::size_t>(m));
    for (Eigen::Index t = 0; t < m; ++t) {
        const Complex c = centroid[std::size_t(t)];
        const int cx = std::min(columns - 1, int((c.real() - x0) / cell));
        cellOf[std::size_t(t)] = int((c.imag() - y0) / cell) * columns + cx;
    }
    std::vector<int> parent(static_cast<std::size_t>(m));
    std::iota(parent.begin(), parent.end(), 0);
    const Eigen::Index solved = d.vertexStart.size() - 1;
    for (Eigen::Index v = 0; v < solved; ++v) {
        for (int k = d.vertexStart(v) + 1; k < d.vertexStart(v + 1); ++k) {
            const int t = d.vertexTriangle(k);
            for (int s = d.vertexStart(v); s < k; ++s) { // join with any same-cell triangle
                const int u = d.vertexTriangle(s);
                if (cellOf[std::size_t(u)] == cellOf[std::size_t(t)]) {
                    unite(parent, u, t);
                    break;
                }
            }
        }
    }
    std::vector<int> size(static_cast<std::size_t>(m), 0);
    int pieces = 0;
    for (Eigen::Index t = 0; t < m; ++t)
        pieces += size[std::size_t(findRoot(parent, int(t)))]++ == 0 ? 1 : 0;
    const double small = kSmallPiece * double(m) / std::max(1, pieces);
    for (Eigen::Index v = 0; v < solved; ++v) { // small pieces join a neighbour, in order
        for (int k = d.vertexStart(v) + 1; k < d.vertexStart(v + 1); ++k) {
            const int a = findRoot(parent, d.vertexTriangle(k)),
                      b = findRoot(parent, d.vertexTriangle(k - 1));
            if (a != b && (size[std::size_t(a)] < small || size[std::size_t(b)] < small)) {
                const int total = size[std::size_t(a)] + size[std::size_t(b)];
                unite(parent, a, b);
                size[std::size_t(findRoot(parent, a))] = total;
            }
        }
    }
    Eigen::VectorXi cluster(m);
    std::vector<int> number(static_cast<std::size_t>(m), -1);
    count = 0;
    for (Eigen::Index t = 0; t < m; ++t) {
        int &n = number[std::size_t(findRoot(parent, int(t)))];
        if (n < 0)
            n = count++;
        cluster(t) = n;
    }
    return cluster;
}

CoarseBuilder::Corners clusterCorners(const ArapPrecompute &d)
{
    const Eigen::Index solved = d.vertexStart.size() - 1;
    CoarseBuilder::Corners c;
    c.start.reserve(std::size_t(solved) + 1);
    c.start.push_back(0);
    for (Eigen::Index v = 0; v < solved; ++v) {
        const std::size_t first = c.cluster.size();
        for (int k = d.vertexStart(v); k < d.vertexStart(v + 1); ++k) {
            const int t = d.vertexTriangle(k), cluster = d.triangleCluster(t);
            const int corner = d.triangles(t, 0) == v ? 0 : d.triangles(t, 1) == v ? 1 : 2;
            const Complex a = std::conj(d.restWeighted(t, corner));
            std::size_t i = first;
            while (i < c.cluster.size() && c.cluster[i] != cluster)
                ++i;
            if (i == c.cluster.size()) {
                c.cluster.push_back(cluster);
                c.weight.push_back(a);
            } else {
                c.weight[i] += a;
            }
        }
        c.start.push_back(int(c.cluster.size()));
    }
    return c;
}

// P_k = H00⁻¹ g_k: the free positions a unit rotation of cluster k alone produces (handles
// at the origin); C(:, k) is every cluster's covariance with it, E(k, :) what the handles
// add to cluster k's covariance (−⅓ P_kᴴ H01 through the free vertices; their own corners
// are added by the caller). Clusters first … first + kBlockWidth − 1 at once (one pass over
// the factor); x holds them row by row, columns past the last cluster stay zero.
void coarseColumns(ArapPrecompute &d, const CoarseBuilder::Corners &c, int first, int count,
                   std::vector<Complex> &x)
{
    constexpr int B = kBlockWidth;
    const Eigen::Index nf = d.freeCount;
    const int last = std::min(first + B, count);
    x.assign(std::size_t(nf) * B, Complex());
    for (Eigen::Index v = 0; v < nf; ++v)
        for (int i = c.start[std::size_t(v)]; i < c.start[std::size_t(v) + 1]; ++i)
            if (const int k = c.cluster[std::size_t(i)]; k >= first && k < last)
                x[std::size_t(v * B + (k - first))] = 3.0 * std::conj(c.weight[std::size_t(i)]);
    backsubstituteBlock(d, x.data());
    for (Eigen::Index v = 0; v < nf; ++v)
        for (int i = c.start[std::size_t(v)]; i < c.start[std::size_t(v) + 1]; ++i)
            for (int k = first; k < last; ++k)
                d.coarseCoupling(c.cluster[std::size_t(i)], k) +=
                    c.weight[std::size_t(i)] * x[std::size_t(v * B + (k - first))];
    for (int k = first; k < last; ++k)
        for (Eigen::Index h = 0; h < d.coarseHandles.cols(); ++h) {
            Complex s;
            for (ArapPrecompute::RealMatrix::InnerIterator it(d.stepTwoCoupling, h); it; ++it)
                s += std::conj(x[std::size_t(it.row() * B + (k - first))]) * it.value();
            d.coarseHandles(k, h) -= s / 3.0;
        }
}

} // namespace

bool CoarseBuilder::prepare(ArapPrecompute &d)
{
    const Eigen::Index nf = d.freeCount, handles = d.handleEntry.size(), m = d.triangles.rows();
    if (nf == 0 || m == 0)
        return false;
    int count = 0;
    Eigen::VectorXi clusters = clusterTriangles(d, count);
    if (count > kMaxClusters)
        return false;
    d.triangleCluster = std::move(clusters);
    m_corners = clusterCorners(d);
    d.coarseCoupling = Eigen::MatrixXcd::Zero(count, count);
    d.coarseHandles = Eigen::MatrixXcd::Zero(count, handles);
    d.coarseThreshold = Eigen::VectorXd::Zero(count);
    for (Eigen::Index t = 0; t < m; ++t)
        d.coarseThreshold(d.triangleCluster(t)) += d.collapseThreshold(t);
    for (Eigen::Index h = 0; h < handles; ++h) { // the handles' own corners
        const auto first = m_corners.start[std::size_t(nf + h)],
                   last = m_corners.start[std::size_t(nf + h) + 1];
        for (int i = first; i < last; ++i)
            d.coarseHandles(m_corners.cluster[std::size_t(i)], h) +=
                m_corners.weight[std::size_t(i)];
    }
    m_count = count;
    return true;
}

void CoarseBuilder::columns(ArapPrecompute &d, int first, std::vector<Complex> &x) const
{
    coarseColumns(d, m_corners, first, m_count, x);
}

void CoarseBuilder::finish(ArapPrecompute &d) const
{
    // The start of the reduced iterations: clusters as similarities (scaled rotations), the
    // convex relaxation of the clustered problem, as step 1 is of the fine one. Its energy
    // 3·Σ_k (ρ_k |R_k|² − 2 Re(conj(R_k) S_k)) + … with S = C R + E q is stationary where
    // (diag(ρ) − C) R = E q.
    Eigen::MatrixXcd relaxed = -d.coarseCoupling;
    for (Eigen::Index t = 0; t < d.triangles.rows(); ++t)
        relaxed(d.triangleCluster(t), d.triangleCluster(t)) += d.restSquaredNorm(t) / 3.0;
    const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(relaxed);
    d.coarseSimilarity = lu.inverse();
    if (!d.coarseSimilarity.allFinite())
        d.coarseSimilarity.resize(0, 0); // start from the harmonic covariance instead
}

void coarseStart(const ArapPrecompute &d, Workspace &w)
{
    const Eigen::Index nf = d.freeCount, handles = d.handleEntry.size();
    const Eigen::Index count = d.coarseCoupling.rows();
    auto &R = w.coarseRotations, &S = w.coarseCovariance, &e = w.coarseHandleTerm;
    e.noalias() = d.coarseHandles * w.positions.segment(nf, handles);
    // Start from the relaxed problem's solution (clusters as similarities), normalized by the
    // first local step; without it (singular relaxation) from R = 0, where S = E·q is the
    // covariance of the handles' harmonic extension. On thin quickdraw meshes of 16–20k
    // vertices the relaxed start left 1.8–11× the converged energy, R = 0 5–330×: the
    // clustered problem has poor local minima that plain iterations from R = 0 fall into.
    R = Eigen::VectorXcd::Ones(count);
    if (d.coarseSimilarity.rows() == count)
        S.noalias() = d.coarseSimilarity * e;
    else
        S = e;
    for (int iteration = 0; iteration < d.coarseIterations; ++iteration) {
        double change = 0.0;
        for (Eigen::Index k = 0; k < count; ++k) {
            const double squared = squaredMagnitude(S(k));
            if (!(squared > d.coarseThreshold(k) * d.coarseThreshold(k)))
                continue; // collapsed: keep what it had
            const Complex r = S(k) / std::sqrt(squared);
            change = std::max(change, squaredMagnitude(r - R(k)));
            R(k) = r;
        }
        if (iteration > 0 && change <= kCoarseTolerance * kCoarseTolerance)
            break;
        S.noalias() = d.coarseCoupling * R;
        S += e;
    }
    const int *cluster = d.triangleCluster.data();
    for (Eigen::Index t = 0; t < d.triangles.rows(); ++t)
        w.rotations(t) = 3.0 * R(cluster[t]);
    globalStep(d, w);
}

} // namespace finbook::deform::detail
