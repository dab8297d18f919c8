// Test meshes for the deform tests and benches: regular triangulated grids, optionally
// jittered, and disjoint unions of them (multi-component stroke groups).
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <random>

namespace finbook::test {

struct GridMesh {
    Eigen::MatrixX2d V; // n×2
    Eigen::MatrixX3i F; // m×3, counter-clockwise in y-up coordinates
    int columns = 0;    // cells along x; vertex (c, r) is r·(columns + 1) + c
    int rows = 0;

    int vertex(int c, int r) const { return r * (columns + 1) + c; }
    double size() const { return (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm(); }
};

// columns×rows cells over [origin, origin + (width, height)], two triangles per cell with
// alternating diagonals (no preferred direction). `jitter` moves interior vertices by up to
// that fraction of a cell; below 0.25 every triangle keeps a healthy shape.
inline GridMesh gridMesh(int columns, int rows, double width, double height, double jitter = 0.0,
                         Eigen::Vector2d origin = Eigen::Vector2d::Zero(), unsigned seed = 1)
{
    GridMesh g;
    g.columns = columns;
    g.rows = rows;
    g.V.resize((columns + 1) * (rows + 1), 2);
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> offset(-jitter, jitter);
    const double dx = width / columns, dy = height / rows;
    for (int r = 0; r <= rows; ++r) {
        for (int c = 0; c <= columns; ++c) {
            const bool interior = c > 0 && c < columns && r > 0 && r < rows;
            const double jx = interior ? offset(random) : 0.0, jy = interior ? offset(random) : 0.0;
            g.V.row(g.vertex(c, r)) = origin + Eigen::Vector2d((c + jx) * dx, (r + jy) * dy);
        }
    }
    g.F.resize(2 * columns * rows, 3);
    int t = 0;
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            const int a = g.vertex(c, r), b = g.vertex(c + 1, r);
            const int d = g.vertex(c, r + 1), e = g.vertex(c + 1, r + 1);
            if ((r + c) % 2 == 0) {
                g.F.row(t++) << a, b, e;
                g.F.row(t++) << a, e, d;
            } else {
                g.F.row(t++) << a, b, d;
                g.F.row(t++) << b, e, d;
            }
        }
    }
    return g;
}

// A square-ish grid with about `vertices` vertices over a size×size square.
inline GridMesh gridMeshWithVertices(int vertices, double size, double jitter = 0.1)
{
    const int side = std::max(2, int(std::lround(std::sqrt(double(vertices)))) - 1);
    return gridMesh(side, side, size, size, jitter);
}

// Appends mesh (V2, F2) to (V, F) as a separate component; returns the index offset of V2.
inline int appendMesh(Eigen::MatrixX2d &V, Eigen::MatrixX3i &F, const Eigen::MatrixX2d &V2,
                      const Eigen::MatrixX3i &F2)
{
    const auto offset = static_cast<int>(V.rows());
    V.conservativeResize(V.rows() + V2.rows(), 2);
    V.bottomRows(V2.rows()) = V2;
    F.conservativeResize(F.rows() + F2.rows(), 3);
    F.bottomRows(F2.rows()) = F2.array() + offset;
    return offset;
}

// Applies x ↦ R(angle)·x + shift to every row.
inline Eigen::MatrixX2d rigidlyMoved(const Eigen::MatrixX2d &P, double angle,
                                     const Eigen::Vector2d &shift)
{
    Eigen::Matrix2d R;
    R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    return (P * R.transpose()).rowwise() + shift.transpose();
}

// Rows of V selected by b (k×2), i.e. the rest positions of the pins.
inline Eigen::MatrixX2d rowsOf(const Eigen::MatrixX2d &V, const Eigen::VectorXi &b)
{
    Eigen::MatrixX2d out(b.size(), 2);
    for (Eigen::Index k = 0; k < b.size(); ++k)
        out.row(k) = V.row(b(k));
    return out;
}

} // namespace finbook::test
