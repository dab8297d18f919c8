// Posing by dragging: turn one bone (forward kinematics), or drag a joint and let a chain of
// bones follow (inverse kinematics). Every function maps the pose at the start of a drag and
// the cursor to a new pose, so a drag event is a pure function of (start pose, cursor): call it
// with the same start pose for every event of one drag, not with the previous event's result.
//
// Locks: a locked joint never moves when another joint is dragged. The IK chain of a joint is
// its bone, its parent's bone, … upwards, stopping below the first bone whose turning would
// move a locked joint (the nearest locked ancestor, or a locked joint on a side branch), at a
// root, or at a branch point (a joint with two or more children): a bone starting at a branch
// point is the last of the chain, and is left out when the chain already has two bones, so a
// limb turns at its own base joint and not about the body's centre. A limb base (a joint the
// automatic skeleton put where a limb leaves the body, IkOptions::limbBase) ends the chain of
// every joint below it the same way, however few bones the limb has: its bone runs into the
// body, so a one-bone ear or foreleg dragged by its tip turns at its base; dragging the base
// itself still turns that bone. Roots are never turned by IK; dragging a root translates the
// whole skeleton.
#pragma once

#include <finbook/deform/deform_error.h>
#include <finbook/deform/skeleton/skeleton.h>
#include <finbook/geometry/expected.h>

#include <Eigen/Core>

#include <vector>

namespace finbook::deform {

// The longest IK chain: a drag turns at most this many bones above the dragged joint, so one
// drag event costs at most a few million steps whatever skeleton a file holds (a chain of
// 100,000 bones would take seconds per event). Drawn skeletons have tens of bones.
constexpr int kMaxIkChainBones = 256;

struct IkOptions {
    int maxChainBones = 0;   // > 0 caps the chain length; 0 = up to a lock or a root (either
                             // way at most kMaxIkChainBones)
    int iterations = 64;     // FABRIK passes for chains of three or more bones
    double tolerance = 1e-4; // px: FABRIK stops once the dragged joint is this close
    // Empty, or one flag per joint: the limb bases (see above). Another size is an error.
    std::vector<bool> limbBase;
};

struct IkResult {
    SkeletonPose pose;
    Eigen::VectorXi chain; // the bones (joints) that turned, from the dragged joint upwards
    double distance = 0.0; // px from the dragged joint to the target after solving
};

// The chain as described above; `locked` has J entries or is empty (nothing locked).
// An empty chain when the joint is locked, a root, or its own bone would move a locked joint,
// and when the joint is not in [0, J) or `locked` has another size.
Eigen::VectorXi ikChain(const Skeleton &skeleton, int joint, const std::vector<bool> &locked,
                        int maxChainBones = 0, const std::vector<bool> &limbBase = {});

// Moves `joint` towards `target` (canvas px) by turning the bones of its chain: one bone turns
// to point at the target, two bones are solved in closed form (keeping the side the middle
// joint bends to in `start`), longer chains by FABRIK with the target walked there from the
// joint's start position in steps of a quarter of the shortest bone (so no bone flips when the
// cursor crosses a joint), then a few damped Gauss–Newton steps. A target out of reach gets the
// chain stretched straight towards it; the result is continuous in the target and never NaN. A root
// joint translates the whole skeleton unless some joint is locked. A locked joint, or an empty
// chain, returns `start` unchanged. Errors: InvalidIndex (joint), SizeMismatch (locked or
// start.angles), NonFiniteInput, CoordinateOutOfRange (target or start).
Expected<IkResult, DeformError> solveIk(const Skeleton &skeleton, const SkeletonPose &start,
                                        int joint, const Eigen::Vector2d &target,
                                        const std::vector<bool> &locked = {},
                                        const IkOptions &options = {});

// Forward-kinematics drag: turns bone `bone` (a root: its whole tree) about its parent joint by
// the angle between grabbed and cursor as seen from that joint in the start pose. Points on
// the pivot give no turn. Errors: InvalidIndex, SizeMismatch, NonFiniteInput,
// CoordinateOutOfRange.
Expected<SkeletonPose, DeformError> rotateBone(const Skeleton &skeleton, const SkeletonPose &start,
                                               int bone, const Eigen::Vector2d &grabbed,
                                               const Eigen::Vector2d &cursor);

} // namespace finbook::deform
