// Cages: simple polygons drawn around an object; dragging their corners poses the object
// through harmonic coordinates (deform/cage/harmonic_cage.h). A cage is c×2 corners,
// implicitly closed (the first corner is not repeated), in either orientation. Edge e joins
// corner e and corner (e + 1) mod c.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>

#include <Eigen/Core>

#include <optional>

namespace finbook::geometry {

// Whether `corners` can be a cage: at least 3 corners, all finite and within ±kMaxCoordinate,
// non-zero area, strictly simple (no two consecutive corners equal, no edge touching or
// crossing any edge but its two neighbours at their shared corner).
// Errors, checked in this order: TooFewCorners, NonFiniteInput, CoordinateOutOfRange,
// DegenerateRegion (zero area, e.g. collinear corners), NotSimple.
std::optional<GeometryError> checkCage(const Eigen::MatrixX2d &corners);

// checkCage, then the cage with positive orientation (shoelace area > 0, see region.h): if it
// has to be reversed, corner 0 stays first and the others follow in reverse order.
Expected<Eigen::MatrixX2d, GeometryError> normalizedCage(const Eigen::MatrixX2d &corners);

// Distance from p to the nearest edge of the cage (any orientation; ≥ 3 finite corners).
double distanceToCage(const Eigen::MatrixX2d &corners, const Eigen::Vector2d &p);

// Rows of `points` (k×2) the cage does not contain, ascending. A point is contained when it is
// inside (crossing number) or on an edge, and at least `clearance` (≥ 0) from every edge;
// non-finite rows are never contained. `corners` must pass checkCage.
// Cost O(k × c): fine for strokes against a coarse cage.
Eigen::VectorXi cageOutsidePoints(const Eigen::MatrixX2d &corners, const Eigen::MatrixX2d &points,
                                  double clearance = 0.0);

// PointsOutsideCage, with a sentence saying how many points stick out and around which part
// of the drawing (their bounding box), when cageOutsidePoints is not empty; else nullopt.
std::optional<GeometryError> checkCageContains(const Eigen::MatrixX2d &corners,
                                               const Eigen::MatrixX2d &points,
                                               double clearance = 0.0);

} // namespace finbook::geometry
