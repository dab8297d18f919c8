// Joining the skeletons of several parts (objects) into one character skeleton, as RealSkel
// does for sub-parts (Ma et al. 2021): a part hangs from another part's skeleton by a bone
// split (its attach point projects inside a bone: the bone is split there and gets a joint)
// or a joint connect (to the nearer end of that bone). Which bone: the cylinder–ball test,
// the attach point lies within the bone's radius interpolated along it.
//
// Joins are data (PartJoin, a list per frame): detaching a part removes its join, dragging
// its root onto another bone replaces it with PartJoin{child, newParent, rootPosition,
// dropPoint}, and the character root is an argument. They are stored as points rather than
// joint indices, so a join survives re-running refinement on either part.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>
#include <finbook/geometry/skeleton/skeleton.h>

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace finbook::geometry {

enum class JoinKind {
    BoneSplit,    // the parent's bone was split and the child hangs from the new joint
    JointConnect, // the child hangs from an existing joint of the parent
};

struct PartJoin {
    int child = -1;  // index of the part that hangs
    int parent = -1; // index of the part it hangs from
    // Where the child attaches: its skeleton's point nearest this becomes the child's root
    // (a bone of the child is split there if that point lies inside it).
    Eigen::Vector2d childAt = Eigen::Vector2d::Zero();
    // Where it hangs: the parent's skeleton point nearest this (split or nearer bone end).
    Eigen::Vector2d parentAt = Eigen::Vector2d::Zero();
};

struct JoinOptions {
    // A point within this fraction of a bone's length of a bone end connects to that end
    // instead of splitting the bone (RealSkel's bone split happens only "inside" a bone).
    // In [0, 0.5).
    double endFraction = 0.15;
};

// The cylinder–ball test between two parts: among the points where a child bone crosses a
// parent bone and the child's joints, the one deepest inside a parent bone's interpolated
// radius (smallest distance / radius); or, the other way round, a parent joint inside a
// child bone's radius (then the child attaches where that joint projects onto it).
// nullopt if no point passes.
std::optional<PartJoin> findJoin(int childPart, const Skeleton &child, int parentPart,
                                 const Skeleton &parent);

// Automatic joins for a character: from rootPart outwards, every part not yet attached hangs
// from the attached part it fits best (findJoin), until no more part fits. Parts that touch
// no attached part stay separate. rootPart out of range: no joins.
std::vector<PartJoin> findJoins(const std::vector<Skeleton> &parts, int rootPart);

struct ResolvedJoin {
    int child = -1;
    int parent = -1;
    JoinKind kind = JoinKind::JointConnect;
    int joint = -1; // the character joint the child hangs from
};

struct Character {
    Skeleton skeleton; // part = index into `parts`; root = rootPart's root
    std::vector<ResolvedJoin> joins;
};

// One skeleton for all parts, joined as `joins` say (in order). A child joint that lands on
// its parent joint (a crossing) merges into it. Parts without a join stay separate trees.
// Errors: InvalidIndex (a part index out of range, a part without joints in a join, a join
// that would close a loop, or rootPart hanging from another part), InvalidOptions
// (endFraction, or a join point not finite).
Expected<Character, GeometryError> assembleCharacter(const std::vector<Skeleton> &parts,
                                                     const std::vector<PartJoin> &joins,
                                                     int rootPart, const JoinOptions &options = {});

} // namespace finbook::geometry
