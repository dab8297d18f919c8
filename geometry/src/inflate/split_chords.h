// Chords are interior edges whose two ends both lie on the outline (across a part one triangle
// wide). Inflated, they stay at height 0, so the surface would pinch to a line there and the
// closed solid would have four triangles on one edge. Splitting them at their midpoints puts
// an interior vertex, with a height, on every such crossing. Internal to geometry/src/inflate.
#pragma once

#include <Eigen/Core>

namespace finbook::geometry::inflate_detail {

// Appends one vertex at the midpoint of every chord of (V, F) (vertices keep their indices)
// and replaces each triangle touching a chord by 2–4 triangles of the same orientation.
// Returns the number of vertices added. F must index V and be consistently oriented.
int splitOutlineChords(Eigen::MatrixX2d &V, Eigen::MatrixX3i &F);

} // namespace finbook::geometry::inflate_detail
