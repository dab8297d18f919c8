// Measures of a posed limb for `finbook-bench limbs`: the limbs of an automatic skeleton,
// self-crossings of a deformed outline, flipped triangles, area kept near a pivot and how far
// the rest of the body moved.
#pragma once

#include <finbook/geometry/skeleton/skeleton.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>
#include <vector>

namespace finbook::bench {

// A limb: the bones from its base joint out to a tip. `first` is the limb's first bone (the
// joint whose angle turns it about `base`), `joints` every joint the turn moves.
struct Limb {
    int tip = -1, base = -1, first = -1;
    std::vector<int> joints;
};

// Every tip whose chain up to the nearest junction (or the root) runs along parent links;
// the base is the joint on that chain the skeleton marks as a limb base nearest the tip (where
// the Bone tool turns the limb when its tip is dragged); without a mark, the first joint below
// that junction when it is already narrower than the junction (the joint where the limb
// leaves the body), else the junction.
inline std::vector<Limb> findLimbs(const geometry::Skeleton &s)
{
    const Eigen::VectorXi degree = geometry::jointDegrees(s);
    const std::vector<std::vector<int>> children = geometry::jointChildren(s);
    std::vector<Limb> limbs;
    for (int t = 0; t < s.jointCount(); ++t) {
        if (degree(t) != 1 || s.parent(t) < 0)
            continue;
        std::vector<int> chain{t};
        while (s.parent(chain.back()) >= 0 && degree(chain.back()) <= 2 &&
               (chain.size() == 1 || degree(chain.back()) == 2))
            chain.push_back(s.parent(chain.back()));
        const int junction = chain.back();
        if (chain.size() < 2)
            continue;
        Limb limb;
        limb.tip = t;
        limb.base = junction;
        limb.first = chain[chain.size() - 2];
        const auto marked = s.limbBase.empty()
                                ? chain.end()
                                : std::find_if(chain.begin() + 1, chain.end(),
                                               [&](int j) { return s.limbBase[std::size_t(j)]; });
        if (marked != chain.end()) {
            limb.base = *marked;
            limb.first = *(marked - 1);
        } else if (chain.size() >= 3 && degree(junction) >= 3 &&
                   s.radius(limb.first) < 0.8 * s.radius(junction)) {
            limb.base = limb.first;
            limb.first = chain[chain.size() - 3];
        }
        std::vector<int> stack{limb.first};
        while (!stack.empty()) {
            const int j = stack.back();
            stack.pop_back();
            limb.joints.push_back(j);
            for (int c : children[std::size_t(j)])
                stack.push_back(c);
        }
        limbs.push_back(std::move(limb));
    }
    return limbs;
}

inline double signedTriangleArea(const Eigen::MatrixX2d &P, const Eigen::MatrixX3i &F,
                                 Eigen::Index t)
{
    const Eigen::RowVector2d a = P.row(F(t, 1)) - P.row(F(t, 0));
    const Eigen::RowVector2d b = P.row(F(t, 2)) - P.row(F(t, 0));
    return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

// Edges used by one triangle: the outline.
inline std::vector<std::pair<int, int>> boundaryEdges(const Eigen::MatrixX3i &F)
{
    std::map<std::pair<int, int>, int> count;
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const int a = F(t, k), b = F(t, (k + 1) % 3);
            ++count[{std::min(a, b), std::max(a, b)}];
        }
    }
    std::vector<std::pair<int, int>> edges;
    for (const auto &[e, n] : count) {
        if (n == 1)
            edges.push_back(e);
    }
    return edges;
}

inline bool properlyCross(const Eigen::Vector2d &a, const Eigen::Vector2d &b,
                          const Eigen::Vector2d &c, const Eigen::Vector2d &d)
{
    auto orient = [](const Eigen::Vector2d &o, const Eigen::Vector2d &p, const Eigen::Vector2d &q) {
        return (p - o).x() * (q - o).y() - (p - o).y() * (q - o).x();
    };
    const double d1 = orient(a, b, c), d2 = orient(a, b, d);
    const double d3 = orient(c, d, a), d4 = orient(c, d, b);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 &&
           d4 != 0;
}

// Pairs of outline edges (indices into E) without a common vertex that cross, found through a
// uniform grid.
inline std::vector<std::pair<int, int>> outlineCrossings(const Eigen::MatrixX2d &U,
                                                         const std::vector<std::pair<int, int>> &E)
{
    if (E.empty())
        return {};
    double mean = 0.0;
    for (const auto &[a, b] : E)
        mean += (U.row(a) - U.row(b)).norm();
    const double cell = std::max(1e-9, 2.0 * mean / double(E.size()));
    std::unordered_map<long long, std::vector<int>> grid;
    auto key = [](long long x, long long y) { return x * 1000003LL + y; };
    for (std::size_t e = 0; e < E.size(); ++e) {
        const Eigen::RowVector2d p = U.row(E[e].first), q = U.row(E[e].second);
        const long long x0 = (long long)std::floor(std::min(p.x(), q.x()) / cell);
        const long long x1 = (long long)std::floor(std::max(p.x(), q.x()) / cell);
        const long long y0 = (long long)std::floor(std::min(p.y(), q.y()) / cell);
        const long long y1 = (long long)std::floor(std::max(p.y(), q.y()) / cell);
        for (long long x = x0; x <= x1; ++x) {
            for (long long y = y0; y <= y1; ++y)
                grid[key(x, y)].push_back(int(e));
        }
    }
    std::vector<std::pair<int, int>> found;
    for (const auto &[k, list] : grid) {
        for (std::size_t i = 0; i < list.size(); ++i) {
            for (std::size_t j = i + 1; j < list.size(); ++j) {
                const auto &e = E[std::size_t(list[i])], &f = E[std::size_t(list[j])];
                if (e.first == f.first || e.first == f.second || e.second == f.first ||
                    e.second == f.second)
                    continue;
                if (properlyCross(U.row(e.first).transpose(), U.row(e.second).transpose(),
                                  U.row(f.first).transpose(), U.row(f.second).transpose()))
                    found.emplace_back(std::min(list[i], list[j]), std::max(list[i], list[j]));
            }
        }
    }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
}

// The drawing's outline as oriented edges (a → b as its triangle runs): the boundary of the
// mesh F, moved onto the vertices of `moved` (the same triangles, vertices copied along cuts,
// deform::cutAtJoints; moved = F for an uncut mesh). Where the outline passes from one piece
// to the next, a chord joins the two copies of its vertex, as the drawing's lines do.
inline std::vector<std::pair<int, int>> drawingOutline(const Eigen::MatrixX3i &F,
                                                       const Eigen::MatrixX3i &moved)
{
    std::map<std::pair<int, int>, int> count;
    for (Eigen::Index t = 0; t < F.rows(); ++t)
        for (int k = 0; k < 3; ++k) {
            const int a = F(t, k), b = F(t, (k + 1) % 3);
            ++count[{std::min(a, b), std::max(a, b)}];
        }
    std::vector<std::pair<int, int>> out;
    std::map<int, int> into, from; // rest vertex → its copy at the end / start of an edge
    for (Eigen::Index t = 0; t < F.rows(); ++t)
        for (int k = 0; k < 3; ++k) {
            const int a = F(t, k), b = F(t, (k + 1) % 3);
            if (count[{std::min(a, b), std::max(a, b)}] != 1)
                continue;
            out.emplace_back(moved(t, k), moved(t, (k + 1) % 3));
            into[b] = moved(t, (k + 1) % 3);
            from[a] = moved(t, k);
        }
    for (const auto &[v, copy] : into) {
        const auto next = from.find(v);
        if (next != from.end() && next->second != copy)
            out.emplace_back(copy, next->second);
    }
    return out;
}

// Area (px², sampled on a grid of `samples`² points) of the disk of `radius` around c that the
// oriented outline E over P covers by the non-zero rule: what the drawing fills there.
inline double coveredArea(const Eigen::MatrixX2d &P, const std::vector<std::pair<int, int>> &E,
                          const Eigen::Vector2d &c, double radius, int samples = 48)
{
    const double step = 2.0 * radius / samples;
    int covered = 0;
    std::vector<std::pair<double, int>> hits;
    for (int row = 0; row < samples; ++row) {
        const double y = c.y() - radius + (row + 0.5) * step;
        hits.clear();
        for (const auto &[a, b] : E) {
            const double ya = P(a, 1), yb = P(b, 1);
            if ((ya <= y) == (yb <= y))
                continue;
            const double x = P(a, 0) + (y - ya) / (yb - ya) * (P(b, 0) - P(a, 0));
            hits.emplace_back(x, ya <= y ? 1 : -1);
        }
        for (int col = 0; col < samples; ++col) {
            const double x = c.x() - radius + (col + 0.5) * step;
            if ((x - c.x()) * (x - c.x()) + (y - c.y()) * (y - c.y()) > radius * radius)
                continue;
            int winding = 0;
            for (const auto &[hx, sign] : hits)
                winding += hx > x ? sign : 0;
            covered += winding != 0 ? 1 : 0;
        }
    }
    return covered * step * step;
}

} // namespace finbook::bench
