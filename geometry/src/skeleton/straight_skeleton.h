// Internal: CGAL's interior straight skeleton of one polygon, as dense-graph nodes and edges.
// The only translation unit of the skeleton feature that includes CGAL.
#pragma once

#include "dense_graph.h"

#include <finbook/geometry/region.h>
#include <finbook/geometry/skeleton/raw_skeleton.h>

namespace finbook::geometry::detail {

enum class StraightSkeletonStatus { Ok, Failed, Cancelled };

// Needs a strictly simple polygon (outer positive, holes negative). Appends the skeleton
// vertices that are not contour vertices (radius = event time, clearance and radius not yet
// corrected for erosion, polygon = polygonIndex) and the bisectors whose both ends are such
// vertices. Failed: CGAL returned no skeleton, or exceeded its event budget (4n + 64 events).
StraightSkeletonStatus appendStraightSkeleton(const Polygon &polygon, int polygonIndex,
                                              const CancelCallback &cancelled, DenseGraph &graph);

} // namespace finbook::geometry::detail
