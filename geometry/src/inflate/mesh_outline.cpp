#include "mesh_outline.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace finbook::geometry::inflate_detail {
namespace {

using Edge = std::pair<int, int>;

std::vector<Edge> boundaryEdges(const Eigen::MatrixX3i &F)
{
    std::vector<Edge> directed;
    directed.reserve(std::size_t(F.rows()) * 3);
    for (Eigen::Index f = 0; f < F.rows(); ++f)
        for (int k = 0; k < 3; ++k)
            directed.emplace_back(F(f, k), F(f, (k + 1) % 3));
    std::vector<Edge> sorted = directed;
    std::sort(sorted.begin(), sorted.end());
    std::vector<Edge> boundary;
    for (const Edge &edge : directed)
        if (!std::binary_search(sorted.begin(), sorted.end(), Edge(edge.second, edge.first)))
            boundary.push_back(edge);
    return boundary;
}

Eigen::RowVector2d leftNormal(const Eigen::RowVector2d &e)
{
    const double length = e.norm();
    return length > 0.0 ? Eigen::RowVector2d(-e.y() / length, e.x() / length)
                        : Eigen::RowVector2d(0.0, 0.0);
}

} // namespace

MeshOutline meshOutline(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F)
{
    const std::vector<Edge> edges = boundaryEdges(F);
    MeshOutline outline;
    const auto B = Eigen::Index(edges.size());
    outline.a.resize(B, 2);
    outline.e.resize(B, 2);
    outline.inward.resize(B, 2);
    outline.invLength2.resize(B);
    outline.ends.resize(B, 2);
    outline.slot.assign(std::size_t(V.rows()), -1);
    int K = 0;
    for (const Edge &edge : edges)
        for (int v : {edge.first, edge.second})
            if (outline.slot[std::size_t(v)] < 0)
                outline.slot[std::size_t(v)] = K++;
    outline.points.resize(K, 2);
    outline.bisector.setZero(K, 2);
    // Per outline vertex: edges in and out, and the turn (cross product of in and out).
    Eigen::VectorXi edgesAt = Eigen::VectorXi::Zero(K);
    Eigen::MatrixX2d in = Eigen::MatrixX2d::Zero(K, 2), out = Eigen::MatrixX2d::Zero(K, 2);
    for (Eigen::Index i = 0; i < B; ++i) {
        const auto [from, to] = edges[std::size_t(i)];
        const Eigen::RowVector2d e = V.row(to) - V.row(from);
        const double length2 = e.squaredNorm();
        outline.a.row(i) = V.row(from);
        outline.e.row(i) = e;
        outline.inward.row(i) = leftNormal(e);
        outline.invLength2(i) = length2 > 0.0 ? 1.0 / length2 : 0.0;
        outline.ends.row(i) << outline.slot[std::size_t(from)], outline.slot[std::size_t(to)];
        for (int v : {from, to}) {
            const int k = outline.slot[std::size_t(v)];
            outline.points.row(k) = V.row(v);
            outline.bisector.row(k) += outline.inward.row(i);
            ++edgesAt(k);
        }
        out.row(outline.slot[std::size_t(from)]) = e;
        in.row(outline.slot[std::size_t(to)]) = e;
    }
    outline.convex.resize(K);
    outline.turnCos.resize(K);
    for (int k = 0; k < K; ++k) {
        const double lengths = in.row(k).norm() * out.row(k).norm();
        outline.turnCos(k) =
            edgesAt(k) == 2 && lengths > 0.0 ? in.row(k).dot(out.row(k)) / lengths : -1.0;
        outline.convex(k) =
            edgesAt(k) == 2 && in(k, 0) * out(k, 1) - in(k, 1) * out(k, 0) > 0.0 ? 1 : 0;
    }
    // Normals of the two edges at a vertex sum to its inward bisector. A hairpin (edges folding
    // back) cancels them: then any edge's normal is the best guess, and the vertex is a tip.
    for (Eigen::Index i = 0; i < B; ++i) {
        for (int v : {edges[std::size_t(i)].first, edges[std::size_t(i)].second}) {
            const int k = outline.slot[std::size_t(v)];
            const double length = outline.bisector.row(k).norm();
            if (length > 1e-9)
                continue;
            const Eigen::RowVector2d along = v == edges[std::size_t(i)].first
                                                 ? outline.e.row(i)
                                                 : Eigen::RowVector2d(-outline.e.row(i));
            const double alongLength = along.norm();
            outline.bisector.row(k) =
                alongLength > 0.0 ? Eigen::RowVector2d(along / alongLength) : outline.inward.row(i);
        }
    }
    for (int k = 0; k < K; ++k) {
        const double length = outline.bisector.row(k).norm();
        if (length > 0.0)
            outline.bisector.row(k) /= length;
        else
            outline.bisector.row(k) << 1.0, 0.0;
    }
    return outline;
}

} // namespace finbook::geometry::inflate_detail
