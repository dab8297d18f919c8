// Nearest-point queries over a fixed 2D point set with unit normals: uniform grids searched
// in growing square rings until no closer cell can remain. Two levels: cells of about two
// points over the bounding box, and, where the points lie densely along lines (a drawing's),
// finer cells holding a few each, which answer the queries near the lines.
// The normal filter makes it "the nearest compatible point": strokes drawn in either
// direction have opposite normals, so a normal and its negation both agree.
#pragma once

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace finbook::deform::between::detail {

class PointGrid {
public:
    PointGrid() = default;
    // P k×2 finite points, N k×2 unit normals (or empty: every query ignores normals).
    PointGrid(const Eigen::MatrixX2d &P, const Eigen::MatrixX2d &N);

    bool empty() const { return m_count == 0; }

    // Row of the nearest point whose normal n has |n·normal| ≥ minAgreement (pass 0, or a zero
    // normal, to accept every point), or −1 if none lies within `within`; `distance` gets its
    // distance (∞ when none). Ties go to the lower row, so the answer does not depend on the
    // order the points were given in beyond their rows. A bounded search (a capped cost) reads
    // only the cells within its reach.
    int nearest(const Eigen::Vector2d &q, const Eigen::Vector2d &normal, double minAgreement,
                double &distance, double within = std::numeric_limits<double>::infinity()) const;

private:
    // A point as the queries read it, stored cell by cell: its place, its normal (zero when
    // there are none) and its row.
    struct Packed {
        double x, y, nx, ny;
        int row;
    };

    // One uniform grid over the points' box (CSR: points of cell c are
    // packed[start[c] … start[c+1])).
    struct Level {
        double cell = 1.0;
        int nx = 1, ny = 1;
        std::vector<int> start;
        std::vector<Packed> packed;

        void build(const Eigen::MatrixX2d &P, const Eigen::MatrixX2d &N, bool normals,
                   const Eigen::Vector2d &lo, const Eigen::Vector2d &extent, double side);
        template <class Fn> void visitRing(int cx, int cy, int ring, Fn &&fn) const;
        // Rings 0 … rings around q, improving best; true when nothing closer can remain.
        template <class Accept>
        bool search(const Eigen::Vector2d &origin, const Eigen::Vector2d &q, int rings,
                    Accept &&accept, int &best, double &bestSquared) const;
    };

    int m_count = 0;
    bool m_normals = false;
    bool m_hasFine = false;
    Eigen::Vector2d m_origin = Eigen::Vector2d::Zero();
    Level m_coarse; // about two points per cell over the box
    Level m_fine;   // a few points per cell along the lines (when the lines are dense)
};

} // namespace finbook::deform::between::detail
