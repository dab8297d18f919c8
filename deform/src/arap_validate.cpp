#include "arap_internal.h"

#include <numeric>
#include <vector>

namespace finbook::deform::detail {
namespace {

// A triangle whose area is this small relative to its longest edge squared has (numerically)
// collinear corners; its local frame in step 1 would be meaningless.
constexpr double kMinRelativeArea = 1e-12;

std::optional<DeformError> validateTriangle(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                            Eigen::Index t)
{
    const Eigen::Vector2d a = V.row(F(t, 0)), b = V.row(F(t, 1)), c = V.row(F(t, 2));
    const Eigen::Vector2d ab = b - a, ac = c - a, bc = c - b;
    const double cross = ab.x() * ac.y() - ab.y() * ac.x();
    const double longest = std::max({ab.squaredNorm(), ac.squaredNorm(), bc.squaredNorm()});
    if (F(t, 0) == F(t, 1) || F(t, 1) == F(t, 2) || F(t, 0) == F(t, 2) ||
        !(std::abs(cross) > kMinRelativeArea * longest))
        return makeError(DeformErrorCode::DegenerateTriangle,
                         "triangle " + std::to_string(t) + " has zero area");
    return std::nullopt;
}

// A vertex where two fans of triangles touch only at that point: its k open fans have
// k more distinct neighbours than triangles. Step 1 could rotate and scale one fan about the
// vertex at no cost, so such meshes are refused (geometry's meshes split these vertices).
int pinchedVertex(Eigen::Index n, const Eigen::MatrixX3i &F)
{
    const VertexRings rings = vertexRings(n, F);
    const std::vector<int> &start = rings.start, &triangle = rings.triangle;
    std::vector<int> seenBy(static_cast<std::size_t>(n), -1);
    for (int v = 0; v < n; ++v) {
        int neighbours = 0;
        for (int c = start[v]; c < start[v + 1]; ++c) {
            for (int k = 0; k < 3; ++k) {
                const int w = F(triangle[c], k);
                if (w != v && seenBy[w] != v) {
                    seenBy[w] = v;
                    ++neighbours;
                }
            }
        }
        if (neighbours - (start[v + 1] - start[v]) >= 2)
            return v;
    }
    return -1;
}

} // namespace

VertexRings vertexRings(Eigen::Index n, const Eigen::MatrixX3i &F)
{
    VertexRings rings;
    rings.start.assign(std::size_t(n) + 1, 0);
    for (Eigen::Index t = 0; t < F.rows(); ++t)
        for (int k = 0; k < 3; ++k)
            ++rings.start[std::size_t(F(t, k)) + 1];
    std::partial_sum(rings.start.begin(), rings.start.end(), rings.start.begin());
    rings.triangle.resize(std::size_t(3 * F.rows()));
    rings.corner.resize(rings.triangle.size());
    std::vector<int> next(rings.start.begin(), rings.start.end() - 1);
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const auto at = std::size_t(next[std::size_t(F(t, k))]++);
            rings.triangle[at] = int(t);
            rings.corner[at] = k;
        }
    }
    return rings;
}

std::optional<DeformError> validateArapInput(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                             const Eigen::VectorXi &b)
{
    if (V.rows() == 0 || F.rows() == 0)
        return makeError(DeformErrorCode::EmptyMesh, "the mesh has no triangles");
    if (!V.allFinite())
        return makeError(DeformErrorCode::NonFiniteInput, "a rest position is not a finite number");
    if (V.size() > 0 && V.cwiseAbs().maxCoeff() > kMaxDeformCoordinate)
        return makeError(DeformErrorCode::CoordinateOutOfRange, "a rest position is too large");
    const auto n = static_cast<int>(V.rows());
    if (V.rows() != n)
        return makeError(DeformErrorCode::InvalidIndex, "too many vertices");
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        for (int k = 0; k < 3; ++k) {
            if (F(t, k) < 0 || F(t, k) >= n)
                return makeError(DeformErrorCode::InvalidIndex,
                                 "triangle " + std::to_string(t) + " refers to vertex " +
                                     std::to_string(F(t, k)) + " of " + std::to_string(n));
        }
        if (auto error = validateTriangle(V, F, t))
            return error;
    }
    if (const int v = pinchedVertex(n, F); v >= 0)
        return makeError(DeformErrorCode::NonManifoldVertex,
                         "the mesh is pinched at vertex " + std::to_string(v) +
                             ": two fans of triangles meet only there");
    for (Eigen::Index e = 0; e < b.size(); ++e) {
        if (b(e) < 0 || b(e) >= n)
            return makeError(DeformErrorCode::InvalidIndex, "pin " + std::to_string(e) +
                                                                " refers to vertex " +
                                                                std::to_string(b(e)));
    }
    return std::nullopt;
}

Eigen::VectorXi componentLabels(Eigen::Index vertexCount, const Eigen::MatrixX3i &F, int &count)
{
    // Union-find with path halving: near-linear and allocation-light at 100k vertices.
    std::vector<int> parent(static_cast<std::size_t>(vertexCount));
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&parent](int v) {
        while (parent[v] != v) {
            parent[v] = parent[parent[v]];
            v = parent[v];
        }
        return v;
    };
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        for (int k = 1; k < 3; ++k) {
            const int a = find(F(t, 0)), c = find(F(t, k));
            if (a != c)
                parent[std::max(a, c)] = std::min(a, c);
        }
    }
    Eigen::VectorXi labels(vertexCount);
    std::vector<int> rootLabel(static_cast<std::size_t>(vertexCount), -1);
    count = 0;
    for (Eigen::Index v = 0; v < vertexCount; ++v) {
        int &label = rootLabel[find(static_cast<int>(v))];
        if (label < 0)
            label = count++;
        labels(v) = label;
    }
    return labels;
}

} // namespace finbook::deform::detail
