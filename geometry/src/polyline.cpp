#include <finbook/geometry/polyline.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace finbook::geometry {
namespace {

Eigen::MatrixX2d selectRows(const Eigen::MatrixX2d &points, const std::vector<bool> &keep)
{
    Eigen::Index count = 0;
    for (bool k : keep)
        count += k ? 1 : 0;
    Eigen::MatrixX2d out(count, 2);
    Eigen::Index row = 0;
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        if (keep[std::size_t(i)])
            out.row(row++) = points.row(i);
    }
    return out;
}

double distanceToSegment(const Eigen::RowVector2d &p, const Eigen::RowVector2d &a,
                         const Eigen::RowVector2d &b)
{
    const Eigen::RowVector2d ab = b - a;
    const double len2 = ab.squaredNorm();
    if (len2 == 0.0)
        return (p - a).norm();
    const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
    return (p - (a + t * ab)).norm();
}

// Marks the points of [first, last] that Douglas–Peucker keeps; iterative so long strokes
// cannot overflow the stack.
void markDouglasPeucker(const Eigen::MatrixX2d &points, Eigen::Index first, Eigen::Index last,
                        double tolerance, std::vector<bool> &keep)
{
    std::vector<std::pair<Eigen::Index, Eigen::Index>> stack{{first, last}};
    while (!stack.empty()) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        double worst = -1.0;
        Eigen::Index worstIndex = -1;
        for (Eigen::Index i = a + 1; i < b; ++i) {
            const double d = distanceToSegment(points.row(i), points.row(a), points.row(b));
            if (d > worst) {
                worst = d;
                worstIndex = i;
            }
        }
        if (worstIndex >= 0 && worst > tolerance) {
            keep[std::size_t(worstIndex)] = true;
            stack.emplace_back(a, worstIndex);
            stack.emplace_back(worstIndex, b);
        }
    }
}

} // namespace

Eigen::MatrixX2d cleanPolyline(const Eigen::MatrixX2d &points, double minDistance, bool closed)
{
    std::vector<bool> keep(std::size_t(points.rows()), false);
    Eigen::Index last = -1;
    Eigen::Index first = -1;
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        if (!points.row(i).allFinite())
            continue;
        if (last >= 0 && (points.row(i) - points.row(last)).norm() <= minDistance)
            continue;
        keep[std::size_t(i)] = true;
        last = i;
        if (first < 0)
            first = i;
    }
    if (closed && last > first && first >= 0 &&
        (points.row(last) - points.row(first)).norm() <= minDistance)
        keep[std::size_t(last)] = false;
    return selectRows(points, keep);
}

double polylineLength(const Eigen::MatrixX2d &points, bool closed)
{
    const Eigen::Index n = points.rows();
    double length = 0.0;
    for (Eigen::Index i = 0; i + 1 < n; ++i)
        length += (points.row(i + 1) - points.row(i)).norm();
    if (closed && n > 2)
        length += (points.row(0) - points.row(n - 1)).norm();
    return length;
}

Eigen::MatrixX2d resample(const Eigen::MatrixX2d &points, double spacing, bool closed)
{
    const Eigen::Index n = points.rows();
    const double length = polylineLength(points, closed);
    if (n < 2 || !(spacing > 0.0) || !(length > 0.0) || !std::isfinite(length))
        return points;
    const double count = std::round(length / spacing);
    const Eigen::Index intervals = std::max<Eigen::Index>(closed ? 3 : 1, Eigen::Index(count));
    const double step = length / double(intervals);
    const Eigen::Index outRows = closed ? intervals : intervals + 1;
    Eigen::MatrixX2d out(outRows, 2);
    Eigen::Index segment = 0;
    double segmentStart = 0.0; // arc length at the start of `segment`
    const Eigen::Index segments = closed ? n : n - 1;
    for (Eigen::Index k = 0; k < outRows; ++k) {
        const double s = std::min(double(k) * step, length);
        auto segmentLength = [&](Eigen::Index i) {
            return (points.row((i + 1) % n) - points.row(i)).norm();
        };
        while (segment + 1 < segments && segmentStart + segmentLength(segment) < s) {
            segmentStart += segmentLength(segment);
            ++segment;
        }
        const double len = segmentLength(segment);
        const double t = len > 0.0 ? std::clamp((s - segmentStart) / len, 0.0, 1.0) : 0.0;
        out.row(k) = (1.0 - t) * points.row(segment) + t * points.row((segment + 1) % n);
    }
    if (!closed)
        out.row(outRows - 1) = points.row(n - 1);
    return out;
}

Eigen::MatrixX2d douglasPeucker(const Eigen::MatrixX2d &points, double tolerance, bool closed)
{
    const Eigen::Index n = points.rows();
    if (n < 3 || !(tolerance >= 0.0))
        return points;
    std::vector<bool> keep(std::size_t(n), false);
    keep.front() = true;
    if (!closed) {
        keep.back() = true;
        markDouglasPeucker(points, 0, n - 1, tolerance, keep);
        return selectRows(points, keep);
    }
    // A ring is split at vertex 0 and the vertex farthest from it; both halves are open
    // polylines, and the split vertices survive so the ring keeps at least 3 points.
    Eigen::Index far = 1;
    for (Eigen::Index i = 1; i < n; ++i) {
        if ((points.row(i) - points.row(0)).squaredNorm() >
            (points.row(far) - points.row(0)).squaredNorm())
            far = i;
    }
    keep[std::size_t(far)] = true;
    markDouglasPeucker(points, 0, far, tolerance, keep);
    Eigen::MatrixX2d wrapped(n - far + 1, 2);
    wrapped.topRows(n - far) = points.bottomRows(n - far);
    wrapped.row(n - far) = points.row(0);
    std::vector<bool> keepWrapped(std::size_t(n - far + 1), false);
    markDouglasPeucker(wrapped, 0, n - far, tolerance, keepWrapped);
    for (Eigen::Index i = 1; i < n - far; ++i)
        keep[std::size_t(far + i)] = keepWrapped[std::size_t(i)];
    Eigen::MatrixX2d out = selectRows(points, keep);
    if (out.rows() < 3) {
        // A sliver ring: keep the vertex farthest from the chord so the ring stays a ring.
        double worst = -1.0;
        Eigen::Index worstIndex = 1;
        for (Eigen::Index i = 1; i < n; ++i) {
            const double d = distanceToSegment(points.row(i), points.row(0), points.row(far));
            if (i != far && d > worst) {
                worst = d;
                worstIndex = i;
            }
        }
        keep[std::size_t(worstIndex)] = true;
        out = selectRows(points, keep);
    }
    return out;
}

double signedArea(const Eigen::MatrixX2d &ring)
{
    const Eigen::Index n = ring.rows();
    if (n < 3)
        return 0.0;
    // Relative to the first point: the same sum, but without cancellation far from the origin.
    double twice = 0.0;
    const Eigen::RowVector2d origin = ring.row(0);
    for (Eigen::Index i = 1; i + 1 < n; ++i) {
        const Eigen::RowVector2d a = ring.row(i) - origin;
        const Eigen::RowVector2d b = ring.row(i + 1) - origin;
        twice += a.x() * b.y() - b.x() * a.y();
    }
    return 0.5 * twice;
}

bool isCounterClockwise(const Eigen::MatrixX2d &ring)
{
    return signedArea(ring) > 0.0;
}

Eigen::MatrixX2d oriented(const Eigen::MatrixX2d &ring, bool positive)
{
    const double area = signedArea(ring);
    if ((positive && area < 0.0) || (!positive && area > 0.0))
        return ring.colwise().reverse();
    return ring;
}

} // namespace finbook::geometry
