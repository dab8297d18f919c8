#include "clipper_bridge.h"

#include <finbook/geometry/polyline.h>
#include <finbook/geometry/silhouette.h>

#include <cmath>
#include <limits>

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

// Points per offset piece. A band with round joins and caps is the union of its segments'
// capsules, so cutting strokes into pieces that share their end points changes nothing, and
// keeps one scribbled-over stroke from meeting itself thousands of times in a single sweep.
constexpr std::size_t kPiecePoints = 48;

// Unites the pieces pairwise, level by level: inner edges of heavily overlapping strokes
// vanish early instead of all crossing each other in one sweep (thousands of overlapping
// strokes would otherwise take minutes).
// With fillHoles, holes are dropped after every union: filling commutes with union (the
// filled union of filled parts is the filled union), and a scribble's thousands of little
// holes would otherwise dominate the cost.
ClipperLib::Paths uniteBalanced(std::vector<ClipperLib::Paths> pieces, bool fillHoles)
{
    while (pieces.size() > 1) {
        std::vector<ClipperLib::Paths> next;
        for (std::size_t i = 0; i < pieces.size(); i += 2) {
            if (i + 1 == pieces.size()) {
                next.push_back(std::move(pieces[i]));
                continue;
            }
            ClipperLib::Clipper clipper;
            clipper.AddPaths(pieces[i], ClipperLib::ptSubject, true);
            clipper.AddPaths(pieces[i + 1], ClipperLib::ptSubject, true);
            ClipperLib::Paths united;
            clipper.Execute(ClipperLib::ctUnion, united, ClipperLib::pftNonZero,
                            ClipperLib::pftNonZero);
            if (fillHoles) // outer rings come out positive, holes negative
                std::erase_if(
                    united, [](const ClipperLib::Path &p) { return !ClipperLib::Orientation(p); });
            next.push_back(std::move(united));
        }
        pieces = std::move(next);
    }
    return pieces.empty() ? ClipperLib::Paths{} : std::move(pieces.front());
}

// Bands of all strokes grown by `extra` px, united.
ClipperLib::Paths dilatedBands(const std::vector<StrokeInput> &strokes,
                               const SilhouetteOptions &options, double extra, double arcTolerance,
                               const detail::ClipperFrame &frame)
{
    std::vector<ClipperLib::Paths> pieces;
    for (const StrokeInput &stroke : strokes) {
        // Dense pen samples cost offset time but hardly change the band: thin them by the
        // arc tolerance (the clearance promised in silhouette.h accounts for it).
        const ClipperLib::Path path =
            frame.toPath(douglasPeucker(cleanPolyline(stroke.points), arcTolerance));
        const double delta = double(frame.units(0.5 * stroke.width + options.margin + extra));
        for (std::size_t first = 0; first < path.size(); first += kPiecePoints - 1) {
            const std::size_t last = std::min(path.size(), first + kPiecePoints);
            ClipperLib::ClipperOffset offset(2.0, arcTolerance * detail::kUnitsPerPixel);
            offset.AddPath(ClipperLib::Path(path.begin() + long(first), path.begin() + long(last)),
                           ClipperLib::jtRound, ClipperLib::etOpenRound);
            pieces.emplace_back();
            offset.Execute(pieces.back(), delta);
            if (last == path.size())
                break;
        }
    }
    return uniteBalanced(std::move(pieces), options.holes == HoleMode::FillEnclosed);
}

ClipperLib::Paths outerRingsOnly(const ClipperLib::PolyTree &tree)
{
    ClipperLib::Paths outer;
    for (const ClipperLib::PolyNode *node : tree.Childs)
        outer.push_back(node->Contour);
    return outer;
}

Expected<Region, GeometryError> computeSilhouette(const std::vector<StrokeInput> &strokes,
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
    detail::uniteToTree(dilatedBands(strokes, options, closeRadius, arcTolerance, frame),
                        ClipperLib::pftNonZero, united);
    ClipperLib::Paths closed;
    if (options.holes == HoleMode::FillEnclosed)
        closed = outerRingsOnly(united);
    else
        ClipperLib::PolyTreeToPaths(united, closed);
    if (closeRadius > 0.0)
        closed = detail::offsetClosed(closed, -closeRadius, arcTolerance, frame);

    ClipperLib::PolyTree tree;
    detail::uniteToTree(closed, ClipperLib::pftNonZero, tree);
    const double tolerance = std::min(options.simplifyTolerance, 0.2 * input->minRadius);
    Region region = detail::simplifyRegion(detail::treeToRegion(tree, frame), tolerance);
    if (region.empty() || !(regionArea(region) > 0.0))
        return unexpected(error(GeometryErrorCode::DegenerateRegion, "The strokes cover no area."));
    return region;
}

} // namespace

Expected<Region, GeometryError> silhouette(const std::vector<StrokeInput> &strokes,
                                           const SilhouetteOptions &options)
{
    return detail::catchExceptions([&] { return computeSilhouette(strokes, options); });
}

} // namespace finbook::geometry
