// Pose bookkeeping of a skeleton rig: posed or not, back to rest, and rebasing after Apply
// Pose (which needs forward kinematics, hence deform/).
#include <finbook/deform/skeleton/skeleton.h>
#include <finbook/model/skeleton/skeleton_rig.h>

#include <algorithm>
#include <cmath>
#include <optional>

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

QPointF RigidMotion::map(QPointF x) const
{
    const double c = std::cos(angle), s = std::sin(angle);
    return QPointF(c * x.x() - s * x.y(), s * x.x() + c * x.y()) + shift;
}

QPointF RigidMotion::unmap(QPointF x) const
{
    const double c = std::cos(angle), s = std::sin(angle);
    const QPointF d = x - shift;
    return QPointF(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
}

RigidMotion RigidMotion::then(const RigidMotion &after) const
{
    RigidMotion m;
    m.angle = angle + after.angle;
    m.shift = after.map(shift);
    return m;
}

bool SkeletonRig::isPosed() const
{
    return rootOffset != QPointF() || (hangs() && !anchor.motion.isIdentity()) ||
           std::any_of(angles.begin(), angles.end(), [](double a) { return a != 0.0; });
}

bool SkeletonRig::isLocked(int joint) const
{
    return joint >= 0 && std::size_t(joint) < locked.size() && locked[std::size_t(joint)];
}

bool SkeletonRig::isLimbBase(int joint) const
{
    return joint >= 0 && std::size_t(joint) < limbBase.size() && limbBase[std::size_t(joint)];
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
    r.anchor.motion = {};
    return r;
}

std::vector<QPointF> SkeletonRig::posedJoints() const
{
    std::vector<QPointF> out = ownPosedJoints();
    if (hangs() && !anchor.motion.isIdentity())
        for (QPointF &p : out)
            p = anchor.motion.map(p);
    return out;
}

namespace {
// Forward kinematics of the part's own pose (no anchor); nullopt when it does not fit.
std::optional<deform::PosedSkeleton> ownPose(const SkeletonRig &rig)
{
    if (!rig.isValid() || rig.joints.empty())
        return std::nullopt;
    const std::size_t n = rig.joints.size();
    Eigen::MatrixX2d V(static_cast<Eigen::Index>(n), 2);
    Eigen::VectorXi P(static_cast<Eigen::Index>(n));
    for (std::size_t j = 0; j < n; ++j) {
        V.row(Eigen::Index(j)) << rig.joints[j].x(), rig.joints[j].y();
        P(Eigen::Index(j)) = rig.parent[j];
    }
    auto skeleton = deform::makeSkeleton(V, P);
    if (!skeleton)
        return std::nullopt;
    deform::SkeletonPose pose;
    pose.angles = Eigen::VectorXd::Zero(V.rows());
    for (std::size_t j = 0; j < rig.angles.size() && j < n; ++j)
        pose.angles(Eigen::Index(j)) = rig.angles[j];
    pose.rootOffset = {rig.rootOffset.x(), rig.rootOffset.y()};
    auto posed = deform::forwardKinematics(*skeleton, pose);
    if (!posed || !posed->joints.allFinite())
        return std::nullopt;
    return std::move(*posed);
}
} // namespace

std::vector<QPointF> SkeletonRig::ownPosedJoints() const
{
    if (rootOffset == QPointF() &&
        std::all_of(angles.begin(), angles.end(), [](double a) { return a == 0.0; }))
        return joints;
    const auto posed = ownPose(*this);
    if (!posed)
        return joints;
    std::vector<QPointF> out(joints.size());
    for (std::size_t j = 0; j < joints.size(); ++j)
        out[j] = QPointF(posed->joints(Eigen::Index(j), 0), posed->joints(Eigen::Index(j), 1));
    return out;
}

std::vector<RigidMotion> SkeletonRig::boneMotions() const
{
    std::vector<RigidMotion> out(joints.size());
    const auto posed = ownPose(*this);
    if (!posed)
        return out;
    const bool anchored = hangs();
    for (std::size_t j = 0; j < joints.size(); ++j) {
        const deform::BoneTransform &T = posed->transforms[j];
        RigidMotion m;
        m.angle = posed->worldAngles(Eigen::Index(j));
        m.shift = QPointF(T(0, 2), T(1, 2));
        out[j] = anchored ? m.then(anchor.motion) : m;
    }
    return out;
}

SkeletonRig SkeletonRig::keepingShownPose(const SkeletonAnchor &newAnchor) const
{
    SkeletonRig r = *this;
    const RigidMotion oldMotion = hangs() ? anchor.motion : RigidMotion{};
    r.anchor = newAnchor;
    const RigidMotion newMotion = newAnchor.valid ? newAnchor.motion : RigidMotion{};
    if (!isValid() || oldMotion == newMotion)
        return r;
    // D = newMotion⁻¹ ∘ oldMotion, taken by the root: M′ = D ∘ M.
    RigidMotion d;
    d.angle = oldMotion.angle - newMotion.angle;
    d.shift = newMotion.unmap(oldMotion.shift);
    r.angles.resize(joints.size(), 0.0);
    for (std::size_t j = 0; j < joints.size(); ++j)
        if (parent[j] < 0)
            r.angles[j] += d.angle;
    const QPointF rootRest = joints[std::size_t(root)];
    r.rootOffset = d.map(rootRest + rootOffset) - rootRest;
    return r;
}

SkeletonRig SkeletonRig::rebased() const
{
    SkeletonRig r = *this;
    r.joints = posedJoints();
    if (r.join.joined()) {
        // The join moves with the drawing: its part point with the root's tree, its parent
        // point with the bone it hangs from (rebased with the parent, Apply Pose bakes a
        // character at once).
        const std::vector<RigidMotion> motions = boneMotions();
        if (root >= 0 && std::size_t(root) < motions.size())
            r.join.childAt = motions[std::size_t(root)].map(join.childAt);
        if (hangs())
            r.join.parentAt = anchor.motion.map(join.parentAt);
    }
    return r.atRest();
}

bool SkeletonRig::sameRest(const SkeletonRig &other) const
{
    return joints == other.joints && parent == other.parent && anchor.valid == other.anchor.valid &&
           (mode == SkinningMode::CutOut) == (other.mode == SkinningMode::CutOut) &&
           (!anchor.valid || (anchor.from == other.anchor.from && anchor.to == other.anchor.to));
}

bool SkeletonRig::isValid() const
{
    const std::size_t n = joints.size();
    if (parent.size() != n || radius.size() != n || (!angles.empty() && angles.size() != n))
        return false;
    for (const std::vector<bool> *flags : {&locked, &limbBase})
        if (!flags->empty() && (flags->size() != n || std::none_of(flags->begin(), flags->end(),
                                                                   [](bool l) { return l; })))
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
    if (!finite(join.childAt) || !finite(join.parentAt) || !finite(anchor.from) ||
        !finite(anchor.to) || !std::isfinite(anchor.motion.angle) || !finite(anchor.motion.shift))
        return false;
    return finite(rootOffset) && unit(settings.complexity) && unit(settings.merge) &&
           unit(settings.prune) && unit(settings.collapse);
}

} // namespace finbook::model
