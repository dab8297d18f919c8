// Joins between the parts of a character: resolving them against the parents' rigs, the
// parts of a character, and automatic joins where parts overlap.
#include <finbook/geometry/skeleton/skeleton_connect.h>
#include <finbook/model/skeleton/skeleton_join.h>
#include <finbook/model/skeleton/skeleton_joint_edit.h>

#include <QLineF>

#include <algorithm>
#include <cmath>
#include <limits>

namespace finbook::model {

namespace {

// Fraction along a → b of the point nearest p, and the distance to it.
std::pair<double, double> project(QPointF p, QPointF a, QPointF b)
{
    const QPointF d = b - a;
    const double len2 = QPointF::dotProduct(d, d);
    const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, d) / len2, 0.0, 1.0) : 0.0;
    return {t, QLineF(p, a + t * d).length()};
}

int indexOf(const Frame &frame, Id id)
{
    for (std::size_t i = 0; i < frame.groups.size(); ++i)
        if (frame.groups[i].id == id)
            return int(i);
    return -1;
}

} // namespace

SkeletonAnchor anchorOn(const SkeletonRig &parent, QPointF parentAt)
{
    SkeletonAnchor a;
    if (parent.empty() || !parent.isValid() || !std::isfinite(parentAt.x()) ||
        !std::isfinite(parentAt.y()))
        return a;
    const std::vector<RigidMotion> motions = parent.boneMotions();
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity(), bestT = 0.0;
    for (std::size_t j = 0; j < parent.joints.size(); ++j) {
        const int p = parent.parent[j];
        if (p < 0)
            continue;
        const auto [t, d] = project(parentAt, parent.joints[std::size_t(p)], parent.joints[j]);
        if (d < bestDistance) {
            bestDistance = d;
            best = int(j);
            bestT = t;
        }
    }
    a.valid = true;
    if (best < 0) { // a skeleton of lone joints: hang from the root's motion
        const int r = parent.root;
        a.from = a.to = parent.joints[std::size_t(r)];
        a.motion = motions[std::size_t(r)];
        return a;
    }
    const int start = parent.parent[std::size_t(best)];
    // The bone the part overlaps skins it. Near the bone's start the part hangs from the
    // joint there, which moves with the bone ending at it (or, at a root, with the whole
    // tree); elsewhere with the bone itself.
    a.from = parent.joints[std::size_t(start)];
    a.to = parent.joints[std::size_t(best)];
    a.motion = motions[std::size_t(bestT < kJoinEndFraction ? start : best)];
    return a;
}

std::vector<Id> resolveJoins(Frame &frame)
{
    // Called on every rig change (each drag event): a frame without joins has nothing to do.
    if (std::none_of(frame.groups.begin(), frame.groups.end(), [](const StrokeGroup &g) {
            return g.rig.skeleton.join.joined() || !(g.rig.skeleton.anchor == SkeletonAnchor{});
        }))
        return {};
    const std::size_t n = frame.groups.size();
    enum State : char { Unvisited, Visiting, Done };
    std::vector<State> state(n, Unvisited);
    std::vector<SkeletonAnchor> anchors(n);
    // Depth-first, parents first; a parent met while still Visiting closes a loop.
    const auto resolve = [&](auto &&self, std::size_t i) -> void {
        if (state[i] != Unvisited)
            return;
        state[i] = Visiting;
        SkeletonRig &rig = frame.groups[i].rig.skeleton;
        SkeletonAnchor anchor;
        if (!rig.empty() && rig.join.joined()) {
            const int p = indexOf(frame, rig.join.parent);
            if (p >= 0 && std::size_t(p) != i && state[std::size_t(p)] != Visiting) {
                self(self, std::size_t(p));
                const SkeletonRig &parent = frame.groups[std::size_t(p)].rig.skeleton;
                if (!parent.empty())
                    anchor = anchorOn(parent, rig.join.parentAt);
            }
        }
        anchors[i] = anchor;
        rig.anchor = anchor; // before the children read this part's motions
        state[i] = Done;
    };
    std::vector<SkeletonAnchor> before(n);
    for (std::size_t i = 0; i < n; ++i)
        before[i] = frame.groups[i].rig.skeleton.anchor;
    for (std::size_t i = 0; i < n; ++i)
        resolve(resolve, i);
    std::vector<Id> changed;
    for (std::size_t i = 0; i < n; ++i)
        if (!(before[i] == anchors[i]))
            changed.push_back(frame.groups[i].id);
    return changed;
}

void remapJoins(Frame &frame, const std::unordered_map<Id, Id> &newIds)
{
    for (StrokeGroup &g : frame.groups) {
        SkeletonJoin &join = g.rig.skeleton.join;
        if (!join.joined())
            continue;
        if (auto it = newIds.find(join.parent); it != newIds.end())
            join.parent = it->second;
    }
}

Id characterRoot(const Frame &frame, Id groupId)
{
    Id at = groupId;
    for (std::size_t steps = 0; steps <= frame.groups.size(); ++steps) {
        const int i = indexOf(frame, at);
        if (i < 0)
            return groupId;
        const SkeletonRig &rig = frame.groups[std::size_t(i)].rig.skeleton;
        if (!rig.hangs())
            return at;
        at = rig.join.parent;
    }
    return groupId; // a loop (resolveJoins never leaves one valid)
}

std::vector<Id> characterParts(const Frame &frame, Id groupId)
{
    const Id root = characterRoot(frame, groupId);
    std::vector<Id> parts{root};
    // Breadth-first down the joins.
    for (std::size_t k = 0; k < parts.size(); ++k)
        for (const StrokeGroup &g : frame.groups)
            if (g.rig.skeleton.hangs() && g.rig.skeleton.join.parent == parts[k] &&
                std::find(parts.begin(), parts.end(), g.id) == parts.end())
                parts.push_back(g.id);
    return parts;
}

std::optional<SkeletonJoin> proposeJoin(const Frame &frame, Id child)
{
    const int c = indexOf(frame, child);
    if (c < 0 || frame.groups[std::size_t(c)].rig.skeleton.empty())
        return std::nullopt;
    const SkeletonRig &rig = frame.groups[std::size_t(c)].rig.skeleton;
    const geometry::Skeleton childSkeleton = geometrySkeleton(rig);
    const std::vector<Id> own = characterParts(frame, child);
    std::optional<SkeletonJoin> best;
    double bestScore = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < frame.groups.size(); ++i) {
        const StrokeGroup &g = frame.groups[i];
        if (g.rig.skeleton.empty() || !g.visible ||
            std::find(own.begin(), own.end(), g.id) != own.end())
            continue; // joining into its own character would close a loop
        const auto join = geometry::findJoin(0, childSkeleton, 1, geometrySkeleton(g.rig.skeleton));
        if (!join)
            continue;
        // Closest fit first: the attach point deepest inside the other part's skeleton.
        const QPointF at(join->parentAt.x(), join->parentAt.y());
        const QPointF from(join->childAt.x(), join->childAt.y());
        const double score = QLineF(at, from).length();
        if (score < bestScore) {
            bestScore = score;
            best = SkeletonJoin{g.id, from, at};
        }
    }
    return best;
}

SkeletonJoin joinAt(const SkeletonRig &child, Id parent, QPointF at)
{
    SkeletonJoin j;
    j.parent = parent;
    j.parentAt = at;
    j.childAt = child.root >= 0 && std::size_t(child.root) < child.joints.size()
                    ? child.joints[std::size_t(child.root)]
                    : at;
    return j;
}

} // namespace finbook::model
