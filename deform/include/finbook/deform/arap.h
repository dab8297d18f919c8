// As-rigid-as-possible shape manipulation after Igarashi, Moscovich & Hughes 2005, with hard
// vertex pins. Precompute depends on the rest mesh and the SET of pinned vertices; every drag
// event only builds right-hand sides and back-substitutes (see ../shared/notes/arap.md).
//
//   step 1   similarity solve, as an n×n complex Hermitian system: u = M q with the dense basis
//            M = −G00⁻¹G01 (one complex solve per pin at precompute time)
//   step 2a  per-triangle rigid fit of the rest triangle to the step-1 result (Procrustes)
//   step 2b  scale adjustment: graph-Laplacian solve H00 u = f, x+iy as one complex
//            right-hand side against the real factor
//
// Pins are resolved per connected component of the mesh: a component with no pin stays at
// rest, one with one pinned vertex translates with it, one with ≥ 2 distinct pinned vertices
// gets the full solve. Vertices referenced by no triangle are components of their own.
#pragma once

#include <finbook/deform/deform_error.h>
#include <finbook/geometry/expected.h>

#include <Eigen/Core>
#include <Eigen/SparseCholesky>

#include <complex>
#include <functional>
#include <memory>

namespace finbook::deform {

struct ArapOptions {
    // Further local/global passes (2a + 2b again, started from the previous result). Each
    // costs about one more step-2 back-substitution; 0 is the paper's method exactly. The
    // result stays a pure function of the pin targets (no warm start across drag events).
    int extraPasses = 0;
};

// Immutable once arapPrecompute returns it; safe to share between threads for solving.
// Internal vertex numbering: [free vertices of fully solved components, in a fill-reducing
// order | distinct pinned vertices of those components ("handles") | vertices of components
// with fewer than two pinned vertices ("rigid")]. Solved systems are assembled pre-permuted
// so both factors use natural ordering and solves skip the permutation.
struct ArapPrecompute {
    using ComplexMatrix = Eigen::SparseMatrix<std::complex<double>>;
    using RealMatrix = Eigen::SparseMatrix<double>;
    // LDLᴴ rather than LLᴴ for the complex system: no square roots, up to 20% faster measured.
    using ComplexFactor =
        Eigen::SimplicialLDLT<ComplexMatrix, Eigen::Upper, Eigen::NaturalOrdering<int>>;
    using RealFactor = Eigen::SimplicialLLT<RealMatrix, Eigen::Upper, Eigen::NaturalOrdering<int>>;

    ArapOptions options;
    Eigen::Index pinEntryCount = 0; // rows of b as passed; bc must have as many rows
    Eigen::VectorXi pinnedVertices; // distinct pinned vertices, ascending (original indices)

    Eigen::VectorXi order;       // n: internal index → original vertex
    Eigen::Index freeCount = 0;  // free vertices (first block)
    Eigen::VectorXi handleEntry; // per handle: entry of b whose target it takes (the last one)
    Eigen::VectorXi rigidEntry; // per rigid vertex: entry of b translating it, −1 = stays at rest
    Eigen::VectorXcd entryRest; // per entry of b: rest position of its vertex, x+iy
    Eigen::VectorXcd rest;      // n rest positions x+iy, internal order

    Eigen::MatrixX3i triangles;        // triangles of solved components, internal indices
    Eigen::MatrixX3cd restCentered;    // their rest corners minus the rest centroid
    Eigen::VectorXd collapseThreshold; // below this |Σ conj(r)·p| the step-1 triangle collapsed
    // Corners around each free vertex, for gathering step 2's right-hand side per vertex:
    // those of free vertex i are cornerStart(i) … cornerStart(i + 1) − 1.
    Eigen::VectorXi cornerStart;    // freeCount + 1
    Eigen::VectorXi cornerTriangle; // row of `triangles` the corner belongs to
    Eigen::VectorXcd cornerRest;    // the corner's centred rest position

    ComplexMatrix stepOneMatrix;   // G00, upper triangle
    ComplexMatrix stepOneCoupling; // G01, freeCount × handles
    ComplexFactor stepOneFactor;   // LDLᴴ of G00
    double stepOneNorm = 0.0;      // ‖G00‖∞, scales the residual test
    // M = −G00⁻¹G01, row-major so that u = M q is one pass. Empty when there are more than
    // 32 handles: then applying it would cost more than step 1 back-substituting per event.
    Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>
        stepOneBasis;
    RealMatrix stepTwoMatrix;            // H00 (uniform-weight graph Laplacian), both halves
    RealMatrix stepTwoCoupling;          // H01, freeCount × handles
    RealFactor stepTwoFactor;            // LLᵀ of H00
    Eigen::VectorXd stepTwoPivotInverse; // 1 / diag(L) of that factor, for the back-substitution
    double stepTwoNorm = 0.0;            // ‖H00‖∞, scales the residual test
};

// Largest relative residual ‖Ax − b‖∞ / (‖A‖∞‖x‖∞ + ‖b‖∞) over the linear solves of one call.
struct ArapSolveReport {
    double relativeResidual = 0.0;
};

using ArapPrecomputeResult = Expected<std::shared_ptr<const ArapPrecompute>, DeformError>;
using ArapSolveResult = Expected<ArapSolveReport, DeformError>;

// V  n×2 rest positions (finite), F  m×3 triangles (any orientation, non-zero area, no vertex
// where fans of triangles touch only at a point; unreferenced vertices allowed), b  k pinned
// vertex indices (may repeat: the LAST entry for a vertex wins). `cancelled` is polled between
// phases and between basis solves; when it returns true the result is DeformErrorCode::Cancelled.
// Errors: EmptyMesh, InvalidIndex, NonFiniteInput, CoordinateOutOfRange, DegenerateTriangle,
// NonManifoldVertex, FactorizationFailed, SolveFailed, Cancelled. Runs a helper thread for large
// meshes.
ArapPrecomputeResult arapPrecompute(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                    const Eigen::VectorXi &b, const ArapOptions &options = {},
                                    std::function<bool()> cancelled = {});

// bc  k×2 targets, one row per entry of b as passed to arapPrecompute. U  out n×2 deformed
// positions (resized). Steps 1, 2a, 2b, then options.extraPasses × (2a, 2b).
// Allocation-free after the first call on a thread (per-thread scratch buffers).
// Errors: SizeMismatch, NonFiniteInput, CoordinateOutOfRange, SolveFailed; U is left
// unspecified on error.
ArapSolveResult arapSolve(const ArapPrecompute &data, const Eigen::MatrixX2d &bc,
                          Eigen::MatrixX2d &U);

// Step 1 only (the similarity result v′ the paper starts step 2 from); same contract as
// arapSolve. Exposed for tests and for showing what step 2 corrects.
ArapSolveResult arapSimilarity(const ArapPrecompute &data, const Eigen::MatrixX2d &bc,
                               Eigen::MatrixX2d &U);

// x ← H00⁻¹ x for a freeCount-row right-hand side with x and y packed as x + iy: one forward
// and one backward pass over the real step-2 factor, the least work a drag event can do.
// Exposed so that benchmarks can measure that floor with the kernel arapSolve uses.
void arapStepTwoBacksubstitute(const ArapPrecompute &data, Eigen::Ref<Eigen::VectorXcd> x);

// Uniform-weight ARAP energy Σ_t Σ_edges(i→j) |(u_j − u_i) − R_t (v_j − v_i)|² with the best
// rotation R_t per triangle: the energy step 2 and every extra pass cannot increase.
// V  n×2 rest, F  m×3, U  n×2 deformed; indices must be valid.
double arapEnergy(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F, const Eigen::MatrixX2d &U);

} // namespace finbook::deform
