// Boundary loops of a triangle mesh (mesh_boundary.h).
#include <finbook/geometry/mesh_boundary.h>

#include <algorithm>
#include <vector>

namespace finbook::geometry {
namespace {

// Half-edges by their start vertex, in compressed rows: those leaving v are
// target[start[v]] … target[start[v + 1] − 1], sorted.
struct Outgoing {
    std::vector<int> start, target;
    bool has(int from, int to) const
    {
        const auto first = target.begin() + start[std::size_t(from)],
                   last = target.begin() + start[std::size_t(from) + 1];
        return std::binary_search(first, last, to);
    }
};

Outgoing outgoing(const Eigen::MatrixX3i &F, int n, bool boundaryOnly, const Outgoing *all)
{
    Outgoing o;
    o.start.assign(std::size_t(n) + 1, 0);
    auto keep = [&](int a, int b) { return !boundaryOnly || !all->has(b, a); };
    for (Eigen::Index t = 0; t < F.rows(); ++t)
        for (int k = 0; k < 3; ++k)
            if (keep(F(t, k), F(t, (k + 1) % 3)))
                ++o.start[std::size_t(F(t, k)) + 1];
    for (std::size_t v = 0; v < std::size_t(n); ++v)
        o.start[v + 1] += o.start[v];
    o.target.resize(std::size_t(o.start.back()));
    std::vector<int> fill(o.start.begin(), o.start.end() - 1);
    for (Eigen::Index t = 0; t < F.rows(); ++t)
        for (int k = 0; k < 3; ++k)
            if (const int a = F(t, k), b = F(t, (k + 1) % 3); keep(a, b))
                o.target[std::size_t(fill[std::size_t(a)]++)] = b;
    for (std::size_t v = 0; v < std::size_t(n); ++v)
        std::sort(o.target.begin() + o.start[v], o.target.begin() + o.start[v + 1]);
    return o;
}

} // namespace

std::vector<Eigen::VectorXi> boundaryLoops(const Eigen::MatrixX3i &F)
{
    std::vector<Eigen::VectorXi> loops;
    if (F.rows() == 0 || F.minCoeff() < 0)
        return loops;
    const int n = F.maxCoeff() + 1;
    const Outgoing all = outgoing(F, n, false, nullptr);
    // Boundary half-edges (no twin), each used once; a vertex where several chains meet
    // hands out its edges in order of their end vertex. Loops start at the lowest vertex
    // with an unused edge.
    Outgoing next = outgoing(F, n, true, &all);
    std::vector<int> cursor(next.start.begin(), next.start.end() - 1);
    auto take = [&](int v) {
        int &at = cursor[std::size_t(v)];
        const int last = next.start[std::size_t(v) + 1];
        if (at >= last)
            return -1;
        const int to = next.target[std::size_t(at++)];
        while (at < last && next.target[std::size_t(at)] == to)
            ++at; // the same half-edge twice (inconsistent input) is one edge
        return to;
    };
    for (int first = 0; first < n; ++first) {
        while (cursor[std::size_t(first)] < next.start[std::size_t(first) + 1]) {
            std::vector<int> loop{first};
            for (int at = take(first); at >= 0 && at != first; at = take(at))
                loop.push_back(at); // an open chain (non-manifold input) keeps what was walked
            if (loop.size() >= 3)
                loops.push_back(
                    Eigen::Map<const Eigen::VectorXi>(loop.data(), Eigen::Index(loop.size())));
        }
    }
    return loops;
}

} // namespace finbook::geometry
