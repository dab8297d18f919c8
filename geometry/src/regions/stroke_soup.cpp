#include "stroke_soup.h"

#include <finbook/geometry/polyline.h>

#include <algorithm>
#include <cmath>

namespace finbook::geometry::detail {

Eigen::Vector2d closestOnSegment(const Eigen::Vector2d &p, const Eigen::Vector2d &a,
                                 const Eigen::Vector2d &b, double *t)
{
    const Eigen::Vector2d ab = b - a;
    const double len2 = ab.squaredNorm();
    const double s = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    if (t)
        *t = s;
    // The end points exactly, so that a link to a stroke's vertex meets it in exact arithmetic.
    return s <= 0.0 ? a : s >= 1.0 ? b : Eigen::Vector2d(a + s * ab);
}

namespace {

constexpr double kVertexSnap = 1e-6; // px

void setPoint(NearestPoint &near, const Eigen::Vector2d &x, const SoupSegment &seg)
{
    near.onVertex = true;
    if ((x - seg.a).norm() <= kVertexSnap)
        near.point = seg.a;
    else if ((x - seg.b).norm() <= kVertexSnap)
        near.point = seg.b;
    else {
        near.point = x;
        near.onVertex = false;
    }
}

double cross(const Eigen::Vector2d &u, const Eigen::Vector2d &v)
{
    return u.x() * v.y() - u.y() * v.x();
}

} // namespace

bool segmentsCross(const Eigen::Vector2d &p, const Eigen::Vector2d &q, const Eigen::Vector2d &a,
                   const Eigen::Vector2d &b, double slack)
{
    const Eigen::Vector2d r = q - p, s = b - a;
    const double denom = cross(r, s);
    const double rr = r.squaredNorm();
    if (!(rr > 0.0))
        return false;
    const auto farFromEnds = [&](const Eigen::Vector2d &x) {
        return (x - p).norm() > slack && (x - q).norm() > slack;
    };
    if (std::abs(denom) <= 1e-12 * std::sqrt(rr * s.squaredNorm())) {
        // Parallel: only a collinear overlap away from the ends counts.
        if (std::abs(cross(r, a - p)) > 1e-9 * rr)
            return false;
        const double t0 = (a - p).dot(r) / rr, t1 = (b - p).dot(r) / rr;
        const double lo = std::max(0.0, std::min(t0, t1)), hi = std::min(1.0, std::max(t0, t1));
        return hi > lo && farFromEnds(p + 0.5 * (lo + hi) * r);
    }
    const double t = cross(a - p, s) / denom, u = cross(a - p, r) / denom;
    if (t < 0.0 || t > 1.0 || u < 0.0 || u > 1.0)
        return false;
    return farFromEnds(p + t * r);
}

StrokeSoup::StrokeSoup(const std::vector<StrokeInput> &strokes, double simplifyFraction)
{
    m_strokes.reserve(strokes.size());
    for (std::size_t s = 0; s < strokes.size(); ++s) {
        SoupStroke stroke;
        stroke.width = strokes[s].width;
        const double tolerance = std::max(0.05, simplifyFraction * stroke.width);
        stroke.points = douglasPeucker(cleanPolyline(strokes[s].points), tolerance);
        stroke.firstSegment = int(m_segments.size());
        double arc = 0.0;
        for (Eigen::Index i = 0; i + 1 < stroke.points.rows(); ++i) {
            const Eigen::Vector2d a = stroke.points.row(i).transpose();
            const Eigen::Vector2d b = stroke.points.row(i + 1).transpose();
            m_segments.push_back({a, b, int(s), arc});
            arc += (b - a).norm();
        }
        stroke.length = arc;
        if (stroke.points.rows() > 0) {
            stroke.lo = stroke.points.colwise().minCoeff().transpose();
            stroke.hi = stroke.points.colwise().maxCoeff().transpose();
        }
        stroke.segmentCount = int(m_segments.size()) - stroke.firstSegment;
        m_strokes.push_back(std::move(stroke));
    }
}

bool StrokeSoup::within(int s, const Eigen::Vector2d &p, double r) const
{
    const SoupStroke &stroke = m_strokes[std::size_t(s)];
    return stroke.segmentCount > 0 && p.x() >= stroke.lo.x() - r && p.x() <= stroke.hi.x() + r &&
           p.y() >= stroke.lo.y() - r && p.y() <= stroke.hi.y() + r;
}

Eigen::Vector2d StrokeSoup::endPoint(int stroke, int end) const
{
    const Eigen::MatrixX2d &pts = m_strokes[std::size_t(stroke)].points;
    return pts.row(end == 0 ? 0 : pts.rows() - 1).transpose();
}

Eigen::Vector2d StrokeSoup::endDirection(int stroke, int end) const
{
    const Eigen::MatrixX2d &pts = m_strokes[std::size_t(stroke)].points;
    const Eigen::Index n = pts.rows();
    if (n < 2)
        return Eigen::Vector2d::Zero();
    const Eigen::Vector2d d = end == 0 ? Eigen::Vector2d(pts.row(0) - pts.row(1))
                                       : Eigen::Vector2d(pts.row(n - 1) - pts.row(n - 2));
    const double len = d.norm();
    return len > 0.0 ? Eigen::Vector2d(d / len) : Eigen::Vector2d::Zero();
}

double StrokeSoup::endArc(int stroke, int end) const
{
    return end == 0 ? 0.0 : m_strokes[std::size_t(stroke)].length;
}

Eigen::Vector2d StrokeSoup::endDirectionOver(int stroke, int end, double arc) const
{
    const Eigen::MatrixX2d &pts = m_strokes[std::size_t(stroke)].points;
    const Eigen::Index n = pts.rows();
    if (n < 2)
        return Eigen::Vector2d::Zero();
    const auto at = [&](Eigen::Index i) -> Eigen::Vector2d {
        return pts.row(end == 0 ? i : n - 1 - i).transpose();
    };
    const Eigen::Vector2d tip = at(0);
    double walked = 0.0;
    Eigen::Vector2d from = at(1);
    for (Eigen::Index i = 1; i < n; ++i) {
        const double step = (at(i) - at(i - 1)).norm();
        if (walked + step >= arc) {
            const double t = step > 0.0 ? (arc - walked) / step : 0.0;
            from = at(i - 1) + t * (at(i) - at(i - 1));
            break;
        }
        walked += step;
        from = at(i);
    }
    const Eigen::Vector2d d = tip - from;
    const double len = d.norm();
    return len > 0.0 ? Eigen::Vector2d(d / len) : endDirection(stroke, end);
}

NearestPoint StrokeSoup::nearestOnStroke(int s, const Eigen::Vector2d &p, int ownStroke,
                                         double ownArc, double arcFactor, double arcExtra) const
{
    const SoupStroke &stroke = m_strokes[std::size_t(s)];
    NearestPoint best;
    best.stroke = s;
    for (int i = stroke.firstSegment; i < stroke.firstSegment + stroke.segmentCount; ++i) {
        const SoupSegment &seg = m_segments[std::size_t(i)];
        double t = 0.0;
        const Eigen::Vector2d c = closestOnSegment(p, seg.a, seg.b, &t);
        const double d = (c - p).norm();
        if (best.distance >= 0.0 && d >= best.distance)
            continue;
        if (s == ownStroke) {
            const double arc = seg.arcA + t * (seg.b - seg.a).norm();
            if (std::abs(arc - ownArc) < arcFactor * d + arcExtra) {
                // The closest point of this segment is too near along the stroke; a point
                // further along the segment may still qualify, take the first such point.
                const double len = (seg.b - seg.a).norm();
                if (len <= 0.0)
                    continue;
                // Walk away from the end along the segment in small steps (rare case).
                bool found = false;
                for (int k = 1; k <= 16 && !found; ++k) {
                    const double tt = ownArc <= seg.arcA ? std::min(1.0, t + k / 16.0 * (1.0 - t))
                                                         : std::max(0.0, t - k / 16.0 * t);
                    const Eigen::Vector2d x = seg.a + tt * (seg.b - seg.a);
                    const double dx = (x - p).norm();
                    const double ax = seg.arcA + tt * len;
                    if (std::abs(ax - ownArc) >= arcFactor * dx + arcExtra &&
                        (best.distance < 0.0 || dx < best.distance)) {
                        setPoint(best, x, seg);
                        best.distance = dx;
                        found = true;
                    }
                }
                continue;
            }
        }
        setPoint(best, c, seg);
        best.distance = d;
    }
    return best;
}

NearestPoint StrokeSoup::castRay(const Eigen::Vector2d &p, const Eigen::Vector2d &dir, double maxT,
                                 int ownStroke, double ownArc, double arcExcluded) const
{
    NearestPoint best;
    if (!(dir.squaredNorm() > 0.0) || !(maxT > 0.0))
        return best;
    const Eigen::Vector2d q = p + maxT * dir;
    for (const SoupSegment &seg : m_segments) {
        if (!within(seg.stroke, p, maxT))
            continue;
        const Eigen::Vector2d r = q - p, s = seg.b - seg.a;
        const double denom = cross(r, s);
        if (std::abs(denom) < 1e-12)
            continue;
        const double t = cross(seg.a - p, s) / denom, u = cross(seg.a - p, r) / denom;
        if (t <= 1e-9 || t > 1.0 || u < 0.0 || u > 1.0)
            continue;
        const double d = t * maxT;
        if (best.distance >= 0.0 && d >= best.distance)
            continue;
        if (seg.stroke == ownStroke &&
            std::abs(seg.arcA + u * s.norm() - ownArc) < arcExcluded + 2.0 * d)
            continue;
        setPoint(best, p + t * r, seg);
        best.distance = d;
        best.stroke = seg.stroke;
    }
    return best;
}

bool StrokeSoup::tooManyCrossings(long budget) const
{
    // Sweep in x: only segments whose x-ranges overlap are compared.
    const long pairBudget = 2000L * budget;
    std::vector<int> order(m_segments.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = int(i);
    const auto minX = [&](int i) {
        return std::min(m_segments[std::size_t(i)].a.x(), m_segments[std::size_t(i)].b.x());
    };
    std::sort(order.begin(), order.end(), [&](int i, int j) { return minX(i) < minX(j); });
    long crossings = 0, pairs = 0;
    for (std::size_t i = 0; i < order.size(); ++i) {
        const SoupSegment &s = m_segments[std::size_t(order[i])];
        const double maxX = std::max(s.a.x(), s.b.x());
        const double loY = std::min(s.a.y(), s.b.y()), hiY = std::max(s.a.y(), s.b.y());
        for (std::size_t j = i + 1; j < order.size() && minX(order[j]) <= maxX; ++j) {
            const SoupSegment &t = m_segments[std::size_t(order[j])];
            if (std::max(t.a.y(), t.b.y()) < loY || std::min(t.a.y(), t.b.y()) > hiY)
                continue;
            if (++pairs > pairBudget)
                return true;
            if (segmentsCross(s.a, s.b, t.a, t.b, 0.0) && ++crossings > budget)
                return true;
        }
    }
    return false;
}

bool StrokeSoup::crossesStrokes(const Eigen::Vector2d &p, const Eigen::Vector2d &q,
                                double slack) const
{
    const Eigen::Vector2d lo = p.cwiseMin(q), hi = p.cwiseMax(q);
    for (const SoupSegment &seg : m_segments) {
        if (seg.a.cwiseMax(seg.b).x() < lo.x() || seg.a.cwiseMin(seg.b).x() > hi.x() ||
            seg.a.cwiseMax(seg.b).y() < lo.y() || seg.a.cwiseMin(seg.b).y() > hi.y())
            continue;
        if (segmentsCross(p, q, seg.a, seg.b, slack))
            return true;
    }
    return false;
}

} // namespace finbook::geometry::detail
