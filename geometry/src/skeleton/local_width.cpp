#include "local_width.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>

namespace finbook::geometry::detail {
namespace {

// Radius of the disk tangent at p with inward unit normal n that first touches the segment
// a–b (+inf if it never does).
double touchRadius(const Eigen::Vector2d &p, const Eigen::Vector2d &n, const Eigen::Vector2d &a,
                   const Eigen::Vector2d &b)
{
    double best = kInfinity;
    for (const Eigen::Vector2d &q : {a, b}) {
        const double along = (q - p).dot(n);
        if (along > 0.0)
            best = std::min(best, (q - p).squaredNorm() / (2.0 * along));
    }
    const Eigen::Vector2d ab = b - a;
    const double length = ab.norm();
    if (!(length > 0.0))
        return best;
    Eigen::Vector2d m(-ab.y() / length, ab.x() / length);
    double offset = m.dot(p - a);
    if (offset < 0.0) {
        m = -m;
        offset = -offset;
    }
    const double mu = m.dot(n);
    if (!(offset > 0.0) || !(mu < 1.0))
        return best;
    const double r = offset / (1.0 - mu);
    const Eigen::Vector2d foot = p + r * n - r * m;
    const double t = (foot - a).dot(ab) / (length * length);
    return t >= 0.0 && t <= 1.0 ? std::min(best, r) : best;
}

// The edges bucketed in a uniform grid of about one edge per cell, so that a disk's first
// touch is found by visiting cells outwards from its tangent point: a disk of radius r
// tangent at p lies within 2r of p, so the search stops once the visited square holds that.
class EdgeGrid {
public:
    EdgeGrid(const std::vector<Eigen::Vector2d> &from, const std::vector<Eigen::Vector2d> &to)
        : m_from(from)
        , m_to(to)
    {
        m_lo = m_hi = from.empty() ? Eigen::Vector2d::Zero() : from.front();
        for (const Eigen::Vector2d &p : from) {
            m_lo = m_lo.cwiseMin(p);
            m_hi = m_hi.cwiseMax(p);
        }
        const Eigen::Vector2d extent = (m_hi - m_lo).cwiseMax(1e-9);
        m_side = std::max(1, int(std::sqrt(double(from.size()))));
        m_cell = std::max(extent.x(), extent.y()) / m_side;
        m_cells.assign(std::size_t(m_side * m_side), {});
        for (std::size_t e = 0; e < from.size(); ++e) {
            const Eigen::Vector2i a = cellOf(from[e].cwiseMin(to[e]));
            const Eigen::Vector2i b = cellOf(from[e].cwiseMax(to[e]));
            for (int y = a.y(); y <= b.y(); ++y)
                for (int x = a.x(); x <= b.x(); ++x)
                    m_cells[std::size_t(y * m_side + x)].push_back(e);
        }
    }

    // The radius of the largest disk tangent at p (inward normal n) that no edge enters but
    // those `skip` says to ignore.
    template <typename Skip>
    double radius(const Eigen::Vector2d &p, const Eigen::Vector2d &n, const Skip &skip) const
    {
        const Eigen::Vector2i c = cellOf(p);
        double best = kInfinity;
        std::vector<char> seen(m_from.size(), 0);
        for (int ring = 0; ring <= m_side; ++ring) {
            // Cells at Chebyshev distance `ring` from c; all points outside the visited square
            // lie at least ring × cell away from p.
            if (double(ring - 1) * m_cell > 2.0 * best)
                break;
            for (int y = c.y() - ring; y <= c.y() + ring; ++y) {
                for (int x = c.x() - ring; x <= c.x() + ring; ++x) {
                    const bool border = std::abs(y - c.y()) == ring || std::abs(x - c.x()) == ring;
                    if (!border || x < 0 || y < 0 || x >= m_side || y >= m_side)
                        continue;
                    for (std::size_t e : m_cells[std::size_t(y * m_side + x)]) {
                        if (seen[e] || skip(e))
                            continue;
                        seen[e] = 1;
                        best = std::min(best, touchRadius(p, n, m_from[e], m_to[e]));
                    }
                }
            }
        }
        return best;
    }

private:
    Eigen::Vector2i cellOf(const Eigen::Vector2d &p) const
    {
        const Eigen::Vector2d q = (p - m_lo) / m_cell;
        return {std::clamp(int(q.x()), 0, m_side - 1), std::clamp(int(q.y()), 0, m_side - 1)};
    }

    const std::vector<Eigen::Vector2d> &m_from, &m_to;
    Eigen::Vector2d m_lo, m_hi;
    double m_cell = 1.0;
    int m_side = 1;
    std::vector<std::vector<std::size_t>> m_cells;
};

} // namespace

std::vector<std::vector<double>> localHalfWidths(const Polygon &polygon, double ignore)
{
    const std::vector<Eigen::MatrixX2d> rings = regionRings(Region{polygon});
    std::vector<Eigen::Vector2d> from, to;
    std::vector<std::size_t> ringOf;
    std::vector<double> arc, perimeter; // per edge: arc length at its start; per ring
    for (std::size_t r = 0; r < rings.size(); ++r) {
        const Eigen::MatrixX2d &ring = rings[r];
        double length = 0.0;
        for (Eigen::Index i = 0; i < ring.rows(); ++i) {
            from.push_back(ring.row(i).transpose());
            to.push_back(ring.row((i + 1) % ring.rows()).transpose());
            ringOf.push_back(r);
            arc.push_back(length);
            length += (to.back() - from.back()).norm();
        }
        perimeter.push_back(length);
    }
    const EdgeGrid grid(from, to);
    std::vector<std::vector<double>> out;
    std::size_t first = 0; // index of the ring's first edge in from/to
    for (std::size_t r = 0; r < rings.size(); ++r) {
        const std::size_t n = std::size_t(rings[r].rows());
        std::vector<double> widths(n, kInfinity);
        for (std::size_t i = 0; i < n && n >= 3; ++i) {
            const std::size_t in = first + (i + n - 1) % n, outEdge = first + i;
            // The material lies left of every edge (outer rings positive, holes negative).
            auto left = [&](std::size_t e) {
                const Eigen::Vector2d d = (to[e] - from[e]).normalized();
                return Eigen::Vector2d(-d.y(), d.x());
            };
            const Eigen::Vector2d sum = left(in) + left(outEdge);
            if (!(sum.norm() > 1e-12))
                continue;
            const Eigen::Vector2d normal = sum.normalized(), p = from[outEdge];
            // Edges within `ignore` along the ring from p: its own stretch of outline.
            const double at = arc[outEdge], around = perimeter[r];
            auto near = [&](double position) {
                const double d = std::abs(position - at);
                return std::min(d, around - d) < ignore;
            };
            widths[i] = grid.radius(p, normal, [&](std::size_t e) {
                return e == in || e == outEdge ||
                       (ringOf[e] == r &&
                        (near(arc[e]) || near(arc[e] + (to[e] - from[e]).norm())));
            });
        }
        out.push_back(std::move(widths));
        first += n;
    }
    return out;
}

} // namespace finbook::geometry::detail
