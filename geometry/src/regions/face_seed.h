// Internal: a point well inside a polygon with holes, for labels and fill seeds.
#pragma once

#include <finbook/geometry/region.h>

#include <Eigen/Core>

namespace finbook::geometry::detail {

// The midpoint of the widest inside interval on a few horizontal scanlines, chosen by its
// distance to the boundary: strictly inside the outer ring and outside every hole whenever
// the polygon has area; the outer ring's first vertex otherwise.
Eigen::Vector2d interiorSeed(const Polygon &polygon);

// Distance from p to the nearest edge of any ring of the polygon.
double boundaryDistance(const Polygon &polygon, const Eigen::Vector2d &p);

} // namespace finbook::geometry::detail
