// Pieces shared by the ARAP precompute and solve translation units.
#pragma once

#include <finbook/deform/arap.h>
#include <finbook/deform/deform_error.h>

#include <Eigen/Core>

#include <complex>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace finbook::deform::detail {

using Complex = std::complex<double>;

inline DeformError makeError(DeformErrorCode code, std::string message)
{
    return DeformError{code, std::move(message)};
}

// Rest positions, triangles and pins as arapPrecompute receives them; nullopt when usable.
std::optional<DeformError> validateArapInput(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                             const Eigen::VectorXi &b);

// Connected-component label per vertex (0 … count−1) over triangle edges; a vertex referenced
// by no triangle is a component of its own. F must hold valid indices.
Eigen::VectorXi componentLabels(Eigen::Index vertexCount, const Eigen::MatrixX3i &F, int &count);

// Fills the step-1 (G00, G01) and step-2 (H00, H01) systems and the per-triangle rest data of
// d for the given triangles; `internal` maps original to internal vertex indices.
void assembleArapSystems(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                         const std::vector<Eigen::Index> &triangles,
                         const std::vector<int> &internal, ArapPrecompute &d);

// Factors G00 and H00 (concurrently), verifies both with a probe solve and builds the step-1
// basis, polling `cancelled` between phases and between basis columns.
std::optional<DeformError> factorArapSystems(ArapPrecompute &d,
                                             const std::function<bool()> &cancelled);

// Best rotation (unit complex number) taking the centred rest corners r onto the centred
// corners p: the 2D Procrustes solution arg(Σ conj(r_k)·p_k). When the sum is below
// `threshold` the target triangle has collapsed (two pins dragged onto one point) and any
// rotation fits equally badly: return the identity instead of dividing by ~0.
inline Complex bestRotation(const Complex r[3], const Complex p[3], double threshold)
{
    const Complex s = std::conj(r[0]) * p[0] + std::conj(r[1]) * p[1] + std::conj(r[2]) * p[2];
    const double length = std::abs(s);
    return length > threshold ? s / length : Complex(1.0, 0.0);
}

// ‖r‖∞ / (‖A‖∞‖x‖∞ + ‖b‖∞), 0 when everything is zero: a backward-error style measure that
// stays meaningful for pixel-scale and unit-scale coordinates alike.
template <class R, class X, class B>
double relativeResidual(const R &residual, double normA, const X &x, const B &rhs)
{
    const double scale = normA * x.cwiseAbs().maxCoeff() + rhs.cwiseAbs().maxCoeff();
    const double r = residual.cwiseAbs().maxCoeff();
    return scale > 0.0 ? r / scale : r;
}

// Solves whose relative residual exceeds this are reported as SolveFailed. Cholesky on these
// well-conditioned SPD systems lands around 1e-16; 1e-8 leaves room for 100k-vertex meshes.
constexpr double kResidualTolerance = 1e-8;

} // namespace finbook::deform::detail
