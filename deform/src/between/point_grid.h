// Nearest-point queries over a fixed 2D point set with unit normals: a uniform grid of about
// two points per cell, searched in growing square rings until no closer cell can remain.
// The normal filter makes it "the nearest compatible point": strokes drawn in either
// direction have opposite normals, so a normal and its negation both agree.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace finbook::deform::between::detail {

class PointGrid {
public:
    PointGrid() = default;
    // P k×2 finite points, N k×2 unit normals (or empty: every query ignores normals).
    PointGrid(const Eigen::MatrixX2d &P, const Eigen::MatrixX2d &N);

    bool empty() const { return m_count == 0; }

    // Row of the nearest point whose normal n has |n·normal| ≥ minAgreement (pass 0, or a zero
    // normal, to accept every point), or −1 if none; `distance` gets its distance. Ties go to
    // the lower row, so the answer does not depend on the order the points were given in
    // beyond their rows.
    int nearest(const Eigen::Vector2d &q, const Eigen::Vector2d &normal, double minAgreement,
                double &distance) const;

private:
    template <class Fn> void visitRing(int cx, int cy, int ring, Fn &&fn) const;

    // A point as the queries read it, stored cell by cell (m_start): its place,
    // its normal (zero when there are none) and its row.
    struct Packed {
        double x, y, nx, ny;
        int row;
    };

    int m_count = 0;
    bool m_normals = false;
    std::vector<Packed> m_packed;
    Eigen::Vector2d m_origin = Eigen::Vector2d::Zero();
    double m_cell = 1.0;
    int m_nx = 1, m_ny = 1;
    std::vector<int> m_start; // CSR: points of cell c are m_packed[m_start[c] … m_start[c+1])
};

} // namespace finbook::deform::between::detail
