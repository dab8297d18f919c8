// The boundary of a triangle mesh: its half-edges without a twin, chained into loops.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry {

// Every closed chain of edges used by exactly one triangle of F (m×3), following the
// triangles' orientation: with counter-clockwise triangles, outer boundaries come out
// counter-clockwise and holes clockwise. A vertex where several chains meet is passed once
// per chain; an open chain (non-manifold input) keeps what was walked. Loops of fewer than
// three vertices are dropped.
std::vector<Eigen::VectorXi> boundaryLoops(const Eigen::MatrixX3i &F);

} // namespace finbook::geometry
