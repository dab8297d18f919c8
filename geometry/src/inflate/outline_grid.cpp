#include "outline_grid.h"

namespace finbook::geometry::inflate_detail {
namespace {

// Cells per edge on average, and a bound on the grid's side, so a thin sliver of a shape or a
// few very long edges cannot ask for millions of cells.
constexpr double kCellsPerEdge = 1.0;
constexpr int kMaxCellsPerSide = 512;

} // namespace

OutlineGrid::OutlineGrid(const MeshOutline &outline)
{
    const Eigen::Index B = outline.edgeCount();
    m_seen.assign(std::size_t(B), 0);
    if (B == 0) {
        m_start.assign(2, 0);
        return;
    }
    const Eigen::RowVector2d lo = outline.a.colwise().minCoeff();
    const Eigen::RowVector2d hi = outline.a.colwise().maxCoeff();
    const double width = hi.x() - lo.x(), height = hi.y() - lo.y();
    const double meanEdge = outline.e.rowwise().norm().mean();
    m_cell = std::max({std::sqrt(width * height / (kCellsPerEdge * double(B))), meanEdge,
                       width / kMaxCellsPerSide, height / kMaxCellsPerSide, 1e-300});
    m_x0 = lo.x();
    m_y0 = lo.y();
    m_nx = std::clamp(int(width / m_cell) + 1, 1, kMaxCellsPerSide + 1);
    m_ny = std::clamp(int(height / m_cell) + 1, 1, kMaxCellsPerSide + 1);
    // Counting sort of (cell, edge) pairs over each edge's bounding box of cells.
    std::vector<int> count(std::size_t(m_nx) * std::size_t(m_ny) + 1, 0);
    const auto forCells = [&](Eigen::Index i, auto &&f) {
        const Eigen::RowVector2d a = outline.a.row(i), b = a + outline.e.row(i);
        for (int y = cellY(std::min(a.y(), b.y())); y <= cellY(std::max(a.y(), b.y())); ++y)
            for (int x = cellX(std::min(a.x(), b.x())); x <= cellX(std::max(a.x(), b.x())); ++x)
                f(y * m_nx + x);
    };
    for (Eigen::Index i = 0; i < B; ++i)
        forCells(i, [&](int cell) { ++count[std::size_t(cell) + 1]; });
    m_start.assign(count.size(), 0);
    for (std::size_t c = 1; c < count.size(); ++c)
        m_start[c] = m_start[c - 1] + count[c];
    m_edges.assign(std::size_t(m_start.back()), 0);
    std::vector<int> fill(m_start.begin(), m_start.end() - 1);
    for (Eigen::Index i = 0; i < B; ++i)
        forCells(i, [&](int cell) { m_edges[std::size_t(fill[std::size_t(cell)]++)] = int(i); });
}

} // namespace finbook::geometry::inflate_detail
