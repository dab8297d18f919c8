#include "../command_text.h"

#include <finbook/model/skeleton/skeleton_join_commands.h>
#include <finbook/model/skeleton/skeleton_joint_edit.h>

#include <QLineF>

#include <algorithm>
#include <cmath>
#include <limits>

namespace finbook::model {

namespace {

StrokeGroup *groupIn(Frame &frame, Id id)
{
    for (StrokeGroup &g : frame.groups)
        if (g.id == id)
            return &g;
    return nullptr;
}

bool ownPoseAtRest(const SkeletonRig &rig)
{
    return rig.rootOffset == QPointF() &&
           std::all_of(rig.angles.begin(), rig.angles.end(), [](double a) { return a == 0.0; });
}

// The joint of `rig` nearest `at`.
int nearestJoint(const SkeletonRig &rig, QPointF at)
{
    int best = rig.root;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < rig.joints.size(); ++j)
        if (const double d = QLineF(rig.joints[j], at).length(); d < bestDistance) {
            bestDistance = d;
            best = int(j);
        }
    return best;
}

// On a working copy of a frame: `child` hangs as `join` says (nullopt: stands alone), showing
// the pose it shows now. With `reroot`, a part whose own pose is at rest turns about where it
// attaches. False when that is impossible (no skeleton, no parent skeleton, a loop).
bool hang(Frame &frame, Id child, const std::optional<SkeletonJoin> &join, bool reroot)
{
    StrokeGroup *c = groupIn(frame, child);
    if (!c || c->rig.skeleton.empty())
        return false;
    SkeletonAnchor anchor;
    if (join) {
        const StrokeGroup *p = groupIn(frame, join->parent);
        if (!p || p == c || p->rig.skeleton.empty())
            return false;
        // The parent must not hang below the child (the child's subtree).
        for (Id at = join->parent; at != kNoId;) {
            if (at == child)
                return false;
            const StrokeGroup *g = groupIn(frame, at);
            at = g && g->rig.skeleton.hangs() ? g->rig.skeleton.join.parent : kNoId;
        }
        anchor = anchorOn(p->rig.skeleton, join->parentAt);
    }
    SkeletonRig rig = c->rig.skeleton;
    if (reroot && join && ownPoseAtRest(rig)) {
        SkeletonRig bare = rig;
        bare.join = {};
        bare.anchor = {};
        if (auto rerooted = withRootJoint(bare, nearestJoint(bare, join->childAt))) {
            rerooted->join = rig.join;
            rerooted->anchor = rig.anchor;
            rig = std::move(*rerooted);
        }
    }
    rig = rig.keepingShownPose(anchor);
    rig.join = join ? *join : SkeletonJoin{};
    c->rig.skeleton = std::move(rig);
    resolveJoins(frame);
    return true;
}

// One SetRigCommand (child of `macro`) per object whose rig differs between the frames.
int addRigChanges(QUndoCommand *macro, Document *doc, const Frame &before, const Frame &after,
                  const QString &text)
{
    int changed = 0;
    for (std::size_t i = 0; i < before.groups.size() && i < after.groups.size(); ++i)
        if (!(before.groups[i].rig == after.groups[i].rig)) {
            new SetRigCommand(doc, after.groups[i].id, after.groups[i].rig, text, macro);
            ++changed;
        }
    return changed;
}

const Frame *frameOf(const Document *doc, Id groupId)
{
    const GroupLocation at = doc->locateGroup(groupId);
    return at.isValid() ? &doc->frameAt(at) : nullptr;
}

} // namespace

JoinPartCommand::JoinPartCommand(Document *doc, Id child, const SkeletonJoin &join,
                                 QUndoCommand *parent)
    : QUndoCommand(Command::tr("Join Part"), parent)
{
    const Frame *frame = frameOf(doc, child);
    Frame after = frame ? *frame : Frame{};
    if (!frame || !join.joined() || !hang(after, child, join, true) ||
        addRigChanges(this, doc, *frame, after, text()) == 0)
        setObsolete(true);
}

namespace {
Rig detached(const Document *doc, Id child)
{
    const Frame *frame = frameOf(doc, child);
    if (!frame)
        return {};
    Frame after = *frame;
    const StrokeGroup *g = groupIn(after, child);
    if (!g || !g->rig.skeleton.join.joined() || !hang(after, child, std::nullopt, false))
        return frame->groups[std::size_t(doc->locateGroup(child).group)].rig;
    return groupIn(after, child)->rig;
}
} // namespace

DetachPartCommand::DetachPartCommand(Document *doc, Id child, QUndoCommand *parent)
    : SetRigCommand(doc, child, detached(doc, child), Command::tr("Detach Part"), parent)
{}

JoinOverlappingPartsCommand::JoinOverlappingPartsCommand(Document *doc, Id frameId,
                                                         QUndoCommand *parent)
    : QUndoCommand(Command::tr("Join Overlapping Parts"), parent)
{
    const Frame *frame = doc->frame(frameId);
    if (!frame) {
        setObsolete(true);
        return;
    }
    Frame after = *frame;
    // Smaller parts hang from bigger ones: the biggest stays the character's root.
    std::vector<std::pair<double, Id>> parts;
    for (const StrokeGroup &g : after.groups) {
        const SkeletonRig &s = g.rig.skeleton;
        if (s.empty() || s.join.joined() || !g.visible)
            continue;
        double length = 0.0;
        for (std::size_t j = 0; j < s.joints.size(); ++j)
            if (s.parent[j] >= 0)
                length += QLineF(s.joints[j], s.joints[std::size_t(s.parent[j])]).length();
        parts.emplace_back(length, g.id);
    }
    std::stable_sort(parts.begin(), parts.end(),
                     [](const auto &a, const auto &b) { return a.first < b.first; });
    for (const auto &[length, id] : parts) {
        if (const auto join = proposeJoin(after, id); join && hang(after, id, *join, true))
            ++m_joined;
    }
    if (m_joined == 0 || addRigChanges(this, doc, *frame, after, text()) == 0)
        setObsolete(true);
}

MakeCharacterRootCommand::MakeCharacterRootCommand(Document *doc, Id part, QUndoCommand *parent)
    : QUndoCommand(Command::tr("Make Character Root"), parent)
{
    const Frame *frame = frameOf(doc, part);
    if (!frame) {
        setObsolete(true);
        return;
    }
    // The way up: part, its parent, …, the old root, with the join each hangs by.
    std::vector<std::pair<Id, SkeletonJoin>> path;
    Frame after = *frame;
    for (Id at = part; at != kNoId && path.size() <= after.groups.size();) {
        const StrokeGroup *g = groupIn(after, at);
        if (!g || !g->rig.skeleton.hangs())
            break;
        path.emplace_back(at, g->rig.skeleton.join);
        at = g->rig.skeleton.join.parent;
    }
    bool ok = !path.empty() && hang(after, part, std::nullopt, false);
    for (std::size_t i = 0; ok && i < path.size(); ++i) {
        const SkeletonJoin &old = path[i].second;
        ok = hang(after, old.parent, SkeletonJoin{path[i].first, old.parentAt, old.childAt}, false);
    }
    if (!ok || addRigChanges(this, doc, *frame, after, text()) == 0)
        setObsolete(true);
}

QUndoCommand *makeApplyPoseCommand(Document *doc, Id groupId)
{
    const Frame *frame = frameOf(doc, groupId);
    const std::vector<Id> parts =
        frame ? characterParts(*frame, groupId) : std::vector<Id>{groupId};
    if (parts.size() <= 1)
        return new ApplyPoseCommand(doc, groupId);
    auto *macro = new QUndoCommand(Command::tr("Apply Pose to Drawing"));
    bool any = false;
    for (Id id : parts) // the root first: a part's new rest hangs from its parent's
        any = !(new ApplyPoseCommand(doc, id, macro))->isObsolete() || any;
    if (!any)
        macro->setObsolete(true);
    return macro;
}

} // namespace finbook::model
