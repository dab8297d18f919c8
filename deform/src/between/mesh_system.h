// A symmetric positive definite n×n system on the pattern of a triangle mesh (an entry for
// every vertex and every pair of vertices sharing a triangle), analysed once and factored as
// often as its values change. The fit changes its data term every iteration and the
// interpolation factors once; both assemble per triangle, so each triangle keeps the slots of
// its 3×3 block in the value array. Links add entries between two vertices that need not share a
// triangle (a hinge between two cut pieces, rigid_fit.h).
#pragma once

#include <finbook/deform/supernodal_cholesky.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <array>
#include <complex>
#include <memory>
#include <vector>

namespace finbook::deform::between::detail {

class MeshSystem {
public:
    // n vertices, F m×3 with indices below n. Vertices marked in `eliminated` (size n, or
    // empty) are left out of the system (Dirichlet vertices); their slots are −1.
    // `links`: pairs of vertices below n whose entry the pattern also holds.
    MeshSystem(int n, const Eigen::MatrixX3i &F, const std::vector<bool> &eliminated = {},
               const std::vector<std::array<int, 2>> &links = {});

    int size() const { return m_free; }
    // Unknown of vertex v, or −1 when v was eliminated.
    int unknown(int v) const { return m_unknown[std::size_t(v)]; }

    void clear();
    // Adds w · β βᵀ to the block of triangle t (corners a, b of the triangle, β per corner).
    void addTriangleBlock(int t, const double beta[3], double w);
    // Adds w to entry (corner a, corner b) and its mirror of triangle t (a ≠ b), or w to the
    // diagonal of corner a (a == b).
    void addEntry(int t, int a, int b, double w);
    void addDiagonal(int v, double w);
    // Adds w·(e_i − e_j)(e_i − e_j)ᵀ for link l (the rows of an eliminated end are left out).
    void addLink(int l, double w);

    // Cholesky of the assembled values; false when not positive definite.
    bool factorize();
    // x ← A⁻¹ x for `columns` right-hand sides per unknown, stored row by row in unknown order
    // (x[unknown·columns + c]); real or x+iy. Const and allocating its own scratch, so a
    // factored system may be shared between threads.
    template <class Scalar> void solveInPlace(Scalar *x, int columns = 1) const;

private:
    int m_free = 0;
    std::vector<int> m_unknown;  // per vertex
    std::vector<int> m_position; // per unknown: its row in the factored (permuted) order
    std::vector<int> m_slots;    // per triangle 9 value indices (row-major 3×3), −1 eliminated
    std::vector<int> m_diagonal; // per unknown: value index of its diagonal
    std::vector<std::array<int, 4>> m_linkSlots; // per link: ii, jj, ij, ji (−1 eliminated)
    Eigen::SparseMatrix<double, Eigen::RowMajor> m_matrix; // permuted, both halves
    std::shared_ptr<const SupernodalSymbolic> m_symbolic;
    SupernodalCholesky<double> m_factor;
};

} // namespace finbook::deform::between::detail
