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
    outline.edgeIn.setConstant(K, -1);
    outline.edgeOut.setConstant(K, -1);
    Eigen::VectorXi edgesAt = Eigen::VectorXi::Zero(K);
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
        outline.edgeOut(outline.ends(i, 0)) = int(i);
        outline.edgeIn(outline.ends(i, 1)) = int(i);
    }
    for (int k = 0; k < K; ++k)
        if (edgesAt(k) != 2)
            outline.edgeIn(k) = outline.edgeOut(k) = -1;
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
    outline.normal = outline.bisector;
    return outline;
}

void smoothOutlineNormals(MeshOutline &outline, double window)
{
    const Eigen::Index K = outline.points.rows(), B = outline.edgeCount();
    const Eigen::VectorXd lengths = outline.e.rowwise().norm();
    for (Eigen::Index k = 0; k < K; ++k) {
        if (outline.edgeIn(k) < 0 || outline.edgeOut(k) < 0)
            continue; // pinched: keep the bisector
        Eigen::RowVector2d sum = Eigen::RowVector2d::Zero();
        // Forward along the edges leaving k, then backward along those entering it.
        for (const bool forward : {true, false}) {
            int edge = forward ? outline.edgeOut(k) : outline.edgeIn(k);
            double distance = 0.0;
            for (Eigen::Index step = 0; edge >= 0 && step < B; ++step) {
                const double weight = window > 0.0 ? 1.0 - distance / window : 0.0;
                if (step > 0 && weight <= 0.0)
                    break;
                sum += (step == 0 ? 1.0 : weight) * lengths(edge) * outline.inward.row(edge);
                distance += lengths(edge);
                const int next = outline.ends(edge, forward ? 1 : 0);
                if (next == int(k))
                    break; // around a whole small loop
                edge = forward ? outline.edgeOut(next) : outline.edgeIn(next);
            }
        }
        const double norm = sum.norm();
        if (norm > 1e-12 * std::max(1.0, lengths.maxCoeff()))
            outline.normal.row(k) = sum / norm;
    }
}

} // namespace finbook::geometry::inflate_detail
