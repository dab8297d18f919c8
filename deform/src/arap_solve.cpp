#include "arap_solver.h"

#include <finbook/deform/arap.h>

namespace finbook::deform {
namespace detail {

Workspace &workspace()
{
    thread_local Workspace w;
    return w;
}

namespace {

Complex target(const Eigen::MatrixX2d &bc, int entry)
{
    return {bc(entry, 0), bc(entry, 1)};
}

std::optional<DeformError> checkTargets(const ArapPrecompute &d, const Eigen::MatrixX2d &bc)
{
    if (bc.rows() != d.pinEntryCount)
        return makeError(DeformErrorCode::SizeMismatch,
                         "expected " + std::to_string(d.pinEntryCount) + " pin targets, got " +
                             std::to_string(bc.rows()));
    if (!bc.allFinite())
        return makeError(DeformErrorCode::NonFiniteInput, "a pin target is not a finite number");
    if (bc.size() > 0 && bc.cwiseAbs().maxCoeff() > kMaxDeformCoordinate)
        return makeError(DeformErrorCode::CoordinateOutOfRange, "a pin target is too large");
    return std::nullopt;
}

// Handles take their targets; components with fewer than two pinned vertices translate with
// their pin (or stay at rest until placeFollowers moves them), which is their zero-energy
// answer and keeps G00, H00 SPD.
void placeConstrained(const ArapPrecompute &d, const Eigen::MatrixX2d &bc, Eigen::VectorXcd &W)
{
    const Eigen::Index nf = d.freeCount, handles = d.handleEntry.size();
    for (Eigen::Index c = 0; c < handles; ++c)
        W(nf + c) = target(bc, d.handleEntry(c));
    for (Eigen::Index i = 0; i < d.rigidEntry.size(); ++i) {
        const int entry = d.rigidEntry(i);
        const Complex shift = entry >= 0 ? target(bc, entry) - d.entryRest(entry) : Complex();
        W(nf + handles + i) = d.rest(nf + handles + i) + shift;
    }
}

std::optional<DeformError> checkSolve(bool finite, double relative, ArapSolveReport &report)
{
    report.relativeResidual = std::max(report.relativeResidual, relative);
    if (!finite || !(relative <= kResidualTolerance))
        return makeError(DeformErrorCode::SolveFailed,
                         "the deformation solve was inaccurate (relative residual " +
                             std::to_string(relative) + ")");
    return std::nullopt;
}

// Right-hand side of step 2b for the free vertices: each triangle's rigid copy contributes
// Σ_j w_kj R(v_k − v_j) = 3·R·restWeighted_k to its corner k (the 3 is in `rotations`). Gathered
// per vertex: sequential writes, no dependency between consecutive rows.
void rigidFitRhs(const ArapPrecompute &d, const Eigen::VectorXcd &rotations, Eigen::VectorXcd &rhs)
{
    const int *start = d.cornerStart.data(), *triangle = d.cornerTriangle.data();
    const Complex *rest = d.cornerRest.data(), *rotation = rotations.data();
    Complex *out = rhs.data();
    for (Eigen::Index v = 0; v < d.freeCount; ++v) {
        Complex sum;
        for (int c = start[v]; c < start[v + 1]; ++c)
            sum += mul(rotation[triangle[c]], rest[c]);
        out[v] = sum;
    }
}

// Relative residual of H00 x = f, row by row (H00 is stored whole and symmetric, so column j
// is row j): one pass over the matrix, no temporaries.
double stepTwoResidual(const ArapPrecompute &d, const Eigen::Ref<const Eigen::VectorXcd> &x,
                       const Eigen::Ref<const Eigen::VectorXcd> &f)
{
    const ArapPrecompute::RealMatrix &H = d.stepTwoMatrix;
    const int *start = H.outerIndexPtr(), *index = H.innerIndexPtr();
    const double *value = H.valuePtr();
    const Complex *xs = x.data(), *fs = f.data();
    double residual = 0.0, xMax = 0.0, fMax = 0.0;
    for (Eigen::Index j = 0; j < H.outerSize(); ++j) {
        Complex row = -fs[j];
        for (int p = start[j]; p < start[j + 1]; ++p)
            row += value[p] * xs[index[p]];
        residual = std::max(residual, squaredMagnitude(row));
        xMax = std::max(xMax, squaredMagnitude(xs[j]));
        fMax = std::max(fMax, squaredMagnitude(fs[j]));
    }
    const double scale = d.stepTwoNorm * std::sqrt(xMax) + std::sqrt(fMax);
    return scale > 0.0 ? std::sqrt(residual) / scale : std::sqrt(residual);
}

} // namespace

std::optional<DeformError> beginSolve(const ArapPrecompute &d, const Eigen::MatrixX2d &bc,
                                      Workspace &w)
{
    if (auto error = checkTargets(d, bc))
        return error;
    w.positions.resize(d.rest.size());
    w.rhs.resize(d.freeCount);
    w.residual.resize(d.freeCount);
    w.rotations.resize(d.triangles.rows());
    placeConstrained(d, bc, w.positions);
    return std::nullopt;
}

// Step 1: the free vertices' best similarity-preserving positions given the handles.
std::optional<DeformError> similarityStep(const ArapPrecompute &d, Workspace &w,
                                          ArapSolveReport &report, bool check)
{
    const Eigen::Index nf = d.freeCount, handles = d.handleEntry.size();
    if (nf == 0)
        return std::nullopt;
    auto u = w.positions.head(nf);
    const auto q = w.positions.segment(nf, handles);
    if (d.stepOneBasis.cols() == handles) { // u = M q, one pass over the row-major basis
        const Complex *m = d.stepOneBasis.data();
        for (Eigen::Index i = 0; i < nf; ++i, m += handles) {
            Complex sum;
            for (Eigen::Index c = 0; c < handles; ++c)
                sum += mul(m[c], q(c));
            u(i) = sum;
        }
        return std::nullopt;
    }
    auto &rhs = w.rhs;
    rhs.noalias() = -(d.stepOneCoupling * q);
    u = rhs;
    d.stepOneFactor.solveInPlace(u.data());
    if (!check) // an initial guess for refinement, which checks the solve it ends with
        return u.allFinite() ? std::nullopt
                             : std::optional(makeError(DeformErrorCode::SolveFailed,
                                                       "the similarity solve failed"));
    w.residual.noalias() = d.stepOneMatrix.selfadjointView<Eigen::Upper>() * u;
    w.residual -= rhs;
    return checkSolve(u.allFinite(), relativeResidual(w.residual, d.stepOneNorm, u, rhs), report);
}

// Step 2a: the best rotation of every triangle's rest shape onto the current positions
// (Procrustes on the weighted edge covariance, see bestRotation), scaled by 3 for rigidFitRhs.
// Kept apart from the scatter so the square roots and divisions of consecutive triangles
// overlap instead of waiting on each other's stores to shared vertices (2.5× faster measured
// at 2k vertices).
double fitRotations(const ArapPrecompute &d, const Eigen::VectorXcd &W, Eigen::VectorXcd &rotations,
                    bool energy)
{
    // Raw pointers: through Eigen accessors the compiler must assume each store may move
    // the matrices' data and reloads them, which halved the speed of this loop.
    const Eigen::Index m = d.triangles.rows();
    const int *i0 = d.triangles.col(0).data(), *i1 = d.triangles.col(1).data(),
              *i2 = d.triangles.col(2).data();
    const Complex *r1 = d.restWeighted.col(1).data(), *r2 = d.restWeighted.col(2).data();
    const double *w0 = d.edgeWeight.col(0).data(), *w1 = d.edgeWeight.col(1).data(),
                 *w2 = d.edgeWeight.col(2).data();
    const double *threshold = d.collapseThreshold.data(), *restNorm = d.restSquaredNorm.data();
    const Complex *p = W.data();
    Complex *out = rotations.data();
    double total = 0.0;
    for (Eigen::Index t = 0; t < m; ++t) {
        // Σ conj(r_k)·p_k is unchanged by shifting p (Σ r_k = 0), so measuring p from one
        // corner drops corner 0's term; it keeps far-from-origin coordinates from amplifying
        // the rounding left in Σ r_k.
        const Complex p0 = p[i0[t]], q1 = p[i1[t]] - p0, q2 = p[i2[t]] - p0;
        const Complex s = mulConj(r1[t], q1) + mulConj(r2[t], q2);
        const double squared = squaredMagnitude(s);
        const bool fits = squared > threshold[t] * threshold[t];
        const double length = std::sqrt(squared);
        out[t] = fits ? s * (3.0 / length) : Complex(3.0, 0.0);
        if (energy) { // Σ_k w_k |e′_k − R e_k|² = Σ w|e′|² + Σ w|e|² − 2 Re(conj(R)·3s)
            const double deformed = w0[t] * squaredMagnitude(q2 - q1) +
                                    w1[t] * squaredMagnitude(q2) + w2[t] * squaredMagnitude(q1);
            total += deformed + restNorm[t] - 6.0 * (fits ? length : s.real());
        }
    }
    return total;
}

void globalStep(const ArapPrecompute &d, Workspace &w)
{
    const Eigen::Index nf = d.freeCount, handles = d.handleEntry.size();
    rigidFitRhs(d, w.rotations, w.rhs);
    w.rhs.noalias() -= d.stepTwoCoupling * w.positions.segment(nf, handles);
    auto x = w.positions.head(nf);
    x = w.rhs;
    arapStepTwoBacksubstitute(d, x);
}

std::optional<DeformError> checkGlobalStep(const ArapPrecompute &d, const Workspace &w,
                                           ArapSolveReport &report)
{
    const auto x = w.positions.head(d.freeCount);
    return checkSolve(x.allFinite(), stepTwoResidual(d, x, w.rhs), report);
}

void scatterPositions(const ArapPrecompute &d, const Eigen::VectorXcd &W, Eigen::MatrixX2d &U)
{
    U.resize(W.size(), 2);
    const int *order = d.order.data();
    const Complex *w = W.data();
    double *x = U.col(0).data(), *y = U.col(1).data();
    for (Eigen::Index k = 0; k < W.size(); ++k) {
        x[order[k]] = w[k].real();
        y[order[k]] = w[k].imag();
    }
}

// The coarse level of a two-level start runs inside a fine solve on the same thread, so it
// has a workspace of its own (a coarse level has no coarse level: options.twoLevelVertices is
// 0 there): a cold start with its coarse rotations or step 1, then its drag event's passes, no
// flip repair (only the rotations are used).
bool solveCoarseLevel(const ArapPrecompute &level, const Eigen::MatrixX2d &bc,
                      Eigen::VectorXcd &rotations)
{
    thread_local Workspace w;
    if (beginSolve(level, bc, w))
        return false;
    ArapSolveReport report;
    if (coldStart(level, w, report))
        return false;
    if (refine(level, w, level.dragPasses, 0, 0.0, 0.0, nullptr, report))
        return false;
    rotations.resize(level.triangles.rows());
    fitRotations(level, w.positions, rotations, false);
    return rotations.allFinite();
}

} // namespace detail

namespace {

using detail::Workspace;

// A 20k-vertex drawing's drag event gets 4–5 passes, and one more for flips was too few: the
// folds a bend's last events squeeze next to a pinned band (a triangle the converged pose keeps
// at a few % of its area) often need two more before local relaxation can open them. On the
// 55 drawings of `finbook-bench arap --quality --density 3.65` the drags' flips beyond the
// converged pose's went from 11 to 4 with 2 (and kUnfoldPatience 2); 3 did no better, and on
// the 9 drawings that fold 6 (with a patience of 6) left the same 4 at twice the cost. They
// are local minima the drag walked into, which a second round of 4 passes did not open either:
// a bat's fold (nor did restarting regions of up to 200 vertices around it) and a face's 3
// beside the 9 its converged pose has. The repair's injective finish (arap_untangle.cpp) opens
// all 4.
constexpr int kMinFlipPasses = 2;

// Steps 1, then `scalePasses` × (2a + 2b): the paper's method (and its extra passes).
ArapSolveResult twoStepSolve(const ArapPrecompute &d, const Eigen::MatrixX2d &bc,
                             Eigen::MatrixX2d &U, int scalePasses)
{
    Workspace &w = detail::workspace();
    if (auto error = detail::beginSolve(d, bc, w))
        return unexpected(std::move(*error));
    ArapSolveReport report;
    if (auto error = detail::similarityStep(d, w, report, true))
        return unexpected(std::move(*error));
    for (int pass = 0; pass < scalePasses && d.freeCount > 0; ++pass) {
        detail::fitRotations(d, w.positions, w.rotations, false);
        detail::globalStep(d, w);
        if (auto error = detail::checkGlobalStep(d, w, report))
            return unexpected(std::move(*error));
        ++report.passes;
    }
    report.flippedTriangles = detail::countFlips(d, w.positions);
    detail::placeFollowers(d, w.positions);
    detail::scatterPositions(d, w.positions, U);
    return report;
}

// `start` non-null: a warm drag event (see arapSolveFrom), already checked by usableStart.
ArapSolveResult refinedSolve(const ArapPrecompute &d, const Eigen::MatrixX2d &bc,
                             Eigen::MatrixX2d &U, ArapStage stage,
                             const std::function<bool()> &cancelled,
                             const Eigen::MatrixX2d *start = nullptr)
{
    Workspace &w = detail::workspace();
    if (auto error = detail::beginSolve(d, bc, w))
        return unexpected(std::move(*error));
    ArapSolveReport report;
    const bool final = stage == ArapStage::Final;
    // Coarse rotations start the stored pose too: on thin ~2k-vertex drawings, whose rotation
    // fields converge slowly, the pose after the same passes was closer to the optimum (the
    // worst of 8 from 1.010× to 1.005× the converged energy).
    int dragPasses = d.dragPasses;
    // The event continues the last one on this thread: momentum applies.
    const bool continued = start && detail::continuesDrag(d, w, *start);
    if (start) {
        const auto passes = detail::warmOrCold(d, *start, w, report, continued);
        if (!passes)
            return unexpected(passes.error());
        dragPasses = *passes;
    } else if (auto error = detail::coldStart(d, w, report, !final)) {
        return unexpected(std::move(*error));
    }
    const int passes = final ? std::max(1, d.options.finalPassCap) : dragPasses;
    const double tolerance = final ? d.options.finalTolerance * d.objectSize : 0.0;
    // Drag: the flip repair may add an eighth of the passes, at least kMinFlipPasses (only for
    // poses with flipped triangles, and only while their count falls, see kUnfoldPatience in
    // arap_refine.cpp); none at the minimum of two passes (large meshes), where the budget has
    // no room and local relaxation alone repairs.
    const int flipPasses = d.options.fixFlips && !final && dragPasses >= 3
                               ? std::max(kMinFlipPasses, dragPasses / 8)
                               : 0;
    const double energyTolerance = final ? d.options.finalEnergyTolerance : 0.0;
    if (auto error = detail::refine(d, w, passes, flipPasses, tolerance, energyTolerance,
                                    final ? cancelled : nullptr, report))
        return unexpected(std::move(*error));
    if (d.options.fixFlips)
        detail::repairFlips(d, w, report, final);
    else
        report.flippedTriangles = detail::countFlips(d, w.positions);
    detail::placeFollowers(d, w.positions);
    detail::scatterPositions(d, w.positions, U);
    if (start)
        detail::rememberDrag(d, w, U);
    return report;
}

} // namespace

ArapSolveResult arapSolve(const ArapPrecompute &data, const Eigen::MatrixX2d &bc,
                          Eigen::MatrixX2d &U)
{
    return twoStepSolve(data, bc, U, 1 + std::max(0, data.options.extraPasses));
}

ArapSolveResult arapSolve(const ArapPrecompute &data, const Eigen::MatrixX2d &bc,
                          Eigen::MatrixX2d &U, ArapStage stage,
                          const std::function<bool()> &cancelled)
{
    if (data.options.method == ArapMethod::TwoStep)
        return arapSolve(data, bc, U);
    return refinedSolve(data, bc, U, stage, cancelled);
}

ArapSolveResult arapSolveFrom(const ArapPrecompute &data, const Eigen::MatrixX2d &bc,
                              const Eigen::MatrixX2d &start, Eigen::MatrixX2d &U)
{
    if (data.options.method == ArapMethod::TwoStep || !detail::usableStart(data, start))
        return arapSolve(data, bc, U, ArapStage::Drag);
    return refinedSolve(data, bc, U, ArapStage::Drag, nullptr, &start);
}

ArapSolveResult arapSimilarity(const ArapPrecompute &data, const Eigen::MatrixX2d &bc,
                               Eigen::MatrixX2d &U)
{
    return twoStepSolve(data, bc, U, 0);
}

} // namespace finbook::deform
