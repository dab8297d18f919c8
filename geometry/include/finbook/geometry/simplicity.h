// Simplicity tests for rings: no edge touches or crosses another edge except its two
// neighbours at the shared end point, no zero-length edges, at least 3 vertices.
// Uses a uniform grid over the edges: about linear time in the number of edges.
#pragma once

#include <finbook/geometry/region.h>

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry {

// One ring (m×2, implicitly closed).
bool isSimple(const Eigen::MatrixX2d &ring);

// A set of rings together: each ring simple and no two rings touching or crossing.
bool isSimple(const std::vector<Eigen::MatrixX2d> &rings);

// Every ring of the region simple, no rings touching; orientation and nesting are not checked.
bool isSimple(const Region &region);

} // namespace finbook::geometry
