#include "clipper_bridge.h"

#include <finbook/geometry/silhouette.h>

#include <cmath>
#include <limits>
#include <map>

namespace finbook::geometry {
namespace {

using detail::error;

struct CheckedInput {
    detail::ClipperFrame frame;
    double minRadius = std::numeric_limits<double>::max(); // thinnest band, px
};

Expected<CheckedInput, GeometryError> checkStrokes(const std::vector<StrokeInput> &strokes,
                                                   const SilhouetteOptions &options)
{
    if (strokes.empty())
        return unexpected(error(GeometryErrorCode::EmptyInput, "The group has no strokes."));
    Eigen::RowVector2d lo = Eigen::RowVector2d::Constant(std::numeric_limits<double>::max());
    Eigen::RowVector2d hi = -lo;
    long total = 0;
    CheckedInput input;
    for (std::size_t s = 0; s < strokes.size(); ++s) {
        const std::string name = "Stroke " + std::to_string(s + 1);
        const double width = strokes[s].width;
        if (!std::isfinite(width) || width < 0.0 || width > kMaxPenWidth)
            return unexpected(error(GeometryErrorCode::InvalidWidth,
                                    name + " has pen width " + std::to_string(width) +
                                        "; widths must be finite and within [0, 1e4] px."));
        auto count = detail::checkPoints(strokes[s].points, name, lo, hi);
        if (!count)
            return unexpected(count.error());
        total += *count;
        if (*count > 0)
            input.minRadius = std::min(input.minRadius, 0.5 * width + options.margin);
    }
    if (total == 0)
        return unexpected(error(GeometryErrorCode::EmptyInput,
                                "The group's strokes have no points with finite coordinates."));
    if (total > kMaxInputPoints)
        return unexpected(
            error(GeometryErrorCode::TooManyPoints, "The group has " + std::to_string(total) +
                                                        " points, more than the supported " +
                                                        std::to_string(kMaxInputPoints) + "."));
    input.frame = detail::frameFor(lo);
    return input;
}

// Bands of all strokes grown by `extra` px, united (NonZero). Strokes of one width share a
// ClipperOffset, which unites its own output.
ClipperLib::Paths dilatedBands(const std::vector<StrokeInput> &strokes,
                               const SilhouetteOptions &options, double extra, double arcTolerance,
                               const detail::ClipperFrame &frame)
{
    std::map<double, ClipperLib::Paths> byWidth;
    for (const StrokeInput &stroke : strokes) {
        ClipperLib::Path path = frame.toPath(stroke.points);
        if (!path.empty())
            byWidth[stroke.width].push_back(std::move(path));
    }
    ClipperLib::Paths all;
    for (const auto &[width, paths] : byWidth) {
        ClipperLib::ClipperOffset offset(2.0, arcTolerance * detail::kUnitsPerPixel);
        offset.AddPaths(paths, ClipperLib::jtRound, ClipperLib::etOpenRound);
        ClipperLib::Paths out;
        offset.Execute(out, double(frame.units(0.5 * width + options.margin + extra)));
        all.insert(all.end(), out.begin(), out.end());
    }
    return all;
}

ClipperLib::Paths outerRingsOnly(const ClipperLib::PolyTree &tree)
{
    ClipperLib::Paths outer;
    for (const ClipperLib::PolyNode *node : tree.Childs)
        outer.push_back(node->Contour);
    return outer;
}

} // namespace

Expected<Region, GeometryError> silhouette(const std::vector<StrokeInput> &strokes,
                                           const SilhouetteOptions &options)
{
    const auto finiteIn = [](double v, double hi) { return std::isfinite(v) && v >= 0 && v <= hi; };
    if (!finiteIn(options.margin, kMaxPenWidth) || !finiteIn(options.gap, kMaxPenWidth) ||
        !finiteIn(options.simplifyTolerance, kMaxPenWidth))
        return unexpected(error(GeometryErrorCode::InvalidOptions,
                                "Silhouette margin, gap and tolerance must be finite and within "
                                "[0, 1e4] px."));
    auto input = checkStrokes(strokes, options);
    if (!input)
        return unexpected(input.error());
    if (!(input->minRadius > 1e-3))
        return unexpected(error(GeometryErrorCode::DegenerateRegion,
                                "A stroke has zero pen width and the margin is zero, so it covers "
                                "no area; set a margin above zero."));
    const detail::ClipperFrame &frame = input->frame;
    // Chords of the round caps cut into the band by at most the arc tolerance; keeping it and
    // the simplification under the thinnest radius keeps every stroke point strictly inside.
    const double arcTolerance = std::min(0.1, 0.05 * input->minRadius);
    const double closeRadius = 0.5 * options.gap;

    ClipperLib::PolyTree united;
    detail::unionStrictlySimple(dilatedBands(strokes, options, closeRadius, arcTolerance, frame),
                                ClipperLib::pftNonZero, united);
    ClipperLib::Paths closed;
    if (options.holes == HoleMode::FillEnclosed)
        closed = outerRingsOnly(united);
    else
        ClipperLib::PolyTreeToPaths(united, closed);
    if (closeRadius > 0.0)
        closed = detail::offsetClosed(closed, -closeRadius, arcTolerance, frame);

    ClipperLib::PolyTree tree;
    detail::unionStrictlySimple(closed, ClipperLib::pftNonZero, tree);
    const double tolerance = std::min(options.simplifyTolerance, 0.2 * input->minRadius);
    Region region = detail::simplifyRegion(detail::treeToRegion(tree, frame), tolerance);
    if (region.empty() || !(regionArea(region) > 0.0))
        return unexpected(error(GeometryErrorCode::DegenerateRegion, "The strokes cover no area."));
    return region;
}

} // namespace finbook::geometry
