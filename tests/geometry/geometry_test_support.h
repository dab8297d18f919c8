// Small builders and predicates shared by the geometry tests and the mesh bench.
#pragma once

#include <QJsonArray>

#include <Eigen/Core>

#include <cmath>
#include <initializer_list>
#include <utility>

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

} // namespace finbook::test
