#include "dense_graph.h"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace finbook::geometry::detail {

int DenseGraph::addNode(const Eigen::Vector2d &p, double r, double c, int poly)
{
    pos.push_back(p);
    radius.push_back(r);
    clearance.push_back(c);
    polygon.push_back(poly);
    adj.emplace_back();
    alive.push_back(1);
    return int(pos.size()) - 1;
}

void DenseGraph::addEdge(int a, int b)
{
    if (a == b)
        return;
    std::vector<int> &na = adj[std::size_t(a)];
    if (std::find(na.begin(), na.end(), b) != na.end())
        return;
    na.push_back(b);
    adj[std::size_t(b)].push_back(a);
}

void DenseGraph::removeEdge(int a, int b)
{
    std::erase(adj[std::size_t(a)], b);
    std::erase(adj[std::size_t(b)], a);
}

void DenseGraph::removeNode(int v)
{
    for (int n : adj[std::size_t(v)])
        std::erase(adj[std::size_t(n)], v);
    adj[std::size_t(v)].clear();
    alive[std::size_t(v)] = 0;
}

void DenseGraph::contract(int keep, int drop)
{
    const std::vector<int> neighbours = adj[std::size_t(drop)];
    removeNode(drop);
    for (int n : neighbours) {
        if (n != keep)
            addEdge(keep, n);
    }
}

namespace {

// Junctions are where limbs meet and tips are how far they reach; a node along a limb can move.
int rank(const DenseGraph &g, int v)
{
    const int d = g.degree(v);
    return d >= 3 ? 2 : (d == 1 ? 1 : 0);
}

double scaleOf(const DenseGraph &g)
{
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = -lo;
    for (int v = 0; v < g.size(); ++v) {
        if (g.alive[std::size_t(v)]) {
            lo = lo.cwiseMin(g.pos[std::size_t(v)]);
            hi = hi.cwiseMax(g.pos[std::size_t(v)]);
        }
    }
    return hi.x() >= lo.x() ? (hi - lo).norm() : 0.0;
}

void collapseEdge(DenseGraph &g, int a, int b)
{
    const int ra = rank(g, a), rb = rank(g, b);
    const bool keepA =
        ra != rb ? ra > rb : g.clearance[std::size_t(a)] >= g.clearance[std::size_t(b)];
    if (keepA)
        g.contract(a, b);
    else
        g.contract(b, a);
}

} // namespace

void collapseShortEdges(DenseGraph &graph, double fraction)
{
    const double tiny = 1e-9 * scaleOf(graph);
    for (;;) {
        double best = 0.0;
        int ba = -1, bb = -1;
        for (int a = 0; a < graph.size(); ++a) {
            for (int b : graph.adj[std::size_t(a)]) {
                if (b < a)
                    continue;
                const double len = graph.length(a, b);
                const double limit =
                    std::max(tiny, fraction * std::min(graph.clearance[std::size_t(a)],
                                                       graph.clearance[std::size_t(b)]));
                if (len <= limit && (ba < 0 || len < best)) {
                    best = len;
                    ba = a;
                    bb = b;
                }
            }
        }
        if (ba < 0)
            return;
        collapseEdge(graph, ba, bb);
    }
}

void breakCycles(DenseGraph &graph)
{
    std::vector<std::tuple<double, int, int>> edges;
    for (int a = 0; a < graph.size(); ++a) {
        for (int b : graph.adj[std::size_t(a)]) {
            if (b > a)
                edges.emplace_back(
                    std::min(graph.clearance[std::size_t(a)], graph.clearance[std::size_t(b)]), a,
                    b);
        }
    }
    std::sort(edges.begin(), edges.end(), [](const auto &x, const auto &y) {
        return std::get<0>(x) != std::get<0>(y) ? std::get<0>(x) > std::get<0>(y) : x < y;
    });
    std::vector<int> root(std::size_t(graph.size()));
    std::iota(root.begin(), root.end(), 0);
    auto find = [&](int v) {
        while (root[std::size_t(v)] != v)
            v = root[std::size_t(v)] = root[std::size_t(root[std::size_t(v)])];
        return v;
    };
    for (const auto &[w, a, b] : edges) {
        const int ra = find(a), rb = find(b);
        if (ra == rb)
            graph.removeEdge(a, b);
        else
            root[std::size_t(ra)] = rb;
    }
}

std::vector<int> terminalPath(const DenseGraph &g, int tip, int &end)
{
    std::vector<int> path{tip};
    int prev = -1, cur = tip;
    for (;;) {
        int next = -1;
        for (int n : g.adj[std::size_t(cur)]) {
            if (n != prev)
                next = n;
        }
        if (next < 0) {
            end = -1;
            return path;
        }
        if (g.degree(next) != 2) {
            end = g.degree(next) >= 3 ? next : -1;
            return path;
        }
        path.push_back(next);
        prev = cur;
        cur = next;
    }
}

namespace {

double pathLength(const DenseGraph &g, const std::vector<int> &path, int end)
{
    double length = 0.0;
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
        length += g.length(path[i], path[i + 1]);
    return length + g.length(path.back(), end);
}

} // namespace

void removeTerminalBranches(DenseGraph &graph, const TerminalTest &remove)
{
    for (;;) {
        double shortest = 0.0;
        std::vector<int> chosen;
        for (int v = 0; v < graph.size(); ++v) {
            if (!graph.alive[std::size_t(v)] || graph.degree(v) != 1)
                continue;
            int junction = -1;
            std::vector<int> path = terminalPath(graph, v, junction);
            if (junction < 0)
                continue;
            const double length = pathLength(graph, path, junction);
            if ((chosen.empty() || length < shortest) && remove(path, junction, length)) {
                shortest = length;
                chosen = std::move(path);
            }
        }
        if (chosen.empty())
            return;
        for (int n : chosen)
            graph.removeNode(n);
    }
}

void removeSpurs(DenseGraph &graph, double slack)
{
    removeTerminalBranches(graph, [&](const std::vector<int> &path, int junction, double) {
        const Eigen::Vector2d &c = graph.pos[std::size_t(junction)];
        double reach = 0.0;
        for (int n : path)
            reach = std::max(reach, (graph.pos[std::size_t(n)] - c).norm() +
                                        graph.clearance[std::size_t(n)]);
        return reach <= (1.0 + slack) * graph.clearance[std::size_t(junction)];
    });
}

DenseGraph compacted(const DenseGraph &graph, std::vector<int> *remap)
{
    std::vector<int> index(std::size_t(graph.size()), -1);
    DenseGraph out;
    for (int v = 0; v < graph.size(); ++v) {
        if (graph.alive[std::size_t(v)])
            index[std::size_t(v)] =
                out.addNode(graph.pos[std::size_t(v)], graph.radius[std::size_t(v)],
                            graph.clearance[std::size_t(v)], graph.polygon[std::size_t(v)]);
    }
    for (int v = 0; v < graph.size(); ++v) {
        for (int n : graph.adj[std::size_t(v)]) {
            if (n > v)
                out.addEdge(index[std::size_t(v)], index[std::size_t(n)]);
        }
    }
    if (remap)
        *remap = std::move(index);
    return out;
}

std::vector<Branch> extractBranches(const DenseGraph &graph)
{
    std::vector<Branch> branches;
    std::vector<std::vector<char>> used(std::size_t(graph.size()));
    for (int v = 0; v < graph.size(); ++v)
        used[std::size_t(v)].assign(graph.adj[std::size_t(v)].size(), 0);
    auto markUsed = [&](int a, int b) {
        const std::vector<int> &na = graph.adj[std::size_t(a)];
        used[std::size_t(a)][std::size_t(std::find(na.begin(), na.end(), b) - na.begin())] = 1;
        const std::vector<int> &nb = graph.adj[std::size_t(b)];
        used[std::size_t(b)][std::size_t(std::find(nb.begin(), nb.end(), a) - nb.begin())] = 1;
    };
    for (int v = 0; v < graph.size(); ++v) {
        if (!graph.alive[std::size_t(v)] || graph.degree(v) == 2)
            continue;
        if (graph.degree(v) == 0) {
            branches.push_back({{v}, 0.0});
            continue;
        }
        for (std::size_t k = 0; k < graph.adj[std::size_t(v)].size(); ++k) {
            if (used[std::size_t(v)][k])
                continue;
            Branch branch{{v}, 0.0};
            int prev = v, cur = graph.adj[std::size_t(v)][k];
            markUsed(prev, cur);
            for (;;) {
                branch.length += graph.length(prev, cur);
                branch.nodes.push_back(cur);
                if (graph.degree(cur) != 2)
                    break;
                const int next = graph.adj[std::size_t(cur)][0] == prev
                                     ? graph.adj[std::size_t(cur)][1]
                                     : graph.adj[std::size_t(cur)][0];
                markUsed(cur, next);
                prev = cur;
                cur = next;
            }
            branches.push_back(std::move(branch));
        }
    }
    return branches;
}

} // namespace finbook::geometry::detail
