// Boundary loops of a triangle mesh (mesh_boundary.h).
#include <finbook/geometry/mesh_boundary.h>

#include <map>

namespace finbook::geometry {

std::vector<Eigen::VectorXi> boundaryLoops(const Eigen::MatrixX3i &F)
{
    std::map<std::pair<int, int>, int> halfEdges; // (from, to) → uses
    for (Eigen::Index t = 0; t < F.rows(); ++t)
        for (int k = 0; k < 3; ++k)
            ++halfEdges[{F(t, k), F(t, (k + 1) % 3)}];
    std::multimap<int, int> next; // boundary half-edges: from → to
    for (const auto &[edge, uses] : halfEdges)
        if (!halfEdges.count({edge.second, edge.first}))
            next.emplace(edge.first, edge.second);
    std::vector<Eigen::VectorXi> loops;
    while (!next.empty()) {
        const int start = next.begin()->first;
        std::vector<int> loop{start};
        int at = start;
        while (true) {
            const auto it = next.find(at);
            if (it == next.end())
                break; // an open chain (non-manifold input): keep what was walked
            at = it->second;
            next.erase(it);
            if (at == start)
                break;
            loop.push_back(at);
        }
        if (loop.size() >= 3)
            loops.push_back(
                Eigen::Map<const Eigen::VectorXi>(loop.data(), Eigen::Index(loop.size())));
    }
    return loops;
}

} // namespace finbook::geometry
