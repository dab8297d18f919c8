#include "clipper_bridge.h"

#include <finbook/geometry/polygon_repair.h>
#include <finbook/geometry/polyline.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace finbook::geometry {
namespace {

using detail::error;

// Checks every ring and returns the clipping frame for them.
Expected<detail::ClipperFrame, GeometryError> checkRings(const std::vector<Eigen::MatrixX2d> &rings)
{
    Eigen::RowVector2d lo = Eigen::RowVector2d::Constant(std::numeric_limits<double>::max());
    Eigen::RowVector2d hi = -lo;
    long total = 0;
    for (std::size_t r = 0; r < rings.size(); ++r) {
        auto count = detail::checkPoints(rings[r], "ring " + std::to_string(r + 1), lo, hi);
        if (!count)
            return unexpected(count.error());
        total += *count;
    }
    if (total == 0)
        return unexpected(error(GeometryErrorCode::EmptyInput,
                                "The shape has no outline points with finite coordinates."));
    if (total > kMaxInputPoints)
        return unexpected(error(GeometryErrorCode::TooManyPoints,
                                "The shape outline has " + std::to_string(total) +
                                    " points, more than the supported " +
                                    std::to_string(kMaxInputPoints) + "; simplify it first."));
    return detail::frameFor(lo);
}

// Pixel outlines carry many collinear points; dropping them first makes the opening several
// times faster. Crossings this may create are resolved by the fill rule like any others.
ClipperLib::Path toSimplifiedPath(const Eigen::MatrixX2d &ring, double tolerance,
                                  const detail::ClipperFrame &frame)
{
    return frame.toPath(douglasPeucker(cleanPolyline(ring, 0.0, true), tolerance, true));
}

bool validOptions(const RepairOptions &options)
{
    return std::isfinite(options.cornerRadius) && options.cornerRadius >= 0.0 &&
           options.cornerRadius <= kMaxPenWidth && std::isfinite(options.simplifyTolerance) &&
           options.simplifyTolerance >= 0.0;
}

// Morphological opening: erode then dilate, which rounds every convex corner to the radius.
ClipperLib::Paths roundCorners(const ClipperLib::Paths &paths, const RepairOptions &options,
                               const detail::ClipperFrame &frame)
{
    if (options.cornerRadius <= 0.0)
        return paths;
    const double arc = std::min(0.1, 0.25 * options.cornerRadius);
    const ClipperLib::Paths eroded = detail::offsetClosed(paths, -options.cornerRadius, arc, frame);
    return detail::offsetClosed(eroded, options.cornerRadius, arc, frame);
}

Expected<Region, GeometryError> finish(const ClipperLib::Paths &paths, const RepairOptions &options,
                                       const detail::ClipperFrame &frame)
{
    ClipperLib::PolyTree tree;
    detail::uniteToTree(roundCorners(paths, options, frame), ClipperLib::pftNonZero, tree);
    Region region =
        detail::simplifyRegion(detail::treeToRegion(tree, frame), options.simplifyTolerance);
    if (region.empty() || !(regionArea(region) > 0.0))
        return unexpected(error(GeometryErrorCode::DegenerateRegion,
                                "The shape encloses no area (it may be a line, a point, or thinner "
                                "than the corner radius)."));
    return region;
}

ClipperLib::PolyFillType clipperFill(FillRule rule)
{
    return rule == FillRule::EvenOdd ? ClipperLib::pftEvenOdd : ClipperLib::pftNonZero;
}

Expected<Region, GeometryError> repairRingsUnguarded(const std::vector<Eigen::MatrixX2d> &rings,
                                                     const RepairOptions &options)
{
    if (!validOptions(options))
        return unexpected(error(GeometryErrorCode::InvalidOptions,
                                "Repair options need a finite corner radius in [0, 1e4] px and "
                                "a finite, non-negative simplification tolerance."));
    const auto checked = checkRings(rings);
    if (!checked)
        return unexpected(checked.error());
    const detail::ClipperFrame &frame = *checked;
    ClipperLib::Paths paths;
    for (const Eigen::MatrixX2d &ring : rings) {
        ClipperLib::Path path = toSimplifiedPath(ring, options.simplifyTolerance, frame);
        if (path.size() >= 3)
            paths.push_back(std::move(path));
    }
    ClipperLib::Paths combined;
    ClipperLib::SimplifyPolygons(paths, combined, clipperFill(options.fillRule));
    return finish(combined, options, frame);
}

Expected<Region, GeometryError> repairRegionUnguarded(const Region &region,
                                                      const RepairOptions &options)
{
    if (!validOptions(options))
        return repairRingsUnguarded({}, options);
    const auto checked = checkRings(regionRings(region));
    if (!checked)
        return unexpected(checked.error());
    const detail::ClipperFrame &frame = *checked;
    // Combine each polygon's rings by the fill rule on its own, so that overlapping polygons
    // add up instead of cancelling, then union everything (outer rings positive after that).
    ClipperLib::Paths combined;
    for (const Polygon &polygon : region) {
        ClipperLib::Paths own;
        for (const Eigen::MatrixX2d &ring : regionRings(Region{polygon})) {
            ClipperLib::Path path = toSimplifiedPath(ring, options.simplifyTolerance, frame);
            if (path.size() >= 3)
                own.push_back(std::move(path));
        }
        ClipperLib::Paths simple;
        ClipperLib::SimplifyPolygons(own, simple, clipperFill(options.fillRule));
        combined.insert(combined.end(), simple.begin(), simple.end());
    }
    return finish(combined, options, frame);
}

} // namespace

Expected<Region, GeometryError> repairRings(const std::vector<Eigen::MatrixX2d> &rings,
                                            const RepairOptions &options)
{
    return detail::catchExceptions([&] { return repairRingsUnguarded(rings, options); });
}

Expected<Region, GeometryError> repairRegion(const Region &region, const RepairOptions &options)
{
    return detail::catchExceptions([&] { return repairRegionUnguarded(region, options); });
}

} // namespace finbook::geometry
