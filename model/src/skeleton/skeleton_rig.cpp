// Pose bookkeeping of a skeleton rig: posed or not, back to rest, and rebasing after Apply
// Pose (which needs forward kinematics, hence deform/).
#include <finbook/deform/skeleton/skeleton.h>
#include <finbook/model/skeleton/skeleton_rig.h>

#include <algorithm>
#include <cmath>

namespace finbook::model {

namespace {
bool finite(QPointF p)
{
    return std::isfinite(p.x()) && std::isfinite(p.y());
}
bool unit(double v)
{
    return v >= 0.0 && v <= 1.0;
}
} // namespace

bool SkeletonRig::isPosed() const
{
    return rootOffset != QPointF() ||
           std::any_of(angles.begin(), angles.end(), [](double a) { return a != 0.0; });
}

bool SkeletonRig::isLocked(int joint) const
{
    return joint >= 0 && std::size_t(joint) < locked.size() && locked[std::size_t(joint)];
}

SkeletonRig SkeletonRig::withLock(int joint, bool on) const
{
    SkeletonRig r = *this;
    if (joint < 0 || joint >= jointCount())
        return r;
    r.locked.resize(joints.size(), false);
    r.locked[std::size_t(joint)] = on;
    if (std::none_of(r.locked.begin(), r.locked.end(), [](bool l) { return l; }))
        r.locked.clear();
    return r;
}

std::vector<std::vector<int>> SkeletonRig::children() const
{
    std::vector<std::vector<int>> c(joints.size());
    for (std::size_t j = 0; j < parent.size() && j < joints.size(); ++j)
        if (parent[j] >= 0 && std::size_t(parent[j]) < joints.size())
            c[std::size_t(parent[j])].push_back(int(j));
    return c;
}

SkeletonRig SkeletonRig::atRest() const
{
    SkeletonRig r = *this;
    r.angles.assign(joints.size(), 0.0);
    r.rootOffset = QPointF();
    return r;
}

std::vector<QPointF> SkeletonRig::posedJoints() const
{
    if (!isPosed() || !isValid())
        return joints;
    Eigen::MatrixX2d V(Eigen::Index(joints.size()), 2);
    Eigen::VectorXi P(Eigen::Index(joints.size()));
    for (std::size_t j = 0; j < joints.size(); ++j) {
        V.row(Eigen::Index(j)) << joints[j].x(), joints[j].y();
        P(Eigen::Index(j)) = parent[j];
    }
    auto skeleton = deform::makeSkeleton(V, P);
    if (!skeleton)
        return joints;
    deform::SkeletonPose pose;
    pose.angles = Eigen::VectorXd::Zero(V.rows());
    for (std::size_t j = 0; j < angles.size() && j < joints.size(); ++j)
        pose.angles(Eigen::Index(j)) = angles[j];
    pose.rootOffset = {rootOffset.x(), rootOffset.y()};
    auto posed = deform::forwardKinematics(*skeleton, pose);
    if (!posed || !posed->joints.allFinite())
        return joints;
    std::vector<QPointF> out(joints.size());
    for (std::size_t j = 0; j < joints.size(); ++j)
        out[j] = QPointF(posed->joints(Eigen::Index(j), 0), posed->joints(Eigen::Index(j), 1));
    return out;
}

SkeletonRig SkeletonRig::rebased() const
{
    SkeletonRig r = *this;
    r.joints = posedJoints();
    return r.atRest();
}

bool SkeletonRig::sameRest(const SkeletonRig &other) const
{
    return joints == other.joints && parent == other.parent;
}

bool SkeletonRig::isValid() const
{
    const std::size_t n = joints.size();
    if (parent.size() != n || radius.size() != n || (!angles.empty() && angles.size() != n))
        return false;
    if (!locked.empty() && (locked.size() != n ||
                            std::none_of(locked.begin(), locked.end(), [](bool l) { return l; })))
        return false;
    if (n == 0)
        return root == -1;
    if (root < 0 || std::size_t(root) >= n || parent[std::size_t(root)] != -1)
        return false;
    for (std::size_t j = 0; j < n; ++j)
        if (!finite(joints[j]) || parent[j] < -1 || parent[j] >= int(j) || !(radius[j] >= 0.0) ||
            !std::isfinite(radius[j]))
            return false;
    if (!std::all_of(angles.begin(), angles.end(), [](double a) { return std::isfinite(a); }))
        return false;
    return finite(rootOffset) && unit(settings.complexity) && unit(settings.merge) &&
           unit(settings.prune) && unit(settings.collapse);
}

} // namespace finbook::model
