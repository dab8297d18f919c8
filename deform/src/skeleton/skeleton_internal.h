// Pieces shared by the skeleton, skinning and kinematics translation units.
#pragma once

#include "../arap_internal.h"

#include <finbook/deform/skeleton/skeleton.h>

#include <Eigen/Core>

#include <algorithm>
#include <vector>

namespace finbook::deform::detail {

// Children of every joint in compressed form: those of joint j are
// child[start[j]] … child[start[j + 1] − 1], in increasing index order.
struct ChildLists {
    std::vector<int> start; // J + 1
    std::vector<int> child; // one entry per non-root joint
};

// parent: J entries in [−1, J) (not checked for cycles).
inline ChildLists childLists(const Eigen::VectorXi &parent)
{
    const auto count = static_cast<std::size_t>(parent.size());
    ChildLists lists{std::vector<int>(count + 1, 0), {}};
    for (Eigen::Index j = 0; j < parent.size(); ++j) {
        if (parent(j) >= 0)
            ++lists.start[static_cast<std::size_t>(parent(j)) + 1];
    }
    for (std::size_t j = 0; j < count; ++j)
        lists.start[j + 1] += lists.start[j];
    lists.child.resize(static_cast<std::size_t>(lists.start[count]));
    std::vector<int> next(lists.start.begin(), lists.start.end() - 1);
    for (Eigen::Index j = 0; j < parent.size(); ++j) {
        if (parent(j) >= 0)
            lists.child[static_cast<std::size_t>(next[static_cast<std::size_t>(parent(j))]++)] =
                static_cast<int>(j);
    }
    return lists;
}

// Squared distance from p to the segment a–b (a point when a = b).
inline double squaredSegmentDistance(const Eigen::Vector2d &p, const Eigen::Vector2d &a,
                                     const Eigen::Vector2d &b)
{
    const Eigen::Vector2d ab = b - a, ap = p - a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp(ap.dot(ab) / length2, 0.0, 1.0) : 0.0;
    return (ap - t * ab).squaredNorm();
}

// Boundary conditions of the harmonic skinning weights (SkinningWeights::owner): n entries,
// the handle joint holding each vertex or −1. Every handle holds at least one vertex unless all
// vertices are already some other handle's only vertex; every mesh component has at least one
// held vertex. V, F (validated) and the skeleton as for computeSkinningWeights; handles a
// non-empty list of its handle joints.
Eigen::VectorXi skinningBoundary(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                 const Skeleton &skeleton, const Eigen::VectorXi &handles,
                                 double reachEdges, const Eigen::VectorXd &jointRadius = {},
                                 double jointFree = 0.0);

} // namespace finbook::deform::detail
