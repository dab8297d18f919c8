// An object's skeleton in one frame: the rest bones (from the automatic skeleton, issue 9),
// the refinement settings they were made with, and the pose (issue 10).
//
// The pose is a pure function of the stored joint angles (relative to rest, radians) and the
// root offset (px), as deform/skeleton/skeleton.h defines it: no drag history, so undo, reopen
// and re-solve give the same strokes. The rest joints and parents are the rest definition (a
// change re-precomputes the skinning on the worker); angles, offset and skinning mode only
// re-solve. Joint locks (issue 10) only steer inverse kinematics: they are neither rest nor
// pose, so toggling one never re-precomputes or re-solves.
#pragma once

#include <QPointF>

#include <vector>

namespace finbook::model {

// The four refinement sliders of the Skeleton panel, each in [0, 1] of the range the raw
// skeleton allows (geometry::refineRanges): 0 = the automatic default.
struct SkeletonSettings {
    double complexity = 0.0; // 0 = fewest bones, 1 = a bone per raw skeleton edge
    double merge = 0.0;      // merge junctions closer than this fraction of the longest branch
    double prune = 0.0;      // remove terminal branches shorter than this fraction
    double collapse = 0.0;   // collapse internal bones shorter than this fraction
    friend bool operator==(const SkeletonSettings &, const SkeletonSettings &) = default;
};

// How the bones move the drawing: posed bones pin an ARAP solve (limbs keep their width at
// bent joints; the default), or linear blend skinning (cheaper, thins bent joints).
enum class SkinningMode { Rigid = 0, LinearBlend = 1 };

struct SkeletonRig {
    // Rest skeleton: joints (canvas px), parent[j] ∈ [−1, j) (−1 = root), inscribed radius
    // per joint (≥ 0, for drawing), and the character root (a root joint).
    std::vector<QPointF> joints;
    std::vector<int> parent;
    std::vector<double> radius;
    int root = -1;
    SkeletonSettings settings;
    // Pose: one angle per joint (empty or all zero = rest) and one offset for every root.
    std::vector<double> angles;
    QPointF rootOffset;
    SkinningMode mode = SkinningMode::Rigid;
    // Joints an IK drag must not move (the chain stops below them): empty when none is locked
    // (kept canonical so files and comparisons agree), else one flag per joint.
    std::vector<bool> locked;

    bool empty() const { return joints.empty(); }
    int jointCount() const { return int(joints.size()); }
    bool isPosed() const;
    bool isLocked(int joint) const;
    // The same skeleton with `joint`'s lock set to `on` (locked stays canonical).
    SkeletonRig withLock(int joint, bool on) const;
    // Children of each joint, in index order.
    std::vector<std::vector<int>> children() const;
    // The same skeleton with every angle zero and no offset.
    SkeletonRig atRest() const;
    // The posed joints become the rest joints, angles zero, offset zero.
    SkeletonRig rebased() const;
    // Joint positions in the current pose (rest when the pose does not fit).
    std::vector<QPointF> posedJoints() const;
    // Same rest joints and parents: what the skinning precompute depends on.
    bool sameRest(const SkeletonRig &other) const;
    // Sizes agree (locked empty or one per joint, not all false), everything finite,
    // parent[j] ∈ [−1, j), root a root, settings in [0, 1].
    bool isValid() const;
    friend bool operator==(const SkeletonRig &, const SkeletonRig &) = default;
};

} // namespace finbook::model
