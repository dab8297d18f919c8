// Simplicity tests for rings: no edge touches or crosses another edge except its two
// neighbours at the shared end point, no zero-length edges, at least 3 vertices.
// Uses a uniform grid over the edges: about linear time in the number of edges.
#pragma once

#include <finbook/geometry/region.h>

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry {

enum class Touching {
    Forbidden, // strictly simple: edges meet only their two neighbours, at the shared vertex
    // Edges may also touch at a point where one of them ends (a pinch where a ring or two
    // rings meet at a vertex, or a T); crossings and overlapping stretches stay forbidden.
    // Clipper's unions produce such pinches, and the mesher handles them.
    AllowedAtPoints,
};

// One ring (m×2, implicitly closed).
bool isSimple(const Eigen::MatrixX2d &ring, Touching touching = Touching::Forbidden);

// A set of rings together: each ring simple and no two rings touching or crossing.
bool isSimple(const std::vector<Eigen::MatrixX2d> &rings, Touching touching = Touching::Forbidden);

// Every ring of the region simple, rings not touching (unless allowed); orientation and
// nesting are not checked.
bool isSimple(const Region &region, Touching touching = Touching::Forbidden);

} // namespace finbook::geometry
