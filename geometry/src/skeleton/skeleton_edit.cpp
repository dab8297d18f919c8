#include "skeleton_tree.h"

#include <finbook/geometry/skeleton/skeleton_edit.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace finbook::geometry {
namespace {

using namespace detail;

GeometryError badIndex(const char *what, int index)
{
    return GeometryError{GeometryErrorCode::InvalidIndex, std::string("The skeleton has no ") +
                                                              what + " " + std::to_string(index) +
                                                              "."};
}

bool hasJoint(const Skeleton &s, int joint)
{
    return joint >= 0 && joint < s.jointCount();
}

Eigen::VectorXi toVector(const std::vector<int> &v)
{
    Eigen::VectorXi out(Eigen::Index(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i)
        out(Eigen::Index(i)) = v[i];
    return out;
}

// Re-orders `graph` keeping the trees' roots: `roots` are joint indices of `graph`, the
// character root first. oldCount: joints of the original skeleton (a prefix of graph's).
SkeletonEdit reorder(const JointGraph &graph, const std::vector<int> &roots, int oldCount,
                     int editedJoint)
{
    std::vector<int> index;
    SkeletonEdit edit;
    edit.skeleton = orderedSkeleton(graph, roots, roots.empty() ? -1 : roots.front(), &index);
    edit.joint = editedJoint >= 0 ? index[std::size_t(editedJoint)] : -1;
    index.resize(std::size_t(oldCount));
    edit.newIndex = toVector(index);
    return edit;
}

} // namespace

Expected<SkeletonEdit, GeometryError> moveJoint(const Skeleton &skeleton, int joint,
                                                const Eigen::Vector2d &to)
{
    if (!hasJoint(skeleton, joint))
        return unexpected(badIndex("joint", joint));
    if (!to.allFinite() || to.cwiseAbs().maxCoeff() > kMaxCoordinate)
        return unexpected(GeometryError{GeometryErrorCode::InvalidOptions,
                                        "A joint cannot move off the canvas."});
    SkeletonEdit edit;
    edit.skeleton = skeleton;
    edit.skeleton.joints.row(joint) = to.transpose();
    edit.newIndex = Eigen::VectorXi::LinSpaced(skeleton.jointCount(), 0,
                                               std::max(0, skeleton.jointCount() - 1));
    edit.joint = joint;
    return edit;
}

Expected<SkeletonEdit, GeometryError> insertJoint(const Skeleton &skeleton, int bone, double t)
{
    if (!hasJoint(skeleton, bone) || skeleton.parent(bone) < 0)
        return unexpected(badIndex("bone", bone));
    if (!(t > 0.0 && t < 1.0))
        return unexpected(GeometryError{GeometryErrorCode::InvalidOptions,
                                        "A joint is inserted strictly inside a bone."});
    JointGraph graph = toJointGraph(skeleton);
    const int parent = skeleton.parent(bone);
    const Eigen::Vector2d at = (1.0 - t) * skeleton.joints.row(parent).transpose() +
                               t * skeleton.joints.row(bone).transpose();
    const double radius = (1.0 - t) * skeleton.radius(parent) + t * skeleton.radius(bone);
    const int added = graph.add(at, radius, skeleton.part(bone));
    graph.disconnect(parent, bone);
    graph.connect(parent, added);
    graph.connect(added, bone);
    return reorder(graph, skeletonRoots(skeleton), skeleton.jointCount(), added);
}

Expected<SkeletonEdit, GeometryError> deleteJoint(const Skeleton &skeleton, int joint)
{
    if (!hasJoint(skeleton, joint) || skeleton.jointCount() == 1)
        return unexpected(badIndex("joint", joint));
    JointGraph graph = toJointGraph(skeleton);
    const std::vector<std::vector<int>> children = jointChildren(skeleton);
    const std::vector<int> &kids = children[std::size_t(joint)];
    const int parent = skeleton.parent(joint);
    // The joint's place goes to its parent, or for a root to its first child.
    const int heir = parent >= 0 ? parent : (kids.empty() ? -1 : kids.front());
    for (int c : kids) {
        graph.disconnect(joint, c);
        graph.connect(heir, c);
    }
    if (parent >= 0)
        graph.disconnect(joint, parent);
    std::vector<int> roots;
    for (int r : skeletonRoots(skeleton)) {
        const int kept = r == joint ? heir : r;
        if (kept >= 0)
            roots.push_back(kept);
    }
    if (roots.empty())
        return unexpected(badIndex("joint", joint));
    std::vector<char> keep(std::size_t(graph.size()), 1);
    keep[std::size_t(joint)] = 0;
    std::vector<int> map;
    const JointGraph without = keptJoints(graph, keep, map);
    for (int &r : roots)
        r = map[std::size_t(r)];
    std::vector<int> index;
    SkeletonEdit edit;
    edit.skeleton = orderedSkeleton(without, roots, roots.front(), &index);
    edit.newIndex.resize(skeleton.jointCount());
    for (int v = 0; v < skeleton.jointCount(); ++v)
        edit.newIndex(v) = map[std::size_t(v)] >= 0 ? index[std::size_t(map[std::size_t(v)])] : -1;
    edit.joint = -1;
    return edit;
}

Expected<SkeletonEdit, GeometryError> setRoot(const Skeleton &skeleton, int joint)
{
    if (!hasJoint(skeleton, joint))
        return unexpected(badIndex("joint", joint));
    std::vector<int> roots{joint};
    for (int r : skeletonRoots(skeleton))
        roots.push_back(r);
    return reorder(toJointGraph(skeleton), roots, skeleton.jointCount(), joint);
}

} // namespace finbook::geometry
