// Hand edits of a rest skeleton: index bookkeeping so that parent[j] < j keeps holding.
#include "../deformation_text.h"

#include <finbook/geometry/skeleton/skeleton_edit.h>
#include <finbook/model/skeleton/skeleton_joint_edit.h>

#include <QLineF>

#include <algorithm>
#include <cmath>

namespace finbook::model {

namespace {

constexpr double kMinSplitLength = 2.0; // px: shorter bones are not split
constexpr double kEndMargin = 0.05;     // a new joint stays this fraction away from bone ends

bool finiteAt(QPointF p)
{
    return std::isfinite(p.x()) && std::isfinite(p.y());
}

std::optional<QString> editable(const SkeletonRig &rig, int joint)
{
    if (rig.empty() || !rig.isValid())
        return Deformation::tr("The skeleton is damaged; build it again.");
    if (rig.isPosed())
        return Deformation::tr("Reset the pose or apply it to the drawing before editing joints.");
    if (joint < 0 || joint >= rig.jointCount())
        return Deformation::tr("There is no such joint.");
    return std::nullopt;
}

// Per-joint flags (locks, limb bases) stay canonical: empty when none is set.
void normaliseLocks(SkeletonRig &rig)
{
    for (std::vector<bool> *flags : {&rig.locked, &rig.limbBase})
        if (std::none_of(flags->begin(), flags->end(), [](bool l) { return l; }))
            flags->clear();
}

} // namespace

Expected<SkeletonRig, QString> withJointMoved(const SkeletonRig &rig, int joint, QPointF at)
{
    if (auto why = editable(rig, joint))
        return unexpected(*why);
    if (!finiteAt(at))
        return unexpected(Deformation::tr("A joint cannot go there."));
    SkeletonRig r = rig;
    r.joints[std::size_t(joint)] = at;
    return r;
}

Expected<InsertedJoint, QString> withJointInserted(const SkeletonRig &rig, int bone, QPointF at)
{
    if (auto why = editable(rig, bone))
        return unexpected(*why);
    const int p = rig.parent[std::size_t(bone)];
    if (p < 0)
        return unexpected(Deformation::tr("A joint can only be inserted on a bone."));
    if (!finiteAt(at))
        return unexpected(Deformation::tr("A joint cannot go there."));
    const QPointF a = rig.joints[std::size_t(p)], b = rig.joints[std::size_t(bone)];
    const QPointF d = b - a;
    const double len2 = QPointF::dotProduct(d, d);
    if (!(len2 >= kMinSplitLength * kMinSplitLength))
        return unexpected(Deformation::tr("The bone is too short to split."));
    const double t =
        std::clamp(QPointF::dotProduct(at - a, d) / len2, kEndMargin, 1.0 - kEndMargin);

    const std::size_t j = std::size_t(bone);
    InsertedJoint out;
    SkeletonRig &r = out.rig;
    r = rig;
    for (int &q : r.parent)
        if (q >= bone)
            ++q;
    r.parent.insert(r.parent.begin() + std::ptrdiff_t(j), p);
    r.parent[j + 1] = bone; // the old child hangs from the new joint
    r.joints.insert(r.joints.begin() + std::ptrdiff_t(j), a + t * d);
    const double ra = rig.radius[std::size_t(p)], rb = rig.radius[j];
    r.radius.insert(r.radius.begin() + std::ptrdiff_t(j), ra + t * (rb - ra));
    r.angles.assign(r.joints.size(), 0.0);
    for (std::vector<bool> *flags : {&r.locked, &r.limbBase})
        if (!flags->empty())
            flags->insert(flags->begin() + std::ptrdiff_t(j), false);
    if (r.root >= bone)
        ++r.root;
    out.joint = bone;
    if (!r.isValid())
        return unexpected(Deformation::tr("The skeleton is damaged; build it again."));
    return out;
}

Expected<SkeletonRig, QString> withJointDeleted(const SkeletonRig &rig, int joint)
{
    if (auto why = editable(rig, joint))
        return unexpected(*why);
    if (rig.jointCount() <= 2)
        return unexpected(Deformation::tr("A skeleton needs at least one bone."));
    SkeletonRig r = rig;
    const std::size_t d = std::size_t(joint);
    const int up = rig.parent[d];
    const std::vector<int> kids = rig.children()[d];
    // Reattach the children (indices after `joint`, so parents still come first).
    int heir = up;
    if (up < 0 && !kids.empty()) {
        heir = kids.front();
        r.parent[std::size_t(heir)] = -1;
    }
    for (int c : kids)
        if (c != heir)
            r.parent[std::size_t(c)] = heir;
    int root = rig.root;
    if (root == joint)
        root = heir;
    r.joints.erase(r.joints.begin() + std::ptrdiff_t(d));
    r.parent.erase(r.parent.begin() + std::ptrdiff_t(d));
    r.radius.erase(r.radius.begin() + std::ptrdiff_t(d));
    for (std::vector<bool> *flags : {&r.locked, &r.limbBase})
        if (!flags->empty())
            flags->erase(flags->begin() + std::ptrdiff_t(d));
    normaliseLocks(r);
    for (int &q : r.parent)
        if (q > joint)
            --q;
    if (root > joint)
        --root;
    if (root < 0) // a childless root of a forest: another root leads
        root = int(std::find(r.parent.begin(), r.parent.end(), -1) - r.parent.begin());
    r.root = root;
    r.angles.assign(r.joints.size(), 0.0);
    if (!r.isValid())
        return unexpected(Deformation::tr("The skeleton is damaged; build it again."));
    return r;
}

geometry::Skeleton geometrySkeleton(const SkeletonRig &rig)
{
    geometry::Skeleton s;
    const Eigen::Index n = Eigen::Index(rig.joints.size());
    s.joints.resize(n, 2);
    s.radius.resize(n);
    s.parent.resize(n);
    s.part = Eigen::VectorXi::Zero(n);
    for (Eigen::Index j = 0; j < n; ++j) {
        s.joints.row(j) << rig.joints[std::size_t(j)].x(), rig.joints[std::size_t(j)].y();
        s.radius(j) = j < Eigen::Index(rig.radius.size()) ? rig.radius[std::size_t(j)] : 0.0;
        s.parent(j) = j < Eigen::Index(rig.parent.size()) ? rig.parent[std::size_t(j)] : -1;
    }
    s.root = rig.root;
    return s;
}

Expected<SkeletonRig, QString> withRootJoint(const SkeletonRig &rig, int joint)
{
    if (auto why = editable(rig, joint))
        return unexpected(*why);
    if (rig.root == joint)
        return rig;
    auto edit = geometry::setRoot(geometrySkeleton(rig), joint);
    if (!edit)
        return unexpected(Deformation::tr("The skeleton is damaged; build it again."));
    SkeletonRig r = rig;
    const geometry::Skeleton &e = edit->skeleton;
    r.joints.resize(std::size_t(e.jointCount()));
    r.radius.resize(r.joints.size());
    r.parent.resize(r.joints.size());
    for (int j = 0; j < e.jointCount(); ++j) {
        r.joints[std::size_t(j)] = QPointF(e.joints(j, 0), e.joints(j, 1));
        r.radius[std::size_t(j)] = e.radius(j);
        r.parent[std::size_t(j)] = e.parent(j);
    }
    r.root = e.root;
    for (auto flags : {&SkeletonRig::locked, &SkeletonRig::limbBase}) {
        if ((rig.*flags).empty())
            continue;
        (r.*flags).assign(r.joints.size(), false);
        for (Eigen::Index j = 0; j < edit->newIndex.size(); ++j)
            if (edit->newIndex(j) >= 0 && (rig.*flags)[std::size_t(j)])
                (r.*flags)[std::size_t(edit->newIndex(j))] = true;
    }
    normaliseLocks(r);
    r.angles.assign(r.joints.size(), 0.0);
    if (!r.isValid())
        return unexpected(Deformation::tr("The skeleton is damaged; build it again."));
    return r;
}

} // namespace finbook::model
