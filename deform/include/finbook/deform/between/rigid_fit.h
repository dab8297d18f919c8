// Fitting drawing A onto drawing B as rigidly as possible: where did each part of key A go in
// key B (issue 50, "Between Drawings").
//
// Method: non-rigid ICP with an ARAP regulariser (Amberg, Romdhani & Vetter 2007, "Optimal
// step nonrigid ICP", with its stiffness term replaced by the 2D ARAP energy of Sorkine &
// Alexa 2007 as in ARAP-regularised registration):
//   1. coarse alignment of the two point sets by their moments (centroid, principal axes;
//      the 4 sign choices of the axes, of which the 2 proper rotations are kept, and the
//      un-rotated placement; lowest symmetric chamfer distance wins, ties to the smaller
//      turn), then through the pins if any (1 pin: the candidate translated onto it; ≥ 2:
//      the best rigid / similarity transform through them);
//   2. a few rigid (or similarity) ICP steps;
//   3. ARAP-regularised ICP, stiffness annealed from stiff to relaxed: each iteration pairs
//      every A sample with the nearest B point whose normal agrees (|n_A·n_B| ≥ cos 60°: a
//      stroke may run either way) and every B point with the nearest agreeing A sample
//      (symmetric, so that limbs of B that A's samples do not reach still pull on A), drops
//      pairs farther than 3 × the median pair distance, and takes one local/global step of
//        α·E_ARAP(U) + w·Σ_pairs ‖A_s(U) − y‖² + w_pin·Σ_pins ‖A_p(U) − q‖²
//      (cotangent-weighted ARAP, a rotation per triangle; A_s(U) a sample's barycentric
//      position), until no vertex moves more than the tolerance.
// All coordinates are canvas pixels; V F as in arap.h. Nothing here throws or returns NaN.
#pragma once

#include <finbook/deform/deform_error.h>
#include <finbook/geometry/embedding.h>
#include <finbook/geometry/expected.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace finbook::deform::between {

struct RigidFitOptions {
    // Also fit one uniform scale (the whole drawing drawn larger or smaller): the moments
    // give the coarse scale, and the ARAP term fits one global scale with the rotations.
    // Off: A keeps its size.
    bool allowScale = false;
    // A pair's normals must agree to |cos| ≥ this (cos 60°).
    double normalAgreement = 0.5;
    // Pairs farther than this × the median pair distance are dropped.
    double rejectFactor = 3.0;
    bool symmetric = true; // also pair every B point with its nearest A sample
    int rigidIterations = 20;
    // ARAP stiffness α per stage, stiff to relaxed; each stage runs until converged or
    // stageIterations. Dimensionless: the energy is α·E_ARAP/area + mean pair distance²/D²
    // (E_ARAP = Σ_t area_t‖J_t − R_t‖², D the diagonal of A's points), so α = 0.01 means a
    // distortion ‖J − R‖ of 0.1 over all of A weighs as much as pairs 1 % of D apart.
    std::vector<double> stiffness = {3e-2, 1e-2, 3e-3, 1e-3, 3e-4};
    int stageIterations = 30;
    double pinWeight = 50.0; // a pin weighs this many pairs' worth
    // A hinge between two pieces of A's mesh (rigidFitPrecompute) holds its two vertices
    // together with this many pairs' worth.
    double hingeWeight = 50.0;
    // Converged: no vertex moved more than tolerance × B's bounding-box diagonal in one
    // iteration of the last stage.
    double tolerance = 2e-4;
    // Pin changes (rigidRefit): iterations at the last stiffness, warm-started.
    int refitIterations = 12;
    // Failed: the median A→B or B→A residual above this fraction of B's diagonal, or A
    // distorted by more than failDistortion (RigidFitResult::distortion).
    double failMedian = 0.05;
    double failDistortion = 0.25;
    // Failed, too: more than failUncovered of B's points farther than failMedian × B's
    // diagonal from every fitted sample of A, or more than failUncoveredStrained of them with A
    // distorted by more than strainedDistortion (a limb crumpled where it could not swing out).
    // On the 478 shared drawings (finbook-bench between) every fit either refuses misses the
    // error targets, and none that meets them is refused.
    double failUncovered = 0.075;
    double failUncoveredStrained = 0.05;
    double strainedDistortion = 0.1;
};

// A's mesh and samples, precomputed once per drawing (the mesh's Laplacian structure and its
// fill-reducing analysis, per-triangle rest data). Immutable; share it between fits.
struct RigidFitSource;

// B's points and normals with a search grid over them. Immutable.
struct RigidFitTarget;

// Correspondence pins: p points of A (barycentric in A's mesh, as geometry::embed gives)
// and where each belongs in B.
struct FitPins {
    geometry::Embedding where; // I p, B p×3
    Eigen::MatrixX2d targets;  // p×2
};

// Pins on samples (rows of the source's sample embedding) or on vertices of A's mesh.
FitPins pinsAtSamples(const geometry::Embedding &samples, const Eigen::VectorXi &rows,
                      const Eigen::MatrixX2d &targets);
FitPins pinsAtVertices(const Eigen::MatrixX3i &F, const Eigen::VectorXi &vertices,
                       const Eigen::MatrixX2d &targets);

using RigidFitSourceResult = Expected<std::shared_ptr<const RigidFitSource>, DeformError>;

// V n×2 rest positions, F m×3 triangles (non-zero area, indices < n), samples: k points
// embedded in (V, F) (geometry::embed; I k with rows of F, B k×3), N k×2 the samples' unit
// normals (a stroke's normal there; either sign). Errors: EmptyMesh (no triangles or no
// samples), InvalidIndex, NonFiniteInput, CoordinateOutOfRange, DegenerateTriangle,
// SizeMismatch (N or B rows ≠ I size).
// `hinges`: pairs of vertices the fit holds together (RigidFitOptions::hingeWeight) though no
// triangle joins them: a mesh of pieces meshed apart (an arm drawn over the body, meshed on its
// own: model/inbetween/between_drawings.h), each piece turning about its hinge as a cut-out
// puppet's limbs do, instead of bending the flesh the union of the two would make.
RigidFitSourceResult rigidFitPrecompute(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                        const geometry::Embedding &samples,
                                        const Eigen::MatrixX2d &N,
                                        const std::vector<std::array<int, 2>> &hinges = {});

// P k×2 B's points, N k×2 their unit normals (either sign). Non-finite rows are dropped;
// an empty target is allowed (every fit against it fails with EmptyTarget).
std::shared_ptr<const RigidFitTarget> rigidFitTarget(const Eigen::MatrixX2d &P,
                                                     const Eigen::MatrixX2d &N);

enum class FitStatus {
    Fitted,
    ResidualTooLarge, // the fit settled, but far from B: see RigidFitResult::where
    EmptyTarget,      // B has no points
    InvalidPins,      // pins with bad triangles or weights, or non-finite targets
    SolveFailed,      // the linear system could not be factored (reported, never NaN)
};

// The transform of the coarse alignment: x ↦ linear·x + translation.
struct CoarseAlignment {
    Eigen::Matrix2d linear = Eigen::Matrix2d::Identity();
    Eigen::Vector2d translation = Eigen::Vector2d::Zero();
    double chamfer = 0.0; // symmetric chamfer distance of the chosen candidate (px)
};

struct RigidFitResult {
    FitStatus status = FitStatus::EmptyTarget;
    bool converged = false;
    int iterations = 0; // ARAP iterations (global solves) in all stages
    // n×2 fitted vertices and k×2 fitted samples; always finite (the rest pose when nothing
    // could be fitted).
    Eigen::MatrixX2d U;
    Eigen::MatrixX2d samples;
    double scale = 1.0; // the global scale the fit settled on (1 unless allowScale)
    CoarseAlignment coarse;
    // Per sample, distance to the nearest agreeing B point (∞ → B's diagonal if none);
    // median and 95th percentile, in px and relative to B's diagonal; and the median of
    // B's points to the nearest agreeing fitted sample (B covered by A).
    Eigen::VectorXd residual;
    double medianResidual = 0.0, p95Residual = 0.0;
    double relativeMedian = 0.0, relativeP95 = 0.0;
    double coverageMedian = 0.0;
    // B's points farther than options.failMedian × B's diagonal from every fitted sample: how
    // many (a share of B's points) and their box in B's coordinates (a part of B that nothing
    // of A landed on, such as a limb B shows where A's could not go).
    double uncoveredShare = 0.0;
    Eigen::AlignedBox2d uncoveredRegion;
    bool partUncovered = false; // failed for that (failUncovered…), not for the medians
    double targetDiagonal = 0.0;
    // How far from rigid the fit is: √(Σ_t area_t‖J_t − s·R_t‖²_F / (2·area)), the RMS
    // stretch of A's triangles (0 for a rigid motion, 0.1 for 10 % stretched everywhere).
    double distortion = 0.0;
    // Where the fit is worst: the samples with the largest residuals (at most 5 %, at least
    // one, largest first), and their bounding box in A's rest coordinates. Filled for every
    // fit; the message says what failed when status is not Fitted.
    std::vector<int> worstSamples;
    Eigen::AlignedBox2d worstRegion;
    std::string message;
};

// The full fit: coarse alignment, rigid ICP, annealed ARAP ICP. ≤ 300 ms at 2k vertices is
// the budget (see `finbook-bench-between`).
RigidFitResult rigidFit(const RigidFitSource &source, const RigidFitTarget &target,
                        const FitPins &pins = {}, const RigidFitOptions &options = {});

// A's skeleton (its automatic one): joints in A's rest coordinates, parent[j] < j (−1 for a
// root). Joints that are not finite, or parents out of range, make it ignored.
struct FitSkeleton {
    std::vector<Eigen::Vector2d> joints;
    std::vector<int> parent;
    bool empty() const { return joints.empty(); }
};

// The same with an articulated coarse step (as in articulated ICP, e.g. Pellegrini et al.
// 2008). After the rigid alignment, the body — the bone with the most samples nearest it — is
// placed by a rigid ICP of its own samples (the whole-drawing alignment is a compromise
// between the body and every limb B shows turned); then, root to tips, each bone is turned
// with everything below it about its base joint by the angle in ±120° that lays its own
// samples best on B (the sum of distances to the nearest agreeing B point, each capped at 5 %
// of B's diagonal; a bone with under 6 samples of its own is judged with everything below
// it). The ARAP stages start from those turned parts (each vertex moved with the bone nearest
// it). Such a start can also put a part on the wrong limb of B, so the first (stiffest) stage
// runs from each start — the rigid alignment, its two articulated starts, and the articulated
// start from the unturned placement when the moments chose a turned one — the two that then
// lie closest run the other stages, and the fit whose samples and B's points lie closest both
// ways (the sum of the two medians and of B's uncovered share times the distance that makes a
// point uncovered, times 1 + distortion) is kept.
// With an empty skeleton this is rigidFit above.
RigidFitResult rigidFit(const RigidFitSource &source, const RigidFitTarget &target,
                        const FitPins &pins, const FitSkeleton &skeleton,
                        const RigidFitOptions &options = {});

// After a pin was added, moved or removed: options.refitIterations ARAP ICP iterations at the
// last stiffness, started from `previous` (a result of the same source; otherwise this is
// rigidFit). Meant for live pin drags (≤ 100 ms at 2k vertices).
RigidFitResult rigidRefit(const RigidFitSource &source, const RigidFitTarget &target,
                          const FitPins &pins, const RigidFitResult &previous,
                          const RigidFitOptions &options = {});

} // namespace finbook::deform::between
