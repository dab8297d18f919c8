// The interior mesh of a cage, on which harmonic coordinates are solved
// (deform/cage/harmonic_cage.h).
//
// Conforming triangulation of the cage polygon (never its convex hull): an equilateral lattice
// of spacing ≈ maxEdge fills the interior, and a strip along the cage is meshed by CGAL's
// constrained Delaunay mesher with the domain marked by nesting depth, shape bound 0.125
// (minimum angle ≈ 20.7°) and size bound maxEdge. Cage edges are split into pieces of at most
// maxEdge (Steiner points), so boundary values can follow the cage exactly.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>

#include <Eigen/Core>

namespace finbook::geometry {

// V  n×2 vertex positions, in this order:
//    rows [0, c)              the cage corners, exactly as given (row i = corner i);
//    rows [c, boundaryCount)  the other vertices on cage edges, by edge, then parameter;
//    rows [boundaryCount, n)  interior vertices.
// F  m×3 vertex indices, every triangle with positive shoelace area (region.h), only
//    triangles inside the cage, every vertex referenced, no vertex where two fans touch.
// boundaryEdge  boundaryCount-vector: the cage edge e (joining corner e and corner (e + 1) mod c)
//    each boundary vertex lies on; boundaryParameter: its position t ∈ [0, 1) along that edge
//    (V.row(k) = (1 − t)·corner(e) + t·corner(e + 1) to rounding). Corner e has edge e, t = 0.
// Every edge of the mesh is at most maxEdge long (unless refinement hit the vertex cap), and
// every triangle has angles ≥ 20.7° except next to cage corners sharper than about 60°.
struct CageMesh {
    Eigen::MatrixX2d V;
    Eigen::MatrixX3i F;
    Eigen::Index cornerCount = 0;
    Eigen::Index boundaryCount = 0;
    Eigen::VectorXi boundaryEdge;
    Eigen::VectorXd boundaryParameter;
    int latticeVertices = 0; // interior vertices placed by the lattice (the rest by CGAL)
};

// A hard ceiling on the mesh size: finer requests are refused (InvalidOptions).
inline constexpr long kMaxCageMeshVertices = 2'000'000;

// corners: c×2, must pass checkCage (cage_polygon.h); either orientation. maxEdge > 0 in the
// corners' units. Errors: those of checkCage; InvalidOptions (maxEdge not finite and > 0, or a
// mesh above kMaxCageMeshVertices); TriangulationFailed (CGAL refused; reported, not thrown).
Expected<CageMesh, GeometryError> meshCage(const Eigen::MatrixX2d &corners, double maxEdge);

// About how many vertices meshCage(corners, maxEdge) makes (the inverse of cageEdgeLength);
// 0 for a cage that fails checkCage or a maxEdge that is not positive and finite.
double cageVertexEstimate(const Eigen::MatrixX2d &corners, double maxEdge);

// The maxEdge for which meshCage gives about targetVertices (≥ 3) vertices on this cage
// (within about ±25%, as tests check, for cages not much thinner than a few edges).
// Corners as for meshCage; returns 0 for a cage that fails checkCage.
double cageEdgeLength(const Eigen::MatrixX2d &corners, long targetVertices);

} // namespace finbook::geometry
