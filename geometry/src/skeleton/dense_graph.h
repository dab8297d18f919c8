// Internal: the dense skeleton graph (straight-skeleton nodes and the bisectors between them)
// and the cleanup steps that run on it before refinement.
#pragma once

#include <finbook/geometry/region.h>

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace finbook::geometry::detail {

struct DenseGraph {
    std::vector<Eigen::Vector2d> pos;
    std::vector<double> radius;    // inscribed distance (CGAL event time + erosion)
    std::vector<double> clearance; // distance to the simplified contour
    std::vector<int> polygon;      // index of the contour polygon the node lies in
    std::vector<std::vector<int>> adj;
    std::vector<char> alive;

    int addNode(const Eigen::Vector2d &p, double r, double c, int poly);
    // Adds a–b unless a == b or the edge exists.
    void addEdge(int a, int b);
    void removeEdge(int a, int b);
    void removeNode(int v);
    // `drop` merges into `keep`: its other edges move to `keep`, `drop` dies.
    void contract(int keep, int drop);
    int degree(int v) const { return int(adj[std::size_t(v)].size()); }
    int size() const { return int(pos.size()); }
    double length(int a, int b) const { return (pos[std::size_t(a)] - pos[std::size_t(b)]).norm(); }
};

// Collapses edges shorter than `fraction` × the smaller clearance of their ends (and exact
// zero-length edges), shortest first. Junctions keep their place; two nodes of equal degree
// meet at the one with the larger clearance.
void collapseShortEdges(DenseGraph &graph, double fraction);

// Cuts cycles (skeleton loops around holes) with a maximum spanning forest whose edge weight
// is the smaller clearance of the ends: each loop is cut where the shape is thinnest.
void breakCycles(DenseGraph &graph);

// The terminal path from leaf `tip` up to (excluding) the first node of degree ≠ 2; `end`
// receives that node if it is a junction, else −1 (the component is a path).
std::vector<int> terminalPath(const DenseGraph &g, int tip, int &end);

// Removes terminal branches (a path from a leaf up to, not including, a junction) for which
// remove(path, junction, length) holds, shortest first, one at a time until none is left.
// A junction left with two edges becomes an inner node. A component is never removed.
using TerminalTest = std::function<bool(const std::vector<int> &path, int junction, double length)>;
void removeTerminalBranches(DenseGraph &graph, const TerminalTest &remove);

// Removes side branches that stay within the junction's inscribed disk: their tip reaches no
// further than `slack` × the junction's clearance beyond it (outline noise).
void removeSpurs(DenseGraph &graph, double slack);

// The graph without dead nodes, node indices compacted (old → new in `remap`, −1 if dead).
DenseGraph compacted(const DenseGraph &graph, std::vector<int> *remap = nullptr);

// A path of nodes from one branch end (degree ≠ 2) to another; both ends included. A whole
// component that is a single node gives a branch of one node.
struct Branch {
    std::vector<int> nodes;
    double length = 0.0;
};

// Every branch of the graph (each edge in exactly one branch); cycles without ends cannot
// occur after breakCycles.
std::vector<Branch> extractBranches(const DenseGraph &graph);

} // namespace finbook::geometry::detail
