// Internal: simplifying a polygon to a vertex budget for the straight skeleton.
#pragma once

#include <finbook/geometry/region.h>

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry::detail {

// For every vertex of a ring, the largest tolerance at which ring Douglas–Peucker
// (douglasPeucker(ring, t, true), polyline.h) still keeps it: the ring at tolerance t is
// exactly the vertices whose value exceeds t. +inf for the vertices a ring always keeps. One
// O(n log n) pass answers every tolerance, so a vertex budget needs no trial runs. With
// `scale` (one positive value per vertex), every distance is divided by its vertex's scale:
// the values are then tolerances in units of the local scale.
std::vector<double> keepTolerances(const Eigen::MatrixX2d &ring,
                                   const std::vector<double> *scale = nullptr);

// Mean half-width of a polygon: area / perimeter (exactly the half-width of a long band).
double thickness(const Polygon &polygon);

// The polygon simplified for the straight skeleton: Douglas–Peucker at the smallest
// tolerance ≥ start that leaves at most `target` vertices, but not past `cap` (so thin parts
// keep their shape) as long as `budget` vertices suffice; then 25 % coarser steps until the
// result is strictly simple (isSimple, Touching::Forbidden), else finer ones. Holes squashed
// below the tolerance are dropped. An empty outer ring: no strictly simple version found.
// `used` receives the tolerance of the result.
Polygon simplifyToBudget(const Polygon &polygon, double start, double cap, int target, int budget,
                         double &used);

// The adaptive vertex budget (issue 21: thin parts kept). Every vertex simplifyToBudget(
// polygon, start, cap = max(start, fraction × thickness), target, budget) keeps stays, and to
// them come the vertices of the outline thinned at ≥ start (at most two budgets of them)
// whose removal would move the outline by more than `fraction` of the local half-width there
// (localHalfWidths, clamped to [4 × start, thickness]): thin limbs, tips and tight bends get
// vertices, wide smooth parts keep the uniform tolerance. If the extra vertices do not fit
// the budget, the fraction grows 25 % at a time until they do; if the result is not strictly
// simple, it shrinks (more vertices) while they fit; failing that, simplifyToBudget's result.
// `used` receives the uniform tolerance (nothing is coarser).
Polygon simplifyAdaptive(const Polygon &polygon, double start, double fraction, int target,
                         int budget, double &used);

} // namespace finbook::geometry::detail
