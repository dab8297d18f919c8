// As-rigid-as-possible shape interpolation (Alexa, Cohen-Or & Levin 2000) between two poses of
// one triangle mesh: the in-betweens of a fitted pair of drawings (issue 50).
//
// Precompute: per triangle the affine map J taking its V0 corners to its V1 corners, split
// into J = R(θ)·S (polar decomposition, S symmetric; positive definite unless the triangle
// turned over). θ is unwrapped over the mesh: each triangle takes the 2π branch closest to the
// last trusted angle on its way from its part's most trusted triangle, the way taken over the
// smallest steps first (quality-guided, as phase unwrapping is), a triangle turned over by a
// fold in V1 passing on nothing of its own; then each connected part is shifted by a whole
// turn so that its area-weighted mean angle lies in (−π, π]. So a limb turned by 170° turns the
// same way in all of its triangles, a limb curled past 180° keeps curling instead of unwinding
// in half of them, and a limb beyond a fold turns by its own angle, not a turn more or less.
// Solve at time t: target A(t) = R(t·θ)·((1 − t)·I + t·S) per triangle, then the vertices
// minimising Σ_t area·‖J_t(U) − A_t(t)‖²_F: one back-substitution (x and y) through the
// cotangent Laplacian factored in the precompute, one vertex per connected part held, then
// each part moved so that its vertex centroid is (1 − t)·c0 + t·c1 (translation is not
// determined by the triangles, and the centroid is the fairest place to fix it).
// t = 0 gives V0 and t = 1 gives V1 (to round-off). Vertices in no triangle blend linearly.
// Links (the hinges between pieces meshed apart, rigid_fit.h) join two vertices that no
// triangle joins: the solve also minimises kLinkWeight·‖(u_i − u_j) − d(t)‖², d(t) the two
// vertices' offset blended linearly from V0 to V1, and parts joined by links are one part,
// placed by the centroid of its largest piece, so a limb meshed apart turns about its hinge on
// a body that stays put, instead of sliding its centroid along a straight line.
#pragma once

#include <finbook/deform/deform_error.h>
#include <finbook/geometry/expected.h>

#include <Eigen/Core>

#include <array>
#include <memory>
#include <vector>

namespace finbook::deform::between {

namespace detail {
class MeshSystem;
}

// Immutable once made; safe to share between threads (solves allocate their own scratch).
struct ArapInterpolation {
    Eigen::MatrixX2d V0, V1;   // n×2
    Eigen::MatrixX3i F;        // m×3
    Eigen::VectorXd angle;     // m: unwrapped rotation θ of each triangle (radians)
    Eigen::MatrixX3d stretch;  // m: S as (s00, s01, s11)
    Eigen::VectorXd area;      // m: rest (V0) area
    Eigen::MatrixXd gradient;  // m×6: ∇φ of corners 0, 1, 2 (x, y each) on V0
    Eigen::VectorXi component; // n: connected part of each vertex (−1: in no triangle)
    // Per part: vertex centroid in V0 and V1 of its placed vertices: all of a part's, or of a
    // part of pieces joined by links its largest piece's.
    Eigen::MatrixX2d centroid0, centroid1;
    std::vector<bool> placed; // n
    int flippedTriangles = 0; // triangles with det J ≤ 0 (turned over between V0 and V1)
    std::vector<std::array<int, 2>> links;
    std::shared_ptr<const detail::MeshSystem> system; // factored Laplacian
};

using ArapInterpolationResult = Expected<std::shared_ptr<const ArapInterpolation>, DeformError>;

// V0, V1 n×2 (finite, same rows), F m×3 (non-zero area in V0, indices < n; V1 may be
// anything finite). Errors: EmptyMesh, InvalidIndex, NonFiniteInput, CoordinateOutOfRange,
// DegenerateTriangle, NonManifoldVertex, SizeMismatch, FactorizationFailed.
// Links: pairs of vertices below n (InvalidIndex otherwise).
ArapInterpolationResult
arapInterpolationPrecompute(const Eigen::MatrixX2d &V0, const Eigen::MatrixX2d &V1,
                            const Eigen::MatrixX3i &F,
                            const std::vector<std::array<int, 2>> &links = {});

// U n×2 at time t (finite; [0, 1] interpolates, outside extrapolates). Errors: NonFiniteInput
// (t), SolveFailed. Allocates O(n).
Expected<Eigen::MatrixX2d, DeformError> arapInterpolate(const ArapInterpolation &data, double t);

} // namespace finbook::deform::between
