#include "bone_graph.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace finbook::geometry::detail {
namespace {

// Bounded Douglas–Peucker on one branch: a stretch becomes one bone when every skeleton node
// it replaces lies within min(tolerance, kBoundFraction × clearance) of it and the bone does
// not cross the contour; otherwise it splits at the node that exceeds its bound the most.
// Returns the kept positions along the branch (first and last always).
std::vector<int> boundedDouglasPeucker(const DenseGraph &g, const std::vector<int> &nodes,
                                       double tolerance, const Contours &contours,
                                       const std::vector<int> &forced)
{
    const int m = int(nodes.size());
    std::vector<char> keep(std::size_t(m), 0);
    keep.front() = keep.back() = 1;
    for (int f : forced) {
        if (f > 0 && f < m - 1)
            keep[std::size_t(f)] = 1;
    }
    std::vector<std::pair<int, int>> stack;
    for (int a = 0, b = 1; b < m; ++b) {
        if (keep[std::size_t(b)]) {
            stack.emplace_back(a, b);
            a = b;
        }
    }
    while (!stack.empty()) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        if (b - a < 2)
            continue;
        const Eigen::Vector2d &pa = g.pos[std::size_t(nodes[std::size_t(a)])];
        const Eigen::Vector2d &pb = g.pos[std::size_t(nodes[std::size_t(b)])];
        double worst = -1.0, farthest = -1.0;
        int worstAt = a + 1, farthestAt = a + 1;
        for (int i = a + 1; i < b; ++i) {
            const int v = nodes[std::size_t(i)];
            const double d = pointSegmentDistance(g.pos[std::size_t(v)], pa, pb);
            const double bound = std::min(tolerance, kBoundFraction * g.clearance[std::size_t(v)]);
            const double excess = bound > 0.0 ? d / bound : (d > 0.0 ? 1e300 : 0.0);
            if (excess > worst) {
                worst = excess;
                worstAt = i;
            }
            if (d > farthest) {
                farthest = d;
                farthestAt = i;
            }
        }
        int split = -1;
        if (worst > 1.0)
            split = worstAt;
        else if (!contours.segmentInside(g.polygon[std::size_t(nodes[std::size_t(a)])], pa, pb))
            split = farthestAt;
        if (split < 0)
            continue;
        keep[std::size_t(split)] = 1;
        stack.emplace_back(a, split);
        stack.emplace_back(split, b);
    }
    std::vector<int> kept;
    for (int i = 0; i < m; ++i) {
        if (keep[std::size_t(i)])
            kept.push_back(i);
    }
    return kept;
}

// Where a collapsed bone's two joints meet: the joint that matters more (junction, then the
// larger clearance), the other one, or the middle; the first that keeps the neighbouring
// bones inside the shape.
bool collapseBone(DenseGraph &g, int a, int b, const Contours &contours)
{
    auto better = [&](int x, int y) {
        const bool jx = isJunction(g, x), jy = isJunction(g, y);
        return jx != jy ? jx : g.clearance[std::size_t(x)] >= g.clearance[std::size_t(y)];
    };
    const int first = better(a, b) ? a : b, second = first == a ? b : a;
    std::vector<int> neighbours;
    for (int v : {a, b}) {
        for (int n : g.adj[std::size_t(v)]) {
            if (n != a && n != b)
                neighbours.push_back(n);
        }
    }
    const Eigen::Vector2d middle = 0.5 * (g.pos[std::size_t(a)] + g.pos[std::size_t(b)]);
    const std::vector<std::pair<int, Eigen::Vector2d>> places{
        {first, g.pos[std::size_t(first)]}, {second, g.pos[std::size_t(second)]}, {first, middle}};
    for (std::size_t k = 0; k < places.size(); ++k) {
        // Named copies, not a structured binding: clang 14 (the fuzz build) cannot capture one.
        const int keep = places[k].first;
        const Eigen::Vector2d &at = places[k].second;
        const double clearance =
            k == 2 ? std::min(g.clearance[std::size_t(a)], g.clearance[std::size_t(b)])
                   : g.clearance[std::size_t(keep)];
        const bool fits = std::all_of(neighbours.begin(), neighbours.end(), [&](int n) {
            return contours.boneFits(g.polygon[std::size_t(keep)], at, clearance,
                                     g.pos[std::size_t(n)], g.clearance[std::size_t(n)]);
        });
        if (!fits)
            continue;
        const int drop = keep == a ? b : a;
        if (k == 2) {
            g.radius[std::size_t(keep)] =
                0.5 * (g.radius[std::size_t(a)] + g.radius[std::size_t(b)]);
            g.clearance[std::size_t(keep)] =
                std::min(g.clearance[std::size_t(a)], g.clearance[std::size_t(b)]);
        }
        g.pos[std::size_t(keep)] = at;
        g.contract(keep, drop);
        return true;
    }
    return false;
}

} // namespace

// The bone graph: branch ends and kept branch nodes become joints.
DenseGraph bonesFromBranches(const DenseGraph &g, double tolerance, const Contours &contours,
                             const ForcedJoints &forced)
{
    DenseGraph bones;
    std::vector<int> joint(std::size_t(g.size()), -1);
    auto jointOf = [&](int v) {
        if (joint[std::size_t(v)] < 0)
            joint[std::size_t(v)] =
                bones.addNode(g.pos[std::size_t(v)], g.radius[std::size_t(v)],
                              g.clearance[std::size_t(v)], g.polygon[std::size_t(v)]);
        return joint[std::size_t(v)];
    };
    for (const Branch &branch : extractBranches(g)) {
        const std::vector<int> kept = boundedDouglasPeucker(
            g, branch.nodes, tolerance, contours, forced ? forced(branch) : std::vector<int>{});
        int previous = jointOf(branch.nodes[std::size_t(kept.front())]);
        for (std::size_t k = 1; k < kept.size(); ++k) {
            const int next = jointOf(branch.nodes[std::size_t(kept[k])]);
            bones.addEdge(previous, next);
            previous = next;
        }
    }
    return bones;
}

void collapseShortBones(DenseGraph &g, double length, double relative, const Contours &contours)
{
    if (!(length > 0.0) && !(relative > 0.0))
        return;
    std::vector<std::pair<int, int>> blocked;
    for (;;) {
        int ba = -1, bb = -1;
        double best = std::numeric_limits<double>::infinity();
        for (int a = 0; a < g.size(); ++a) {
            if (!g.alive[std::size_t(a)] || g.degree(a) < 2)
                continue;
            for (int b : g.adj[std::size_t(a)]) {
                const double l = g.length(a, b);
                const double limit =
                    std::max(length, relative * std::min(g.clearance[std::size_t(a)],
                                                         g.clearance[std::size_t(b)]));
                if (b < a || g.degree(b) < 2 || l >= limit || l >= best ||
                    std::find(blocked.begin(), blocked.end(), std::pair{a, b}) != blocked.end())
                    continue;
                best = l;
                ba = a;
                bb = b;
            }
        }
        if (ba < 0)
            return;
        if (!collapseBone(g, ba, bb, contours))
            blocked.emplace_back(ba, bb);
    }
}

} // namespace finbook::geometry::detail
