// The skeleton's half of a DeformSetup: the rest skeleton as the skinning engine takes it,
// harmonic skinning weights of the object's mesh, and the rigid (ARAP-pinned) precompute.
// Built on the worker; solving it is the per-drag step.
#pragma once

#include <finbook/deform/skeleton/cut_out.h>
#include <finbook/deform/skeleton/linear_blend_skinning.h>
#include <finbook/deform/skeleton/rigid_skinning.h>
#include <finbook/model/deform_setup.h>

namespace finbook::model {

struct SkeletonSetup {
    deform::Skeleton skeleton;
    std::shared_ptr<const deform::SkinningWeights> weights;
    deform::SkinBinding vertices; // the mesh vertices bound for linear blend skinning
    std::shared_ptr<const deform::RigidSkinning> rigid;
    // A Cut-out rig's instead of `rigid`: the mesh cut at the joints, which solves and the
    // strokes' embedding follow (same triangles, vertices copied along the cuts), and the
    // rigid precompute of its pieces (SkeletonRig::sameRest rebuilds the setup when the mode
    // turns to or from Cut-out).
    std::optional<deform::CutMesh> cut;
    std::shared_ptr<const deform::RigidSkinning> cutRigid;
};

// The rest skeleton for deform/ (joints and parents). Errors: sentences for the user.
Expected<deform::Skeleton, QString> deformSkeleton(const SkeletonRig &rig);

// The skeleton that skins the object: its own joints, then, for a part hanging from another
// object's bone (SkeletonRig::hangs), that bone as two more joints (a tree of its own), so
// the weights include the bone it is joined to. Errors: sentences for the user.
Expected<deform::Skeleton, QString> skinningSkeleton(const SkeletonRig &rig);

// Forward kinematics of skinningSkeleton(rig) in the rig's pose, the anchor's motion
// composed after the part's own (the parent's bone moves by it alone).
Expected<deform::PosedSkeleton, QString> posedSkinningSkeleton(const deform::Skeleton &skeleton,
                                                               const SkeletonRig &rig);

// The stored pose for deform/: J angles (missing entries are 0) and the root offset.
deform::SkeletonPose skeletonPose(const SkeletonRig &rig);

// Weights, binding and rigid precompute of `meshed` for the rig's rest skeleton.
Expected<std::shared_ptr<const SkeletonSetup>, QString>
buildSkeletonSetup(const MeshedObject &meshed, const SkeletonRig &rig,
                   const deform::ArapOptions &options, const std::function<bool()> &cancelled);

// For a cut-out setup (setup.cut), the pieces of the pose U (its solveSkeleton vertices) that
// paintLayers draws one over the other: DeformedStrokes::pieceOf from each stroke point's
// triangle, DeformedStrokes::pieces from each cut piece's outline. `out.strokes` must hold
// the object's strokes in the embedding's order; DeformedStrokes::sockets from each cut's
// socket moved by the bone above it in `rig`'s pose. Other setups leave `out` as it is.
void addCutOutPieces(const SkeletonSetup &setup, const MeshedObject &meshed,
                     const Eigen::MatrixX2d &U, const SkeletonRig &rig, DeformedStrokes &out);

// Deformed mesh vertices (n×2) for the rig's pose in its skinning mode. `rig` must have the
// setup's rest joints.
Expected<Eigen::MatrixX2d, QString>
solveSkeleton(const MeshedObject &meshed, const SkeletonSetup &setup, const SkeletonRig &rig);

} // namespace finbook::model
