#include "skeleton_contour.h"

#include "../clipper_bridge.h"
#include "contour_simplify.h"

#include <finbook/geometry/polyline.h>
#include <finbook/geometry/simplicity.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace finbook::geometry::detail {
namespace {

// The simplification may move the outline by at most this fraction of the polygon's mean
// half-width once the vertex target is missed but the budget holds, and by at most this
// fraction of the local half-width where the budget allows (simplifyAdaptive).
constexpr double kThicknessFraction = 0.25;

GeometryError cancelledError()
{
    return error(GeometryErrorCode::Cancelled, "The skeleton was cancelled.");
}

bool contourIsStrictlySimple(const Polygon &polygon)
{
    if (polygon.outer.rows() < 3 || !(signedArea(polygon.outer) > 0.0))
        return false;
    return isSimple(Region{polygon}, Touching::Forbidden);
}

std::uint64_t mix(std::uint64_t x)
{
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

// A deterministic displacement in [−amplitude, amplitude]² from the point's own bits, so
// equal outlines get equal jitter wherever they are listed.
void jitter(Eigen::MatrixX2d &ring, double amplitude)
{
    for (Eigen::Index i = 0; i < ring.rows(); ++i) {
        const std::uint64_t h = mix(std::bit_cast<std::uint64_t>(ring(i, 0)) ^
                                    mix(std::bit_cast<std::uint64_t>(ring(i, 1))));
        const double u = double(h & 0xffffffffULL) / double(0xffffffffULL);
        const double v = double(h >> 32) / double(0xffffffffULL);
        ring(i, 0) += amplitude * (2.0 * u - 1.0);
        ring(i, 1) += amplitude * (2.0 * v - 1.0);
    }
}

Polygon jittered(const Polygon &polygon, double amplitude)
{
    Polygon out = polygon;
    jitter(out.outer, amplitude);
    for (Eigen::MatrixX2d &hole : out.holes)
        jitter(hole, amplitude);
    return contourIsStrictlySimple(out) ? out : polygon;
}

// True if the rings are simple together (pinches allowed) and oriented as region.h says:
// then Clipper's offset can take them as they are.
bool wellFormed(const Region &region)
{
    for (const Polygon &polygon : region) {
        if (!(signedArea(polygon.outer) > 0.0))
            return false;
        for (const Eigen::MatrixX2d &hole : polygon.holes) {
            if (!(signedArea(hole) < 0.0))
                return false;
        }
    }
    return isSimple(region, Touching::AllowedAtPoints);
}

// Erosion, after a union (non-zero: loops of a scribble fill) when the rings cross or are
// oriented wrongly. The erosion opens pinches where rings touch by 2 × erosion. The rings
// are first thinned by Douglas–Peucker at half the tolerance: pixel outlines carry many
// redundant points, and the final simplification is coarser anyway.
Expected<Region, GeometryError> erode(const Region &region, double erosion,
                                      const Eigen::RowVector2d &lo, double tolerance)
{
    Region thinned = region;
    for (Polygon &polygon : thinned) {
        polygon.outer =
            douglasPeucker(cleanPolyline(polygon.outer, 0.0, true), 0.5 * tolerance, true);
        for (Eigen::MatrixX2d &hole : polygon.holes)
            hole = douglasPeucker(cleanPolyline(hole, 0.0, true), 0.5 * tolerance, true);
    }
    const ClipperFrame frame = frameFor(lo);
    ClipperLib::Paths paths;
    for (const Eigen::MatrixX2d &ring : regionRings(thinned)) {
        ClipperLib::Path path = frame.toPath(ring);
        if (path.size() >= 3)
            paths.push_back(std::move(path));
    }
    const bool unite = !wellFormed(thinned);
    return catchExceptions([&]() -> Expected<Region, GeometryError> {
        if (unite) {
            ClipperLib::Clipper clipper;
            clipper.AddPaths(paths, ClipperLib::ptSubject, true);
            ClipperLib::Paths united;
            clipper.Execute(ClipperLib::ctUnion, united, ClipperLib::pftNonZero,
                            ClipperLib::pftNonZero);
            paths = std::move(united);
        }
        ClipperLib::ClipperOffset offset(2.0);
        offset.AddPaths(paths, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
        ClipperLib::PolyTree tree;
        offset.Execute(tree, -double(frame.units(erosion)));
        return treeToRegion(tree, frame);
    });
}

} // namespace

Expected<PreparedContour, GeometryError> prepareContour(const Region &region,
                                                        const SkeletonOptions &options)
{
    Eigen::RowVector2d lo = Eigen::RowVector2d::Constant(std::numeric_limits<double>::max());
    Eigen::RowVector2d hi = -lo;
    long count = 0;
    const std::vector<Eigen::MatrixX2d> rings = regionRings(region);
    for (std::size_t i = 0; i < rings.size(); ++i) {
        const auto finite = checkPoints(rings[i], "Ring " + std::to_string(i + 1), lo, hi);
        if (!finite)
            return unexpected(finite.error());
        count += *finite;
        if (count > kMaxInputPoints)
            return unexpected(error(GeometryErrorCode::TooManyPoints,
                                    "The outline has too many points for a skeleton."));
    }
    if (count == 0)
        return unexpected(
            error(GeometryErrorCode::EmptyInput, "There is no outline to build a skeleton from."));
    PreparedContour out;
    const double diagonal = (hi - lo).norm();
    out.tolerance = options.simplifyTolerance > 0.0 ? options.simplifyTolerance
                                                    : std::clamp(0.0025 * diagonal, 0.05, 1.0);
    // A fraction of the tolerance: enough to open pinches, far below any limb's width.
    out.erosion = 0.25 * out.tolerance;
    if (!(diagonal > 0.0))
        return out;
    const auto eroded = erode(region, out.erosion, lo, out.tolerance);
    if (!eroded)
        return unexpected(eroded.error());
    out.amplitude = std::min(1e-7 * diagonal, 1e-3 * out.tolerance);
    const double start = out.tolerance;
    for (const Polygon &polygon : *eroded) {
        if (options.cancelled && options.cancelled())
            return unexpected(cancelledError());
        double used = start;
        Polygon simple = simplifyAdaptive(polygon, start, kThicknessFraction,
                                          options.targetVertices, options.maxVertices, used);
        if (simple.outer.rows() < 3)
            continue;
        // Over the cap only when the budget forced it: the outline has more detail than
        // maxVertices can carry, and bones may then cross filled-in notches a little.
        out.add(polygon, jittered(simple, out.amplitude), used);
    }
    return out;
}

Polygon retryPolygon(const PreparedContour &prepared, std::size_t p, int attempt,
                     const SkeletonOptions &options)
{
    const double factor = std::pow(1.5, attempt);
    const double start = prepared.tolerances[p] * factor;
    double used = start;
    const Polygon simple = simplifyToBudget(prepared.sources[p], start, start,
                                            options.targetVertices, options.maxVertices, used);
    if (simple.outer.rows() < 3)
        return simple;
    return jittered(simple, prepared.amplitude * std::pow(100.0, attempt));
}

Eigen::MatrixX2d regionPoints(const Region &region)
{
    const std::vector<Eigen::MatrixX2d> rings = regionRings(region);
    Eigen::Index total = 0;
    for (const Eigen::MatrixX2d &ring : rings)
        total += ring.rows();
    Eigen::MatrixX2d points(total, 2);
    Eigen::Index row = 0;
    for (const Eigen::MatrixX2d &ring : rings) {
        for (Eigen::Index i = 0; i < ring.rows(); ++i) {
            if (ring.row(i).allFinite())
                points.row(row++) = ring.row(i);
        }
    }
    points.conservativeResize(row, 2);
    return points;
}

Eigen::RowVector2d regionCentroid(const Region &region)
{
    double area = 0.0;
    Eigen::RowVector2d moment = Eigen::RowVector2d::Zero();
    for (const Eigen::MatrixX2d &ring : regionRings(region)) {
        const Eigen::MatrixX2d r = cleanPolyline(ring);
        for (Eigen::Index i = 0; i < r.rows(); ++i) {
            const Eigen::RowVector2d a = r.row(i), b = r.row((i + 1) % r.rows());
            const double cross = a.x() * b.y() - b.x() * a.y();
            area += 0.5 * cross;
            moment += cross * (a + b) / 6.0;
        }
    }
    const Eigen::MatrixX2d points = regionPoints(region);
    const double scale =
        points.rows() > 0
            ? (points.colwise().maxCoeff() - points.colwise().minCoeff()).squaredNorm()
            : 0.0;
    if (std::abs(area) > 1e-9 * scale && std::isfinite(area))
        return moment / area;
    if (points.rows() == 0)
        return Eigen::RowVector2d::Zero();
    return points.colwise().mean();
}

Eigen::Vector2d nearestOnSegment(const Eigen::Vector2d &p, const Eigen::Vector2d &a,
                                 const Eigen::Vector2d &b)
{
    const Eigen::Vector2d ab = b - a;
    const double len2 = ab.squaredNorm();
    if (len2 == 0.0)
        return a;
    return a + std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) * ab;
}

double pointSegmentDistance(const Eigen::Vector2d &p, const Eigen::Vector2d &a,
                            const Eigen::Vector2d &b)
{
    return (p - nearestOnSegment(p, a, b)).norm();
}

ContourIndex::ContourIndex(const Polygon &polygon)
{
    for (const Eigen::MatrixX2d &ring : regionRings(Region{polygon})) {
        for (Eigen::Index i = 0; i < ring.rows(); ++i) {
            m_a.push_back(ring.row(i).transpose());
            m_b.push_back(ring.row((i + 1) % ring.rows()).transpose());
        }
    }
}

double ContourIndex::distance(const Eigen::Vector2d &p) const
{
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < m_a.size(); ++i)
        best = std::min(best, pointSegmentDistance(p, m_a[i], m_b[i]));
    return best;
}

namespace {
double cross(const Eigen::Vector2d &o, const Eigen::Vector2d &a, const Eigen::Vector2d &b)
{
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

bool boxesOverlap(const Eigen::Vector2d &a, const Eigen::Vector2d &b, const Eigen::Vector2d &c,
                  const Eigen::Vector2d &d)
{
    return std::max(a.x(), b.x()) >= std::min(c.x(), d.x()) &&
           std::max(c.x(), d.x()) >= std::min(a.x(), b.x()) &&
           std::max(a.y(), b.y()) >= std::min(c.y(), d.y()) &&
           std::max(c.y(), d.y()) >= std::min(a.y(), b.y());
}

bool segmentsMeet(const Eigen::Vector2d &a, const Eigen::Vector2d &b, const Eigen::Vector2d &c,
                  const Eigen::Vector2d &d)
{
    if (!boxesOverlap(a, b, c, d))
        return false;
    const double d1 = cross(a, b, c), d2 = cross(a, b, d);
    const double d3 = cross(c, d, a), d4 = cross(c, d, b);
    return ((d1 <= 0.0 && d2 >= 0.0) || (d1 >= 0.0 && d2 <= 0.0)) &&
           ((d3 <= 0.0 && d4 >= 0.0) || (d3 >= 0.0 && d4 <= 0.0));
}
} // namespace

bool ContourIndex::segmentInside(const Eigen::Vector2d &a, const Eigen::Vector2d &b) const
{
    for (std::size_t i = 0; i < m_a.size(); ++i) {
        if (segmentsMeet(a, b, m_a[i], m_b[i]))
            return false;
    }
    return inside(0.5 * (a + b));
}

double ContourIndex::segmentDistance(const Eigen::Vector2d &a, const Eigen::Vector2d &b) const
{
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < m_a.size(); ++i) {
        if (segmentsMeet(a, b, m_a[i], m_b[i]))
            return 0.0;
        best = std::min({best, pointSegmentDistance(a, m_a[i], m_b[i]),
                         pointSegmentDistance(b, m_a[i], m_b[i]),
                         pointSegmentDistance(m_a[i], a, b), pointSegmentDistance(m_b[i], a, b)});
    }
    return best;
}

bool ContourIndex::inside(const Eigen::Vector2d &p) const
{
    bool in = false;
    for (std::size_t i = 0; i < m_a.size(); ++i) {
        const Eigen::Vector2d &a = m_a[i], &b = m_b[i];
        if ((a.y() > p.y()) != (b.y() > p.y()) &&
            p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
            in = !in;
    }
    return in;
}

} // namespace finbook::geometry::detail
