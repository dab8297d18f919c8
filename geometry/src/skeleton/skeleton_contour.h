// Internal: the outline a straight skeleton is built from, and distance / inside tests on it.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>
#include <finbook/geometry/region.h>
#include <finbook/geometry/skeleton/raw_skeleton.h>

#include <Eigen/Core>

#include <algorithm>
#include <vector>

namespace finbook::geometry::detail {

struct PreparedContour {
    Region region;          // strictly simple, outer rings positive, holes negative, jittered
    double erosion = 0.0;   // px
    double tolerance = 0.0; // px: the largest Douglas–Peucker tolerance used on a polygon
    double amplitude = 0.0; // px: the jitter
    // Per polygon of `region`: the eroded polygon it was simplified from, and the tolerance.
    std::vector<Polygon> sources;
    std::vector<double> tolerances;

    void add(const Polygon &source, Polygon simplified, double used)
    {
        region.push_back(std::move(simplified));
        sources.push_back(source);
        tolerances.push_back(used);
        tolerance = std::max(tolerance, used);
    }
};

// Erodes, simplifies to the vertex budget and jitters (raw_skeleton.h). An empty region in
// the result means the erosion left nothing (a line, a zero-area scribble).
// Errors: EmptyInput, CoordinateOutOfRange, TooManyPoints, ClippingFailed, Cancelled.
Expected<PreparedContour, GeometryError> prepareContour(const Region &region,
                                                        const SkeletonOptions &options);

// Another strictly simple version of polygon p for a retry after CGAL gave up on it
// (attempt ≥ 1): 1.5^attempt times coarser, with a 100^attempt times larger jitter. An empty
// outer ring: none.
Polygon retryPolygon(const PreparedContour &prepared, std::size_t p, int attempt,
                     const SkeletonOptions &options);

// All finite ring points of a region, stacked (m×2).
Eigen::MatrixX2d regionPoints(const Region &region);

// Area centroid of a region (outer rings minus holes); the mean of the points when the area
// is zero.
Eigen::RowVector2d regionCentroid(const Region &region);

// The edges of one polygon (outer ring and holes). Brute force: polygons have at most a few
// hundred edges after simplification, and a node's nearest edge is always in its own polygon.
class ContourIndex {
public:
    explicit ContourIndex(const Polygon &polygon);

    // Distance from p to the nearest edge (+inf without edges).
    double distance(const Eigen::Vector2d &p) const;

    // True if the segment a–b crosses or touches no edge and its midpoint is inside.
    bool segmentInside(const Eigen::Vector2d &a, const Eigen::Vector2d &b) const;

    // Distance from the segment a–b to the nearest edge: 0 if it crosses or touches one;
    // +inf without edges. Says nothing about which side the segment is on.
    double segmentDistance(const Eigen::Vector2d &a, const Eigen::Vector2d &b) const;

    // Even-odd inside test over the rings.
    bool inside(const Eigen::Vector2d &p) const;

private:
    std::vector<Eigen::Vector2d> m_a, m_b; // edge i runs m_a[i] → m_b[i]
};

// The point of segment [a, b] nearest p, and its distance from p.
Eigen::Vector2d nearestOnSegment(const Eigen::Vector2d &p, const Eigen::Vector2d &a,
                                 const Eigen::Vector2d &b);
double pointSegmentDistance(const Eigen::Vector2d &p, const Eigen::Vector2d &a,
                            const Eigen::Vector2d &b);

} // namespace finbook::geometry::detail
