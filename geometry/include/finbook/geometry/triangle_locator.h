// Fast point location in a triangle mesh: a uniform grid over the triangles' bounding boxes
// (about one triangle per cell), so a query inspects a handful of triangles.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry {

struct Location {
    int triangle = -1;                                 // row of F, −1 if F is empty
    Eigen::Vector3d weights = Eigen::Vector3d::Zero(); // barycentric, sum to 1, all ≥ 0
    bool inside = false; // false: the nearest triangle's closest point (clamped weights)
};

class TriangleLocator {
public:
    // V: n×2, F: m×3 (any orientation; degenerate triangles are never returned as containing).
    // Non-finite V or indices outside V make an empty locator (every query: triangle −1).
    TriangleLocator(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F);

    // Containing triangle, or the nearest one for points outside the mesh. A non-finite
    // query returns triangle 0 with weights 1/3 and inside = false.
    Location locate(const Eigen::Vector2d &p) const;

private:
    bool weightsIn(int t, const Eigen::Vector2d &p, Eigen::Vector3d &w) const;
    Location nearest(const Eigen::Vector2d &p) const;
    template <class Fn> void forCell(int x, int y, Fn &&fn) const;

    Eigen::MatrixX2d m_V;
    Eigen::MatrixX3i m_F;
    Eigen::Vector2d m_origin = Eigen::Vector2d::Zero();
    double m_cell = 1.0;
    int m_nx = 0, m_ny = 0;
    std::vector<int> m_cellStart; // CSR: triangles of cell c are m_cellTriangles[start[c]..]
    std::vector<int> m_cellTriangles;
};

} // namespace finbook::geometry
