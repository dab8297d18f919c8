// Internal: turning an undirected joint graph (a forest) into a Skeleton with parent[j] < j.
#pragma once

#include <finbook/geometry/skeleton/skeleton.h>

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry::detail {

struct JointGraph {
    std::vector<Eigen::Vector2d> pos;
    std::vector<double> radius;
    std::vector<int> part;
    std::vector<std::vector<int>> adj; // must be a forest

    int add(const Eigen::Vector2d &p, double r, int partId);
    void connect(int a, int b);
    void disconnect(int a, int b);
    int size() const { return int(pos.size()); }
};

// The graph without the joints whose keep flag is 0; map receives old → new (−1: dropped).
JointGraph keptJoints(const JointGraph &graph, const std::vector<char> &keep,
                      std::vector<int> &map);

// The bones of a skeleton as an undirected graph (same joint indices).
JointGraph toJointGraph(const Skeleton &skeleton);

// Orders every tree depth first from its root, children in increasing index order; trees in
// the order of their smallest joint, except that the character root's tree comes first.
// roots: preferred roots; a tree takes the first one it contains, else its smallest joint.
// characterRoot: a joint (−1: the first tree's root). newIndex (optional): old → new.
Skeleton orderedSkeleton(const JointGraph &graph, const std::vector<int> &roots, int characterRoot,
                         std::vector<int> *newIndex = nullptr);

// Roots of a skeleton's trees, character root first.
std::vector<int> skeletonRoots(const Skeleton &skeleton);

} // namespace finbook::geometry::detail
