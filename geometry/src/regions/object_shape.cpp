#include "../clipper_bridge.h"

#include <finbook/geometry/object_shape.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace finbook::geometry {
namespace {

// Faces adding less than this fraction of the silhouette's area leave it as it is: a tidy
// closed outline keeps exactly the shape it had before regions existed.
constexpr double kNegligibleGrowth = 1e-3;

void addPolygon(const Polygon &polygon, const detail::ClipperFrame &frame, ClipperLib::Paths &out)
{
    out.push_back(frame.toPath(polygon.outer));
    for (const Eigen::MatrixX2d &hole : polygon.holes)
        out.push_back(frame.toPath(hole));
}

// The outline simplification silhouette() uses: at most a fifth of the thinnest band's radius.
double simplifyTolerance(const std::vector<StrokeInput> &strokes, const SilhouetteOptions &options)
{
    double r = std::numeric_limits<double>::max();
    for (const StrokeInput &s : strokes)
        if (s.points.rows() > 0)
            r = std::min(r, 0.5 * s.width + options.margin);
    return std::min(options.simplifyTolerance, 0.2 * r);
}

// The lower corner of every ring of `region`, and of `lo`.
Eigen::RowVector2d lowerCorner(const Region &region, Eigen::RowVector2d lo)
{
    for (const Eigen::MatrixX2d &ring : regionRings(region))
        lo = lo.cwiseMin(ring.colwise().minCoeff());
    return lo;
}

constexpr double kFar = std::numeric_limits<double>::max();

Expected<Region, GeometryError> unite(const Region &bands, const std::vector<Face> &faces,
                                      const std::vector<StrokeInput> &strokes,
                                      const SilhouetteOptions &options)
{
    Eigen::RowVector2d lo = lowerCorner(bands, Eigen::RowVector2d::Constant(kFar));
    for (const Face &f : faces)
        lo = lo.cwiseMin(f.polygon.outer.colwise().minCoeff());
    const detail::ClipperFrame frame = detail::frameFor(lo);
    ClipperLib::Paths paths;
    for (const Polygon &p : bands)
        addPolygon(p, frame, paths);
    for (const Face &f : faces)
        addPolygon(f.polygon, frame, paths);
    ClipperLib::PolyTree tree;
    detail::uniteToTree(paths, ClipperLib::pftNonZero, tree);
    if (options.holes == HoleMode::FillEnclosed) {
        ClipperLib::Paths outer;
        for (const ClipperLib::PolyNode *node : tree.Childs)
            outer.push_back(node->Contour);
        detail::uniteToTree(outer, ClipperLib::pftNonZero, tree);
    }
    Region region = detail::simplifyRegion(detail::treeToRegion(tree, frame),
                                           simplifyTolerance(strokes, options));
    if (region.empty() || !(regionArea(region) > 0.0))
        return unexpected(
            detail::error(GeometryErrorCode::DegenerateRegion, "The strokes cover no area."));
    return region;
}

// A piece the silhouette's closing added is a slit to open again when it touches one part of
// the shape without the closing (it fills a concavity of one part instead of bridging two)...
// ...and is long: its area more than this many squared gaps, a slit at least 8 gaps deep (the
// slits between the fingers of kimia99_hand_7_1 imported as a stroke, 700–800 px² at the
// default 8 px gap, and an octopus's arms, 600–1,000 px²). Shorter ones stay filled: the notch
// where two strokes meet at an angle, and the shallow cleft between two sketched fingers
// (quickdraw hand_5341, 280–340 px²), whose filling smooths the outline the skeleton sees.
constexpr double kSlitAreaInGaps = 8.0;
// ...and no free stroke end lies in it or beside it: a sketchy stroke that stops short of
// (or overshoots into) another leaves a sliver of the same kind, and keeping that filled keeps
// the outline as the closing smoothed it (opened, a quickdraw octopus's arm got a notch and a
// knot of small bones)...
// ...and holds no disk wider than three gaps (its radius this many gaps). The closing also
// fills a slit that widens behind a narrow mouth (it fills what the dilated bands enclose), as
// between an octopus's arms (10–15 px wide behind 8 px); a wide piece is a body enclosed by an
// outline with a gap the regions did not close (wider than their close-gap distance, or too
// tangled to find them), which stays.
constexpr double kSlitWidthInGaps = 1.5;

double pathsArea(const ClipperLib::PolyNode &node)
{
    double area = std::abs(ClipperLib::Area(node.Contour));
    for (const ClipperLib::PolyNode *hole : node.Childs)
        area -= std::abs(ClipperLib::Area(hole->Contour));
    return area;
}

ClipperLib::IntRect bounds(const ClipperLib::Path &path)
{
    ClipperLib::IntRect r{
        std::numeric_limits<ClipperLib::cInt>::max(), std::numeric_limits<ClipperLib::cInt>::max(),
        std::numeric_limits<ClipperLib::cInt>::min(), std::numeric_limits<ClipperLib::cInt>::min()};
    for (const ClipperLib::IntPoint &p : path) {
        r.left = std::min(r.left, p.X);
        r.right = std::max(r.right, p.X);
        r.top = std::min(r.top, p.Y);
        r.bottom = std::max(r.bottom, p.Y);
    }
    return r;
}

bool overlaps(const ClipperLib::IntRect &a, const ClipperLib::IntRect &b)
{
    return a.left <= b.right && b.left <= a.right && a.top <= b.bottom && b.top <= a.bottom;
}

// a ∩ b or a − b (closed paths, non-zero filling) into `out` (Paths or PolyTree).
template <class Out>
void clip(ClipperLib::ClipType type, const ClipperLib::Paths &a, const ClipperLib::Paths &b,
          Out &out)
{
    ClipperLib::Clipper clipper;
    clipper.AddPaths(a, ClipperLib::ptSubject, true);
    clipper.AddPaths(b, ClipperLib::ptClip, true);
    clipper.Execute(type, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
}

bool meets(const ClipperLib::Paths &a, const ClipperLib::Paths &b)
{
    ClipperLib::Paths out;
    clip(ClipperLib::ctIntersection, a, b, out);
    return !out.empty();
}

// `closed` (the shape with the silhouette's closing) without the slits the closing filled:
// narrow concavities of one stroke's outline, such as the slits between an octopus's arms,
// which the closing (meant to bridge gaps between strokes) filled as if they were webbing, so
// the skeleton joined neighbouring arms and the mesh tied them together. `open` is the same
// shape without the closing.
Region reopenSlits(const Region &closed, const Region &open, double gap, double tolerance,
                   const std::vector<Eigen::RowVector2d> &freeEnds, double endReach)
{
    const detail::ClipperFrame frame = detail::frameFor(
        lowerCorner(open, lowerCorner(closed, Eigen::RowVector2d::Constant(kFar))));
    ClipperLib::Paths closedPaths, openPaths;
    for (const Polygon &p : closed)
        addPolygon(p, frame, closedPaths);
    std::vector<ClipperLib::Paths> parts; // each part of the open shape
    std::vector<ClipperLib::IntRect> partBounds;
    for (const Polygon &p : open) {
        addPolygon(p, frame, openPaths);
        parts.push_back({frame.toPath(p.outer)});
        partBounds.push_back(bounds(parts.back().front()));
    }
    ClipperLib::PolyTree added;
    clip(ClipperLib::ctDifference, closedPaths, openPaths, added);
    const double unit = frame.units(1.0);
    const double longArea = kSlitAreaInGaps * gap * gap * unit * unit;
    const double arcTolerance = 0.1;
    ClipperLib::Paths slits;
    for (const ClipperLib::PolyNode *piece : added.Childs) {
        if (pathsArea(*piece) <= longArea)
            continue;
        const ClipperLib::Paths outline{piece->Contour};
        // Wide somewhere: an area the closing enclosed, not a slit.
        if (!detail::offsetClosed(outline, -(kSlitWidthInGaps * gap), arcTolerance, frame).empty())
            continue;
        const ClipperLib::Paths near = detail::offsetClosed(outline, endReach, arcTolerance, frame);
        const bool nearEnd = std::any_of(freeEnds.begin(), freeEnds.end(), [&](const auto &end) {
            const ClipperLib::IntPoint at = frame.toPath(end).front();
            return std::any_of(near.begin(), near.end(), [&](const ClipperLib::Path &ring) {
                return ClipperLib::PointInPolygon(at, ring) != 0;
            });
        });
        if (nearEnd)
            continue;
        const ClipperLib::Paths touch = detail::offsetClosed(outline, 0.5, arcTolerance, frame);
        const ClipperLib::IntRect box = bounds(touch.empty() ? piece->Contour : touch.front());
        int touched = 0;
        for (std::size_t i = 0; i < parts.size() && touched < 2; ++i)
            if (overlaps(box, partBounds[i]) && meets(touch, parts[i]))
                ++touched;
        if (touched <= 1)
            slits.push_back(piece->Contour);
    }
    if (slits.empty())
        return closed;
    ClipperLib::PolyTree tree;
    clip(ClipperLib::ctDifference, closedPaths, slits, tree);
    Region region = detail::simplifyRegion(detail::treeToRegion(tree, frame), tolerance);
    return region.empty() || !(regionArea(region) > 0.0) ? closed : region;
}

// The shape from the strokes' bands (silhouette()) and the regions' faces (none: the bands).
Expected<Region, GeometryError> shapeOf(Region bands, const std::vector<StrokeInput> &strokes,
                                        const SilhouetteOptions &silhouetteOptions,
                                        const Regions &regions)
{
    if (regions.faces.empty())
        return bands;
    auto united = detail::catchExceptions(
        [&] { return unite(bands, regions.faces, strokes, silhouetteOptions); });
    if (!united)
        return united;
    const double before = regionArea(bands);
    return regionArea(*united) <= before * (1.0 + kNegligibleGrowth) ? bands : *united;
}

} // namespace

Expected<Region, GeometryError> objectShape(const std::vector<StrokeInput> &strokes,
                                            const SilhouetteOptions &silhouetteOptions,
                                            const RegionsOptions &regionsOptions)
{
    auto bands = silhouette(strokes, silhouetteOptions);
    if (!bands)
        return bands;
    auto regions = computeRegions(strokes, regionsOptions);
    // Too tangled to find regions quickly: the ink alone, as before.
    if (!regions && regions.error().code == GeometryErrorCode::TooManyPoints)
        return bands;
    if (!regions)
        return unexpected(regions.error());
    auto shape = shapeOf(std::move(*bands), strokes, silhouetteOptions, *regions);
    if (!shape || !(silhouetteOptions.gap > 0.0))
        return shape;
    // The same shape without the silhouette's closing.
    SilhouetteOptions unclosed = silhouetteOptions;
    unclosed.gap = 0.0;
    auto openBands = silhouette(strokes, unclosed);
    if (!openBands)
        return shape;
    const auto open = shapeOf(std::move(*openBands), strokes, silhouetteOptions, *regions);
    if (!open)
        return shape;
    // Free ends: the ends of strokes that do not close on themselves.
    std::vector<Eigen::RowVector2d> freeEnds;
    double widest = 0.0;
    for (const StrokeInput &stroke : strokes) {
        const Eigen::Index n = stroke.points.rows();
        widest = std::max(widest, stroke.width);
        if (n == 0 || !stroke.points.allFinite())
            continue;
        if ((stroke.points.row(0) - stroke.points.row(n - 1)).norm() > stroke.width) {
            freeEnds.push_back(stroke.points.row(0));
            freeEnds.push_back(stroke.points.row(n - 1));
        }
    }
    const double endReach = 0.5 * widest + silhouetteOptions.margin + silhouetteOptions.gap;
    const double tolerance = simplifyTolerance(strokes, silhouetteOptions);
    auto reopened = detail::catchExceptions([&]() -> Expected<Region, GeometryError> {
        return reopenSlits(*shape, *open, silhouetteOptions.gap, tolerance, freeEnds, endReach);
    });
    return reopened ? reopened : shape;
}

} // namespace finbook::geometry
