#include "../clipper_bridge.h"

#include <finbook/geometry/cage/cage_polygon.h>
#include <finbook/geometry/cage/fit_cage.h>
#include <finbook/geometry/object_shape.h>
#include <finbook/geometry/polyline.h>
#include <finbook/geometry/simplicity.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace finbook::geometry {
namespace {

using detail::error;

// Rounds of pushing the cage further out when a point still sticks out or the pushed polygon
// crosses itself, before falling back to the convex hull.
constexpr int kGrowRounds = 6;
// Bisection steps on the simplification tolerance: the corner count is settled long before.
constexpr int kToleranceSteps = 30;
// Clipper's miter limit (× offset): sharper corners are squared off, adding a corner.
constexpr double kMiterLimit = 4.0;

struct Input {
    detail::ClipperFrame frame;
    Eigen::MatrixX2d points; // finite rows of mustContain
    ClipperLib::Paths outer; // outer rings of the shape
    double extent = 0.0;     // bounding-box diagonal of everything
};

Expected<Input, GeometryError> checkInput(const Region &shape, const Eigen::MatrixX2d &mustContain,
                                          const FitCageOptions &options)
{
    if (options.corners < kMinFitCorners || options.corners > kMaxFitCorners ||
        !std::isfinite(options.margin) || options.margin < 0.0 || options.margin > kMaxPenWidth)
        return unexpected(
            error(GeometryErrorCode::InvalidOptions,
                  "Fit Cage needs 3 to 1000 corners and a margin within [0, 1e4] px."));
    Eigen::RowVector2d lo = Eigen::RowVector2d::Constant(std::numeric_limits<double>::max());
    Eigen::RowVector2d hi = -lo;
    long total = 0;
    for (const Polygon &polygon : shape) {
        auto count = detail::checkPoints(polygon.outer, "The shape", lo, hi);
        if (!count)
            return unexpected(count.error());
        total += *count;
    }
    auto count = detail::checkPoints(mustContain, "A point", lo, hi);
    if (!count)
        return unexpected(count.error());
    total += *count;
    if (total == 0)
        return unexpected(error(GeometryErrorCode::EmptyInput,
                                "There is nothing with finite coordinates to put a cage around."));
    if (total > kMaxInputPoints)
        return unexpected(
            error(GeometryErrorCode::TooManyPoints, "Too many points to put a cage around."));
    Input input;
    input.frame = detail::frameFor(lo);
    input.extent = std::max((hi - lo).norm(), 1.0);
    input.points.resize(*count, 2);
    Eigen::Index k = 0;
    for (Eigen::Index i = 0; i < mustContain.rows(); ++i)
        if (mustContain.row(i).allFinite())
            input.points.row(k++) = mustContain.row(i);
    for (const Polygon &polygon : shape)
        input.outer.push_back(input.frame.toPath(polygon.outer));
    if (shape.empty()) // points alone: their dots, grown by the margin, are the outline
        for (Eigen::Index i = 0; i < input.points.rows(); ++i)
            input.outer.push_back(input.frame.toPath(input.points.row(i)));
    return input;
}

// Round-joined growth of rings, and of dots and segments (Clipper ignores closed paths with
// fewer than three points, so those are grown as open paths with round ends).
ClipperLib::Paths grow(const ClipperLib::Paths &paths, double deltaPx, double arcPx,
                       const detail::ClipperFrame &frame)
{
    ClipperLib::ClipperOffset offset(2.0, arcPx * detail::kUnitsPerPixel);
    for (const ClipperLib::Path &path : paths)
        offset.AddPath(path, ClipperLib::jtRound,
                       path.size() >= 3 ? ClipperLib::etClosedPolygon : ClipperLib::etOpenRound);
    ClipperLib::Paths out;
    offset.Execute(out, double(frame.units(deltaPx)));
    return out;
}

// The outline grown by the margin, as one ring: parts further apart are bridged by a closing
// (grow, unite, shrink back) with a radius doubled until they merge.
Expected<Eigen::MatrixX2d, GeometryError> grownOutline(const Input &input, double margin)
{
    const double arc = std::max(0.01, 0.002 * input.extent);
    const double radius = std::max(margin, 1e-3 * input.extent);
    for (double bridge = 0.0; bridge <= 8.0 * input.extent;
         bridge = std::max(2.0 * bridge, radius)) {
        ClipperLib::PolyTree tree;
        detail::uniteToTree(grow(input.outer, radius + bridge, arc, input.frame),
                            ClipperLib::pftNonZero, tree);
        if (bridge > 0.0 && tree.ChildCount() == 1) {
            const ClipperLib::Paths outer{tree.Childs.front()->Contour};
            detail::uniteToTree(detail::offsetClosed(outer, -bridge, arc, input.frame),
                                ClipperLib::pftNonZero, tree);
        }
        if (tree.ChildCount() == 1)
            return oriented(input.frame.toRing(tree.Childs.front()->Contour), true);
    }
    return unexpected(error(GeometryErrorCode::ClippingFailed,
                            "The drawing's outline could not be grown into one piece."));
}

// The Douglas–Peucker simplification pushed out by `tolerance` with mitred corners: it
// covers the outline (every dropped vertex was within the tolerance of its chord).
Eigen::MatrixX2d pushedOut(const Eigen::MatrixX2d &simplified, double tolerance, const Input &input)
{
    ClipperLib::ClipperOffset offset(kMiterLimit);
    offset.AddPath(input.frame.toPath(simplified), ClipperLib::jtMiter,
                   ClipperLib::etClosedPolygon);
    ClipperLib::Paths out;
    offset.Execute(out, double(input.frame.units(tolerance)));
    if (out.empty())
        return {};
    const auto largest = std::max_element(out.begin(), out.end(), [](const auto &a, const auto &b) {
        return std::abs(ClipperLib::Area(a)) < std::abs(ClipperLib::Area(b));
    });
    return cleanPolyline(oriented(input.frame.toRing(*largest), true), 1e-6 * input.extent, true);
}

// The smallest tolerance whose simplification has at most `corners` corners.
double toleranceFor(const Eigen::MatrixX2d &ring, int corners, double extent)
{
    double lo = 0.0, hi = extent;
    for (int step = 0; step < kToleranceSteps; ++step) {
        const double mid = 0.5 * (lo + hi);
        (douglasPeucker(ring, mid, true).rows() <= corners ? hi : lo) = mid;
    }
    return hi;
}

bool usable(const Eigen::MatrixX2d &cage, const Input &input, double clearance)
{
    return cage.rows() >= 3 && !checkCage(cage) &&
           cageOutsidePoints(cage, input.points, clearance).size() == 0;
}

Eigen::MatrixX2d convexHull(Eigen::MatrixX2d points)
{
    std::vector<Eigen::RowVector2d> p(std::size_t(points.rows()));
    for (Eigen::Index i = 0; i < points.rows(); ++i)
        p[std::size_t(i)] = points.row(i);
    std::sort(p.begin(), p.end(), [](const auto &a, const auto &b) {
        return a.x() != b.x() ? a.x() < b.x() : a.y() < b.y();
    });
    const auto cross = [](const auto &o, const auto &a, const auto &b) {
        return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
    };
    std::vector<Eigen::RowVector2d> hull(2 * p.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < p.size(); ++i) { // Andrew's monotone chain
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0)
            --k;
        hull[k++] = p[i];
    }
    for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(hull[k - 2], hull[k - 1], p[i]) <= 0)
            --k;
        hull[k++] = p[i];
    }
    Eigen::MatrixX2d ring(Eigen::Index(k > 1 ? k - 1 : k), 2);
    for (Eigen::Index i = 0; i < ring.rows(); ++i)
        ring.row(i) = hull[std::size_t(i)];
    return ring;
}

Expected<Eigen::MatrixX2d, GeometryError>
computeCage(const Region &shape, const Eigen::MatrixX2d &mustContain, const FitCageOptions &options)
{
    auto input = checkInput(shape, mustContain, options);
    if (!input)
        return unexpected(input.error());
    const double clearance = 0.5 * options.margin;
    const auto grown = grownOutline(*input, options.margin);
    if (!grown)
        return unexpected(grown.error());
    const Eigen::MatrixX2d &outline = *grown;
    double tolerance = toleranceFor(outline, options.corners, input->extent);
    for (int round = 0; round < kGrowRounds; ++round) {
        const Eigen::MatrixX2d simplified = douglasPeucker(outline, tolerance, true);
        // Corners the mitre squares off may exceed the budget: simplify a little more.
        Eigen::MatrixX2d cage = pushedOut(simplified, tolerance, *input);
        if (cage.rows() > options.corners + 2) {
            tolerance *= 1.25;
            continue;
        }
        if (usable(cage, *input, clearance))
            return cage;
        tolerance = tolerance * 1.5 + options.margin; // push further out and retry
    }
    // Last resort: the convex hull of the grown outline and the points, simplified; for a
    // convex polygon the pushed-out simplification always covers it.
    Eigen::MatrixX2d all(outline.rows() + input->points.rows(), 2);
    all << outline, input->points;
    const Eigen::MatrixX2d hull = convexHull(all);
    const double hullTolerance = toleranceFor(hull, options.corners, input->extent);
    Eigen::MatrixX2d cage =
        pushedOut(douglasPeucker(hull, hullTolerance, true), hullTolerance + clearance, *input);
    if (usable(cage, *input, clearance))
        return cage;
    return unexpected(
        error(GeometryErrorCode::ClippingFailed, "No cage could be fitted around the drawing."));
}

} // namespace

Expected<Eigen::MatrixX2d, GeometryError>
fitCage(const Region &shape, const Eigen::MatrixX2d &mustContain, const FitCageOptions &options)
{
    return detail::catchExceptions([&] { return computeCage(shape, mustContain, options); });
}

Expected<Eigen::MatrixX2d, GeometryError> fitCage(const std::vector<StrokeInput> &strokes,
                                                  const FitCageOptions &options)
{
    auto region = objectShape(strokes, options.silhouette, options.regions);
    if (!region)
        return unexpected(region.error());
    long total = 0;
    for (const StrokeInput &stroke : strokes)
        total += long(stroke.points.rows());
    Eigen::MatrixX2d points(total, 2);
    total = 0;
    for (const StrokeInput &stroke : strokes) {
        points.middleRows(total, stroke.points.rows()) = stroke.points;
        total += long(stroke.points.rows());
    }
    return fitCage(*region, points, options);
}

} // namespace finbook::geometry
