#include "cage_lattice.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace finbook::geometry::detail {
namespace {

double segmentDistance(const Eigen::Vector2d &p, const Eigen::Vector2d &a, const Eigen::Vector2d &b)
{
    const Eigen::Vector2d ab = b - a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return (a + t * ab - p).norm();
}

} // namespace

CageLattice::CageLattice(const Eigen::MatrixX2d &corners, double h, double clearance)
    : m_h(h)
    , m_dy(0.5 * std::sqrt(3.0) * h)
{
    const Eigen::Vector2d lo = corners.colwise().minCoeff().transpose();
    const Eigen::Vector2d hi = corners.colwise().maxCoeff().transpose();
    m_rows = long(std::floor((hi.y() - lo.y()) / m_dy)) + 1;
    // Rows centred in the cage's height; x is anchored per row by the inside spans.
    m_origin = {lo.x() - m_h, lo.y() + 0.5 * ((hi.y() - lo.y()) - double(m_rows - 1) * m_dy)};
    markInside(corners);
    for (Eigen::Index e = 0; e < corners.rows(); ++e)
        clearNear(corners.row(e).transpose(), corners.row((e + 1) % corners.rows()).transpose(),
                  clearance);
}

void CageLattice::markInside(const Eigen::MatrixX2d &corners)
{
    m_first.assign(std::size_t(m_rows), 0);
    m_count.assign(std::size_t(m_rows), 0);
    m_offset.assign(std::size_t(m_rows) + 1, 0);
    std::vector<std::vector<double>> spans{std::size_t(m_rows)};
    for (long r = 0; r < m_rows; ++r) {
        const double y = m_origin.y() + double(r) * m_dy;
        std::vector<double> &xs = spans[std::size_t(r)];
        for (Eigen::Index i = 0, j = corners.rows() - 1; i < corners.rows(); j = i++) {
            const double ay = corners(i, 1), by = corners(j, 1);
            if ((ay > y) != (by > y))
                xs.push_back(corners(i, 0) +
                             (corners(j, 0) - corners(i, 0)) * (y - ay) / (by - ay));
        }
        std::sort(xs.begin(), xs.end());
        const double shift = m_origin.x() + 0.5 * double(r % 2) * m_h;
        long first = 0, last = -1;
        for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
            const long a = long(std::ceil((xs[k] - shift) / m_h));
            const long b = long(std::floor((xs[k + 1] - shift) / m_h));
            if (b < a)
                continue;
            first = last < first ? a : std::min(first, a);
            last = std::max(last, b);
        }
        m_first[std::size_t(r)] = first;
        m_count[std::size_t(r)] = std::max(0L, last - first + 1);
        m_offset[std::size_t(r) + 1] = m_offset[std::size_t(r)] + m_count[std::size_t(r)];
    }
    m_deep.assign(std::size_t(m_offset.back()), 0);
    for (long r = 0; r < m_rows; ++r) {
        const std::vector<double> &xs = spans[std::size_t(r)];
        const double shift = m_origin.x() + 0.5 * double(r % 2) * m_h;
        for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
            const long a = long(std::ceil((xs[k] - shift) / m_h));
            const long b = long(std::floor((xs[k + 1] - shift) / m_h));
            for (long i = a; i <= b; ++i)
                m_deep[std::size_t(m_offset[std::size_t(r)] + i - m_first[std::size_t(r)])] = 1;
        }
    }
}

void CageLattice::clearNear(const Eigen::Vector2d &a, const Eigen::Vector2d &b, double clearance)
{
    // Rows whose horizontal line comes within `clearance` of the edge; per row, only the
    // lattice points over the part of the edge inside the slab |y − y_r| ≤ clearance.
    const double ylo = std::min(a.y(), b.y()) - clearance, yhi = std::max(a.y(), b.y()) + clearance;
    const long r0 = std::max(0L, long(std::ceil((ylo - m_origin.y()) / m_dy)));
    const long r1 = std::min(m_rows - 1, long(std::floor((yhi - m_origin.y()) / m_dy)));
    for (long r = r0; r <= r1; ++r) {
        const double y = m_origin.y() + double(r) * m_dy;
        double t0 = 0.0, t1 = 1.0;
        if (b.y() != a.y()) {
            const double ta = (y - clearance - a.y()) / (b.y() - a.y());
            const double tb = (y + clearance - a.y()) / (b.y() - a.y());
            t0 = std::max(0.0, std::min(ta, tb));
            t1 = std::min(1.0, std::max(ta, tb));
            if (t1 < t0)
                continue;
        }
        const double xa = a.x() + t0 * (b.x() - a.x()), xb = a.x() + t1 * (b.x() - a.x());
        const double shift = m_origin.x() + 0.5 * double(r % 2) * m_h;
        const long first = m_first[std::size_t(r)], count = m_count[std::size_t(r)];
        const long i0 =
            std::max(first, long(std::floor((std::min(xa, xb) - clearance - shift) / m_h)));
        const long i1 = std::min(first + count - 1,
                                 long(std::ceil((std::max(xa, xb) + clearance - shift) / m_h)));
        for (long i = i0; i <= i1; ++i) {
            unsigned char &deep = m_deep[std::size_t(m_offset[std::size_t(r)] + i - first)];
            const Eigen::Vector2d p(shift + double(i) * m_h, y);
            if (deep && segmentDistance(p, a, b) < clearance)
                deep = 0;
        }
    }
}

void CageLattice::exclude(long cell)
{
    if (cell >= 0 && cell < long(m_deep.size()) && m_deep[std::size_t(cell)])
        m_deep[std::size_t(cell)] = 2;
}

// Kept triangles as (q, r, up?): corners (q,r) (q+1,r) (q,r+1) for an up triangle,
// (q+1,r) (q+1,r+1) (q,r+1) for a down one, counter-clockwise in y-up axes.
struct CageLattice::Kept {
    long q, r;
    bool up;
};

std::vector<CageLattice::Kept> CageLattice::keepTriangles(std::vector<int> &id, Tiling &t) const
{
    std::vector<Kept> kept;
    kept.reserve(2 * m_deep.size());
    for (long r = 0; r + 1 < m_rows; ++r) {
        const long lo =
            std::min(m_first[std::size_t(r)] - r / 2, m_first[std::size_t(r + 1)] - (r + 1) / 2);
        const long hi =
            std::max(m_first[std::size_t(r)] + m_count[std::size_t(r)] - r / 2,
                     m_first[std::size_t(r + 1)] + m_count[std::size_t(r + 1)] - (r + 1) / 2);
        long c00 = deepAt(lo, r), c01 = deepAt(lo, r + 1); // corners (q, r) and (q, r + 1)
        for (long q = lo; q < hi; ++q) {
            const long c10 = deepAt(q + 1, r), c11 = deepAt(q + 1, r + 1);
            if (c00 >= 0 && c10 >= 0 && c01 >= 0) {
                t.triangles.emplace_back(use(c00, q, r, id, t), use(c10, q + 1, r, id, t),
                                         use(c01, q, r + 1, id, t));
                kept.push_back({q, r, true});
            }
            if (c10 >= 0 && c11 >= 0 && c01 >= 0) {
                t.triangles.emplace_back(use(c10, q + 1, r, id, t), use(c11, q + 1, r + 1, id, t),
                                         use(c01, q, r + 1, id, t));
                kept.push_back({q, r, false});
            }
            c00 = c10;
            c01 = c11;
        }
    }
    return kept;
}

void CageLattice::findFront(const std::vector<Kept> &kept, Tiling &t) const
{
    for (std::size_t k = 0; k < kept.size(); ++k) {
        const auto [q, r, up] = kept[k];
        // Per edge (corner e → e + 1): the neighbour's third corner, the reflection a + b − c
        // of the opposite corner c (a lattice rhombus).
        const std::array<std::array<long, 2>, 3> across =
            up ? std::array<std::array<long, 2>, 3>{{{q + 1, r - 1},
                                                     {q + 1, r + 1},
                                                     {q - 1, r + 1}}}
               : std::array<std::array<long, 2>, 3>{{{q + 2, r}, {q, r + 2}, {q, r}}};
        for (int e = 0; e < 3; ++e) {
            if (deepAt(across[std::size_t(e)][0], across[std::size_t(e)][1]) >= 0)
                continue;
            t.front.emplace_back(t.triangles[k][e], t.triangles[k][(e + 1) % 3]);
            t.frontTriangle.push_back(int(k));
        }
    }
}

CageLattice::Tiling CageLattice::tiling() const
{
    Tiling t;
    t.points.reserve(m_deep.size());
    t.cells.reserve(m_deep.size());
    t.triangles.reserve(2 * m_deep.size());
    std::vector<int> id(m_deep.size(), -1);
    findFront(keepTriangles(id, t), t);
    t.usedCount = t.points.size();
    for (long r = 0; r < m_rows; ++r) { // deep points no kept triangle uses: loose points
        for (long i = 0; i < m_count[std::size_t(r)]; ++i) {
            const long cell = m_offset[std::size_t(r)] + i;
            if (m_deep[std::size_t(cell)] && id[std::size_t(cell)] < 0)
                use(cell, m_first[std::size_t(r)] + i - r / 2, r, id, t);
        }
    }
    return t;
}

} // namespace finbook::geometry::detail
