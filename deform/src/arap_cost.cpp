// How many refinement passes fit a drag event. The count must not depend on a clock: a drag
// pose has to be the same bits whenever and wherever it is solved (undo, reopen, export), so
// the time of a pass is predicted from the sizes that set it, with constants measured by
// `finbook-bench arap` on the 2-core development machine (memory-bound back-substitution).
#include "arap_solver.h"

#include <algorithm>
#include <cmath>

namespace finbook::deform::detail {
namespace {

// Nanoseconds per unit of work in one pass: per triangle (rotation fit, right-hand side,
// energy), per stored entry of the step-2 factor (forward and backward substitution with a
// complex right-hand side) and per free vertex (acceleration: history update, dot products,
// extrapolation).
// Fitted to 2k–100k-vertex grids, bars and drawings (a pass measured 0.07–0.15 ms at 2–3k
// vertices, 1.4 ms at 20k, 9.7 ms at 100k on a busy machine), rounded up.
constexpr double kTriangleNs = 15.0;
constexpr double kFactorEntryNs = 2.0;
constexpr double kFreeVertexNs = 15.0;
// Step 1 per basis entry (u = M q), or per factor entry when it back-substitutes through the
// complex factor instead (more than 32 handles); per vertex for the rest of an event
// (scatter, followers, flip check).
constexpr double kBasisEntryNs = 1.0;
constexpr double kComplexFactorEntryNs = 2.5;
constexpr double kVertexNs = 6.0;
// A drag event on a large mesh may take this many times the modelled cost of the paper's two
// steps. At 2 a warm drag event at 20k vertices held 2 passes (0.8 of a 60 Hz frame's time was
// left unused: 5 ms of thread CPU per event) and thin drawings lagged up to 3× the converged
// energy behind the pins; at 3 it holds 4–5 passes in 7–14 ms (a busy 2-core machine), which
// took 12 hard drawings' median from 1.55× to 1.12× the converged energy.
constexpr double kTwoStepShare = 3.0;

} // namespace

double chooseDragPasses(ArapPrecompute &d)
{
    const double factorEntries = d.freeCount > 0 ? double(d.stepTwoLower.nonZeros()) : 0.0;
    d.estimatedPassMs =
        1e-6 * (kTriangleNs * double(d.triangles.rows()) + kFactorEntryNs * factorEntries +
                kFreeVertexNs * double(d.freeCount));
    const double stepOneNs = d.handleEntry.size() <= kMaxBasisHandles
                                 ? kBasisEntryNs * double(d.freeCount * d.handleEntry.size())
                                 : kComplexFactorEntryNs * factorEntries;
    const double vertexMs = 1e-6 * kVertexNs * double(d.rest.size());
    const double stepOneMs = 1e-6 * stepOneNs;
    // With coarse rotations an event starts with E·q, the reduced iterations (at most) and
    // one global step instead of step 1.
    const double clusters = double(d.coarseCoupling.rows());
    // Where the budget cannot hold even the paper's two steps (large meshes), a drag event
    // may take up to kTwoStepShare times what they cost, with the same model on both sides.
    const double budgetMs = std::max(d.options.dragBudgetMs,
                                     kTwoStepShare * (stepOneMs + vertexMs + d.estimatedPassMs));
    const double iterationMs = 1e-6 * kBasisEntryNs * clusters * clusters;
    d.coarseIterations =
        iterationMs > 0.0 ? int(std::clamp(std::floor(kCoarseBudgetShare * budgetMs / iterationMs),
                                           double(kCoarseIterations), double(kMaxCoarseIterations)))
                          : kCoarseIterations;
    // A two-level start solves the coarse level's drag event (its own model), hands its
    // rotations over and takes one fine global step.
    const ArapPrecompute *level = d.coarseLevel.get();
    const double levelMs = level ? double(level->dragPasses + 2) * level->estimatedPassMs +
                                       1e-6 * kVertexNs * double(level->rest.size())
                                 : 0.0;
    const double fixedMs =
        level ? levelMs + d.estimatedPassMs + vertexMs
        : d.triangleCluster.size() > 0
            ? 1e-6 * kBasisEntryNs *
                      (double(d.coarseHandles.size()) + clusters * clusters * d.coarseIterations) +
                  d.estimatedPassMs + vertexMs
            : stepOneMs + vertexMs;
    const int cap = std::max(1, d.options.maxDragPasses);
    // The coarse start ends with a global step, worth one of the minimum's passes: with it one
    // fine pass left the 20k bar at 1.15× the converged energy, where two from step 1 left 1.51×.
    const int minimum = d.options.minDragPasses - (level || d.triangleCluster.size() > 0 ? 1 : 0);
    if (!(d.estimatedPassMs > 0.0)) {
        d.dragPasses = d.warmDragPasses = cap;
        return INFINITY;
    }
    const double fit = std::floor((budgetMs - fixedMs) / d.estimatedPassMs);
    d.dragPasses = int(std::clamp(fit, double(std::clamp(minimum, 1, cap)), double(cap)));
    // A warm event starts from the previous pose moved by step 1's answer to the handles'
    // move (no coarse rotations): step 1 and the per-vertex rest are fixed, and it runs at
    // least the cold event's minimum.
    const double warmFit = std::floor((budgetMs - stepOneMs - vertexMs) / d.estimatedPassMs);
    d.warmDragPasses =
        int(std::clamp(warmFit, double(std::clamp(d.options.minDragPasses, 1, cap)), double(cap)));
    return fit;
}

} // namespace finbook::deform::detail
