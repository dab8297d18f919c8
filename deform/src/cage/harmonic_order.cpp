#include "harmonic_internal.h"

#include <algorithm>
#include <numeric>

namespace finbook::deform::detail {
namespace {

// Below this many vertices a part is eliminated as it comes: its fill is negligible.
constexpr std::size_t kLeafSize = 8;

struct Dissector {
    const Eigen::MatrixX2d &V;
    const VertexAdjacency &adjacency;
    std::vector<unsigned char> side; // per vertex: 0 elsewhere, 1 lower half, 2 upper half
    Dissection result;

    // Appends [begin, end) to the order as one supernode with the given children.
    int addNode(const int *begin, const int *end, std::vector<int> children)
    {
        SupernodeTree::Node node;
        node.first = int(result.order.size());
        node.size = int(end - begin);
        node.children = std::move(children);
        result.order.insert(result.order.end(), begin, end);
        result.tree.nodes.push_back(std::move(node));
        return int(result.tree.nodes.size()) - 1;
    }

    bool touchesUpper(int v) const
    {
        for (int p = adjacency.start[std::size_t(v)]; p < adjacency.start[std::size_t(v) + 1]; ++p)
            if (side[std::size_t(adjacency.neighbour[std::size_t(p)])] == 2)
                return true;
        return false;
    }

    // Orders the vertices [begin, end) (rearranging them in place) and returns their node.
    int split(int *begin, int *end)
    {
        if (std::size_t(end - begin) <= kLeafSize)
            return addNode(begin, end, {});
        Eigen::Vector2d lo = V.row(*begin), hi = lo;
        for (const int *v = begin; v != end; ++v) {
            lo = lo.cwiseMin(V.row(*v).transpose());
            hi = hi.cwiseMax(V.row(*v).transpose());
        }
        const double *coordinate = V.col((hi - lo).x() >= (hi - lo).y() ? 0 : 1).data();
        int *middle = begin + (end - begin) / 2;
        std::nth_element(begin, middle, end,
                         [&](int a, int b) { return coordinate[a] < coordinate[b]; });
        for (int *v = begin; v != end; ++v)
            side[std::size_t(*v)] = v < middle ? 1 : 2;
        // One-sided separator: the lower half's vertices with a neighbour in the upper half,
        // moved to [separator, middle).
        int *separator = std::partition(begin, middle, [&](int v) { return !touchesUpper(v); });
        for (int *v = begin; v != end; ++v)
            side[std::size_t(*v)] = 0;
        std::vector<int> children;
        if (separator != begin)
            children.push_back(split(begin, separator));
        children.push_back(split(middle, end));
        return addNode(separator, middle, std::move(children));
    }
};

} // namespace

VertexAdjacency vertexAdjacency(Eigen::Index vertexCount, const Eigen::MatrixX3i &F)
{
    VertexAdjacency a;
    std::vector<int> start(std::size_t(vertexCount) + 1, 0);
    for (Eigen::Index t = 0; t < F.rows(); ++t)
        for (int k = 0; k < 3; ++k)
            start[std::size_t(F(t, k)) + 1] += 2;
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<int> all(std::size_t(start.back()));
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const auto v = std::size_t(F(t, k));
            all[std::size_t(fill[v]++)] = F(t, (k + 1) % 3);
            all[std::size_t(fill[v]++)] = F(t, (k + 2) % 3);
        }
    }
    // Interior edges are listed twice (once per triangle): sort each short list, drop repeats.
    a.start.assign(std::size_t(vertexCount) + 1, 0);
    a.neighbour.reserve(all.size() / 2 + std::size_t(vertexCount));
    for (std::size_t v = 0; v < std::size_t(vertexCount); ++v) {
        const auto begin = all.begin() + start[v], end = all.begin() + start[v + 1];
        std::sort(begin, end);
        a.neighbour.insert(a.neighbour.end(), begin, std::unique(begin, end));
        a.start[v + 1] = int(a.neighbour.size());
    }
    return a;
}

Dissection nestedDissection(const Eigen::MatrixX2d &V, const VertexAdjacency &adjacency,
                            Eigen::Index first)
{
    Dissector d{V, adjacency, std::vector<unsigned char>(std::size_t(V.rows()), 0), {}};
    std::vector<int> part(std::size_t(V.rows() - first));
    std::iota(part.begin(), part.end(), int(first));
    d.result.order.reserve(part.size());
    if (!part.empty())
        d.split(part.data(), part.data() + part.size());
    return std::move(d.result);
}

} // namespace finbook::deform::detail
