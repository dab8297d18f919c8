// An object's skeleton in one frame: the rest bones (from the automatic skeleton, issue 9),
// the refinement settings they were made with, and the pose (issue 10).
//
// The pose is a pure function of the stored joint angles (relative to rest, radians) and the
// root offset (px), as deform/skeleton/skeleton.h defines it: no drag history, so undo, reopen
// and re-solve give the same strokes. The rest joints and parents are the rest definition (a
// change re-precomputes the skinning on the worker); angles, offset and skinning mode only
// re-solve (except a change to or from Cut-out, which skins another mesh). Joint locks (issue 10)
// only steer inverse kinematics: they are neither rest nor pose, so toggling one never
// re-precomputes or re-solves.
#pragma once

#include <QPointF>

#include <cstdint>
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
// bent joints; the default), linear blend skinning (cheaper, thins bent joints), or cut-out:
// the drawing cut apart at the joints where a limb narrows (deform/skeleton/cut_out.h), each
// piece turning rigidly with its bone, as a cut-out puppet's limbs do.
enum class SkinningMode { Rigid = 0, LinearBlend = 1, CutOut = 2 };
constexpr int kLastSkinningMode = 2;

// A rigid motion of the canvas, x ↦ R(angle) x + shift (R as in deform/skeleton/skeleton.h).
struct RigidMotion {
    double angle = 0.0;
    QPointF shift;
    QPointF map(QPointF x) const;
    QPointF unmap(QPointF x) const;                   // the inverse motion
    RigidMotion then(const RigidMotion &after) const; // this first, then `after`
    bool isIdentity() const { return angle == 0.0 && shift == QPointF(); }
    friend bool operator==(const RigidMotion &, const RigidMotion &) = default;
};

// Parts of a character (issue 9): an object's skeleton can hang from a bone of another object
// in the same frame, so posing the parent moves the part (its root follows that bone) and the
// part's skinning weights include that bone. Stored as points, like geometry::PartJoin, so a
// join survives rebuilding either skeleton. A part without a join is a character root.
struct SkeletonJoin {
    std::uint64_t parent = 0; // Id of the object it hangs from (types.h); 0 = not joined
    QPointF childAt;          // where it attaches: near its own root (rest, canvas px)
    QPointF parentAt;         // where it hangs: on the parent's rest skeleton
    bool joined() const { return parent != 0; }
    friend bool operator==(const SkeletonJoin &, const SkeletonJoin &) = default;
};

// A join resolved against the parent's rig as it is now (model::resolveJoins; the Document
// keeps it current whenever a rig in the frame changes). Derived: never saved, never edited.
struct SkeletonAnchor {
    bool valid = false; // the parent exists in the frame with a skeleton, and no loop
    // The parent's rest bone the part overlaps, which its weights include (from == to: a
    // parent of lone joints), in the part's rest coordinates (all objects share the canvas
    // at rest): a rest definition.
    QPointF from, to;
    // How the point it hangs from moves from rest to the parent's pose (that bone's motion,
    // or the joint's at the bone's start; the parent's own anchor included): applied after
    // the part's own pose. Identity when the parent is at rest.
    RigidMotion motion;
    friend bool operator==(const SkeletonAnchor &, const SkeletonAnchor &) = default;
};

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
    // Joints where a limb leaves the body (the shoulder, the hip), as the automatic skeleton
    // found them (geometry::Skeleton::limbBase): an IK drag of a joint below one turns the limb
    // there instead of swinging the bone into the body. Empty when there is none (canonical,
    // as `locked`), else one flag per joint; hand edits keep the flags of the joints they keep.
    std::vector<bool> limbBase;
    // Where this part hangs in a character (rest definition), and that join resolved.
    SkeletonJoin join;
    SkeletonAnchor anchor;

    bool empty() const { return joints.empty(); }
    int jointCount() const { return int(joints.size()); }
    // Own angles or offset, or a parent that moves the part.
    bool isPosed() const;
    // The anchor applies: the part follows its parent's bone.
    bool hangs() const { return join.joined() && anchor.valid; }
    bool isLocked(int joint) const;
    bool isLimbBase(int joint) const;
    // The same skeleton with `joint`'s lock set to `on` (locked stays canonical).
    SkeletonRig withLock(int joint, bool on) const;
    // Children of each joint, in index order.
    std::vector<std::vector<int>> children() const;
    // The same skeleton with every angle zero and no offset.
    SkeletonRig atRest() const;
    // The posed joints become the rest joints, angles zero, offset zero.
    SkeletonRig rebased() const;
    // Joint positions in the current pose, the anchor's motion included (rest when the pose
    // does not fit).
    std::vector<QPointF> posedJoints() const;
    // The same without the anchor: the part's own pose, in its parent bone's rest frame.
    std::vector<QPointF> ownPosedJoints() const;
    // Per joint, the motion of its bone from rest to the shown pose (a root: its tree's
    // motion), the anchor's included. Identity motions when the pose does not fit.
    std::vector<RigidMotion> boneMotions() const;
    // The same pose shown with `newAnchor` (applied when valid: the caller sets the join that
    // goes with it) instead of the current anchor: the root's angle
    // and the offset absorb the difference, so the drawing does not jump when a join is made,
    // broken or turned around (exact for the root's tree; other roots of a forest share the
    // offset and may shift).
    SkeletonRig keepingShownPose(const SkeletonAnchor &newAnchor) const;
    // Same rest joints and parents and anchor bone, and both cut out or neither: what the
    // skinning precompute depends on (a cut-out rig skins a mesh cut at its joints).
    bool sameRest(const SkeletonRig &other) const;
    // Sizes agree (locked and limbBase empty or one per joint, not all false), everything finite,
    // parent[j] ∈ [−1, j), root a root, settings in [0, 1].
    bool isValid() const;
    friend bool operator==(const SkeletonRig &, const SkeletonRig &) = default;
};

} // namespace finbook::model
