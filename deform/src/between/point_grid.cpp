#include "point_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace finbook::deform::between::detail {

PointGrid::PointGrid(const Eigen::MatrixX2d &P, const Eigen::MatrixX2d &N)
    : m_count(int(P.rows()))
    , m_normals(N.rows() == P.rows())
{
    if (m_count == 0)
        return;
    const Eigen::Vector2d lo = P.colwise().minCoeff(), hi = P.colwise().maxCoeff();
    const Eigen::Vector2d extent = hi - lo;
    // About two points per cell over the bounding box; a degenerate box (one point, a line)
    // gets cells from its longer side.
    const double area = std::max(extent.x() * extent.y(), 1e-300);
    double cell = std::sqrt(2.0 * area / double(m_count));
    cell = std::max(cell, extent.maxCoeff() / 1024.0);
    if (!(cell > 0.0) || !std::isfinite(cell))
        cell = 1.0;
    m_cell = cell;
    m_origin = lo;
    m_nx = std::clamp(int(extent.x() / cell) + 1, 1, 4096);
    m_ny = std::clamp(int(extent.y() / cell) + 1, 1, 4096);
    std::vector<int> cellOf(static_cast<std::size_t>(m_count));
    m_start.assign(std::size_t(m_nx) * std::size_t(m_ny) + 1, 0);
    for (int i = 0; i < m_count; ++i) {
        const int cx = std::clamp(int((P(i, 0) - lo.x()) / cell), 0, m_nx - 1);
        const int cy = std::clamp(int((P(i, 1) - lo.y()) / cell), 0, m_ny - 1);
        cellOf[std::size_t(i)] = cy * m_nx + cx;
        ++m_start[std::size_t(cellOf[std::size_t(i)]) + 1];
    }
    for (std::size_t c = 1; c < m_start.size(); ++c)
        m_start[c] += m_start[c - 1];
    m_packed.resize(std::size_t(m_count));
    std::vector<int> fill(m_start.begin(), m_start.end() - 1);
    for (int i = 0; i < m_count; ++i)
        m_packed[std::size_t(fill[std::size_t(cellOf[std::size_t(i)])]++)] = {
            P(i, 0), P(i, 1), m_normals ? N(i, 0) : 0.0, m_normals ? N(i, 1) : 0.0, i};
}

template <class Fn> void PointGrid::visitRing(int cx, int cy, int ring, Fn &&fn) const
{
    const auto cellAt = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= m_nx || y >= m_ny)
            return;
        const std::size_t c = std::size_t(y) * std::size_t(m_nx) + std::size_t(x);
        for (int k = m_start[c]; k < m_start[c + 1]; ++k)
            fn(m_packed[std::size_t(k)]);
    };
    if (ring == 0) {
        cellAt(cx, cy);
        return;
    }
    for (int x = cx - ring; x <= cx + ring; ++x) {
        cellAt(x, cy - ring);
        cellAt(x, cy + ring);
    }
    for (int y = cy - ring + 1; y <= cy + ring - 1; ++y) {
        cellAt(cx - ring, y);
        cellAt(cx + ring, y);
    }
}

int PointGrid::nearest(const Eigen::Vector2d &q, const Eigen::Vector2d &normal, double minAgreement,
                       double &distance) const
{
    distance = std::numeric_limits<double>::infinity();
    if (m_count == 0 || !q.allFinite())
        return -1;
    const bool filter = minAgreement > 0.0 && m_normals && normal.squaredNorm() > 0.0;
    const double fx = (q.x() - m_origin.x()) / m_cell, fy = (q.y() - m_origin.y()) / m_cell;
    // Queries far outside the grid start from the nearest cell; rings grow from there.
    const int cx = int(std::clamp(std::floor(fx), -1.0, double(m_nx)));
    const int cy = int(std::clamp(std::floor(fy), -1.0, double(m_ny)));
    const double outside =
        std::hypot(std::max({0.0, -fx, fx - m_nx}), std::max({0.0, -fy, fy - m_ny})) * m_cell;
    // Inside the grid q lies in the centre cell, this far (cells) from its nearest side.
    const double margin =
        outside > 0.0 ? 0.0
                      : std::max(0.0, std::min({fx - cx, cx + 1.0 - fx, fy - cy, cy + 1.0 - fy}));
    int best = -1;
    double bestSquared = std::numeric_limits<double>::infinity();
    const int maxRing = std::max(m_nx, m_ny) + 2;
    for (int ring = 0; ring <= maxRing; ++ring) {
        // Every point in ring r ≥ 1 is at least r − 1 cells and the margin from q (beyond it
        // when q is outside the grid), and every point at least as far as the grid is.
        const double bound =
            std::max(ring == 0 ? 0.0 : (double(ring - 1) + margin) * m_cell, outside);
        if (best >= 0 && bound * bound > bestSquared)
            break;
        visitRing(cx, cy, ring, [&](const Packed &p) {
            if (filter && std::abs(p.nx * normal.x() + p.ny * normal.y()) < minAgreement)
                return;
            const double dx = p.x - q.x(), dy = p.y - q.y();
            const double d = dx * dx + dy * dy;
            if (d < bestSquared || (d == bestSquared && p.row < best)) {
                bestSquared = d;
                best = p.row;
            }
        });
    }
    if (best >= 0)
        distance = std::sqrt(bestSquared);
    return best;
}

} // namespace finbook::deform::between::detail
