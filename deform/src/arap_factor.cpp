#include "arap_internal.h"

#include <exception>
#include <thread>

namespace finbook::deform::detail {
namespace {

// Dense step-1 basis columns cost freeCount complex numbers each, and applying one costs
// about as much as streaming 1/40 of the step-1 factor; past this many handles a per-event
// back-substitution is cheaper in both memory and time.
constexpr Eigen::Index kMaxBasisHandles = 32;

DeformError cancelledError()
{
    return makeError(DeformErrorCode::Cancelled, "precompute was cancelled");
}

// G00 (complex) and H00 (real) are independent and similar in cost: factor them side by side.
std::optional<DeformError> factorBoth(ArapPrecompute &d)
{
    std::exception_ptr failure;
    std::thread helper([&d, &failure] {
        try {
            d.stepTwoFactor.compute(d.stepTwoMatrix);
        } catch (...) {
            failure = std::current_exception();
        }
    });
    try {
        d.stepOneFactor.compute(d.stepOneMatrix);
    } catch (...) {
        helper.join();
        throw;
    }
    helper.join();
    if (failure)
        std::rethrow_exception(failure);
    if (d.stepOneFactor.info() != Eigen::Success || d.stepTwoFactor.info() != Eigen::Success)
        return makeError(DeformErrorCode::FactorizationFailed,
                         "the deformation system could not be factored");
    return std::nullopt;
}

// Simplicial Cholesky reports Success for NaN and for numerically singular matrices, so
// solve for a known vector and check the answer is finite with a small residual.
template <class Factor, class Matrix>
std::optional<DeformError> probe(const Factor &factor, const Matrix &upper, double norm)
{
    using Vector = Eigen::Matrix<typename Matrix::Scalar, Eigen::Dynamic, 1>;
    const Vector known = Vector::LinSpaced(upper.rows(), 1.0, 2.0);
    const Vector rhs = upper.template selfadjointView<Eigen::Upper>() * known;
    const Vector x = factor.solve(rhs);
    const Vector residual = upper.template selfadjointView<Eigen::Upper>() * x - rhs;
    if (!x.allFinite() || relativeResidual(residual, norm, x, rhs) > kResidualTolerance)
        return makeError(DeformErrorCode::FactorizationFailed,
                         "the deformation system is numerically singular");
    return std::nullopt;
}

// M = −G00⁻¹G01, one complex solve per handle, so step 1 per event is a k-column product.
std::optional<DeformError> buildBasis(ArapPrecompute &d, const std::function<bool()> &stop)
{
    const Eigen::Index handles = d.handleEntry.size();
    if (handles > kMaxBasisHandles)
        return std::nullopt;
    d.stepOneBasis.resize(d.freeCount, handles);
    for (Eigen::Index c = 0; c < handles; ++c) {
        if (stop())
            return cancelledError();
        const Eigen::VectorXcd rhs = -Eigen::VectorXcd(d.stepOneCoupling.col(c));
        d.stepOneBasis.col(c) = d.stepOneFactor.solve(rhs);
        const Eigen::VectorXcd residual =
            d.stepOneMatrix.selfadjointView<Eigen::Upper>() * d.stepOneBasis.col(c) - rhs;
        if (!d.stepOneBasis.col(c).allFinite() ||
            relativeResidual(residual, d.stepOneNorm, d.stepOneBasis.col(c), rhs) >
                kResidualTolerance)
            return makeError(DeformErrorCode::SolveFailed,
                             "the similarity basis could not be computed accurately");
    }
    return std::nullopt;
}

} // namespace

std::optional<DeformError> factorArapSystems(ArapPrecompute &d,
                                             const std::function<bool()> &cancelled)
{
    const std::function<bool()> stop = [&cancelled] { return cancelled && cancelled(); };
    if (d.freeCount == 0) // every vertex of every solved component is pinned
        return std::nullopt;
    if (stop())
        return cancelledError();
    if (auto error = factorBoth(d))
        return error;
    if (stop())
        return cancelledError();
    if (auto error = probe(d.stepOneFactor, d.stepOneMatrix, d.stepOneNorm))
        return error;
    if (auto error = probe(d.stepTwoFactor, d.stepTwoMatrix, d.stepTwoNorm))
        return error;
    return buildBasis(d, stop);
}

} // namespace finbook::deform::detail
