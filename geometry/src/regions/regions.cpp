#include "../clipper_bridge.h"
#include "face_seed.h"
#include "gap_closing.h"
#include "planar_map.h"
#include "stroke_soup.h"

#include <finbook/geometry/regions.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace finbook::geometry {
namespace {

using detail::error;

// Douglas–Peucker tolerance of the centre lines, as a fraction of the pen width: well below
// what can change which faces exist, enough to drop most raw pen samples.
constexpr double kSimplifyFraction = 0.1;
// Beyond these the arrangement would take longer than an interactive tool may (scribbles).
constexpr long kMaxSegments = 20000;
constexpr long kMaxCrossings = 4000;
// Automatic close gap: this fraction of the bounding-box diagonal, clamped to pen widths.
constexpr double kAutoGapFraction =
    0.06; // measured on shared/data: 4 % left three near-closed outlines open
constexpr double kAutoGapMinWidths = 4.0;
constexpr double kAutoGapMaxWidths = 40.0;

double medianWidth(const std::vector<StrokeInput> &strokes)
{
    std::vector<double> widths;
    for (const StrokeInput &s : strokes)
        if (std::isfinite(s.width) && s.width >= 0.0 && s.points.rows() > 0)
            widths.push_back(s.width);
    if (widths.empty())
        return 0.0;
    std::nth_element(widths.begin(), widths.begin() + long(widths.size() / 2), widths.end());
    return widths[widths.size() / 2];
}

Expected<long, GeometryError> checkInput(const std::vector<StrokeInput> &strokes,
                                         const RegionsOptions &options)
{
    if (std::isnan(options.closeGap) || options.closeGap > kMaxPenWidth)
        return unexpected(error(GeometryErrorCode::InvalidOptions,
                                "The close-gap distance must be a number no larger than 1e4 px."));
    if (strokes.empty())
        return unexpected(error(GeometryErrorCode::EmptyInput, "The group has no strokes."));
    Eigen::RowVector2d lo = Eigen::RowVector2d::Constant(std::numeric_limits<double>::max());
    Eigen::RowVector2d hi = -lo;
    long total = 0;
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
    }
    if (total == 0)
        return unexpected(error(GeometryErrorCode::EmptyInput,
                                "The group's strokes have no points with finite coordinates."));
    if (total > kMaxInputPoints)
        return unexpected(
            error(GeometryErrorCode::TooManyPoints, "The group has " + std::to_string(total) +
                                                        " points, more than the supported " +
                                                        std::to_string(kMaxInputPoints) + "."));
    return total;
}

Expected<Regions, GeometryError> compute(const std::vector<StrokeInput> &strokes,
                                         const RegionsOptions &options)
{
    auto checked = checkInput(strokes, options);
    if (!checked)
        return unexpected(checked.error());
    Regions regions;
    regions.closeGap = options.closeGap < 0.0 ? autoCloseGap(strokes) : options.closeGap;
    const detail::StrokeSoup soup(strokes, kSimplifyFraction);
    if (long(soup.segments().size()) > kMaxSegments || soup.tooManyCrossings(kMaxCrossings))
        return unexpected(error(GeometryErrorCode::TooManyPoints,
                                "The strokes cross each other too often to find closed regions "
                                "quickly (scribbled shading?); the object keeps its ink as its "
                                "shape."));
    detail::PlanarMap map;
    detail::GapClosingResult gaps =
        detail::closeGaps(soup, regions.closeGap, options.closeMouths, map);
    regions.closures = std::move(gaps.closures);
    regions.freeEnds = gaps.freeEnds;
    const double w = std::max(medianWidth(strokes), 0.5);
    map.mergeSlivers(w, 2.0 * w * w);
    for (detail::MapFace &f : map.faces()) {
        Face face;
        face.seed = detail::interiorSeed(f.polygon);
        face.polygon = std::move(f.polygon);
        face.strokes = std::move(f.labels);
        face.area = f.area;
        regions.faces.push_back(std::move(face));
    }
    return regions;
}

} // namespace

double autoCloseGap(const std::vector<StrokeInput> &strokes)
{
    Eigen::RowVector2d lo = Eigen::RowVector2d::Constant(std::numeric_limits<double>::max());
    Eigen::RowVector2d hi = -lo;
    bool any = false;
    for (const StrokeInput &s : strokes)
        for (Eigen::Index i = 0; i < s.points.rows(); ++i)
            if (s.points.row(i).allFinite()) {
                lo = lo.cwiseMin(s.points.row(i));
                hi = hi.cwiseMax(s.points.row(i));
                any = true;
            }
    if (!any)
        return 0.0;
    const double w = std::max(medianWidth(strokes), 0.5);
    const double diagonal = std::min((hi - lo).norm(), 1e7);
    return std::clamp(kAutoGapFraction * diagonal, kAutoGapMinWidths * w,
                      std::min(kAutoGapMaxWidths * w, kMaxPenWidth));
}

Expected<Regions, GeometryError> computeRegions(const std::vector<StrokeInput> &strokes,
                                                const RegionsOptions &options)
{
    return detail::catchExceptions([&] { return compute(strokes, options); });
}

int faceAt(const Regions &regions, double x, double y)
{
    int best = -1;
    for (std::size_t i = 0; i < regions.faces.size(); ++i) {
        const Face &f = regions.faces[i];
        if (f.polygon.outer.rows() < 3 || x < f.polygon.outer.col(0).minCoeff() ||
            x > f.polygon.outer.col(0).maxCoeff() || y < f.polygon.outer.col(1).minCoeff() ||
            y > f.polygon.outer.col(1).maxCoeff())
            continue;
        if (regionContains(Region{f.polygon}, x, y) &&
            (best < 0 || f.area < regions.faces[std::size_t(best)].area))
            best = int(i);
    }
    return best;
}

double closureShare(const Regions &regions, int face)
{
    if (face < 0 || std::size_t(face) >= regions.faces.size())
        return 0.0;
    // An outline edge lies on a closure when both its ends do (closures reach 0.01 px past
    // the line they end on, and the arrangement splits them where they cross a stroke).
    constexpr double kOnClosure = 0.05;
    const auto onClosure = [&](const Eigen::Vector2d &p) {
        for (const GapClosure &g : regions.closures) {
            const Eigen::Vector2d d = g.to - g.from;
            const double length2 = d.squaredNorm();
            const double t =
                length2 > 0.0 ? std::clamp((p - g.from).dot(d) / length2, 0.0, 1.0) : 0.0;
            if ((g.from + t * d - p).norm() <= kOnClosure)
                return true;
        }
        return false;
    };
    const Eigen::MatrixX2d &ring = regions.faces[std::size_t(face)].polygon.outer;
    double total = 0.0, closed = 0.0;
    for (Eigen::Index i = 0; i < ring.rows(); ++i) {
        const Eigen::Vector2d a = ring.row(i).transpose();
        const Eigen::Vector2d b = ring.row((i + 1) % ring.rows()).transpose();
        const double length = (b - a).norm();
        total += length;
        if (onClosure(a) && onClosure(b) && onClosure(0.5 * (a + b)))
            closed += length;
    }
    return total > 0.0 ? closed / total : 0.0;
}

} // namespace finbook::geometry
