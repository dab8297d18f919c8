// A rest skeleton, a pose of it, and forward kinematics.
//
// Joints form a forest given by parent indices. Bone j runs from joint parent(j) to joint j for
// every non-root joint j, so bones are indexed by their child joint. A pose stores, per joint,
// an angle relative to rest and one offset for all roots; nothing else (no drag history), so a
// posed skeleton is a pure function of (rest skeleton, angles, root offset):
//
//   world angle  Θ_r = θ_r for a root r,   Θ_j = Θ_parent(j) + θ_j otherwise
//   posed joint  p_r = r_r + rootOffset,   p_j = p_parent(j) + R(Θ_j) (r_j − r_parent(j))
//   transform    T_j(x) = R(Θ_j) (x − r_j) + p_j
//
// So θ_j turns bone j, and everything below it, about its parent joint; a root's angle turns
// its whole tree about the root. T_j is the rigid motion of bone j (it maps the rest bone onto
// the posed bone); R(Θ) = [cos −sin; sin cos] turns +x towards +y, i.e. clockwise on the y-down
// canvas.
#pragma once

#include <finbook/deform/deform_error.h>
#include <finbook/geometry/expected.h>

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace finbook::deform {

// Immutable once makeSkeleton returns it.
struct Skeleton {
    Eigen::MatrixX2d joints; // J×2 rest positions (canvas px, y down)
    Eigen::VectorXi parent;  // J: parent joint, −1 for roots
    Eigen::VectorXi order;   // J: every joint after its parent (a topological order)

    Eigen::Index jointCount() const { return joints.rows(); }
    bool isRoot(Eigen::Index j) const { return parent(j) < 0; }
};

// joints J×2 finite (|x| ≤ kMaxDeformCoordinate), parent J entries in [−1, J), no joint its own
// ancestor. Errors: InvalidSkeleton (J = 0, sizes differ, parent out of range, cycle),
// NonFiniteInput, CoordinateOutOfRange.
Expected<Skeleton, DeformError> makeSkeleton(const Eigen::MatrixX2d &joints,
                                             const Eigen::VectorXi &parent);

struct SkeletonPose {
    Eigen::VectorXd angles;                               // J radians, relative to rest
    Eigen::Vector2d rootOffset = Eigen::Vector2d::Zero(); // added to every root, px
};

// All angles zero, no offset: forwardKinematics gives the rest skeleton.
SkeletonPose restPose(const Skeleton &skeleton);

// x ↦ T.leftCols<2>() x + T.col(2): the rigid motion of one bone from rest to pose.
using BoneTransform = Eigen::Matrix<double, 2, 3>;

struct PosedSkeleton {
    Eigen::MatrixX2d joints;               // J×2 posed joint positions
    Eigen::VectorXd worldAngles;           // J: Θ_j, the bone's rotation from rest
    std::vector<BoneTransform> transforms; // J: T_j as above (for a root: its tree's motion)
};

// pose.angles must have J finite entries, rootOffset finite and ≤ kMaxDeformCoordinate.
// Errors: SizeMismatch, NonFiniteInput, CoordinateOutOfRange (out is then unspecified).
// Allocation-free when `out` already holds J joints (as from a previous call).
std::optional<DeformError> forwardKinematics(const Skeleton &skeleton, const SkeletonPose &pose,
                                             PosedSkeleton &out);
Expected<PosedSkeleton, DeformError> forwardKinematics(const Skeleton &skeleton,
                                                       const SkeletonPose &pose);

// Applies a bone transform to a point.
inline Eigen::Vector2d transformPoint(const BoneTransform &T, const Eigen::Vector2d &x)
{
    return T.leftCols<2>() * x + T.col(2);
}

} // namespace finbook::deform
