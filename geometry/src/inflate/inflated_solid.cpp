#include <finbook/geometry/inflate/inflated_solid.h>

#include <Eigen/Geometry>

namespace finbook::geometry {

InflatedSolid inflatedSolid(const Inflation &inflation)
{
    const Eigen::Index n = inflation.V.rows(), m = inflation.F.rows();
    // Bottom copies: one per vertex off the outline; outline vertices serve both halves.
    std::vector<int> below(std::size_t(n), 0);
    Eigen::Index k = n;
    for (Eigen::Index i = 0; i < n; ++i)
        below[std::size_t(i)] = inflation.outline(i) ? int(i) : int(k++);
    InflatedSolid solid;
    solid.V.resize(k, 3);
    solid.N.resize(k, 3);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double x = inflation.V(i, 0), y = -inflation.V(i, 1), h = inflation.height(i);
        const double nx = inflation.normal(i, 0), ny = -inflation.normal(i, 1);
        const double nz = inflation.normal(i, 2);
        solid.V.row(i) << x, y, h;
        solid.N.row(i) << nx, ny, nz;
        const int j = below[std::size_t(i)];
        if (j != int(i)) {
            solid.V.row(j) << x, y, -h;
            solid.N.row(j) << nx, ny, -nz;
        }
    }
    // Flipping y reverses the canvas triangles' turn: seen from +z (outside the top half) they
    // run clockwise, so the top takes them reversed and the bottom (seen from −z) as they are.
    solid.F.resize(2 * m, 3);
    for (Eigen::Index f = 0; f < m; ++f) {
        const int a = inflation.F(f, 0), b = inflation.F(f, 1), c = inflation.F(f, 2);
        solid.F.row(f) << a, c, b;
        solid.F.row(m + f) << below[std::size_t(a)], below[std::size_t(b)], below[std::size_t(c)];
    }
    return solid;
}

double signedVolume(const InflatedSolid &solid)
{
    double volume = 0.0;
    for (Eigen::Index f = 0; f < solid.F.rows(); ++f) {
        const Eigen::Vector3d a = solid.V.row(solid.F(f, 0)), b = solid.V.row(solid.F(f, 1)),
                              c = solid.V.row(solid.F(f, 2));
        volume += a.dot(b.cross(c)) / 6.0;
    }
    return volume;
}

} // namespace finbook::geometry
