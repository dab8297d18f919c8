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

} // namespace

void chooseDragPasses(ArapPrecompute &d)
{
    const double factorEntries =
        d.freeCount > 0 ? double(d.stepTwoFactor.matrixL().nestedExpression().nonZeros()) : 0.0;
    d.estimatedPassMs =
        1e-6 * (kTriangleNs * double(d.triangles.rows()) + kFactorEntryNs * factorEntries +
                kFreeVertexNs * double(d.freeCount));
    const double stepOneNs = d.stepOneBasis.cols() == d.handleEntry.size()
                                 ? kBasisEntryNs * double(d.stepOneBasis.size())
                                 : kComplexFactorEntryNs * factorEntries;
    const double fixedMs = 1e-6 * (stepOneNs + kVertexNs * double(d.rest.size()));
    const int cap = std::max(1, d.options.maxDragPasses);
    const int floor = std::clamp(d.options.minDragPasses, 1, cap);
    if (!(d.estimatedPassMs > 0.0)) {
        d.dragPasses = cap;
        return;
    }
    const double fit = std::floor((d.options.dragBudgetMs - fixedMs) / d.estimatedPassMs);
    d.dragPasses = int(std::clamp(fit, double(floor), double(cap)));
}

} // namespace finbook::deform::detail
