// Small builders and predicates shared by the geometry tests and the mesh bench.
#pragma once

#include <QJsonArray>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>
#include <vector>

namespace finbook::test {

// An n×2 matrix from a list of (x, y) pairs.
inline Eigen::MatrixX2d rows(std::initializer_list<std::pair<double, double>> points)
{
    Eigen::MatrixX2d m(Eigen::Index(points.size()), 2);
    Eigen::Index i = 0;
    for (const auto &[x, y] : points)
        m.row(i++) << x, y;
    return m;
}

// n points on an axis-aligned ellipse around c, in increasing angle (positive shoelace area).
inline Eigen::MatrixX2d ellipse(int n, double rx, double ry, Eigen::RowVector2d c = {0, 0})
{
    Eigen::MatrixX2d ring(n, 2);
    for (int i = 0; i < n; ++i)
        ring.row(i) = c + Eigen::RowVector2d(rx * std::cos(2 * M_PI * i / n),
                                             ry * std::sin(2 * M_PI * i / n));
    return ring;
}

inline Eigen::MatrixX2d circle(int n, double r, Eigen::RowVector2d c = {0, 0})
{
    return ellipse(n, r, r, c);
}

// Even-odd point-in-ring test (crossing number).
inline bool insideRing(const Eigen::MatrixX2d &ring, const Eigen::RowVector2d &p)
{
    bool in = false;
    for (Eigen::Index i = 0, j = ring.rows() - 1; i < ring.rows(); j = i++) {
        const Eigen::RowVector2d a = ring.row(i), b = ring.row(j);
        if ((a.y() > p.y()) != (b.y() > p.y()) &&
            p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
            in = !in;
    }
    return in;
}

// [[x, y], ...] from the data files as an n×2 matrix.
inline Eigen::MatrixX2d toMatrix(const QJsonArray &points)
{
    Eigen::MatrixX2d m(points.size(), 2);
    for (qsizetype i = 0; i < points.size(); ++i) {
        const QJsonArray p = points[i].toArray();
        m(i, 0) = p[0].toDouble();
        m(i, 1) = p[1].toDouble();
    }
    return m;
}

// A silhouette's contours as `finbook-bench import` places them for the app: closed polylines
// fitted into 1100 × 600 px round the canvas centre (640, 360), proportions kept.
inline std::vector<Eigen::MatrixX2d> contoursAsStrokes(const QJsonArray &contours)
{
    std::vector<Eigen::MatrixX2d> strokes;
    Eigen::RowVector2d lo = Eigen::RowVector2d::Constant(HUGE_VAL), hi = -lo;
    for (const QJsonValue &contour : contours) {
        Eigen::MatrixX2d points = toMatrix(contour.toArray());
        if (points.rows() == 0)
            continue;
        points.conservativeResize(points.rows() + 1, 2);
        points.row(points.rows() - 1) = points.row(0);
        lo = lo.cwiseMin(points.colwise().minCoeff());
        hi = hi.cwiseMax(points.colwise().maxCoeff());
        strokes.push_back(points);
    }
    const double scale =
        std::min(1100.0 / std::max(1.0, hi.x() - lo.x()), 600.0 / std::max(1.0, hi.y() - lo.y()));
    for (Eigen::MatrixX2d &points : strokes)
        points = ((points.rowwise() - 0.5 * (lo + hi)) * scale).rowwise() +
                 Eigen::RowVector2d(640.0, 360.0);
    return strokes;
}

} // namespace finbook::test
