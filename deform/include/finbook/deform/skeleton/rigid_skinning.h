// "Rigid" skeleton deformation: the vertices along each bone (the boundary conditions of the
// skinning weights) become ARAP pins that follow their bone rigidly, and the ARAP solver
// (arap.h) places everything else. Linear blend skinning averages rotations, so the flesh at a
// bent joint shrinks; ARAP keeps triangles as rigid as it can, which keeps limbs from thinning.
// Same split as the other deformers: precompute per rest mesh and skeleton (worker), solve per
// pose (drag).
#pragma once

#include <finbook/deform/arap.h>
#include <finbook/deform/deform_error.h>
#include <finbook/deform/skeleton/linear_blend_skinning.h>
#include <finbook/deform/skeleton/skeleton.h>
#include <finbook/deform/skeleton/skinning_weights.h>
#include <finbook/geometry/expected.h>

#include <Eigen/Core>

#include <functional>
#include <memory>

namespace finbook::deform {

// The pinned vertices, ascending: every vertex a bone holds (weights.owner ≥ 0), plus, in a
// mesh component with fewer than two of those, its vertex farthest from the first one (ARAP
// needs two pins per component to rotate it; the extra pin follows linear blend skinning).
// V n×2 and F m×3 as given to computeSkinningWeights. Errors: SizeMismatch (weights of
// another mesh) and those of arapPrecompute's input checks.
Expected<Eigen::VectorXi, DeformError>
rigidSkinPins(const SkinningWeights &weights, const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F);

// Immutable once rigidSkinPrecompute returns it; safe to share between threads for solving.
struct RigidSkinning {
    std::shared_ptr<const ArapPrecompute> arap; // pins = pinVertices, in that order
    Eigen::VectorXi pinVertices;                // k, as from rigidSkinPins
    SkinBinding pins; // the pins' rest positions and weights: their targets are LBS of them,
                      // i.e. exactly their bone's motion for vertices a bone holds
};

using RigidSkinningResult = Expected<std::shared_ptr<const RigidSkinning>, DeformError>;

// V n×2, F m×3 and weights as for computeSkinningWeights; options for the ARAP solve.
// Errors: those of arapPrecompute (Cancelled when `cancelled` returns true).
RigidSkinningResult rigidSkinPrecompute(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                        const SkinningWeights &weights,
                                        const ArapOptions &options = {},
                                        std::function<bool()> cancelled = {});

// U n×2 ← ARAP with every pin at its bone-driven position for this pose. posed from
// forwardKinematics of the skeleton the weights were computed for. Allocation-free after the
// first call on a thread. Errors: SizeMismatch and those of arapSolve (U then unspecified).
Expected<ArapSolveReport, DeformError>
rigidSkinSolve(const RigidSkinning &rig, const PosedSkeleton &posed, Eigen::MatrixX2d &U);

} // namespace finbook::deform
