// Internal: how thin a polygon is at each of its vertices, for the adaptive vertex budget.
#pragma once

#include <finbook/geometry/region.h>

#include <limits>
#include <vector>

namespace finbook::geometry::detail {

// +inf, as localHalfWidths gives it where nothing bounds a vertex.
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Per ring of `polygon` (outer first, then the holes), per vertex: the radius of the largest
// disk inside the polygon that touches the outline at that vertex (tangent to the vertex's
// averaged edge normal), against every edge but the vertex's own two and those that start or
// end within `ignore` of it along its ring (so steps and jaggies of the outline smaller than
// that do not count as thinness). Across a limb that is the limb's half-width; at a tip or a
// tight bend, the bend's radius at that scale; +inf where nothing bounds it. Edges are found
// through a uniform grid, about n·√n for n vertices: call it on an already thinned outline.
std::vector<std::vector<double>> localHalfWidths(const Polygon &polygon, double ignore);

} // namespace finbook::geometry::detail
