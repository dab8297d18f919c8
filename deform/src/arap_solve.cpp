#include "arap_internal.h"

#include <finbook/deform/arap.h>

namespace finbook::deform {
namespace {

using detail::Complex;
using detail::makeError;

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
// their pin (or stay at rest), which is their zero-energy answer and keeps G00, H00 SPD.
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

std::optional<DeformError> checkSolve(const Eigen::VectorXcd &x, const Eigen::VectorXcd &residual,
                                      double norm, const Eigen::VectorXcd &rhs,
                                      ArapSolveReport &report)
{
    const double relative = detail::relativeResidual(residual, norm, x, rhs);
    report.relativeResidual = std::max(report.relativeResidual, relative);
    if (!x.allFinite() || !(relative <= detail::kResidualTolerance))
        return makeError(DeformErrorCode::SolveFailed,
                         "the deformation solve was inaccurate (relative residual " +
                             std::to_string(relative) + ")");
    return std::nullopt;
}

// Step 1: the free vertices' best similarity-preserving positions given the handles.
std::optional<DeformError> similarityStep(const ArapPrecompute &d, Eigen::VectorXcd &W,
                                          ArapSolveReport &report)
{
    const Eigen::Index nf = d.freeCount, handles = d.handleEntry.size();
    if (nf == 0)
        return std::nullopt;
    const Eigen::VectorXcd q = W.segment(nf, handles);
    if (d.stepOneBasis.cols() == handles) {
        W.head(nf).noalias() = d.stepOneBasis * q;
        return std::nullopt;
    }
    const Eigen::VectorXcd rhs = -(d.stepOneCoupling * q);
    const Eigen::VectorXcd x = d.stepOneFactor.solve(rhs);
    const Eigen::VectorXcd residual = d.stepOneMatrix.selfadjointView<Eigen::Upper>() * x - rhs;
    if (auto error = checkSolve(x, residual, d.stepOneNorm, rhs, report))
        return error;
    W.head(nf) = x;
    return std::nullopt;
}

// Step 2a fused with the right-hand side of 2b: each triangle's rigid copy R·r contributes
// Σ_edges ±R(r_j − r_i) = 3·R·r_k to corner k (the rest corners r are centred). Rows of
// constrained vertices are accumulated too and simply ignored: cheaper than branching.
void rigidFitRhs(const ArapPrecompute &d, const Eigen::VectorXcd &W, Eigen::VectorXcd &rhs)
{
    rhs.setZero(W.size());
    for (Eigen::Index t = 0; t < d.triangles.rows(); ++t) {
        const int i0 = d.triangles(t, 0), i1 = d.triangles(t, 1), i2 = d.triangles(t, 2);
        const Complex centroid = (W(i0) + W(i1) + W(i2)) / 3.0;
        const Complex p[3] = {W(i0) - centroid, W(i1) - centroid, W(i2) - centroid};
        const Complex r[3] = {d.restCentered(t, 0), d.restCentered(t, 1), d.restCentered(t, 2)};
        const Complex rotation = 3.0 * detail::bestRotation(r, p, d.collapseThreshold(t));
        rhs(i0) += rotation * r[0];
        rhs(i1) += rotation * r[1];
        rhs(i2) += rotation * r[2];
    }
}

// Steps 2a + 2b: rigid fit per triangle, then the Laplacian solve for x + iy at once.
std::optional<DeformError> scaleStep(const ArapPrecompute &d, Eigen::VectorXcd &W,
                                     Eigen::VectorXcd &rhs, ArapSolveReport &report)
{
    const Eigen::Index nf = d.freeCount, handles = d.handleEntry.size();
    if (nf == 0)
        return std::nullopt;
    rigidFitRhs(d, W, rhs);
    rhs.conservativeResize(nf);
    rhs.noalias() -= d.stepTwoCoupling * W.segment(nf, handles);
    const Eigen::VectorXcd x = d.stepTwoFactor.solve(rhs);
    const Eigen::VectorXcd residual = d.stepTwoMatrix.selfadjointView<Eigen::Upper>() * x - rhs;
    if (auto error = checkSolve(x, residual, d.stepTwoNorm, rhs, report))
        return error;
    W.head(nf) = x;
    return std::nullopt;
}

void scatter(const ArapPrecompute &d, const Eigen::VectorXcd &W, Eigen::MatrixX2d &U)
{
    U.resize(W.size(), 2);
    for (Eigen::Index k = 0; k < W.size(); ++k) {
        U(d.order(k), 0) = W(k).real();
        U(d.order(k), 1) = W(k).imag();
    }
}

ArapSolveResult solve(const ArapPrecompute &d, const Eigen::MatrixX2d &bc, Eigen::MatrixX2d &U,
                      int scalePasses)
{
    if (auto error = checkTargets(d, bc))
        return unexpected(std::move(*error));
    ArapSolveReport report;
    Eigen::VectorXcd W(d.rest.size()), rhs;
    placeConstrained(d, bc, W);
    if (auto error = similarityStep(d, W, report))
        return unexpected(std::move(*error));
    for (int pass = 0; pass < scalePasses; ++pass) {
        if (auto error = scaleStep(d, W, rhs, report))
            return unexpected(std::move(*error));
    }
    scatter(d, W, U);
    return report;
}

} // namespace

ArapSolveResult arapSolve(const ArapPrecompute &data, const Eigen::MatrixX2d &bc,
                          Eigen::MatrixX2d &U)
{
    return solve(data, bc, U, 1 + std::max(0, data.options.extraPasses));
}

ArapSolveResult arapSimilarity(const ArapPrecompute &data, const Eigen::MatrixX2d &bc,
                               Eigen::MatrixX2d &U)
{
    return solve(data, bc, U, 0);
}

} // namespace finbook::deform
