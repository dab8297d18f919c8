// Skinning precompute and solve for a skeleton rig (deform/skeleton/*), in the shape the
// generic deform setup dispatches to.
#include "../deformation_text.h"

#include <finbook/model/skeleton/skeleton_setup.h>

namespace finbook::model {

namespace {
QString message(const deform::DeformError &e)
{
    return QString::fromStdString(e.message);
}
} // namespace

Expected<deform::Skeleton, QString> deformSkeleton(const SkeletonRig &rig)
{
    if (!rig.isValid() || rig.empty())
        return unexpected(Deformation::tr("The skeleton is damaged; build it again."));
    const Eigen::Index n = Eigen::Index(rig.joints.size());
    Eigen::MatrixX2d joints(n, 2);
    Eigen::VectorXi parent(n);
    for (Eigen::Index j = 0; j < n; ++j) {
        joints.row(j) << rig.joints[std::size_t(j)].x(), rig.joints[std::size_t(j)].y();
        parent(j) = rig.parent[std::size_t(j)];
    }
    auto skeleton = deform::makeSkeleton(joints, parent);
    if (!skeleton)
        return unexpected(
            Deformation::tr("The skeleton cannot be used: %1").arg(message(skeleton.error())));
    return std::move(*skeleton);
}

deform::SkeletonPose skeletonPose(const SkeletonRig &rig)
{
    deform::SkeletonPose pose;
    pose.angles = Eigen::VectorXd::Zero(Eigen::Index(rig.joints.size()));
    for (std::size_t j = 0; j < rig.angles.size() && j < rig.joints.size(); ++j)
        pose.angles(Eigen::Index(j)) = rig.angles[j];
    pose.rootOffset = {rig.rootOffset.x(), rig.rootOffset.y()};
    return pose;
}

Expected<std::shared_ptr<const SkeletonSetup>, QString>
buildSkeletonSetup(const MeshedObject &meshed, const SkeletonRig &rig,
                   const deform::ArapOptions &options, const std::function<bool()> &cancelled)
{
    auto skeleton = deformSkeleton(rig);
    if (!skeleton)
        return unexpected(skeleton.error());
    auto setup = std::make_shared<SkeletonSetup>();
    setup->skeleton = std::move(*skeleton);
    const Eigen::MatrixX2d &V = meshed.mesh.V;
    const Eigen::MatrixX3i &F = meshed.mesh.F;
    auto weights = deform::computeSkinningWeights(V, F, setup->skeleton, {}, cancelled);
    if (!weights)
        return unexpected(Deformation::tr("The skeleton cannot skin this drawing: %1")
                              .arg(message(weights.error())));
    setup->weights = *weights;
    setup->vertices = deform::bindVertices(*setup->weights, V);
    auto rigid = deform::rigidSkinPrecompute(V, F, *setup->weights, options, cancelled);
    if (!rigid)
        return unexpected(Deformation::tr("The skeleton cannot skin this drawing: %1")
                              .arg(message(rigid.error())));
    setup->rigid = *rigid;
    return std::shared_ptr<const SkeletonSetup>(std::move(setup));
}

Expected<Eigen::MatrixX2d, QString>
solveSkeleton(const MeshedObject &meshed, const SkeletonSetup &setup, const SkeletonRig &rig)
{
    auto posed = deform::forwardKinematics(setup.skeleton, skeletonPose(rig));
    if (!posed)
        return unexpected(
            Deformation::tr("The bones could not be posed: %1").arg(message(posed.error())));
    Eigen::MatrixX2d U;
    if (rig.mode == SkinningMode::LinearBlend) {
        if (auto error = deform::skin(setup.vertices, *posed, U))
            return unexpected(
                Deformation::tr("The bones could not be posed: %1").arg(message(*error)));
    } else {
        U = meshed.mesh.V;
        auto solved = deform::rigidSkinSolve(*setup.rigid, *posed, U);
        if (!solved)
            return unexpected(
                Deformation::tr("The bones could not be posed: %1").arg(message(solved.error())));
    }
    return U;
}

} // namespace finbook::model
