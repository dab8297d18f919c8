// Pieces of the flip repair shared by the local relaxation (arap_flips.cpp) and the
// injective finish (arap_untangle.cpp). Positions are x + iy in the internal vertex order.
#pragma once

#include "arap_solver.h"

namespace finbook::deform::detail {

// Twice the signed area of triangle t at W, in the triangle's own corner order.
double signedDoubleArea(const ArapPrecompute &d, const Eigen::VectorXcd &W, Eigen::Index t);

// Strictly opposite orientation to the rest triangle's (a collapsed triangle is not flipped).
bool flipped(const ArapPrecompute &d, const Eigen::VectorXcd &W, Eigen::Index t);

// Best rotation of triangle t at W (unit complex number; identity when collapsed).
Complex rotationOf(const ArapPrecompute &d, const Eigen::VectorXcd &W, Eigen::Index t);

// The energy minimum of free vertex v with everything else fixed (rotations refitted).
Complex relaxedPosition(const ArapPrecompute &d, const Eigen::VectorXcd &W, int v);

// w.region: the free corners of the flipped triangles (w.mark set for them).
void seedRegion(const ArapPrecompute &d, Workspace &w);

// Adds the free vertices of the triangles around the region's vertices, `rings` times.
void grow(const ArapPrecompute &d, Workspace &w, int rings);

// Flipped triangles around the region's vertices, once per region corner (a measure of
// progress, not a count).
int regionFlips(const ArapPrecompute &d, const Workspace &w);

// The injective finish for folds the relaxation leaves (arap_untangle.cpp): moves the free
// corners of flipped triangles into the kernel of their one-rings where it is not empty,
// then relaxes the region with steps that keep its upright triangles upright. Kept only if
// it leaves fewer flips and adds at most maxCost of the pose's energy (refine's); spends at
// most `budget` vertex updates.
void untangleFlips(const ArapPrecompute &d, Workspace &w, double maxCost, Eigen::Index &budget);

} // namespace finbook::deform::detail
