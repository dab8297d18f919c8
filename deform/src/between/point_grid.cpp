#include "point_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace finbook::deform::between::detail {
namespace {

// The fine level's cells hold about this many points where a line crosses them.
constexpr double kPointsPerLineCell = 3.0;
constexpr double kMaxFineCells = double(1 << 20);
// Rings of fine cells searched before the coarse level takes over.
constexpr int kFineRings = 3;

} // namespace

void PointGrid::Level::build(const Eigen::MatrixX2d &P, const Eigen::MatrixX2d &N, bool normals,
                             const Eigen::Vector2d &lo, const Eigen::Vector2d &extent, double side)
{
    cell = side;
    nx = std::clamp(int(extent.x() / cell) + 1, 1, 4096);
    ny = std::clamp(int(extent.y() / cell) + 1, 1, 4096);
    const auto count = std::size_t(P.rows());
    std::vector<int> cellOf(count);
    start.assign(std::size_t(nx) * std::size_t(ny) + 1, 0);
    for (std::size_t i = 0; i < count; ++i) {
        const auto r = Eigen::Index(i);
        const int cx = std::clamp(int((P(r, 0) - lo.x()) / cell), 0, nx - 1);
        const int cy = std::clamp(int((P(r, 1) - lo.y()) / cell), 0, ny - 1);
        cellOf[i] = cy * nx + cx;
        ++start[std::size_t(cellOf[i]) + 1];
    }
    for (std::size_t c = 1; c < start.size(); ++c)
        start[c] += start[c - 1];
    packed.resize(count);
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < count; ++i) {
        const auto r = Eigen::Index(i);
        packed[std::size_t(fill[std::size_t(cellOf[i])]++)] = {
            P(r, 0), P(r, 1), normals ? N(r, 0) : 0.0, normals ? N(r, 1) : 0.0, int(i)};
    }
}

PointGrid::PointGrid(const Eigen::MatrixX2d &P, const Eigen::MatrixX2d &N)
    : m_count(int(P.rows()))
    , m_normals(N.rows() == P.rows())
{
    if (m_count == 0)
        return;
    const Eigen::Vector2d lo = P.colwise().minCoeff(), hi = P.colwise().maxCoeff();
    const Eigen::Vector2d extent = hi - lo;
    m_origin = lo;
    // Coarse: about two points per cell over the bounding box; a degenerate box (one point, a
    // line) gets cells from its longer side. Far queries read few of its cells.
    const double area = std::max(extent.x() * extent.y(), 1e-300);
    double cell = std::sqrt(2.0 * area / double(m_count));
    cell = std::max(cell, extent.maxCoeff() / 1024.0);
    if (!(cell > 0.0) || !std::isfinite(cell))
        cell = 1.0;
    m_coarse.build(P, N, m_normals, lo, extent, cell);
    // Fine: a drawing's points lie along lines, not over the box, so the coarse cells a line
    // crosses hold tens of points (a dense outline's: 46 read per query). The fine cells shrink
    // until those hold a few; queries near the lines, most of a fit's, end in them.
    const double smallest = std::max(extent.maxCoeff() / 1024.0, std::sqrt(area / kMaxFineCells));
    double fine = cell;
    std::vector<std::int64_t> keys(static_cast<std::size_t>(m_count));
    for (int attempt = 0; attempt < 3 && fine > smallest; ++attempt) {
        for (int i = 0; i < m_count; ++i)
            keys[std::size_t(i)] = std::int64_t(std::floor((P(i, 1) - lo.y()) / fine)) * (1 << 30) +
                                   std::int64_t(std::floor((P(i, 0) - lo.x()) / fine));
        std::sort(keys.begin(), keys.end());
        const auto occupied = std::unique(keys.begin(), keys.end()) - keys.begin();
        const double perCell = double(m_count) / double(std::max<std::ptrdiff_t>(occupied, 1));
        if (perCell <= 1.5 * kPointsPerLineCell)
            break;
        // Along a line a cell's points grow with its side: shrink in proportion.
        fine = std::max(smallest, fine * kPointsPerLineCell / perCell);
    }
    if (fine < 0.75 * cell) {
        m_fine.build(P, N, m_normals, lo, extent, fine);
        m_hasFine = true;
    }
}

template <class Fn> void PointGrid::Level::visitRing(int cx, int cy, int ring, Fn &&fn) const
{
    const auto cellAt = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= nx || y >= ny)
            return;
        const std::size_t c = std::size_t(y) * std::size_t(nx) + std::size_t(x);
        for (int k = start[c]; k < start[c + 1]; ++k)
            fn(packed[std::size_t(k)]);
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

template <class Accept>
bool PointGrid::Level::search(const Eigen::Vector2d &origin, const Eigen::Vector2d &q, int rings,
                              Accept &&accept, int &best, double &bestSquared) const
{
    const double fx = (q.x() - origin.x()) / cell, fy = (q.y() - origin.y()) / cell;
    // Queries far outside the grid start from the nearest cell; rings grow from there.
    const int cx = int(std::clamp(std::floor(fx), -1.0, double(nx)));
    const int cy = int(std::clamp(std::floor(fy), -1.0, double(ny)));
    const double outside =
        std::hypot(std::max({0.0, -fx, fx - nx}), std::max({0.0, -fy, fy - ny})) * cell;
    // Inside the grid q lies in the centre cell, this far (cells) from its nearest side.
    const double margin =
        outside > 0.0 ? 0.0
                      : std::max(0.0, std::min({fx - cx, cx + 1.0 - fx, fy - cy, cy + 1.0 - fy}));
    const int last = std::min(rings, std::max(nx, ny) + 2);
    for (int ring = 0; ring <= last; ++ring) {
        // Every point in ring r ≥ 1 is at least r − 1 cells and the margin from q (beyond it
        // when q is outside the grid), and every point at least as far as the grid is.
        const double bound =
            std::max(ring == 0 ? 0.0 : (double(ring - 1) + margin) * cell, outside);
        if (bound * bound > bestSquared)
            return true;
        visitRing(cx, cy, ring, [&](const Packed &p) {
            if (!accept(p))
                return;
            const double dx = p.x - q.x(), dy = p.y - q.y();
            const double d = dx * dx + dy * dy;
            if (d < bestSquared || (d == bestSquared && p.row < best)) {
                bestSquared = d;
                best = p.row;
            }
        });
    }
    // Every cell read: nothing is left beyond the last ring.
    return last < rings;
}

int PointGrid::nearest(const Eigen::Vector2d &q, const Eigen::Vector2d &normal, double minAgreement,
                       double &distance, double within) const
{
    distance = std::numeric_limits<double>::infinity();
    if (m_count == 0 || !q.allFinite())
        return -1;
    const bool filter = minAgreement > 0.0 && m_normals && normal.squaredNorm() > 0.0;
    const auto accept = [&](const Packed &p) {
        return !filter || std::abs(p.nx * normal.x() + p.ny * normal.y()) >= minAgreement;
    };
    int best = -1;
    // Points farther than `within` are not looked for: the search stops past it.
    double bestSquared =
        within < std::numeric_limits<double>::infinity()
            ? std::nextafter(within * within, std::numeric_limits<double>::infinity())
            : std::numeric_limits<double>::infinity();
    // The fine level answers what lies within its first rings; past them the coarse level
    // goes on from the best found (points it reads again change nothing: ties go to the lower
    // row on both levels).
    const bool done =
        m_hasFine && m_fine.search(m_origin, q, kFineRings, accept, best, bestSquared);
    if (!done)
        m_coarse.search(m_origin, q, std::numeric_limits<int>::max() / 4, accept, best,
                        bestSquared);
    if (best >= 0)
        distance = std::sqrt(bestSquared);
    return best;
}

} // namespace finbook::deform::between::detail
