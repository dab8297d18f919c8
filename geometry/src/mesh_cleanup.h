// Internal: make raw triangle soups safe for OpenMesh and for the ObjectMesh promises.
#pragma once

#include <Eigen/Core>

namespace finbook::geometry::detail {

// Drops triangles whose shoelace area is not positive (never expected from CGAL, but the
// promise must not depend on it) and vertices no triangle references.
void dropDegenerate(Eigen::MatrixX2d &V, Eigen::MatrixX3i &F);

// A vertex where two fans of triangles touch only at a point (a pinched outline) cannot be
// represented by OpenMesh's halfedge structure; each extra fan gets its own copy.
void splitNonManifoldVertices(Eigen::MatrixX2d &V, Eigen::MatrixX3i &F);

} // namespace finbook::geometry::detail
