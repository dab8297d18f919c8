// Pieces shared by the ARAP precompute and solve translation units.
#pragma once

#include <finbook/deform/arap.h>
#include <finbook/deform/deform_error.h>

#include <Eigen/Core>

#include <cmath>
#include <complex>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace finbook::deform::detail {

using Complex = std::complex<double>;

// Right-hand sides the step-2 back-substitution takes at once (backsubstituteBlock).
constexpr int kBlockWidth = 4;

// x ← H00⁻¹ x for kBlockWidth right-hand sides stored row by row (x[v·kBlockWidth + b]):
// the same operations, in the same order, as arapStepTwoBacksubstitute on each column (less
// the columns of L it reaches with all B entries still zero, which add nothing), with
// one pass over the factor for all of them (that pass, not the arithmetic, is what a
// back-substitution of a large mesh waits for).
void backsubstituteBlock(const ArapPrecompute &data, Complex *x);

inline DeformError makeError(DeformErrorCode code, std::string message)
{
    return DeformError{code, std::move(message)};
}

// Weight of the edge opposite each corner of the rest triangle z: ½ cot of the corner's angle
// (the standard ARAP energy's, for ArapMethod::Refined; negative for an obtuse angle) or 1
// (the paper's uniform weights). z must have non-zero area.
inline void edgeWeights(const Complex z[3], bool cotangent, double w[3])
{
    for (int k = 0; k < 3; ++k) {
        if (!cotangent) {
            w[k] = 1.0;
            continue;
        }
        const Complex a = z[(k + 1) % 3] - z[k], b = z[(k + 2) % 3] - z[k];
        const double dot = a.real() * b.real() + a.imag() * b.imag();
        const double cross = a.real() * b.imag() - a.imag() * b.real();
        w[k] = 0.5 * dot / std::abs(cross);
    }
}

// The triangles around each vertex of F (n vertices, every index below n): those of v are
// triangle[start[v]] … triangle[start[v + 1] − 1], in ascending order, v being corner
// corner[i] of triangle[i].
struct VertexRings {
    std::vector<int> start, triangle, corner;
};
VertexRings vertexRings(Eigen::Index n, const Eigen::MatrixX3i &F);

// Rest positions, triangles and pins as arapPrecompute receives them; nullopt when usable.
std::optional<DeformError> validateArapInput(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                             const Eigen::VectorXi &b);

// Connected-component label per vertex (0 … count−1) over triangle edges; a vertex referenced
// by no triangle is a component of its own. F must hold valid indices.
Eigen::VectorXi componentLabels(Eigen::Index vertexCount, const Eigen::MatrixX3i &F, int &count);

// Fills the step-1 systems (G00 on H00's pattern, G01), the step-2 coupling H01 and the
// per-triangle rest data of d; `internal` maps original to internal vertex indices. Only reads
// d.stepTwoMatrix, so it may run while ArapFactorization factors H00.
void assembleArapSystems(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                         const std::vector<Eigen::Index> &triangles,
                         const std::vector<int> &internal, ArapPrecompute &d);

// The two factorizations are independent, so for large systems they run side by side:
// constructing this starts factoring and probing H00 on a helper thread (H00 and its norm
// must be ready) while the caller assembles G00; finish() factors G00 while the helper
// chooses the drag passes and starts on coarse rotations (chooseDragPasses, CoarseBuilder),
// then both share the rest of the coarse columns and the step-1 basis. Small systems do all
// of it in finish(), on the caller.
class ArapFactorization {
public:
    explicit ArapFactorization(ArapPrecompute &d);
    ~ArapFactorization(); // releases and joins the helper when finish() was never reached
    ArapFactorization(const ArapFactorization &) = delete;
    ArapFactorization &operator=(const ArapFactorization &) = delete;

    // Polls `cancelled` (on this thread only) before factoring and between basis columns.
    std::optional<DeformError> finish(const std::function<bool()> &cancelled);

private:
    struct Shared;
    std::unique_ptr<Shared> m_shared;
    std::thread m_helper;
    std::exception_ptr m_helperFailure;
};

// ‖A‖∞ of the self-adjoint matrix defined by the upper triangle of `upper` (entries below
// the diagonal, if stored, are ignored like the Upper factors ignore them).
template <class Scalar> double selfAdjointNorm(const Eigen::SparseMatrix<Scalar> &upper)
{
    Eigen::VectorXd rowSum = Eigen::VectorXd::Zero(upper.rows());
    for (Eigen::Index col = 0; col < upper.outerSize(); ++col) {
        for (typename Eigen::SparseMatrix<Scalar>::InnerIterator it(upper, col); it; ++it) {
            if (it.row() > it.col())
                continue;
            rowSum(it.row()) += std::abs(it.value());
            if (it.row() != it.col())
                rowSum(it.col()) += std::abs(it.value());
        }
    }
    return rowSum.size() > 0 ? rowSum.maxCoeff() : 0.0;
}

// |z|². libstdc++'s std::norm computes abs(z)² through hypot() unless -ffast-math, which
// made it the most expensive operation of the per-event loops.
inline double squaredMagnitude(Complex z)
{
    return z.real() * z.real() + z.imag() * z.imag();
}

// Best rotation (unit complex number) taking the centred rest corners r onto the centred
// corners p: the 2D Procrustes solution arg(Σ conj(r_k)·p_k). When |Σ| is below `threshold`
// the target triangle has collapsed (two pins dragged onto one point) and any rotation fits
// equally badly: return the identity instead of dividing by ~0. Squared norms avoid hypot(),
// which dominated the per-event profile.
inline Complex bestRotation(const Complex r[3], const Complex p[3], double threshold)
{
    const Complex s = std::conj(r[0]) * p[0] + std::conj(r[1]) * p[1] + std::conj(r[2]) * p[2];
    const double squared = squaredMagnitude(s);
    return squared > threshold * threshold ? s / std::sqrt(squared) : Complex(1.0, 0.0);
}

// ‖r‖∞ / (‖A‖∞‖x‖∞ + ‖b‖∞), 0 when everything is zero: a backward-error style measure that
// stays meaningful for pixel-scale and unit-scale coordinates alike.
template <class R, class X, class B>
double relativeResidual(const R &residual, double normA, const X &x, const B &rhs)
{
    // Squared magnitudes first: cwiseAbs() on complex vectors calls hypot() per entry.
    const auto maxAbs = [](const auto &v) {
        return v.size() > 0 ? std::sqrt(v.cwiseAbs2().maxCoeff()) : 0.0;
    };
    const double scale = normA * maxAbs(x) + maxAbs(rhs);
    const double r = maxAbs(residual);
    return scale > 0.0 ? r / scale : r;
}

// Dense step-1 basis columns cost freeCount complex numbers each, and applying one costs
// about as much as streaming 1/40 of the step-1 factor; past this many handles a per-event
// back-substitution is cheaper in both memory and time.
constexpr Eigen::Index kMaxBasisHandles = 32;

// Below this many free vertices the whole factorization takes a few milliseconds and a second
// thread costs more in start-up and scheduling (especially on a busy machine) than it saves.
constexpr Eigen::Index kParallelFreeVertices = 8000;

// Solves whose relative residual exceeds this are reported as SolveFailed. Cholesky on these
// well-conditioned SPD systems lands around 1e-16; 1e-8 leaves room for 100k-vertex meshes.
constexpr double kResidualTolerance = 1e-8;

} // namespace finbook::deform::detail
