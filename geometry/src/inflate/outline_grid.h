// A uniform grid over the outline's edges, so the nearest-point and first-contact searches of
// the inflation visit the edges near a point first and stop at a distance bound instead of
// scanning the whole outline for every mesh vertex. Internal to geometry/src/inflate.
#pragma once

#include "mesh_outline.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <vector>

namespace finbook::geometry::inflate_detail {

class OutlineGrid {
public:
    explicit OutlineGrid(const MeshOutline &outline);

    // Calls visit(edge) once for every edge in the cells around p, ring by ring outward, until
    // the next ring lies farther from p than limit() (re-read after every ring) or the grid
    // ends. Edges in a ring nearer than limit() are all visited; farther ones may be too.
    template <class Visit, class Limit>
    void visitNear(const Eigen::RowVector2d &p, Visit visit, Limit limit) const
    {
        ++m_stamp;
        const int cx = cellX(p.x()), cy = cellY(p.y());
        const int rings = std::max({cx, m_nx - 1 - cx, cy, m_ny - 1 - cy});
        for (int k = 0; k <= rings; ++k) {
            if (k > 1 && double(k - 1) * m_cell > limit())
                return;
            for (int j = cy - k; j <= cy + k; ++j) {
                if (j < 0 || j >= m_ny)
                    continue;
                const int step = (j == cy - k || j == cy + k) ? 1 : 2 * k;
                for (int i = cx - k; i <= cx + k; i += std::max(step, 1)) {
                    if (i < 0 || i >= m_nx)
                        continue;
                    const int cell = j * m_nx + i;
                    for (int c = m_start[std::size_t(cell)]; c < m_start[std::size_t(cell) + 1];
                         ++c) {
                        const int edge = m_edges[std::size_t(c)];
                        if (m_seen[std::size_t(edge)] == m_stamp)
                            continue;
                        m_seen[std::size_t(edge)] = m_stamp;
                        visit(edge);
                    }
                }
            }
        }
    }

private:
    int cellX(double x) const
    {
        return std::clamp(int(std::floor((x - m_x0) / m_cell)), 0, m_nx - 1);
    }
    int cellY(double y) const
    {
        return std::clamp(int(std::floor((y - m_y0) / m_cell)), 0, m_ny - 1);
    }

    double m_x0 = 0.0, m_y0 = 0.0, m_cell = 1.0;
    int m_nx = 1, m_ny = 1;
    std::vector<int> m_start; // cell c holds m_edges[m_start[c] .. m_start[c + 1])
    std::vector<int> m_edges;
    mutable std::vector<unsigned> m_seen; // per edge: the query that last visited it
    mutable unsigned m_stamp = 0;
};

} // namespace finbook::geometry::inflate_detail
