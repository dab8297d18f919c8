// Harmonic coordinates for cages (Joshi, Meyer, DeRose, Green & Sanocki 2007): an object is
// posed by the corners of a polygon drawn around it (see ../shared/notes/harmonic.md).
//
// For every corner i the coordinate h_i solves Laplace's equation inside the cage, with the
// piecewise-linear hat of corner i as boundary values (1 at corner i, falling linearly to 0
// along its two edges, 0 on every other edge). Discretely: the cotangent Laplacian of a
// constrained Delaunay mesh of the cage interior (geometry/cage/cage_mesh.h); every boundary
// vertex, corners and Steiner points alike, gets its edge's hat values; the interior block is
// factored once and solved for all corners in one multi-right-hand-side solve. Properties
// (up to rounding): Σ_i h_i = 1, Σ_i h_i c_i = p, h_i = hat values on the cage, and h_i ≥ 0 even
// in strongly concave cages (the mesh's cotangent weights are non-negative, so the discrete
// maximum principle holds).
//
// Precompute (mesh + factor + solve) depends on the rest cage only; binding depends on the rest
// cage and the rest points; a drag only multiplies the bound weights by the posed corners.
#pragma once

#include <finbook/deform/deform_error.h>
#include <finbook/geometry/cage/cage_mesh.h>
#include <finbook/geometry/expected.h>
#include <finbook/geometry/triangle_locator.h>

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <optional>

namespace finbook::deform {

struct CageOptions {
    // Interior mesh size: about this many vertices (geometry::cageEdgeLength), whatever the
    // cage's size, so precompute time is predictable. Ignored when maxEdge > 0.
    long targetVertices = 3000;
    double maxEdge = 0.0; // longest mesh edge, in the corners' units
};

// Ceilings on what cagePrecompute builds: mesh vertices, and mesh vertices × corners (the
// entries of W, 8 bytes each).
inline constexpr long kMaxCageVertices = 500'000;
inline constexpr long kMaxCageCoordinates = 32'000'000;

using CageRowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Immutable once cagePrecompute returns it; safe to share between threads.
struct CagePrecompute {
    Eigen::MatrixX2d restCorners; // c×2, exactly as passed (either orientation)
    // n vertices, as geometry::meshCage promises (rows [0, c) of mesh.V are the corners); the
    // interior vertices are numbered in the factorization's elimination order.
    geometry::CageMesh mesh;
    // n×c harmonic coordinates: row v holds every corner's weight at mesh vertex v. Rows of
    // boundary vertices are their hat values exactly.
    CageRowMatrix W;
    std::optional<geometry::TriangleLocator> locator; // over mesh.V, mesh.F (always set)
    // ‖L_II x − b‖∞ / (‖L_II‖∞‖x‖∞ + ‖b‖∞) for x = W_I s, b = B s with fixed positive weights s
    // (one residual checks every column); refused above 1e-8, typically 1e-16.
    double relativeResidual = 0.0;
    // Edges at interior vertices whose cotangent weight is negative beyond rounding (0 on the
    // meshes meshCage makes: L_II is then an M-matrix and −L_IB ≥ 0, so W ≥ 0 by the discrete
    // maximum principle).
    int negativeEdgeWeights = 0;
    double minCoordinate = 0.0; // min over W
    double extent = 0.0;        // diagonal of the cage's bounding box
};

using CagePrecomputeResult = Expected<std::shared_ptr<const CagePrecompute>, DeformError>;

// corners: c×2 rest cage (checkCage: ≥ 3 corners, finite, simple, non-zero area; either
// orientation; column i of W belongs to corner i as given). `cancelled` is polled between
// stages (mesh, assembly, factorization, solve); when it returns true the result is
// DeformErrorCode::Cancelled. Meshes above a few thousand vertices use a second thread for the
// point locator, half of the factorization and half of the solve (2 cores: about 1.5× faster).
// Errors: InvalidCage (geometry's sentence), TooLarge (more than kMaxCageVertices, or
// kMaxCageCoordinates, or memory ran out), MeshingFailed, FactorizationFailed, SolveFailed,
// Cancelled.
CagePrecomputeResult cagePrecompute(const Eigen::MatrixX2d &corners,
                                    const CageOptions &options = {},
                                    std::function<bool()> cancelled = {});

// Points bound to a cage: one dense row of corner weights per point, so that a drag is one
// (P×c)·(c×2) product.
struct CageBinding {
    CageRowMatrix weights; // P×c: row p sums to 1 and reproduces rest point p from the rest cage
    Eigen::MatrixX2d restPoints; // P×2 as bound
};

using CageBindResult = Expected<CageBinding, DeformError>;

// points: P×2 rest positions. Each is located in the cage mesh (geometry::TriangleLocator) and
// gets the barycentric blend of its triangle's rows of W. Points on the cage or outside it by
// at most 1e-9 × the cage's extent (rounding) are bound to the nearest boundary point. Cost
// O(1) per point after the precompute (thousands of points: well under a millisecond per
// 10k; a second thread from 50k points on).
// Errors: NonFiniteInput, PointsOutsideCage (DeformError::items lists the rows, ascending).
CageBindResult cageBind(const CagePrecompute &data, const Eigen::MatrixX2d &points);

// posedCorners: c×2. out: P×2 = weights · posedCorners; resized only when it does not have P
// rows, so a drag that reuses `out` allocates nothing. Any posed cage works, even one that
// crosses itself (the coordinates stay defined; the result just folds over).
// Errors: SizeMismatch, NonFiniteInput, CoordinateOutOfRange (out is then unspecified).
std::optional<DeformError> cageDeform(const CageBinding &binding,
                                      const Eigen::MatrixX2d &posedCorners, Eigen::MatrixX2d &out);

// The same, returning a new P×2 matrix (allocates; for one-off poses such as Apply Pose).
Expected<Eigen::MatrixX2d, DeformError> cageDeform(const CageBinding &binding,
                                                   const Eigen::MatrixX2d &posedCorners);

// The posed interior mesh, n×2 = W · posedCorners (to draw the cage's mesh). Same errors.
Expected<Eigen::MatrixX2d, DeformError> cageDeformMesh(const CagePrecompute &data,
                                                       const Eigen::MatrixX2d &posedCorners);

} // namespace finbook::deform
