// As-rigid-as-possible shape manipulation after Igarashi, Moscovich & Hughes 2005, with hard
// vertex pins. Precompute depends on the rest mesh and the SET of pinned vertices; every drag
// event only builds right-hand sides and back-substitutes (see ../shared/notes/arap.md).
//
//   step 1   similarity solve, as an n×n complex Hermitian system: u = M q with the dense basis
//            M = −G00⁻¹G01 (one complex solve per pin at precompute time)
//   step 2a  per-triangle rigid fit of the rest triangle to the step-1 result (Procrustes)
//   step 2b  scale adjustment: graph-Laplacian solve H00 u = f, x+iy as one complex
//            right-hand side against the real factor
//
// Refinement (ArapMethod::Refined, the default): step 1, then local/global iterations of the
// standard, cotangent-weighted ARAP energy Σ_t area_t ‖J_t − R_t‖²_F (Sorkine & Alexa 2007,
// Liu et al. 2008; libigl's ELEMENTS energy): 2a fits each triangle's rotation to its
// cotangent-weighted edge covariance and 2b solves with the cotangent Laplacian, so the first
// pass is the paper's two steps with step 2 in those weights. The passes are accelerated
// (over-relaxation, then Anderson acceleration with an energy safeguard): a budgeted number
// per drag event, to convergence for a stored pose; then flipped triangles are repaired by
// local relaxation of the same energy. The cotangent weight of an edge is negative where the
// angles opposite it add up to more than 180° (a non-Delaunay edge, or a boundary edge facing an
// obtuse angle); the CDT meshes the app builds have none (an edge whose opposite angles add up to
// exactly 180° weighs 0, whatever sign its round-off has), and where one occurs it is kept as
// it is: the energy is still a sum of per-triangle squares area·‖J − R‖², so both systems
// stay positive definite and every pass still lowers it.
//
// Pins are resolved per connected component of the mesh: one with ≥ 2 distinct pinned
// vertices gets the full solve, one with one pinned vertex translates with it, one with no
// pin follows the nearest pinned component rigidly (options.followNearestComponent; else,
// or when nothing is pinned, it stays at rest). Vertices referenced by no triangle are
// components of their own.
#pragma once

#include <finbook/deform/deform_error.h>
#include <finbook/deform/supernodal_cholesky.h>
#include <finbook/geometry/expected.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <complex>
#include <functional>
#include <memory>
#include <vector>

namespace finbook::deform {

// What a pose is solved with (the Deform → Rigidity setting).
enum class ArapMethod {
    // Igarashi 2005 exactly: steps 1, 2a, 2b (uniform weights, as in the paper), then
    // ArapOptions::extraPasses more 2a/2b passes, the same while dragging and when stored.
    // No flip fix.
    TwoStep,
    // Step 1, then accelerated local/global passes toward the cotangent-weighted ARAP optimum:
    // dragPasses of them per drag event, to convergence for a final (stored) pose; flipped
    // triangles that the optimum does not force are repaired.
    Refined,
};

// Which pose a solve is for. The model asks for Drag while a pin moves and for Final when
// the drag ends and whenever a pose is stored, saved, exported or baked; the method decides
// what each costs (see arapSolve below).
enum class ArapStage {
    Drag,
    Final,
};

struct ArapOptions {
    // Further local/global passes (2a + 2b again, started from the previous result). Each
    // costs about one more step-2 back-substitution; 0 is the paper's method exactly. The
    // result stays a pure function of the pin targets (no warm start across drag events).
    // Used by ArapMethod::TwoStep and by the three-argument arapSolve.
    int extraPasses = 0;
    ArapMethod method = ArapMethod::Refined;
    // Refined, Drag: per-event budget in ms (or 3× the modelled two steps, if more). It
    // becomes a pass count from the mesh size (a cost model, never a clock), so a drag pose
    // is a deterministic function of the pins (and of the start, for arapSolveFrom); see
    // ArapPrecompute::dragPasses. Half a 60 Hz frame: at 4 ms thin 17k-vertex sketches, whose
    // passes are cheap, got 3 passes per event (3 ms) and lagged up to 3× the converged
    // energy behind the pins; at 8 ms they get 8–12 (9–10 ms of thread CPU measured on a
    // busy 2-core machine, where the model's 8 ms take longer).
    double dragBudgetMs = 8.0;
    // Refined, Drag: at least / at most this many passes (a coarse start counts as one). Below
    // 2 a drag pose is barely better than the paper's; 35–70 fit 4 ms at 2k vertices (thin
    // drawings with nearly rigid optima need them: 32 left one at 1.57× the converged energy).
    int minDragPasses = 2;
    int maxDragPasses = 64;
    // Refined, Final: stop when no vertex moved more than finalTolerance × the object size
    // (diagonal of the solved components' bounding box) in a pass and the pass before lowered
    // the energy by no more than finalEnergyTolerance of it (0: not checked), or after
    // finalPassCap.
    double finalTolerance = 1e-6;
    double finalEnergyTolerance = 1e-7;
    // 400 left thin drawings meshed at ~20k vertices (slow, low-frequency rotation fields) up
    // to 1.06× the converged cotangent energy.
    int finalPassCap = 1000;
    // Refined: look for flipped triangles after a solve and repair those that the ARAP
    // optimum does not force: a drag pose gets up to dragPasses / 8 more passes (from 3
    // drag passes on) while the count of flips still falls, then every pose a bounded local
    // relaxation around what is left (which never raises the energy). Off only to measure
    // or test it.
    bool fixFlips = true;
    // A connected component without any pin follows the nearest pinned component rigidly
    // (rotation and translation of the pinned mesh where it is closest) instead of staying
    // at rest: a leg drawn apart from the body moves with the body.
    bool followNearestComponent = true;
    // Refined: a mesh whose solved part has at least this many vertices gets a two-level
    // start for its cold drag events (see ArapPrecompute::coarseLevel); 0 never. Below it
    // the budget holds enough fine passes (the 55 drawings at ~2k vertices: median 1.0000×
    // the converged energy); a 7.4k-vertex hand went from 1.29× to 1.03× with it.
    int twoLevelVertices = 5000;
};

// Immutable once arapPrecompute returns it; safe to share between threads for solving.
// Internal vertex numbering: [free vertices of fully solved components, in a fill-reducing
// order | distinct pinned vertices of those components ("handles") | vertices of components
// with fewer than two pinned vertices ("rigid")]. Solved systems are assembled pre-permuted
// so both factors use natural ordering and solves skip the permutation.
struct ArapPrecompute {
    using ComplexMatrix = Eigen::SparseMatrix<std::complex<double>>;
    using RealMatrix = Eigen::SparseMatrix<double>;
    // Both systems are factored by supernodes (supernodal_cholesky.h) in the same
    // fill-reducing order, so one symbolic analysis serves both.
    using ComplexFactor = CholeskyFactor<std::complex<double>>;

    ArapOptions options;
    // Refined, Drag: passes after step 1 (or coarse start) per drag event, from options and the
    // cost model below; estimatedPassMs is that model's cost of one pass on the reference
    // machine (the 2-core development machine): Final costs about that per pass it runs.
    int dragPasses = 0;
    // Refined, Drag started from the previous event's pose (arapSolveFrom): no step 1 or
    // coarse start to pay for, so the same budget holds more passes.
    int warmDragPasses = 0;
    double estimatedPassMs = 0.0;
    double objectSize = 0.0;        // bounding-box diagonal of the solved components (rest)
    Eigen::Index pinEntryCount = 0; // rows of b as passed; bc must have as many rows
    Eigen::VectorXi pinnedVertices; // distinct pinned vertices, ascending (original indices)

    Eigen::VectorXi order;       // n: internal index → original vertex
    Eigen::Index freeCount = 0;  // free vertices (first block)
    Eigen::VectorXi handleEntry; // per handle: entry of b whose target it takes (the last one)
    Eigen::VectorXi rigidEntry;  // per rigid vertex: entry of b translating it, else −1 (rest
                                 // or following, see rigidFollowGroup)
    Eigen::VectorXcd entryRest;  // per entry of b: rest position of its vertex, x+iy
    Eigen::VectorXcd rest;       // n rest positions x+iy, internal order

    Eigen::MatrixX3i triangles;     // triangles of solved components, internal indices
    Eigen::MatrixX3cd restCentered; // their rest corners minus the rest centroid
    // Per triangle and corner k: the weight w_k of the edge opposite k (½ cot of the angle at
    // k for Refined, 1 for TwoStep), and ⅓ Σ_j w_kj (v_k − v_j) over the two edges at k, which
    // is restCentered for uniform weights. Step 2a's covariance is Σ conj(restWeighted_k)·p_k
    // and step 2b's right-hand side gathers 3·R·restWeighted_k.
    Eigen::MatrixX3d edgeWeight;
    Eigen::MatrixX3cd restWeighted;
    Eigen::VectorXd collapseThreshold; // below this |Σ conj(r)·p| the step-1 triangle collapsed
    Eigen::VectorXd restSquaredNorm;   // Σ_k w_k |rest edge opposite k|² per triangle
    Eigen::VectorXd restDoubleArea;    // signed, in the triangle's own corner order
    int negativeWeightEdges = 0;       // edges whose assembled weight is below 0 (see above)
    // Corners around each free vertex, for gathering step 2's right-hand side per vertex:
    // those of free vertex i are cornerStart(i) … cornerStart(i + 1) − 1.
    Eigen::VectorXi cornerStart;    // freeCount + 1
    Eigen::VectorXi cornerTriangle; // row of `triangles` the corner belongs to
    Eigen::VectorXcd cornerRest;    // the corner's centred rest position

    ComplexMatrix stepOneMatrix;                             // G00, upper triangle
    ComplexMatrix stepOneCoupling;                           // G01, freeCount × handles
    std::shared_ptr<const SupernodalSymbolic> factorPattern; // of H00, which G00 shares
    ComplexFactor stepOneFactor; // LLᴴ of G00, only kept without a basis (see below)
    double stepOneNorm = 0.0;    // ‖G00‖∞, scales the residual test
    // M = −G00⁻¹G01, row-major so that u = M q is one pass. Empty when there are more than
    // 32 handles: then applying it would cost more than step 1 back-substituting per event.
    Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>
        stepOneBasis;
    RealMatrix stepTwoMatrix;   // H00 (the edge-weighted Laplacian: cotangent or uniform)
    RealMatrix stepTwoCoupling; // H01, freeCount × handles
    // L of H00 = LLᵀ, compressed columns with the diagonal first in each (what the step-2
    // back-substitution kernel walks), and 1 / diag(L).
    RealMatrix stepTwoLower;
    Eigen::VectorXd stepTwoPivotInverse;
    double stepTwoNorm = 0.0; // ‖H00‖∞, scales the residual test

    // Triangles around each solved vertex (free and handles, internal index < freeCount +
    // handles): those of vertex v are vertexTriangle(vertexStart(v)) … (vertexStart(v+1) − 1).
    // Used by the flip repair and to find the rotation a following component takes.
    Eigen::VectorXi vertexStart;
    Eigen::VectorXi vertexTriangle;
    // Components without pins that follow another (options.followNearestComponent): per
    // rigid vertex, the follower group it belongs to or −1; per group, the internal index of
    // the anchor vertex (the pinned component's vertex nearest to the group at rest).
    Eigen::VectorXi rigidFollowGroup;
    Eigen::VectorXi followAnchor;

    // Coarse rotations (Refined, Drag, when the budget allows only a few passes): the solved
    // triangles are grouped into K compact clusters that share one rotation, and that reduced
    // ARAP problem is solved exactly in K dimensions before the fine passes. With the global
    // step linear in the rotations, a cluster's covariance Σ conj(r)·p is S = C·R + E·q
    // (R the K unit rotations, q the handle targets). Empty when not used.
    Eigen::VectorXi triangleCluster;   // per row of `triangles`: its cluster
    Eigen::MatrixXcd coarseCoupling;   // C, K×K, Hermitian
    Eigen::MatrixXcd coarseHandles;    // E, K×handles
    Eigen::VectorXd coarseThreshold;   // per cluster: below this |S| the cluster collapsed
    Eigen::MatrixXcd coarseSimilarity; // (diag(ρ) − C)⁻¹, K×K: the relaxed start (or empty)
    int coarseIterations = 0;          // reduced iterations per drag event at most (cost model)

    // Two-level start (Refined, options.twoLevelVertices solved vertices or more): the
    // solved part meshed again with about a tenth of the vertices and precomputed with its own
    // pins; a cold event (drag or stored pose) solves it first and starts the fine passes from
    // its triangles' rotations. Empty when not used (then coarse rotations or step 1 start).
    std::shared_ptr<const ArapPrecompute> coarseLevel;
    Eigen::VectorXi coarseLevelTriangle; // per row of `triangles`: the coarse row it lies in
    // Per pin of the coarse level (its b as passed): its target is Σ_r weight·(target of
    // handle r) + offset, handles numbered 0 … handles − 1.
    Eigen::MatrixX3i coarseLevelHandles;
    Eigen::MatrixX3d coarseLevelWeights;
    Eigen::VectorXcd coarseLevelOffset;
};

// relativeResidual: largest ‖Ax − b‖∞ / (‖A‖∞‖x‖∞ + ‖b‖∞) over the linear solves of one
// call (Refined checks the solve each result comes from, not every intermediate pass).
struct ArapSolveReport {
    double relativeResidual = 0.0;
    int passes = 0;            // 2a/2b passes (global solves) after step 1
    bool converged = false;    // Final: the tolerance was met before options.finalPassCap
    int flippedTriangles = 0;  // flipped triangles in the returned pose
    int repairedTriangles = 0; // flipped triangles the repair turned back (fixFlips)
    // Refined: how much the last accelerated pass lowered the energy, relative to it (before
    // the flip repair, which only lowers it further).
    double lastEnergyChange = 0.0;
};

using ArapPrecomputeResult = Expected<std::shared_ptr<const ArapPrecompute>, DeformError>;
using ArapSolveResult = Expected<ArapSolveReport, DeformError>;

// V  n×2 rest positions (finite), F  m×3 triangles (any orientation, non-zero area, no vertex
// where fans of triangles touch only at a point; unreferenced vertices allowed), b  k pinned
// vertex indices (may repeat: the LAST entry for a vertex wins). `cancelled` is polled between
// phases and between basis solves; when it returns true the result is DeformErrorCode::Cancelled.
// Errors: EmptyMesh, InvalidIndex, NonFiniteInput, CoordinateOutOfRange, DegenerateTriangle,
// NonManifoldVertex, FactorizationFailed, SolveFailed, Cancelled. Runs a helper thread for large
// meshes.
ArapPrecomputeResult arapPrecompute(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                    const Eigen::VectorXi &b, const ArapOptions &options = {},
                                    std::function<bool()> cancelled = {});

// bc  k×2 targets, one row per entry of b as passed to arapPrecompute. U  out n×2 deformed
// positions (resized). Steps 1, 2a, 2b, then options.extraPasses × (2a, 2b), whatever
// options.method says (the paper's method, as before ArapMethod existed; with a Refined
// precompute step 2 uses its cotangent weights).
// Allocation-free after the first call on a thread (per-thread scratch buffers).
// Errors: SizeMismatch, NonFiniteInput, CoordinateOutOfRange, SolveFailed; U is left
// unspecified on error.
ArapSolveResult arapSolve(const ArapPrecompute &data, const Eigen::MatrixX2d &bc,
                          Eigen::MatrixX2d &U);

// The pose for `stage` with data.options.method (pure function of data and bc: the same
// bits for the same pins and precompute, on any thread, whatever was solved before):
//   TwoStep            steps 1, 2a, 2b + options.extraPasses, for both stages;
//   Refined, Drag      step 1 or coarse rotations + dragPasses accelerated passes, flip fix;
//   Refined, Final     the same start + accelerated passes until converged (see
//                      ArapOptions::finalTolerance; or finalPassCap), flip repair.
// Final costs about estimatedPassMs per pass; drawings of ~2k vertices took 1–400 passes
// (median 51, 35 ms on a very busy 2-core machine) in `finbook-bench arap --quality`, so run it
// on a worker when estimatedPassMs × finalPassCap exceeds a frame. `cancelled` is polled
// between passes (Final only); then the result is DeformErrorCode::Cancelled.
// Errors as the three-argument form, plus Cancelled.
ArapSolveResult arapSolve(const ArapPrecompute &data, const Eigen::MatrixX2d &bc,
                          Eigen::MatrixX2d &U, ArapStage stage,
                          const std::function<bool()> &cancelled = {});

// A drag event started from `start` (n×2: the pose the previous event of this drag returned, or
// the stored pose the drag began from) instead of from step 1 or the coarse rotations: with
// Refined, data.warmDragPasses accelerated passes from there, then the flip repair, as the Drag
// stage. Each event then only corrects how far the pins moved since the last one, so along a
// drag the pose stays close to the converged one, where a cold event's few passes on a large
// mesh cannot reach it. The pose depends on the drag's path, so it is only for showing a
// drag: the stored pose is the Final stage's, a pure function of the pins. With TwoStep, or a
// start of the wrong size or with a non-finite or out-of-range coordinate, it is the Drag
// stage's pose (start ignored). When `start` is, bit for bit, the pose the previous
// arapSolveFrom on this thread returned for the same precompute (the app's drag: its events
// run on one thread, each from the pose the last one showed), the event continues that one:
// its start also takes what the last event's passes added to their start, scaled by how far
// the handles moved this time along last time's move, where that lowers the energy
// (momentum: in a steady drag the pose keeps up with the pins instead of lagging behind).
// Errors as the three-argument form.
ArapSolveResult arapSolveFrom(const ArapPrecompute &data, const Eigen::MatrixX2d &bc,
                              const Eigen::MatrixX2d &start, Eigen::MatrixX2d &U);

// Step 1 only (the similarity result v′ the paper starts step 2 from); same contract as
// arapSolve. Exposed for tests and for showing what step 2 corrects.
ArapSolveResult arapSimilarity(const ArapPrecompute &data, const Eigen::MatrixX2d &bc,
                               Eigen::MatrixX2d &U);

// x ← H00⁻¹ x for a freeCount-row right-hand side with x and y packed as x + iy: one forward
// and one backward pass over the real step-2 factor, the least work a drag event can do.
// Exposed so that benchmarks can measure that floor with the kernel arapSolve uses.
void arapStepTwoBacksubstitute(const ArapPrecompute &data, Eigen::Ref<Eigen::VectorXcd> x);

// Uniform-weight ARAP energy Σ_t Σ_edges(i→j) |(u_j − u_i) − R_t (v_j − v_i)|² with the best
// rotation R_t per triangle: the energy the paper's step 2 and its extra passes cannot increase.
// V  n×2 rest, F  m×3, U  n×2 deformed; indices must be valid.
double arapEnergy(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F, const Eigen::MatrixX2d &U);

// The standard ARAP energy Σ_t area_t ‖J_t − R_t‖²_F (J_t the triangle's deformation
// gradient, R_t its closest rotation), which equals Σ_t Σ_edges ½ cot(opposite angle)·
// |(u_j − u_i) − R_t (v_j − v_i)|²: what ArapMethod::Refined minimises, independent of how the
// shape was triangulated. Computed from J directly. Same requirements as arapEnergy, and rest
// triangles of non-zero area.
double arapCotangentEnergy(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                           const Eigen::MatrixX2d &U);

// Triangles of F whose signed area in U has the strictly opposite sign to the one in V:
// turned inside out (collapsed ones do not count). Same requirements as arapEnergy.
int arapFlippedTriangles(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                         const Eigen::MatrixX2d &U);
// The same triangles' rows of F, ascending (Show Mesh draws them).
std::vector<int> arapFlippedTriangleRows(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                         const Eigen::MatrixX2d &U);

} // namespace finbook::deform
