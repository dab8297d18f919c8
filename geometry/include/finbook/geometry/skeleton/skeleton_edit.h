// Hand edits of a skeleton as pure functions: each takes a skeleton and returns a new one, so
// an undo command keeps the two values and nothing else. Joints are renumbered to keep
// parent[j] < j (skeleton.h); newIndex says where every old joint went.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>
#include <finbook/geometry/skeleton/skeleton.h>

#include <Eigen/Core>

namespace finbook::geometry {

struct SkeletonEdit {
    Skeleton skeleton;
    Eigen::VectorXi newIndex; // old joint → new joint, −1 for a deleted joint
    int joint = -1;           // the joint the edit moved, inserted or made root; −1 otherwise
};

// Moves a joint; its radius stays. Indices do not change.
// Errors: InvalidIndex (no such joint), InvalidOptions (`to` not finite or beyond
// kMaxCoordinate).
Expected<SkeletonEdit, GeometryError> moveJoint(const Skeleton &skeleton, int joint,
                                                const Eigen::Vector2d &to);

// Splits bone `bone` (the bone ending at joint `bone`, from its parent) at fraction t of the
// way from the parent, with the radius interpolated; the new joint belongs to the bone's
// part. Errors: InvalidIndex (no such bone: bone is a root or out of range), InvalidOptions
// (t not strictly between 0 and 1).
Expected<SkeletonEdit, GeometryError> insertJoint(const Skeleton &skeleton, int bone, double t);

// Removes a joint. Its children hang from its parent instead; a root's first child becomes
// the tree's root (and the character root if the deleted joint was), its other children hang
// from that one. Errors: InvalidIndex (no such joint, or the skeleton's only joint).
Expected<SkeletonEdit, GeometryError> deleteJoint(const Skeleton &skeleton, int joint);

// Makes a joint the root of its tree and the character root. Errors: InvalidIndex.
Expected<SkeletonEdit, GeometryError> setRoot(const Skeleton &skeleton, int joint);

} // namespace finbook::geometry
