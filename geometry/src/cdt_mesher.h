// Internal: CGAL constrained Delaunay triangulation + Delaunay refinement of a simple region.
// Kept apart so only one translation unit pays for the CGAL headers.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>
#include <finbook/geometry/region.h>

#include <Eigen/Core>

namespace finbook::geometry::detail {

struct RawMesh {
    Eigen::MatrixX2d V; // n×2
    Eigen::MatrixX3i F; // m×3, positive shoelace area, only triangles inside the region
};

// maxEdge: CGAL size bound (px). Refinement stops early (mesh still valid, some triangles
// larger or skinnier) once vertexCap vertices exist, so absurd inputs stay bounded.
Expected<RawMesh, GeometryError> refineRegion(const Region &region, double maxEdge, long vertexCap);

} // namespace finbook::geometry::detail
