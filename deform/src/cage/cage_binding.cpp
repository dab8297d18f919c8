#include "harmonic_internal.h"

#include <exception>
#include <sstream>
#include <thread>

namespace finbook::deform {
namespace {

using detail::cageError;

// Points this far outside the mesh (relative to the cage's extent) are rounding, not outside.
constexpr double kSnapRelative = 1e-9;
// Binding costs about 0.07 µs per point; below this many points a second thread saves less
// than its start and hand-over can cost on a busy machine (measured: 10k points bound in
// 0.75 ms on one thread, 9 ms wall on two when other processes kept both cores busy).
constexpr Eigen::Index kParallelPoints = 50000;

DeformError outsideError(std::vector<int> rows, const Eigen::MatrixX2d &points)
{
    Eigen::Vector2d lo = points.row(rows.front()).transpose(), hi = lo;
    for (const int k : rows) {
        lo = lo.cwiseMin(points.row(k).transpose());
        hi = hi.cwiseMax(points.row(k).transpose());
    }
    std::ostringstream text;
    text << rows.size() << (rows.size() == 1 ? " point lies" : " points lie")
         << " outside the cage, between (" << lo.x() << ", " << lo.y() << ") and (" << hi.x()
         << ", " << hi.y() << ").";
    return DeformError{DeformErrorCode::PointsOutsideCage, text.str(), std::move(rows)};
}

std::optional<DeformError> checkCorners(Eigen::Index cornerCount, const Eigen::MatrixX2d &posed)
{
    if (posed.rows() != cornerCount)
        return cageError(DeformErrorCode::SizeMismatch,
                         "the posed cage has " + std::to_string(posed.rows()) +
                             " corners, the rest cage " + std::to_string(cornerCount));
    if (!posed.allFinite())
        return cageError(DeformErrorCode::NonFiniteInput, "a posed corner is not a finite number");
    if (posed.size() > 0 && posed.cwiseAbs().maxCoeff() > kMaxDeformCoordinate)
        return cageError(DeformErrorCode::CoordinateOutOfRange, "a posed corner is too large");
    return std::nullopt;
}

} // namespace

namespace {

// Binds points [begin, end): their weight rows, and the rows that lie outside the cage.
void bindRange(const CagePrecompute &data, const Eigen::MatrixX2d &points, Eigen::Index begin,
               Eigen::Index end, CageRowMatrix &weights, std::vector<int> &outside)
{
    const double snap = kSnapRelative * data.extent;
    const Eigen::MatrixX3i &F = data.mesh.F;
    const Eigen::MatrixX2d &V = data.mesh.V;
    for (Eigen::Index k = begin; k < end; ++k) {
        const Eigen::Vector2d p = points.row(k).transpose();
        const geometry::Location at = data.locator->locate(p);
        const Eigen::Vector3d &b = at.weights;
        const int t = at.triangle;
        if (t < 0 || (!at.inside && (b(0) * V.row(F(t, 0)) + b(1) * V.row(F(t, 1)) +
                                     b(2) * V.row(F(t, 2)) - p.transpose())
                                            .norm() > snap)) {
            outside.push_back(int(k));
            continue;
        }
        weights.row(k) =
            b(0) * data.W.row(F(t, 0)) + b(1) * data.W.row(F(t, 1)) + b(2) * data.W.row(F(t, 2));
    }
}

} // namespace

CageBindResult cageBind(const CagePrecompute &data, const Eigen::MatrixX2d &points)
{
    std::vector<int> nonFinite;
    for (Eigen::Index k = 0; k < points.rows(); ++k)
        if (!points.row(k).allFinite())
            nonFinite.push_back(int(k));
    if (!nonFinite.empty())
        return unexpected(
            DeformError{DeformErrorCode::NonFiniteInput,
                        std::to_string(nonFinite.size()) + " points to bind are not finite numbers",
                        std::move(nonFinite)});
    CageBinding binding;
    binding.restPoints = points;
    binding.weights.resize(points.rows(), data.W.cols());
    std::vector<int> outside, outsideLater;
    const Eigen::Index count = points.rows();
    if (count >= kParallelPoints) {
        std::exception_ptr failure;
        std::thread helper([&] {
            try {
                bindRange(data, points, count / 2, count, binding.weights, outsideLater);
            } catch (...) {
                failure = std::current_exception();
            }
        });
        bindRange(data, points, 0, count / 2, binding.weights, outside);
        helper.join();
        if (failure)
            std::rethrow_exception(failure);
        outside.insert(outside.end(), outsideLater.begin(), outsideLater.end());
    } else {
        bindRange(data, points, 0, count, binding.weights, outside);
    }
    if (!outside.empty())
        return unexpected(outsideError(std::move(outside), points));
    return binding;
}

std::optional<DeformError> cageDeform(const CageBinding &binding,
                                      const Eigen::MatrixX2d &posedCorners, Eigen::MatrixX2d &out)
{
    if (auto error = checkCorners(binding.weights.cols(), posedCorners))
        return error;
    const Eigen::Index count = binding.weights.rows(), c = binding.weights.cols();
    if (out.rows() != count)
        out.resize(count, 2);
    // Row p of the result is the dot product of weight row p with the two corner columns;
    // written out so that nothing allocates (Eigen's GEMM may allocate blocking buffers).
    const double *x = posedCorners.data(), *y = posedCorners.data() + c;
    for (Eigen::Index p = 0; p < count; ++p) {
        const double *w = binding.weights.data() + p * c;
        double sx = 0.0, sy = 0.0;
        for (Eigen::Index i = 0; i < c; ++i) {
            sx += w[i] * x[i];
            sy += w[i] * y[i];
        }
        out(p, 0) = sx;
        out(p, 1) = sy;
    }
    return std::nullopt;
}

Expected<Eigen::MatrixX2d, DeformError> cageDeform(const CageBinding &binding,
                                                   const Eigen::MatrixX2d &posedCorners)
{
    Eigen::MatrixX2d out;
    if (auto error = cageDeform(binding, posedCorners, out))
        return unexpected(std::move(*error));
    return out;
}

Expected<Eigen::MatrixX2d, DeformError> cageDeformMesh(const CagePrecompute &data,
                                                       const Eigen::MatrixX2d &posedCorners)
{
    if (auto error = checkCorners(data.W.cols(), posedCorners))
        return unexpected(std::move(*error));
    Eigen::MatrixX2d V = data.W * posedCorners;
    return V;
}

} // namespace finbook::deform
