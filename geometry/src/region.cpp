#include <finbook/geometry/polyline.h>
#include <finbook/geometry/region.h>

namespace finbook::geometry {

double regionArea(const Region &region)
{
    double area = 0.0;
    for (const Polygon &polygon : region) {
        area += signedArea(polygon.outer);
        for (const Eigen::MatrixX2d &hole : polygon.holes)
            area += signedArea(hole);
    }
    return area;
}

double regionPerimeter(const Region &region)
{
    double length = 0.0;
    for (const Eigen::MatrixX2d &ring : regionRings(region))
        length += polylineLength(ring, true);
    return length;
}

std::vector<Eigen::MatrixX2d> regionRings(const Region &region)
{
    std::vector<Eigen::MatrixX2d> rings;
    for (const Polygon &polygon : region) {
        rings.push_back(polygon.outer);
        rings.insert(rings.end(), polygon.holes.begin(), polygon.holes.end());
    }
    return rings;
}

long regionVertexCount(const Region &region)
{
    long count = 0;
    for (const Polygon &polygon : region) {
        count += polygon.outer.rows();
        for (const Eigen::MatrixX2d &hole : polygon.holes)
            count += hole.rows();
    }
    return count;
}

bool regionContains(const Region &region, double x, double y)
{
    bool inside = false;
    const auto cross = [&](const Eigen::MatrixX2d &ring) {
        for (Eigen::Index i = 0, j = ring.rows() - 1; i < ring.rows(); j = i++) {
            const double ax = ring(i, 0), ay = ring(i, 1), bx = ring(j, 0), by = ring(j, 1);
            if ((ay > y) != (by > y) && x < (bx - ax) * (y - ay) / (by - ay) + ax)
                inside = !inside;
        }
    };
    for (const Polygon &polygon : region) {
        cross(polygon.outer);
        for (const Eigen::MatrixX2d &hole : polygon.holes)
            cross(hole);
    }
    return inside;
}

} // namespace finbook::geometry
