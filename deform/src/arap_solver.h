// The per-solve pieces shared by the two-step solve (arap_solve.cpp), the refinement passes
// (arap_refine.cpp), the flip repair (arap_flips.cpp) and following components
// (arap_follow.cpp). All positions are x + iy in the internal vertex order of ArapPrecompute.
#pragma once

#include "arap_internal.h"

#include <finbook/deform/arap.h>

#include <Eigen/SparseCore>

#include <vector>

namespace finbook::deform::detail {

// Per-thread buffers: a drag event must not allocate (at 100k vertices fresh megabyte-sized
// vectors cost more page faults than the whole back-substitution).
struct Workspace {
    Eigen::VectorXcd positions;      // n, internal order: v′, then v″
    Eigen::VectorXcd rhs;            // freeCount
    Eigen::VectorXcd residual;       // freeCount, only for the step-1 fallback without basis
    Eigen::VectorXcd rotations;      // per solved triangle, 3·R
    Eigen::VectorXcd trialRotations; // the same for an extrapolated candidate
    // Refinement (Anderson acceleration) state, freeCount rows each.
    Eigen::VectorXcd iterate, mapped, mappedBefore, residualBefore;
    Eigen::MatrixXcd mappedSteps, residualSteps;    // freeCount × history
    std::vector<int> region, mark;                  // flip repair
    std::vector<int> untangleFlipped, untangleLeft; // flip repair: flips before/after the finish
    double refinedEnergy = 0.0; // the energy refine() ended with (an upper bound of the pose's)
    Eigen::VectorXcd saved;     // flip repair: the region's positions before a restart
    Eigen::VectorXcd pushSaved; // flip repair: the region's positions before an apex push
    Eigen::VectorXcd coarseRotations, coarseCovariance, coarseHandleTerm; // K each
    Eigen::VectorXcd coarseLevelRotations; // two-level start: 3·R per coarse-level triangle
    Eigen::VectorXcd handleTargets;        // handles: a warm start's targets while step 1 moves it
    // A drag's momentum (arap_solve.cpp): the precompute and the pose the last warm event on
    // this thread returned; that event's start moved by step 1 (free vertices), its handles'
    // move, and what its passes added to that start. warmPlain and handleMove are the current
    // event's, before it ends.
    const ArapPrecompute *dragOwner = nullptr;
    Eigen::MatrixX2d dragPose;
    Eigen::VectorXcd warmPlain, handleMove, lastCorrection, lastMove;
    Eigen::VectorXcd olderCorrection;  // the correction of the event before the last
    Eigen::VectorXcd correctionChange; // lastCorrection − olderCorrection (acceleration)
};

Workspace &workspace();

// Plain complex products: std::complex's operator* adds NaN-recovery branches (Annex G) to
// the hottest loops, and inputs here are finite by construction.
inline Complex mul(Complex a, Complex b)
{
    return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

inline Complex mulConj(Complex a, Complex b) // conj(a)·b
{
    return {a.real() * b.real() + a.imag() * b.imag(), a.real() * b.imag() - a.imag() * b.real()};
}

// Sizes the workspace for d, checks bc and places handles and pinned components (step 0).
std::optional<DeformError> beginSolve(const ArapPrecompute &d, const Eigen::MatrixX2d &bc,
                                      Workspace &w);

// Step 1 into w.positions.head(freeCount); `check` adds the residual test of the solve (when
// there is no basis).
std::optional<DeformError> similarityStep(const ArapPrecompute &d, Workspace &w,
                                          ArapSolveReport &report, bool check);

// Step 2a at w.positions: 3·(best rotation) per triangle into w.rotations. With `energy`
// it also returns the uniform ARAP energy of w.positions (the solved components' part).
double fitRotations(const ArapPrecompute &d, const Eigen::VectorXcd &W, Eigen::VectorXcd &rotations,
                    bool energy);

// Step 2b from w.rotations: w.positions.head(freeCount) ← H00⁻¹ f, f kept in w.rhs.
void globalStep(const ArapPrecompute &d, Workspace &w);

// Relative residual check of the last globalStep (into report), SolveFailed when too large.
std::optional<DeformError> checkGlobalStep(const ArapPrecompute &d, const Workspace &w,
                                           ArapSolveReport &report);

// Accelerated local/global passes from the step-1 result in w.positions (Refined). Runs
// `passes` passes, or with tolerance > 0 until no free vertex moves more than `tolerance` in a
// pass or (energyTolerance > 0) a pass lowers the energy by no more than energyTolerance of
// it (at most `passes`); then up to `flipPasses` more while a triangle is flipped. Leaves
// the result of the last global step in w.positions.
std::optional<DeformError> refine(const ArapPrecompute &d, Workspace &w, int passes, int flipPasses,
                                  double tolerance, double energyTolerance,
                                  const std::function<bool()> &cancelled, ArapSolveReport &report);

// Flipped triangles at W (signed area ≤ 0 relative to the rest orientation).
int countFlips(const ArapPrecompute &d, const Eigen::VectorXcd &W);

// Local ARAP relaxation of the free vertices around flipped triangles until none is left or a
// sweep cap is reached (never increases the energy), then one restart from a smoothed region
// for folds that survive it (kept only with fewer flips), then the injective finish for those
// that survive that (kept only with fewer flips and at most a small share more energy, more
// for a drag pose than a `final` one). Fills report.flipped/repairedTriangles.
void repairFlips(const ArapPrecompute &d, Workspace &w, ArapSolveReport &report, bool final);

// Moves the vertices of follower components with their anchors (after the solve).
void placeFollowers(const ArapPrecompute &d, Eigen::VectorXcd &W);

// Precompute side of following: fills d.rigidFollowGroup and d.followAnchor.
void buildFollowers(const Eigen::VectorXi &componentLabel, const std::vector<bool> &pinned,
                    ArapPrecompute &d);

// Precompute side of the cost model: d.estimatedPassMs and d.dragPasses. Returns how many
// passes the budget holds before the options' minimum and maximum apply.
double chooseDragPasses(ArapPrecompute &d);

// When the drag budget holds fewer passes than this, a precompute adds coarse rotations:
// not only on large meshes (the bars of `finbook-bench arap` needed 3–4 passes after them at
// 20k vertices) but on thin 2k-vertex drawings with nearly rigid optima, where 35–70 plain
// passes from step 1 left up to 4.6× the converged energy. Smaller meshes, whose budget holds
// more, converge by plain passes within maxDragPasses.
constexpr int kCoarseBelowPasses = 128;
// Reduced iterations per drag event at most (K² work each): kCoarseIterations, or up to
// kMaxCoarseIterations while their modelled cost stays within kCoarseBudgetShare of the drag
// budget (see ArapPrecompute::coarseIterations). Plain reduced iterations converge slowly on
// thin drawings: on a 2k-vertex quickdraw hand (71 clusters) 200 left the drag pose at 1.48×
// the converged energy, 400 at 1.22×, even with fewer fine passes after them.
constexpr int kCoarseIterations = 200;
constexpr int kMaxCoarseIterations = 400;
constexpr double kCoarseBudgetShare = 0.5;

// Precompute side of coarse rotations, in steps so that two threads can share the columns
// (one step-2 back-substitution each): prepare() clusters the solved triangles and sizes C
// and E (false: not used, too many clusters); column(k) fills column k of C and row k of E,
// so distinct k may run at once; finish() after all columns.
class CoarseBuilder {
public:
    struct Corners { // per solved vertex: its clusters and Σ conj(r) over its corners in each
        std::vector<int> start, cluster;
        std::vector<Complex> weight;
    };
    bool prepare(ArapPrecompute &d);
    int count() const { return m_count; }
    // Columns first … first + kBlockWidth − 1 (those below count()); x is scratch.
    void columns(ArapPrecompute &d, int first, std::vector<Complex> &x) const;
    void finish(ArapPrecompute &d) const;

private:
    Corners m_corners;
    int m_count = 0;
};

// Drag start with coarse rotations: solves the clustered problem from the handles in
// w.positions, then one global step with those rotations into w.positions.head(freeCount).
void coarseStart(const ArapPrecompute &d, Workspace &w);

// Two-level start (arap_two_level.cpp), for meshes whose solved part has at least
// options.twoLevelVertices vertices (Refined). The coarse level's drag event gets
// kTwoLevelBudgetShare of the drag budget (measured before the outline was meshed at a fixed
// size: at half, 21 coarse passes left the 20k bar at 1.11× the converged energy, at three
// quarters 33 passes 1.08×, a converged coarse level 1.004×).
constexpr double kTwoLevelBudgetShare = 0.75;

// What the precompute builds beside the fine systems (from the original numbering; it may run
// on another thread): the coarse level and, per coarse pin, its three fine pinned vertices,
// weights and offset (see ArapPrecompute::coarseLevelHandles).
struct TwoLevelBuild {
    std::shared_ptr<const ArapPrecompute> level;
    Eigen::MatrixX3i entryVertices;
    Eigen::MatrixX3d entryWeights;
    Eigen::VectorXcd entryOffset;
};
// No value when the outline cannot be meshed coarser, a coarse part would not be solved, or the
// coarse mesh would not be much smaller.
std::optional<TwoLevelBuild> buildTwoLevel(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                           const std::vector<Eigen::Index> &solvedTriangles,
                                           const Eigen::VectorXi &b, const ArapOptions &options);
// Hands the build to d in its internal numbering and re-runs the cost model; false (d
// unchanged) when it does not fit.
bool attachTwoLevel(ArapPrecompute &d, const TwoLevelBuild &build,
                    const std::vector<int> &internal);
// The cold start from the coarse level: solves it for the handles in w.positions (its drag
// event, or converged when `final`), then one fine global step with its rotations. False
// when the coarse solve fails (then nothing was changed).
bool twoLevelStart(const ArapPrecompute &d, Workspace &w);
// The coarse level's solve, on a workspace of its own: 3·R per row of level.triangles.
bool solveCoarseLevel(const ArapPrecompute &level, const Eigen::MatrixX2d &bc,
                      Eigen::VectorXcd &rotations);

// Drag events from the previous pose (arap_warm.cpp). A start of the mesh's size, finite and in
// range; the cold event's start (coarse rotations or step 1) into w.positions; the start of a
// warm event into w.positions and the passes that follow it (with `continued`, the momentum
// of the last event); whether `start` is the pose the last warm event on w returned for d;
// and remembering this event's pose and correction for the next one.
bool usableStart(const ArapPrecompute &d, const Eigen::MatrixX2d &start);
std::optional<DeformError> coldStart(const ArapPrecompute &d, Workspace &w, ArapSolveReport &report,
                                     bool drag = false);
Expected<int, DeformError> warmOrCold(const ArapPrecompute &d, const Eigen::MatrixX2d &start,
                                      Workspace &w, ArapSolveReport &report, bool continued);
bool continuesDrag(const ArapPrecompute &d, const Workspace &w, const Eigen::MatrixX2d &start);
void rememberDrag(const ArapPrecompute &d, Workspace &w, const Eigen::MatrixX2d &U);

// Writes internal-order positions into U (n×2, original order).
void scatterPositions(const ArapPrecompute &d, const Eigen::VectorXcd &W, Eigen::MatrixX2d &U);

} // namespace finbook::deform::detail
