// A skeleton as plain Eigen data: joints, and one bone from each joint to its parent.
//
// The shape every skeleton function takes and returns, and what the skinning engine reads:
//   joints  J×2  joint positions, canvas px (x right, y down)
//   radius  J    inscribed distance of the outline at the joint (≥ 0, px): how thick the shape
//                is there; a joint is drawn as a circle of this radius
//   parent  J    −1 for the root of a tree, otherwise parent[j] < j (so one forward pass over
//                the joints visits every parent before its children)
//   part    J    the part (object) a joint belongs to: 0 for one part's skeleton, the part's
//                index in a character assembled from several parts (skeleton_connect.h)
//   root         the character's root joint (parent[root] == −1); −1 only when J == 0
//   limbBase     empty, or J flags: the joints where a limb leaves the body (the shoulder, the
//                hip), set by an animator rig's refinement (skeleton_refine.h); inverse
//                kinematics turns a limb there, not at the body's centre
// Bone j runs from joints.row(parent[j]) to joints.row(j) for every non-root j, so a skeleton
// has J − (number of roots) bones. Several roots make a forest: separate lobes of one object,
// or parts that are not joined to the character.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry {

struct Skeleton {
    Eigen::MatrixX2d joints;
    Eigen::VectorXd radius;
    Eigen::VectorXi parent;
    Eigen::VectorXi part;
    int root = -1;
    std::vector<bool> limbBase;

    int jointCount() const { return int(joints.rows()); }
};

enum class JointKind {
    Isolated, // no bone: a tree of one joint (a dot, a round blob)
    Terminal, // one bone: the tip of a limb
    Inner,    // two bones: a bend along a limb
    Junction, // three or more bones: where limbs meet
};

// Number of bones (non-root joints).
int boneCount(const Skeleton &skeleton);

// Bones per joint (J). Promise: sum = 2 × boneCount.
Eigen::VectorXi jointDegrees(const Skeleton &skeleton);

// The kind of every joint, from its degree.
std::vector<JointKind> jointKinds(const Skeleton &skeleton);

// Length of bone j (0 for roots), J entries.
Eigen::VectorXd boneLengths(const Skeleton &skeleton);

// True if the shapes agree (limbBase empty or J), everything is finite, radius ≥ 0,
// parent[j] ∈ [−1, j), root is a root (or −1 with no joints) and part ≥ 0.
bool isValidSkeleton(const Skeleton &skeleton);

// Children of every joint, in increasing index order.
std::vector<std::vector<int>> jointChildren(const Skeleton &skeleton);

} // namespace finbook::geometry
