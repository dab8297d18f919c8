// Triangle meshes in the OFF format (Object File Format, as written by libigl, CGAL, Geomview)
// read as flat 2D meshes: z is ignored. The cage benchmark's and File → Import's source for
// meshes such as the 2D character "woody" of the harmonic-coordinates notebook.
//
//   OFF                      (COFF, NOFF, CNOFF also accepted; extra values per line ignored)
//   # comments anywhere
//   nVertices nFaces nEdges  (may follow OFF on the same line)
//   x y z                    (nVertices lines)
//   k i1 … ik                (nFaces lines: polygons with k ≥ 3, 0-based indices)
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace finbook::geometry {

// V  n×2 (x, y). F  m×3: polygons fanned into triangles, oriented so that the total shoelace
// area is positive (region.h; faces are flipped as a whole if needed).
// boundaryLoops: every closed chain of edges used by exactly one face, following the faces'
// orientation: outer boundaries come out with positive area, holes negative. Vertices where
// several boundary chains meet are passed once per chain.
struct OffMesh {
    Eigen::MatrixX2d V;
    Eigen::MatrixX3i F;
    std::vector<Eigen::VectorXi> boundaryLoops;
};

inline constexpr long kMaxOffElements = 5'000'000; // vertices or faces
inline constexpr long long kMaxOffFileBytes = 512LL * 1024 * 1024;

// Errors: MalformedFile (what is wrong and on which line; also nan, inf), CoordinateOutOfRange,
// TooManyPoints (counts above kMaxOffElements; checked before allocating).
Expected<OffMesh, GeometryError> parseOff(const std::string &text);

// Reads the file (at most kMaxOffFileBytes), then parseOff. Errors: EmptyInput when the file
// cannot be read, those of parseOff.
Expected<OffMesh, GeometryError> readOff(const std::string &path);

// The boundary loops as rings (k×2 each, in boundaryLoops' order).
std::vector<Eigen::MatrixX2d> boundaryRings(const OffMesh &mesh);

} // namespace finbook::geometry
