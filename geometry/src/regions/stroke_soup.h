// Internal: the simplified centre lines of a drawing as segments, with the distance and
// crossing queries gap closing needs. No CGAL here; the exact work is in planar_map.cpp.
#pragma once

#include <finbook/geometry/stroke_input.h>

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry::detail {

struct SoupSegment {
    Eigen::Vector2d a, b;
    int stroke = -1;
    double arcA = 0.0; // arc length of a along its stroke
};

struct SoupStroke {
    Eigen::MatrixX2d points; // cleaned and simplified; one row for a dot
    double width = 0.0;
    double length = 0.0;
    int firstSegment = 0, segmentCount = 0;
    Eigen::Vector2d lo = Eigen::Vector2d::Zero(), hi = Eigen::Vector2d::Zero(); // bounding box
};

struct NearestPoint {
    Eigen::Vector2d point = Eigen::Vector2d::Zero();
    double distance = -1.0; // < 0: none found
    int stroke = -1;
    // The point is exactly a vertex of the stroke (points within 1e-6 px of one are moved
    // onto it), so a link ending there meets the stroke in exact arithmetic.
    bool onVertex = false;
};

class StrokeSoup {
public:
    StrokeSoup(const std::vector<StrokeInput> &strokes, double simplifyFraction);

    const std::vector<SoupStroke> &strokes() const { return m_strokes; }
    const std::vector<SoupSegment> &segments() const { return m_segments; }

    // End point (end 0 = first, 1 = last) and the unit direction the pen was moving in when
    // it left the stroke there (outward).
    Eigen::Vector2d endPoint(int stroke, int end) const;
    Eigen::Vector2d endDirection(int stroke, int end) const;
    // Arc length of the end along its stroke (0 or the stroke's length).
    double endArc(int stroke, int end) const;
    // The unit direction from the point `arc` px along the stroke from its end to the end:
    // the way the line leaves at the scale of `arc` rather than of its last segment.
    Eigen::Vector2d endDirectionOver(int stroke, int end, double arc) const;

    // Whether stroke s has segments and comes within r of p (its bounding box does).
    bool within(int s, const Eigen::Vector2d &p, double r) const;

    // Nearest point of stroke `s` to p. For the stroke the end belongs to (ownStroke == s),
    // points whose arc-length distance from ownArc is below arcFactor·d + arcExtra are
    // ignored (they are the end's own neighbourhood, not a loop coming back).
    NearestPoint nearestOnStroke(int s, const Eigen::Vector2d &p, int ownStroke, double ownArc,
                                 double arcFactor, double arcExtra) const;

    // First stroke point hit by the ray p + t·dir, 0 < t ≤ maxT, ignoring the own stroke
    // within the arc-length neighbourhood as above.
    NearestPoint castRay(const Eigen::Vector2d &p, const Eigen::Vector2d &dir, double maxT,
                         int ownStroke, double ownArc, double arcExcluded) const;

    // Whether the open segment (p, q) properly crosses a stroke segment, ignoring contacts
    // within `slack` px of p or q.
    bool crossesStrokes(const Eigen::Vector2d &p, const Eigen::Vector2d &q, double slack) const;

    // Whether the segments cross each other more than `budget` times, or so many of their
    // bounding boxes overlap that counting would itself be slow (scribbled shading):
    // the arrangement's cost grows with the crossings.
    bool tooManyCrossings(long budget) const;

private:
    std::vector<SoupStroke> m_strokes;
    std::vector<SoupSegment> m_segments;
};

// Closest point to p on segment [a, b] and its parameter in [0, 1].
Eigen::Vector2d closestOnSegment(const Eigen::Vector2d &p, const Eigen::Vector2d &a,
                                 const Eigen::Vector2d &b, double *t = nullptr);

// Whether segments (p, q) and (a, b) cross at a point more than `slack` px from p and q.
bool segmentsCross(const Eigen::Vector2d &p, const Eigen::Vector2d &q, const Eigen::Vector2d &a,
                   const Eigen::Vector2d &b, double slack);

} // namespace finbook::geometry::detail
