#include "skeleton_internal.h"

#include <finbook/deform/skeleton/skeleton.h>

#include <cmath>
#include <string>
#include <vector>

namespace finbook::deform {
namespace {

using detail::makeError;

std::optional<DeformError> validateJoints(const Eigen::MatrixX2d &joints,
                                          const Eigen::VectorXi &parent)
{
    const Eigen::Index count = joints.rows();
    if (count == 0)
        return makeError(DeformErrorCode::InvalidSkeleton, "the skeleton has no joints");
    if (parent.size() != count)
        return makeError(DeformErrorCode::InvalidSkeleton,
                         "the skeleton has " + std::to_string(count) + " joints but " +
                             std::to_string(parent.size()) + " parent entries");
    if (!joints.allFinite())
        return makeError(DeformErrorCode::NonFiniteInput, "a joint position is not finite");
    if (joints.cwiseAbs().maxCoeff() > kMaxDeformCoordinate)
        return makeError(DeformErrorCode::CoordinateOutOfRange, "a joint position is too large");
    for (Eigen::Index j = 0; j < count; ++j) {
        if (parent(j) < -1 || parent(j) >= count || parent(j) == j)
            return makeError(DeformErrorCode::InvalidSkeleton, "joint " + std::to_string(j) +
                                                                   " has an invalid parent " +
                                                                   std::to_string(parent(j)));
    }
    return std::nullopt;
}

// Roots first, then breadth-first over children; a joint never reached lies on a cycle.
std::optional<Eigen::VectorXi> topologicalOrder(const Eigen::VectorXi &parent)
{
    const auto count = static_cast<int>(parent.size());
    const detail::ChildLists children = detail::childLists(parent);
    Eigen::VectorXi order(count);
    int filled = 0;
    for (int j = 0; j < count; ++j) {
        if (parent(j) < 0)
            order(filled++) = j;
    }
    for (int next = 0; next < filled; ++next) {
        const int j = order(next);
        for (int c = children.start[j]; c < children.start[j + 1]; ++c)
            order(filled++) = children.child[c];
    }
    if (filled != count)
        return std::nullopt;
    return order;
}

} // namespace

Expected<Skeleton, DeformError> makeSkeleton(const Eigen::MatrixX2d &joints,
                                             const Eigen::VectorXi &parent)
{
    if (auto error = validateJoints(joints, parent))
        return unexpected(*error);
    std::optional<Eigen::VectorXi> order = topologicalOrder(parent);
    if (!order)
        return unexpected(
            makeError(DeformErrorCode::InvalidSkeleton, "the joints' parents form a cycle"));
    return Skeleton{joints, parent, std::move(*order)};
}

SkeletonPose restPose(const Skeleton &skeleton)
{
    return SkeletonPose{Eigen::VectorXd::Zero(skeleton.jointCount()), Eigen::Vector2d::Zero()};
}

std::optional<DeformError> forwardKinematics(const Skeleton &skeleton, const SkeletonPose &pose,
                                             PosedSkeleton &out)
{
    const Eigen::Index count = skeleton.jointCount();
    if (pose.angles.size() != count)
        return makeError(DeformErrorCode::SizeMismatch,
                         "the pose has " + std::to_string(pose.angles.size()) + " angles for " +
                             std::to_string(count) + " joints");
    if (!pose.angles.allFinite() || !pose.rootOffset.allFinite())
        return makeError(DeformErrorCode::NonFiniteInput, "a pose angle or offset is not finite");
    if (pose.rootOffset.cwiseAbs().maxCoeff() > kMaxDeformCoordinate)
        return makeError(DeformErrorCode::CoordinateOutOfRange, "the root offset is too large");
    out.joints.resize(count, 2);
    out.worldAngles.resize(count);
    out.transforms.resize(static_cast<std::size_t>(count));
    for (Eigen::Index k = 0; k < count; ++k) {
        const int j = skeleton.order(k), p = skeleton.parent(j);
        const Eigen::Vector2d rest = skeleton.joints.row(j).transpose();
        const double angle = (p < 0 ? 0.0 : out.worldAngles(p)) + pose.angles(j);
        const double c = std::cos(angle), s = std::sin(angle);
        BoneTransform &T = out.transforms[static_cast<std::size_t>(j)];
        T << c, -s, 0.0, s, c, 0.0;
        // The bone turns about its parent joint, so p_j is built from the posed parent: bones
        // stay attached to rounding whatever the chain length.
        const Eigen::Vector2d posed =
            p < 0 ? Eigen::Vector2d(rest + pose.rootOffset)
                  : Eigen::Vector2d(out.joints.row(p).transpose() +
                                    T.leftCols<2>() * (rest - skeleton.joints.row(p).transpose()));
        T.col(2) = posed - T.leftCols<2>() * rest;
        out.worldAngles(j) = angle;
        out.joints.row(j) = posed.transpose();
    }
    return std::nullopt;
}

Expected<PosedSkeleton, DeformError> forwardKinematics(const Skeleton &skeleton,
                                                       const SkeletonPose &pose)
{
    PosedSkeleton out;
    if (auto error = forwardKinematics(skeleton, pose, out))
        return unexpected(*error);
    return out;
}

} // namespace finbook::deform
