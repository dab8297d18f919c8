// Internal: the regular part of a cage mesh. An equilateral triangular lattice of spacing h
// tiles the cage interior wherever every corner of a lattice triangle is at least `clearance`
// from the cage; the strip left along the cage goes to the Delaunay mesher. Building the
// tiling costs O(1) per vertex, where Delaunay refinement costs microseconds per vertex, and
// its equilateral triangles give the cotangent Laplacian positive weights.
#pragma once

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace finbook::geometry::detail {

// Which lattice vertices are "deep" (inside the cage, at least `clearance` from every edge).
// With clearance ≥ 0.6 h (more than a lattice triangle's circumradius, h/√3) every lattice
// triangle with three deep corners lies strictly inside the cage.
class CageLattice {
public:
    CageLattice(const Eigen::MatrixX2d &corners, double h, double clearance);

    struct Tiling {
        std::vector<Eigen::Vector2d> points;    // vertices of kept triangles, then free deep points
        std::vector<long> cells;                // per point: its lattice cell, for exclude()
        std::size_t usedCount = 0;              // points in kept triangles
        std::vector<Eigen::Vector3i> triangles; // kept triangles, positive area
        // Edges of kept triangles whose neighbour across is not kept, oriented so that the
        // kept triangle lies on their left: the boundary of the tiled region.
        std::vector<std::pair<int, int>> front;
        std::vector<int> frontTriangle; // per front edge: the kept triangle it belongs to
    };

    Tiling tiling() const;
    // Takes a lattice vertex (a `cells` entry) out of the tiling: its triangles join the strip,
    // the vertex stays as a loose point of the strip.
    void exclude(long cell);

private:
    struct Kept;
    long cellOf(long q, long r) const // −1 outside the stored rows
    {
        if (r < 0 || r >= m_rows)
            return -1;
        const long i = q + r / 2 - m_first[std::size_t(r)];
        return i >= 0 && i < m_count[std::size_t(r)] ? m_offset[std::size_t(r)] + i : -1;
    }
    long deepAt(long q, long r) const // the cell if it may be tiled, else −1
    {
        const long c = cellOf(q, r);
        return c >= 0 && m_deep[std::size_t(c)] == 1 ? c : -1L;
    }
    // Numbers the lattice vertex (q, r) in t on first use (id: per cell, −1 = not yet).
    int use(long cell, long q, long r, std::vector<int> &id, Tiling &t) const
    {
        int &slot = id[std::size_t(cell)];
        if (slot < 0) {
            slot = int(t.points.size());
            t.points.push_back(position(q, r));
            t.cells.push_back(cell);
        }
        return slot;
    }
    std::vector<Kept> keepTriangles(std::vector<int> &id, Tiling &t) const;
    void findFront(const std::vector<Kept> &kept, Tiling &t) const;
    Eigen::Vector2d position(long q, long r) const
    {
        return m_origin + Eigen::Vector2d((double(q) + 0.5 * double(r)) * m_h, double(r) * m_dy);
    }
    void markInside(const Eigen::MatrixX2d &corners);
    void clearNear(const Eigen::Vector2d &a, const Eigen::Vector2d &b, double clearance);

    double m_h = 1.0, m_dy = 1.0;
    Eigen::Vector2d m_origin = Eigen::Vector2d::Zero();
    long m_rows = 0;
    // Per row r: stored index range [m_first[r], m_first[r] + m_count[r]) of i (the i-th
    // lattice point of the row), at m_offset[r] in m_deep. Axial q = i − ⌊r/2⌋.
    std::vector<long> m_first, m_count, m_offset;
    std::vector<unsigned char> m_deep; // 0 not deep, 1 may be tiled, 2 loose point only
};

} // namespace finbook::geometry::detail
