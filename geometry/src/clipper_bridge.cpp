#include "clipper_bridge.h"

#include <finbook/geometry/polyline.h>
#include <finbook/geometry/simplicity.h>

#include <cmath>
#include <sstream>

namespace finbook::geometry::detail {

ClipperLib::cInt ClipperFrame::units(double px) const
{
    return ClipperLib::cInt(std::llround(px * kUnitsPerPixel));
}

ClipperLib::Path ClipperFrame::toPath(const Eigen::MatrixX2d &points) const
{
    ClipperLib::Path path;
    path.reserve(std::size_t(points.rows()));
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        if (!points.row(i).allFinite())
            continue;
        const Eigen::RowVector2d p = points.row(i) - origin;
        ClipperLib::IntPoint q(units(p.x()), units(p.y()));
        if (path.empty() || !(path.back() == q))
            path.push_back(q);
    }
    return path;
}

Eigen::MatrixX2d ClipperFrame::toRing(const ClipperLib::Path &path) const
{
    Eigen::MatrixX2d ring(Eigen::Index(path.size()), 2);
    for (std::size_t i = 0; i < path.size(); ++i) {
        ring(Eigen::Index(i), 0) = pixels(double(path[i].X)) + origin.x();
        ring(Eigen::Index(i), 1) = pixels(double(path[i].Y)) + origin.y();
    }
    return ring;
}

ClipperFrame frameFor(const Eigen::RowVector2d &lo)
{
    ClipperFrame frame;
    // Whole pixels keep the translation exact, so equal inputs map to equal integers.
    frame.origin = lo.array().floor().matrix();
    return frame;
}

namespace {
void collectOuter(const ClipperLib::PolyNode &node, const ClipperFrame &frame, Region &region)
{
    // `node` is an outer ring; its children are holes, their children outer rings again.
    Polygon polygon;
    polygon.outer = oriented(frame.toRing(node.Contour), true);
    for (const ClipperLib::PolyNode *hole : node.Childs) {
        polygon.holes.push_back(oriented(frame.toRing(hole->Contour), false));
        for (const ClipperLib::PolyNode *island : hole->Childs)
            collectOuter(*island, frame, region);
    }
    region.push_back(std::move(polygon));
}
} // namespace

Region treeToRegion(const ClipperLib::PolyTree &tree, const ClipperFrame &frame)
{
    Region region;
    for (const ClipperLib::PolyNode *node : tree.Childs)
        collectOuter(*node, frame, region);
    return region;
}

void uniteToTree(const ClipperLib::Paths &paths, ClipperLib::PolyFillType fill,
                 ClipperLib::PolyTree &tree)
{
    ClipperLib::Clipper clipper;
    clipper.AddPaths(paths, ClipperLib::ptSubject, true);
    clipper.Execute(ClipperLib::ctUnion, tree, fill, fill);
}

ClipperLib::Paths offsetClosed(const ClipperLib::Paths &paths, double deltaPx,
                               double arcTolerancePx, const ClipperFrame &frame)
{
    ClipperLib::ClipperOffset offset(2.0, arcTolerancePx * kUnitsPerPixel);
    offset.AddPaths(paths, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    ClipperLib::Paths out;
    offset.Execute(out, double(frame.units(deltaPx)));
    return out;
}

Region simplifyRegion(const Region &region, double tolerance)
{
    if (!(tolerance > 0.0))
        return region;
    Region simplified = region;
    for (Polygon &polygon : simplified) {
        polygon.outer = douglasPeucker(polygon.outer, tolerance, true);
        for (Eigen::MatrixX2d &hole : polygon.holes)
            hole = douglasPeucker(hole, tolerance, true);
    }
    return isSimple(simplified, Touching::AllowedAtPoints) ? simplified : region;
}

Expected<long, GeometryError> checkPoints(const Eigen::MatrixX2d &points, const std::string &what,
                                          Eigen::RowVector2d &lo, Eigen::RowVector2d &hi)
{
    long finite = 0;
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        if (!points.row(i).allFinite())
            continue;
        if (points.row(i).cwiseAbs().maxCoeff() > kMaxCoordinate) {
            std::ostringstream text;
            text << what << " has a point at (" << points(i, 0) << ", " << points(i, 1)
                 << "), beyond the supported ±" << kMaxCoordinate
                 << " px; the drawing data looks corrupt.";
            return unexpected(error(GeometryErrorCode::CoordinateOutOfRange, text.str()));
        }
        lo = lo.cwiseMin(points.row(i));
        hi = hi.cwiseMax(points.row(i));
        ++finite;
    }
    return finite;
}

GeometryError error(GeometryErrorCode code, std::string message)
{
    return GeometryError{code, std::move(message)};
}

} // namespace finbook::geometry::detail
