#include "../clipper_bridge.h"

#include <finbook/geometry/object_shape.h>

#include <algorithm>
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

double thinnestRadius(const std::vector<StrokeInput> &strokes, double margin)
{
    double r = std::numeric_limits<double>::max();
    for (const StrokeInput &s : strokes)
        if (s.points.rows() > 0)
            r = std::min(r, 0.5 * s.width + margin);
    return r;
}

Expected<Region, GeometryError> unite(const Region &bands, const std::vector<Face> &faces,
                                      const std::vector<StrokeInput> &strokes,
                                      const SilhouetteOptions &options)
{
    Eigen::RowVector2d lo = Eigen::RowVector2d::Constant(std::numeric_limits<double>::max());
    for (const Eigen::MatrixX2d &ring : regionRings(bands))
        lo = lo.cwiseMin(ring.colwise().minCoeff());
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
    const double tolerance =
        std::min(options.simplifyTolerance, 0.2 * thinnestRadius(strokes, options.margin));
    Region region = detail::simplifyRegion(detail::treeToRegion(tree, frame), tolerance);
    if (region.empty() || !(regionArea(region) > 0.0))
        return unexpected(
            detail::error(GeometryErrorCode::DegenerateRegion, "The strokes cover no area."));
    return region;
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
    if (!regions && regions.error().code == GeometryErrorCode::TooManyPoints)
        return bands; // too tangled to find regions quickly: the ink alone, as before
    if (!regions)
        return unexpected(regions.error());
    if (regions->faces.empty())
        return bands;
    auto united = detail::catchExceptions(
        [&] { return unite(*bands, regions->faces, strokes, silhouetteOptions); });
    if (!united)
        return united;
    const double before = regionArea(*bands);
    return regionArea(*united) <= before * (1.0 + kNegligibleGrowth) ? bands : united;
}

} // namespace finbook::geometry
