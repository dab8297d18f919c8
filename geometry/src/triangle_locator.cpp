#include <finbook/geometry/triangle_locator.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace finbook::geometry {
namespace {

// Slack for points on shared edges: weights this far below 0 still count as inside, so edge
// and vertex points reproduce exactly instead of being snapped.
constexpr double kInsideSlack = 1e-12;

// Closest point of triangle abc to p as barycentric weights (Ericson, Real-Time Collision
// Detection, 5.1.5), so a snapped point is a proper convex combination.
Eigen::Vector3d closestWeights(const Eigen::Vector2d &p, const Eigen::Vector2d &a,
                               const Eigen::Vector2d &b, const Eigen::Vector2d &c)
{
    const Eigen::Vector2d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0)
        return {1, 0, 0};
    const Eigen::Vector2d bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3)
        return {0, 1, 0};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const double t = d1 / (d1 - d3);
        return {1 - t, t, 0};
    }
    const Eigen::Vector2d cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6)
        return {0, 0, 1};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const double t = d2 / (d2 - d6);
        return {1 - t, 0, t};
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {0, 1 - t, t};
    }
    const double denom = va + vb + vc;
    if (!(std::abs(denom) > 0)) // degenerate triangle: its first vertex is as good as any
        return {1, 0, 0};
    return {va / denom, vb / denom, vc / denom};
}

} // namespace

TriangleLocator::TriangleLocator(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F)
    : m_V(V)
    , m_F(F)
{
    const Eigen::Index m = F.rows();
    // A mesh the grid cannot index (NaN positions, bad indices) locates nothing.
    if (m == 0 || !V.allFinite() || F.minCoeff() < 0 || F.maxCoeff() >= V.rows()) {
        m_F.resize(0, 3);
        return;
    }
    // Cells about the size of a triangle: a query then tests two or three triangles.
    std::vector<Eigen::AlignedBox2d> boxes(static_cast<std::size_t>(m));
    Eigen::AlignedBox2d all;
    double sizeSum = 0.0;
    for (Eigen::Index t = 0; t < m; ++t) {
        Eigen::AlignedBox2d &box = boxes[std::size_t(t)];
        for (int k = 0; k < 3; ++k)
            box.extend(V.row(F(t, k)).transpose());
        all.extend(box);
        sizeSum += box.sizes().maxCoeff();
    }
    const Eigen::Vector2d extent = all.sizes().cwiseMax(1e-9);
    m_origin = all.min();
    // At most ~4 cells per triangle, whatever the spread of the lobes.
    m_cell = std::max({sizeSum / double(m), std::sqrt(extent.prod() / (4.0 * double(m))),
                       extent.maxCoeff() / 4096.0});
    m_nx = std::max(1, int(std::ceil(extent.x() / m_cell)));
    m_ny = std::max(1, int(std::ceil(extent.y() / m_cell)));
    m_cellStart.assign(std::size_t(m_nx) * std::size_t(m_ny) + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<int> fill(m_cellStart.begin(), m_cellStart.end() - 1);
        for (Eigen::Index t = 0; t < m; ++t) {
            const Eigen::AlignedBox2d &box = boxes[std::size_t(t)];
            const int x0 = std::min(int((box.min().x() - m_origin.x()) / m_cell), m_nx - 1);
            const int x1 = std::min(int((box.max().x() - m_origin.x()) / m_cell), m_nx - 1);
            const int y0 = std::min(int((box.min().y() - m_origin.y()) / m_cell), m_ny - 1);
            const int y1 = std::min(int((box.max().y() - m_origin.y()) / m_cell), m_ny - 1);
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) {
                    const std::size_t c = std::size_t(y) * std::size_t(m_nx) + std::size_t(x);
                    if (pass == 0)
                        ++m_cellStart[c + 1];
                    else
                        m_cellTriangles[std::size_t(fill[c]++)] = int(t);
                }
        }
        if (pass == 0) {
            for (std::size_t c = 1; c < m_cellStart.size(); ++c)
                m_cellStart[c] += m_cellStart[c - 1];
            m_cellTriangles.resize(std::size_t(m_cellStart.back()));
        }
    }
}

bool TriangleLocator::weightsIn(int t, const Eigen::Vector2d &p, Eigen::Vector3d &w) const
{
    const Eigen::Vector2d a = m_V.row(m_F(t, 0)), u = m_V.row(m_F(t, 1)).transpose() - a,
                          v = m_V.row(m_F(t, 2)).transpose() - a, q = p - a;
    const double det = u.x() * v.y() - u.y() * v.x();
    if (!(std::abs(det) > 0.0))
        return false; // degenerate: never reported as containing
    const double w1 = (q.x() * v.y() - q.y() * v.x()) / det;
    const double w2 = (u.x() * q.y() - u.y() * q.x()) / det;
    w = {1.0 - w1 - w2, w1, w2};
    return true;
}

template <class Fn> void TriangleLocator::forCell(int x, int y, Fn &&fn) const
{
    const std::size_t c = std::size_t(y) * std::size_t(m_nx) + std::size_t(x);
    for (int i = m_cellStart[c]; i < m_cellStart[c + 1]; ++i)
        fn(m_cellTriangles[std::size_t(i)]);
}

Location TriangleLocator::locate(const Eigen::Vector2d &p) const
{
    if (m_F.rows() == 0)
        return {};
    if (!p.allFinite())
        return {0, Eigen::Vector3d::Constant(1.0 / 3.0), false};
    const Eigen::Vector2d q = (p - m_origin) / m_cell;
    if (q.x() >= 0 && q.y() >= 0 && q.x() < m_nx && q.y() < m_ny) {
        Location best;
        double bestMin = -std::numeric_limits<double>::infinity();
        forCell(int(q.x()), int(q.y()), [&](int t) {
            Eigen::Vector3d w;
            if (bestMin >= 0 || !weightsIn(t, p, w))
                return;
            if (w.minCoeff() > bestMin) {
                bestMin = w.minCoeff();
                best = {t, w, true};
            }
        });
        if (bestMin >= -kInsideSlack)
            return best;
    }
    return nearest(p);
}

Location TriangleLocator::nearest(const Eigen::Vector2d &p) const
{
    // Rings of cells around the cell nearest to p. A triangle not met by ring k − 1 has its
    // closest point at least (k − 1) cells from the projection of p onto the grid, hence at
    // least that far from p: stop once that bound exceeds the best distance found.
    const Eigen::Vector2d q = (p - m_origin) / m_cell;
    const int cx = std::clamp(int(std::floor(std::clamp(q.x(), -1.0, double(m_nx)))), 0, m_nx - 1);
    const int cy = std::clamp(int(std::floor(std::clamp(q.y(), -1.0, double(m_ny)))), 0, m_ny - 1);
    Location best;
    double bestDistance = std::numeric_limits<double>::infinity();
    const auto visit = [&](int t) {
        const Eigen::Vector2d a = m_V.row(m_F(t, 0)), b = m_V.row(m_F(t, 1)),
                              c = m_V.row(m_F(t, 2));
        const Eigen::Vector3d w = closestWeights(p, a, b, c);
        const double d = (w.x() * a + w.y() * b + w.z() * c - p).norm();
        if (d < bestDistance) {
            bestDistance = d;
            best = {t, w, false};
        }
    };
    const int maxRing = std::max(m_nx, m_ny);
    for (int k = 0; k <= maxRing; ++k) {
        if (double(k - 1) * m_cell > bestDistance)
            break;
        for (int y = cy - k; y <= cy + k; ++y) {
            if (y < 0 || y >= m_ny)
                continue;
            const bool edgeRow = (y == cy - k || y == cy + k);
            for (int x = cx - k; x <= cx + k; x += edgeRow ? 1 : 2 * std::max(k, 1)) {
                if (x >= 0 && x < m_nx)
                    forCell(x, y, visit);
            }
        }
    }
    return best;
}

} // namespace finbook::geometry
