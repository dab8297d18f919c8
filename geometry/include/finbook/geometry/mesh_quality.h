// Measurements of a triangle mesh V (n×2), F (m×3) used by tests, benches and sanity checks.
#pragma once

#include <Eigen/Core>

namespace finbook::geometry {

// m-vector of shoelace areas (positive = counter-clockwise in y-up axes, see region.h).
Eigen::VectorXd triangleSignedAreas(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F);

// Smallest interior angle over all triangles, degrees (180 for an empty mesh).
double minAngleDegrees(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F);

// Connected components of faces sharing a vertex; returns their count and fills
// `faceComponent` (m-vector) if given.
int connectedComponents(const Eigen::MatrixX3i &F, Eigen::Index vertexCount,
                        Eigen::VectorXi *faceComponent = nullptr);

} // namespace finbook::geometry
