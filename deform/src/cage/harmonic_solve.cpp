#include "harmonic_internal.h"

#include <cmath>

namespace finbook::deform::detail {
namespace {

// Cholesky on these SPD systems lands near 1e-16; see arap_internal.h.
constexpr double kHarmonicResidualTolerance = 1e-8;

// Fixed pseudo-random positive weights s: any wrong or non-finite column of X shows in
// X s (barring an exact cancellation), so one residual checks all columns at the cost of one.
Eigen::VectorXd combination(Eigen::Index columns)
{
    Eigen::VectorXd weights(columns);
    for (Eigen::Index i = 0; i < columns; ++i)
        weights(i) = 1.0 + 0.5 * std::sin(1.7 * double(i) + 0.3);
    return weights;
}

// ‖A x − b‖∞ / (‖A‖∞‖x‖∞ + ‖b‖∞) with A given by its lower triangle.
double residual(const HarmonicSystem &s, const Eigen::VectorXd &x, const Eigen::VectorXd &b)
{
    Eigen::VectorXd r = -b;
    const Eigen::SparseMatrix<double> &A = s.A;
    for (Eigen::Index j = 0; j < A.outerSize(); ++j) {
        for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) {
            r(it.row()) += it.value() * x(j);
            if (it.row() != j)
                r(j) += it.value() * x(it.row());
        }
    }
    const double scale = s.normA * x.cwiseAbs().maxCoeff() + b.cwiseAbs().maxCoeff();
    const double worst = r.size() > 0 ? r.cwiseAbs().maxCoeff() : 0.0;
    return scale > 0.0 ? worst / scale : worst;
}

} // namespace

std::optional<DeformError> solveHarmonicSystem(const HarmonicSystem &system, CageRowMatrix &W,
                                               double &relativeResidual,
                                               const std::function<bool()> &cancelled)
{
    relativeResidual = 0.0;
    const Eigen::Index ni = system.A.rows(), c = W.cols();
    if (ni == 0) // every vertex on the cage: nothing to solve
        return std::nullopt;
    MultifrontalCholesky factor;
    // A numerically singular matrix can still factor: the residual check below catches it.
    if (!factor.factor(system.A, system.tree))
        return cageError(DeformErrorCode::FactorizationFailed,
                         "The cage's Laplacian could not be factored.");
    if (cancelled && cancelled())
        return cageError(DeformErrorCode::Cancelled, "precompute was cancelled");
    auto interior = W.bottomRows(ni);
    const Eigen::VectorXd weights = combination(c);
    const Eigen::VectorXd b = interior * weights;
    double *x = interior.data();
    factor.solve(x, c, c);
    relativeResidual = residual(system, interior * weights, b);
    // The rows are contiguous: one vectorised pass (a strided allFinite() took milliseconds).
    if (!Eigen::Map<const Eigen::ArrayXd>(x, ni * c).allFinite() ||
        !(relativeResidual <= kHarmonicResidualTolerance))
        return cageError(DeformErrorCode::SolveFailed,
                         "Solving for the cage's coordinates was inaccurate (relative residual " +
                             std::to_string(relativeResidual) + ").");
    return std::nullopt;
}

} // namespace finbook::deform::detail
