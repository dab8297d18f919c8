// Polyline and ring utilities. Points are n×2 (one row per point). "closed" treats the
// polyline as a ring whose last point connects back to the first (not repeated).
#pragma once

#include <Eigen/Core>

namespace finbook::geometry {

// Drops non-finite rows and consecutive points closer than minDistance (exact repeats when
// 0). For a closed ring the last point is also dropped when it repeats the first.
Eigen::MatrixX2d cleanPolyline(const Eigen::MatrixX2d &points, double minDistance = 0.0,
                               bool closed = false);

// Total length; for closed rings including the closing edge.
double polylineLength(const Eigen::MatrixX2d &points, bool closed = false);

// Points at uniform arc-length spacing (the last interval absorbs the remainder so open
// polylines keep both end points; rings get round(length / spacing) ≥ 3 points).
// Returns the input unchanged if it has < 2 points, zero length or spacing is not > 0.
Eigen::MatrixX2d resample(const Eigen::MatrixX2d &points, double spacing, bool closed = false);

// Douglas–Peucker: keeps a subset of the points (end points always, for rings at least 3)
// such that every dropped point lies within tolerance of the kept chord.
Eigen::MatrixX2d douglasPeucker(const Eigen::MatrixX2d &points, double tolerance,
                                bool closed = false);

// Shoelace area of a ring (see region.h for the sign convention).
double signedArea(const Eigen::MatrixX2d &ring);

// True if signedArea > 0 (counter-clockwise in y-up math axes).
bool isCounterClockwise(const Eigen::MatrixX2d &ring);

// The ring with its orientation chosen: positive → signedArea ≥ 0, else ≤ 0.
Eigen::MatrixX2d oriented(const Eigen::MatrixX2d &ring, bool positive);

} // namespace finbook::geometry
