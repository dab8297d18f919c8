// Characters made of parts (issue 9): each object's skeleton may hang from a bone of another
// object in the same frame (SkeletonRig::join). This resolves joins into anchors (which bone,
// and how it moves in the parent's pose), finds the parts of a character, and proposes joins
// where parts overlap (geometry::findJoin, RealSkel's bone split / joint connect).
#pragma once

#include <finbook/model/types.h>

#include <optional>
#include <unordered_map>
#include <vector>

namespace finbook::model {

// Near a bone's start (within this fraction of its length) a part hangs from the joint there
// (a joint connect), which moves with the bone ending at it, or with its whole tree at a
// root; elsewhere it hangs from the bone itself (a bone split, or a connect at its end).
// Either way the bone it overlaps is the bone its weights include.
constexpr double kJoinEndFraction = 0.15;

// Where a part hanging at `parentAt` (the parent's rest coordinates) hangs on `parent`: the
// nearest rest bone (or the joint at its start, see kJoinEndFraction), and that bone's motion
// in the parent's shown pose (its own anchor included). Invalid when `parent` is empty.
SkeletonAnchor anchorOn(const SkeletonRig &parent, QPointF parentAt);

// Resolves the anchor of every skeleton in the frame against its parent as it is now,
// parents first. A join whose parent is missing, has no skeleton, or closes a loop resolves
// invalid (the part then stands alone until the parent is back). Returns the ids of the
// objects whose anchor changed.
std::vector<Id> resolveJoins(Frame &frame);

// After a frame's objects got new ids (a duplicated frame, in-betweens): joins follow them.
// Joins to objects not in the map are left as they are (they resolve invalid).
void remapJoins(Frame &frame, const std::unordered_map<Id, Id> &newIds);

// The objects of the character `groupId` belongs to (joined to it either way, transitively,
// by valid joins), its root part first; just `groupId` when it stands alone.
std::vector<Id> characterParts(const Frame &frame, Id groupId);

// The part at the top of `groupId`'s character (the one that hangs from nothing).
Id characterRoot(const Frame &frame, Id groupId);

// Where `child` would hang if joined automatically: geometry::findJoin between its skeleton
// and each other object's skeleton in the frame (rest coordinates), not creating a loop; the
// best fitting parent. nullopt when no part overlaps it.
std::optional<SkeletonJoin> proposeJoin(const Frame &frame, Id child);

// The join that hangs `child` from `parent` at the rest point `at` of the parent's skeleton
// (for dragging a part's root onto a bone): childAt is the child's root.
SkeletonJoin joinAt(const SkeletonRig &child, Id parent, QPointF at);

} // namespace finbook::model
