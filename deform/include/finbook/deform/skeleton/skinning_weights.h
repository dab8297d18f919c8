// Skinning weights: how much each bone moves each mesh vertex.
//
// Harmonic weights with bone boundary conditions: every vertex within a bone's reach is fixed
// to that bone (weight 1, the others 0), every bone fixes at least its nearest vertex, and the
// remaining vertices get the discrete harmonic interpolation of those values over the mesh
// (cotangent Laplacian, one sparse Cholesky factorization, one right-hand side per bone).
// Measured inside the mesh, so a finger's weight does not cross a gap into the next finger;
// the Laplacian's edge weights are clamped positive (an M-matrix), so the discrete maximum
// principle keeps every weight in [0, 1], and the weights of a vertex sum to 1 because the
// boundary values do. Chosen over bounded biharmonic weights (a QP: 0.84 s at 5.4k vertices in
// ../shared/notes/skeleton.md, about 75× this), unconstrained biharmonic weights (3–4× this
// and far outside [0, 1]) and Euclidean falloff (leaks across gaps); measured in issue 10.
#pragma once

#include <finbook/deform/deform_error.h>
#include <finbook/deform/skeleton/skeleton.h>
#include <finbook/geometry/expected.h>

#include <Eigen/Core>

#include <functional>
#include <memory>

namespace finbook::deform {

struct SkinningOptions {
    // Vertices closer to a bone than reach × (mean mesh edge length) are fixed to the nearest
    // such bone. Larger values make limbs stiffer and joints' transitions narrower.
    double reach = 0.5;
    // Joints whose bones skin this mesh; empty = every handle of the skeleton. A character
    // skeleton spans several objects: pass each object the bones that belong to it (and the
    // bone it is joined to), or a far bone would still take the vertex nearest to it.
    // Entries that are not handles (roots with children) are ignored.
    Eigen::VectorXi bones;
    // Joint zones (issue 21): with J radii (the inscribed radius at each joint, px), vertices
    // within jointFree × radius of a joint where bones meet (a bend or a junction) are held by
    // no bone, so the weights blend across the whole joint and the rigid mode's ARAP solve
    // places the joint's flesh itself: the inner side of a bend compresses, the outer side
    // stretches, instead of curling between pins of the two bones. Empty, or jointFree 0: off.
    Eigen::VectorXd jointRadius;
    double jointFree = 0.0;
};

// The joint-zone factor the app skins with: measured with `finbook-bench limbs` against the
// plain bone boundary (0) on ../shared/data.
inline constexpr double kDefaultJointFree = 1.0;

// Immutable once computeSkinningWeights returns it; safe to share between threads.
// "Handles" are what carries weight: every bone (column j for the bone ending at joint j) and
// every root without children (its column is the motion of that lone joint). Columns of other
// roots are zero.
struct SkinningWeights {
    Eigen::MatrixXd W;     // n×J: W(i, j) ∈ [0, 1] weight of handle j at vertex i, rows sum to 1
    Eigen::VectorXi owner; // n: handle whose boundary condition fixes vertex i, −1 if free
    Eigen::VectorXi handles; // joints that are handles (and in options.bones), ascending
    Eigen::VectorXi active;  // handles with a non-zero column, ascending (what skinning visits)
    // Of the harmonic solve for the sum of all bones (the solve is linear):
    // ‖L x − b‖∞ / (‖L‖∞‖x‖∞ + ‖b‖∞) with x = X·1, b = B·1.
    double relativeResidual = 0.0;
};

// W is dense: n × J doubles. Far above any character (30k vertices × 100 bones is 3M), far
// below what would exhaust memory.
inline constexpr double kMaxSkinningEntries = 2e7;

using SkinningWeightsResult = Expected<std::shared_ptr<const SkinningWeights>, DeformError>;

// V n×2 rest vertices, F m×3 triangles (as for arapPrecompute: non-degenerate, no pinched
// vertex), skeleton in the same coordinates. Bones may leave the mesh; a mesh component no bone
// reaches follows the bone nearest to it rigidly. `cancelled` is polled between phases and
// between right-hand sides. Errors: those of arapPrecompute's input checks, InvalidSkeleton
// (options.reach or jointFree negative or not finite, jointRadius neither empty nor J finite
// non-negative entries, options.bones naming no handle, or n × J beyond
// kMaxSkinningEntries), InvalidIndex (options.bones out of range), FactorizationFailed,
// SolveFailed, Cancelled.
SkinningWeightsResult computeSkinningWeights(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                             const Skeleton &skeleton,
                                             const SkinningOptions &options = {},
                                             std::function<bool()> cancelled = {});

// The same weights with joint zones in the boundary only (SkinningOptions::jointFree): every
// vertex within jointFree × jointRadius(j) of a joint j where bones meet is no longer held,
// (a bone left without any keeps the one nearest its middle). W is unchanged, so linear blend
// skinning is the same; the rigid mode built from the result (rigidSkinPins) leaves those vertices
// to the ARAP solve. jointRadius: J entries (other sizes, or jointFree ≤ 0: the weights unchanged).
SkinningWeights withJointZones(const SkinningWeights &weights, const Eigen::MatrixX2d &V,
                               const Skeleton &skeleton, const Eigen::VectorXd &jointRadius,
                               double jointFree = kDefaultJointFree);

// The handles of a skeleton (see SkinningWeights::handles).
Eigen::VectorXi skinningHandles(const Skeleton &skeleton);

} // namespace finbook::deform
