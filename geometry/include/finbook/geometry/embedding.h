// Embedding of points (stroke samples) in a mesh: triangle + barycentric weights, so that the
// points follow the mesh when its vertices move.
#pragma once

#include <finbook/geometry/object_mesh.h>

#include <Eigen/Core>

namespace finbook::geometry {

// I: k-vector of triangle rows of F (−1 only if F was empty); B: k×3 barycentric weights
// (rows sum to 1). `snapped` counts points that were outside the mesh and got the nearest
// triangle's closest point; `unlocated` counts non-finite points (bound to triangle 0's
// centroid, so applying never yields NaN).
struct Embedding {
    Eigen::VectorXi I;
    Eigen::MatrixX3d B;
    int snapped = 0;
    int unlocated = 0;
};

// V: n×2, F: m×3, points: k×2. Builds a TriangleLocator (O(m)), then O(1) per point.
Embedding embed(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                const Eigen::MatrixX2d &points);
Embedding embed(const ObjectMesh &mesh, const Eigen::MatrixX2d &points);

// k×2 positions of the embedded points on the mesh with vertices Vdeformed (n×2, same F as
// for embed). With the rest V this reproduces inside points to rounding (~1e-15 × size).
// Points with I = −1 map to (0, 0).
Eigen::MatrixX2d applyEmbedding(const Embedding &embedding, const Eigen::MatrixX2d &Vdeformed,
                                const Eigen::MatrixX3i &F);

} // namespace finbook::geometry
