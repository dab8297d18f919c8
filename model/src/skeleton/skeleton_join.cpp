// Joins between the parts of a character: resolving them against the parents' rigs, the
// parts of a character, and automatic joins where parts overlap.
#include "join_resolution.h"
#include "nearest_bone.h"

#include <finbook/geometry/skeleton/skeleton_connect.h>
#include <finbook/model/skeleton/skeleton_join.h>
#include <finbook/model/skeleton/skeleton_joint_edit.h>

#include <QLineF>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <unordered_set>

namespace finbook::model {

namespace {

using join_detail::BoneIndex;
using join_detail::NearestBone;

// Skeletons up to this many joints are scanned; larger ones with parts hanging get an index.
constexpr std::size_t kScanJoints = 32;

// A parent's rig prepared once for all the parts hanging from it: its validity, its bones'
// motions and (when large) the nearest-bone index, each O(J) or O(J log J) instead of that per
// part. `rig` must outlive it and keep its anchor meanwhile (resolveJoins sets a parent's
// anchor before any part reads it).
class ParentBones {
public:
    ParentBones(const SkeletonRig &rig, bool indexed, std::int64_t &work)
        : m_rig(rig)
        , m_valid(!rig.empty() && rig.isValid())
    {
        work += 4 * std::int64_t(rig.joints.size());
        if (!m_valid)
            return;
        m_motions = rig.boneMotions();
        if (indexed && rig.joints.size() > kScanJoints)
            m_index.emplace(rig);
    }

    SkeletonAnchor anchorAt(QPointF parentAt, std::int64_t &work) const
    {
        SkeletonAnchor a;
        if (!m_valid || !std::isfinite(parentAt.x()) || !std::isfinite(parentAt.y()))
            return a;
        const NearestBone nearest = m_index ? m_index->nearest(parentAt, work)
                                            : join_detail::nearestByScan(m_rig, parentAt, work);
        a.valid = true;
        if (nearest.joint < 0) { // a skeleton of lone joints: hang from the root's motion
            const int r = m_rig.root;
            a.from = a.to = m_rig.joints[std::size_t(r)];
            a.motion = m_motions[std::size_t(r)];
            return a;
        }
        const int best = nearest.joint;
        const int start = m_rig.parent[std::size_t(best)];
        // The bone the part overlaps skins it. Near the bone's start the part hangs from the
        // joint there, which moves with the bone ending at it (or, at a root, with the whole
        // tree); elsewhere with the bone itself.
        a.from = m_rig.joints[std::size_t(start)];
        a.to = m_rig.joints[std::size_t(best)];
        a.motion = m_motions[std::size_t(nearest.t < kJoinEndFraction ? start : best)];
        return a;
    }

private:
    const SkeletonRig &m_rig;
    bool m_valid;
    std::vector<RigidMotion> m_motions;
    std::optional<BoneIndex> m_index;
};

// Every object's index in the frame by id (the first, should an id repeat).
std::unordered_map<Id, std::size_t> indexById(const Frame &frame)
{
    std::unordered_map<Id, std::size_t> index;
    index.reserve(frame.groups.size());
    for (std::size_t i = 0; i < frame.groups.size(); ++i)
        index.emplace(frame.groups[i].id, i);
    return index;
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
    std::int64_t work = 0;
    return ParentBones(parent, false, work).anchorAt(parentAt, work);
}

namespace join_detail {

bool resolveJoinsWithin(Frame &frame, std::int64_t &budget, std::vector<Id> *changed)
{
    if (changed)
        changed->clear();
    // Called on every rig change (each drag event): a frame without joins has nothing to do.
    if (std::none_of(frame.groups.begin(), frame.groups.end(), [](const StrokeGroup &g) {
            return g.rig.skeleton.join.joined() || !(g.rig.skeleton.anchor == SkeletonAnchor{});
        }))
        return true;
    const std::size_t n = frame.groups.size();
    const std::unordered_map<Id, std::size_t> byId = indexById(frame);
    constexpr std::size_t kNone = std::size_t(-1);
    const auto parentOf = [&](std::size_t i) {
        const SkeletonRig &rig = frame.groups[i].rig.skeleton;
        if (rig.empty() || !rig.join.joined())
            return kNone;
        const auto it = byId.find(rig.join.parent);
        return it == byId.end() || it->second == i ? kNone : it->second;
    };
    enum State : char { Unvisited, Visiting, Done };
    std::vector<State> state(n, Unvisited);
    std::vector<SkeletonAnchor> anchors(n), before(n);
    for (std::size_t i = 0; i < n; ++i)
        before[i] = frame.groups[i].rig.skeleton.anchor;
    std::vector<std::unique_ptr<ParentBones>> prepared(n);
    std::int64_t work = 0;
    // Depth-first, parents first, on an explicit stack (a chain of joins as long as the file
    // holds objects must not exhaust the call stack); a parent met while still Visiting closes
    // a loop, and the part meeting it stands alone.
    std::vector<std::size_t> stack;
    for (std::size_t first = 0; first < n; ++first) {
        if (state[first] != Unvisited)
            continue;
        stack.push_back(first);
        while (!stack.empty()) {
            const std::size_t i = stack.back();
            const std::size_t p = parentOf(i);
            if (state[i] == Unvisited) {
                state[i] = Visiting;
                if (p != kNone && state[p] == Unvisited) {
                    stack.push_back(p); // back to i once its parent is done
                    continue;
                }
            }
            SkeletonAnchor anchor;
            if (p != kNone && state[p] == Done) {
                if (!prepared[p])
                    prepared[p] =
                        std::make_unique<ParentBones>(frame.groups[p].rig.skeleton, true, work);
                anchor = prepared[p]->anchorAt(frame.groups[i].rig.skeleton.join.parentAt, work);
                if (work > budget)
                    return false;
            }
            anchors[i] = anchor;
            frame.groups[i].rig.skeleton.anchor = anchor; // before its parts read its motions
            state[i] = Done;
            stack.pop_back();
        }
    }
    budget -= work;
    if (changed)
        for (std::size_t i = 0; i < n; ++i)
            if (!(before[i] == anchors[i]))
                changed->push_back(frame.groups[i].id);
    return true;
}

std::int64_t joinWorkAllowance(const std::vector<Frame> &frames)
{
    std::int64_t items = 0;
    for (const Frame &f : frames)
        for (const StrokeGroup &g : f.groups)
            items += 1 + std::int64_t(g.rig.skeleton.joints.size());
    // A part costs about log J tree nodes and a few leaves of bones (under a hundred in all
    // even on a 100,000-joint skeleton); preparing a parent a few units per joint.
    return (std::int64_t(1) << 20) + 64 * items;
}

} // namespace join_detail

std::vector<Id> resolveJoins(Frame &frame)
{
    std::int64_t unlimited = std::numeric_limits<std::int64_t>::max();
    std::vector<Id> changed;
    join_detail::resolveJoinsWithin(frame, unlimited, &changed);
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
    const std::unordered_map<Id, std::size_t> byId = indexById(frame);
    Id at = groupId;
    for (std::size_t steps = 0; steps <= frame.groups.size(); ++steps) {
        const auto it = byId.find(at);
        if (it == byId.end())
            return groupId;
        const SkeletonRig &rig = frame.groups[it->second].rig.skeleton;
        if (!rig.hangs())
            return at;
        at = rig.join.parent;
    }
    return groupId; // a loop (resolveJoins never leaves one valid)
}

std::vector<Id> characterParts(const Frame &frame, Id groupId)
{
    const Id root = characterRoot(frame, groupId);
    // Each object's parts, in frame order, then breadth-first down the joins.
    std::unordered_map<Id, std::vector<Id>> partsOf;
    for (const StrokeGroup &g : frame.groups)
        if (g.rig.skeleton.hangs())
            partsOf[g.rig.skeleton.join.parent].push_back(g.id);
    std::vector<Id> parts{root};
    std::unordered_set<Id> seen{root};
    for (std::size_t k = 0; k < parts.size(); ++k)
        if (const auto it = partsOf.find(parts[k]); it != partsOf.end())
            for (Id part : it->second)
                if (seen.insert(part).second)
                    parts.push_back(part);
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
