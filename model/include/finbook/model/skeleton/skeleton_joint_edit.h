// Editing a rest skeleton by hand (issue 9): move a joint, split a bone with a new joint,
// delete a joint. Pure functions on a SkeletonRig; the commands in skeleton_commands.h wrap
// them. They keep the rig's invariants (parent[j] < j, a root that is a root, canonical locks)
// and refuse a posed skeleton: a rest edit under a pose would make the shown bones jump.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/skeleton/skeleton.h>
#include <finbook/model/skeleton/skeleton_rig.h>

#include <QString>

namespace finbook::model {

// `joint` moved to `at` (canvas px). Errors: posed, no such joint, `at` not finite.
Expected<SkeletonRig, QString> withJointMoved(const SkeletonRig &rig, int joint, QPointF at);

struct InsertedJoint {
    SkeletonRig rig;
    int joint = -1; // the new joint's index (the split bone's old child index)
};

// Bone `bone` (the bone ending at joint `bone`) split by a new joint at the point of the bone
// nearest `at`, kept a little away from both ends. The new joint takes index `bone`; later
// joints move up by one, so parents still come before children. Its radius is interpolated,
// it is unlocked. Errors: posed, `bone` not a bone, `at` not finite, a bone too short to split.
Expected<InsertedJoint, QString> withJointInserted(const SkeletonRig &rig, int bone, QPointF at);

// `joint` removed. Its children hang from its parent; a root's first child becomes the root
// and takes its siblings. Errors: posed, no such joint, fewer than two joints would be left.
Expected<SkeletonRig, QString> withJointDeleted(const SkeletonRig &rig, int joint);

// The rest skeleton as the geometry layer takes it (every joint in part 0).
geometry::Skeleton geometrySkeleton(const SkeletonRig &rig);

// `joint` made the root of its tree and the skeleton's root (bones along the way turn
// around; joints are renumbered so parents come first, locks follow their joints).
// Errors: posed, no such joint.
Expected<SkeletonRig, QString> withRootJoint(const SkeletonRig &rig, int joint);

} // namespace finbook::model
