#include <finbook/geometry/cage/cage_polygon.h>
#include <finbook/geometry/polyline.h>
#include <finbook/geometry/simplicity.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace finbook::geometry {
namespace {

// Areas below this fraction of the squared extent are rounding noise: the corners are
// collinear (or all but collinear) and no mesh could fill the cage.
constexpr double kMinRelativeArea = 1e-12;
// Points this close to an edge (relative to the cage's extent) are on it: hat values apply.
constexpr double kOnEdgeRelative = 1e-12;

GeometryError cageError(GeometryErrorCode code, std::string message)
{
    return GeometryError{code, std::move(message)};
}

double extent(const Eigen::MatrixX2d &corners)
{
    return (corners.colwise().maxCoeff() - corners.colwise().minCoeff()).norm();
}

double segmentDistance(const Eigen::Vector2d &p, const Eigen::Vector2d &a, const Eigen::Vector2d &b)
{
    const Eigen::Vector2d ab = b - a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return (a + t * ab - p).norm();
}

bool crossingInside(const Eigen::MatrixX2d &corners, const Eigen::Vector2d &p)
{
    bool inside = false;
    for (Eigen::Index i = 0, j = corners.rows() - 1; i < corners.rows(); j = i++) {
        const double ay = corners(i, 1), by = corners(j, 1);
        if ((ay > p.y()) == (by > p.y()))
            continue;
        const double x = corners(i, 0) + (corners(j, 0) - corners(i, 0)) * (p.y() - ay) / (by - ay);
        if (p.x() < x)
            inside = !inside;
    }
    return inside;
}

} // namespace

std::optional<GeometryError> checkCage(const Eigen::MatrixX2d &corners)
{
    const Eigen::Index c = corners.rows();
    if (c < 3)
        return cageError(GeometryErrorCode::TooFewCorners,
                         "A cage needs at least three corners; this one has " + std::to_string(c) +
                             ".");
    if (!corners.allFinite())
        return cageError(GeometryErrorCode::NonFiniteInput,
                         "A corner of the cage is not a finite number.");
    if (corners.cwiseAbs().maxCoeff() > kMaxCoordinate)
        return cageError(GeometryErrorCode::CoordinateOutOfRange,
                         "A corner of the cage lies beyond the supported ±1e6 px.");
    const double size = extent(corners);
    if (!(std::abs(signedArea(corners)) > kMinRelativeArea * size * size))
        return cageError(GeometryErrorCode::DegenerateRegion,
                         "The cage encloses no area: its corners lie on one line.");
    for (Eigen::Index i = 0; i < c; ++i) {
        if (corners.row(i) == corners.row((i + 1) % c))
            return cageError(GeometryErrorCode::NotSimple,
                             "Corners " + std::to_string(i + 1) + " and " +
                                 std::to_string((i + 1) % c + 1) +
                                 " of the cage lie on the same spot.");
    }
    if (!isSimple(corners, Touching::Forbidden))
        return cageError(GeometryErrorCode::NotSimple,
                         "The cage crosses or touches itself; move a corner so that its edges "
                         "no longer meet.");
    return std::nullopt;
}

Expected<Eigen::MatrixX2d, GeometryError> normalizedCage(const Eigen::MatrixX2d &corners)
{
    if (auto error = checkCage(corners))
        return unexpected(std::move(*error));
    if (signedArea(corners) > 0.0)
        return corners;
    Eigen::MatrixX2d reversed(corners.rows(), 2);
    reversed.row(0) = corners.row(0);
    for (Eigen::Index i = 1; i < corners.rows(); ++i)
        reversed.row(i) = corners.row(corners.rows() - i);
    return reversed;
}

double distanceToCage(const Eigen::MatrixX2d &corners, const Eigen::Vector2d &p)
{
    double best = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0, j = corners.rows() - 1; i < corners.rows(); j = i++)
        best = std::min(best, segmentDistance(p, corners.row(j), corners.row(i)));
    return best;
}

Eigen::VectorXi cageOutsidePoints(const Eigen::MatrixX2d &corners, const Eigen::MatrixX2d &points,
                                  double clearance)
{
    const double onEdge = kOnEdgeRelative * extent(corners);
    std::vector<int> outside;
    for (Eigen::Index k = 0; k < points.rows(); ++k) {
        const Eigen::Vector2d p = points.row(k).transpose();
        bool contained = p.allFinite();
        if (contained) {
            const double distance = distanceToCage(corners, p);
            contained = (distance <= onEdge || crossingInside(corners, p)) &&
                        (clearance <= 0.0 || distance >= clearance);
        }
        if (!contained)
            outside.push_back(int(k));
    }
    return Eigen::Map<const Eigen::VectorXi>(outside.data(), Eigen::Index(outside.size()));
}

std::optional<GeometryError> checkCageContains(const Eigen::MatrixX2d &corners,
                                               const Eigen::MatrixX2d &points, double clearance)
{
    const Eigen::VectorXi outside = cageOutsidePoints(corners, points, clearance);
    if (outside.size() == 0)
        return std::nullopt;
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector2d hi = -lo;
    for (const int k : outside) {
        if (points.row(k).allFinite()) {
            lo = lo.cwiseMin(points.row(k).transpose());
            hi = hi.cwiseMax(points.row(k).transpose());
        }
    }
    std::ostringstream text;
    text << outside.size() << (outside.size() == 1 ? " point lies" : " points lie")
         << " outside the cage";
    if (lo.allFinite())
        text << ", between (" << std::lround(lo.x()) << ", " << std::lround(lo.y()) << ") and ("
             << std::lround(hi.x()) << ", " << std::lround(hi.y()) << ")";
    text << "; enlarge the cage there.";
    return cageError(GeometryErrorCode::PointsOutsideCage, text.str());
}

} // namespace finbook::geometry
