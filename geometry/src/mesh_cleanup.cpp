#include "mesh_cleanup.h"

#include <finbook/geometry/mesh_quality.h>

#include <numeric>
#include <vector>

namespace finbook::geometry::detail {
namespace {

int findRoot(std::vector<int> &parent, int i)
{
    while (parent[std::size_t(i)] != i) {
        parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
        i = parent[std::size_t(i)];
    }
    return i;
}

// CSR lists of the faces around each vertex.
void vertexFaces(const Eigen::MatrixX3i &F, Eigen::Index n, std::vector<int> &start,
                 std::vector<int> &faces)
{
    start.assign(std::size_t(n) + 1, 0);
    for (Eigen::Index f = 0; f < F.rows(); ++f)
        for (int k = 0; k < 3; ++k)
            ++start[std::size_t(F(f, k)) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    faces.assign(std::size_t(start.back()), 0);
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (Eigen::Index f = 0; f < F.rows(); ++f)
        for (int k = 0; k < 3; ++k)
            faces[std::size_t(fill[std::size_t(F(f, k))]++)] = int(f);
}

} // namespace

void dropDegenerate(Eigen::MatrixX2d &V, Eigen::MatrixX3i &F)
{
    const Eigen::VectorXd areas = triangleSignedAreas(V, F);
    std::vector<int> keep;
    for (Eigen::Index f = 0; f < F.rows(); ++f)
        if (areas(f) > 0.0)
            keep.push_back(int(f));
    Eigen::MatrixX3i kept(Eigen::Index(keep.size()), 3);
    for (std::size_t i = 0; i < keep.size(); ++i)
        kept.row(Eigen::Index(i)) = F.row(keep[i]);
    std::vector<int> remap(std::size_t(V.rows()), -1);
    int next = 0;
    for (Eigen::Index f = 0; f < kept.rows(); ++f)
        for (int k = 0; k < 3; ++k) {
            int &r = remap[std::size_t(kept(f, k))];
            if (r < 0)
                r = next++;
            kept(f, k) = r;
        }
    Eigen::MatrixX2d compact(next, 2);
    for (std::size_t v = 0; v < remap.size(); ++v)
        if (remap[v] >= 0)
            compact.row(remap[v]) = V.row(Eigen::Index(v));
    V = std::move(compact);
    F = std::move(kept);
}

void splitNonManifoldVertices(Eigen::MatrixX2d &V, Eigen::MatrixX3i &F)
{
    std::vector<int> start, faces;
    vertexFaces(F, V.rows(), start, faces);
    std::vector<Eigen::RowVector2d> extra;
    const Eigen::Index n = V.rows();
    for (Eigen::Index v = 0; v < n; ++v) {
        const int begin = start[std::size_t(v)], count = start[std::size_t(v) + 1] - begin;
        std::vector<int> parent(static_cast<std::size_t>(count));
        std::iota(parent.begin(), parent.end(), 0);
        // Two faces around v belong to one fan when they share an edge (v, w).
        for (int i = 0; i < count; ++i)
            for (int j = i + 1; j < count; ++j) {
                const auto fi = F.row(faces[std::size_t(begin + i)]);
                const auto fj = F.row(faces[std::size_t(begin + j)]);
                int shared = 0;
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b)
                        shared += (fi(a) == fj(b)) ? 1 : 0;
                if (shared >= 2)
                    parent[std::size_t(findRoot(parent, i))] = findRoot(parent, j);
            }
        std::vector<int> copyOfRoot(static_cast<std::size_t>(count), -1);
        const int firstRoot = count > 0 ? findRoot(parent, 0) : 0;
        for (int i = 0; i < count; ++i) {
            const int root = findRoot(parent, i);
            if (root == firstRoot)
                continue;
            int &copy = copyOfRoot[std::size_t(root)];
            if (copy < 0) {
                copy = int(n + Eigen::Index(extra.size()));
                extra.push_back(V.row(v));
            }
            for (int k = 0; k < 3; ++k)
                if (F(faces[std::size_t(begin + i)], k) == int(v))
                    F(faces[std::size_t(begin + i)], k) = copy;
        }
    }
    if (extra.empty())
        return;
    V.conservativeResize(n + Eigen::Index(extra.size()), 2);
    for (std::size_t i = 0; i < extra.size(); ++i)
        V.row(n + Eigen::Index(i)) = extra[i];
}

} // namespace finbook::geometry::detail
