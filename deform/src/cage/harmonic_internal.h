// Internal pieces of the harmonic cage precompute: the interior system, its elimination order
// and its multi-right-hand-side solve.
#pragma once

#include <finbook/deform/cage/harmonic_cage.h>
#include <finbook/deform/deform_error.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <functional>
#include <limits>
#include <optional>
#include <vector>

namespace finbook::deform::detail {

// Unique neighbours of every vertex over the triangles of F, ascending (CSR: the neighbours of
// v are neighbour[start[v]] … neighbour[start[v + 1] − 1]).
struct VertexAdjacency {
    std::vector<int> start, neighbour;
};

VertexAdjacency vertexAdjacency(Eigen::Index vertexCount, const Eigen::MatrixX3i &F);

// The separator tree of a nested dissection: node k eliminates the columns [first, first +
// size) as one dense block (a supernode). Nodes are in post-order (children before parents),
// so a node's columns follow all of its descendants' columns.
struct SupernodeTree {
    struct Node {
        int first = 0, size = 0;
        std::vector<int> children;
    };
    std::vector<Node> nodes;
};

// Elimination order of the vertices [first, V.rows()) (the interior of a cage mesh) by
// geometric nested dissection: parts split at the median coordinate along their longer side,
// each separator after both halves. Cheaper than AMD on these meshes, with as little fill,
// and its separators are the supernodes of the factorization.
struct Dissection {
    std::vector<int> order; // elimination position → vertex
    SupernodeTree tree;
};

Dissection nestedDissection(const Eigen::MatrixX2d &V, const VertexAdjacency &adjacency,
                            Eigen::Index first);

// Gives the interior vertices [nb, n) of `mesh` the numbers nb + k in elimination order
// (order[k] is the old number of the k-th), in V, F and the adjacency. Then the interior rows
// of W are the solve's unknowns in factor order, and it can work in place.
void renumberInterior(geometry::CageMesh &mesh, VertexAdjacency &adjacency,
                      const std::vector<int> &order);

// L_II W_I = B, the interior block of the harmonic coordinates' system, with interior vertex
// nb + k as unknown k (renumberInterior first).
struct HarmonicSystem {
    SupernodeTree tree;            // the dissection's separators, for the factorization
    Eigen::SparseMatrix<double> A; // ni×ni lower triangle of L_II: column j holds the
                                   // diagonal first, then rows > j ascending
    double normA = 0.0;            // ‖L_II‖∞
    int negativeWeights = 0; // edges at interior vertices with cotangent weight below −1e-12
};

// Cotangent weights w_ij = ½(cot α + cot β) summed over the triangles of mesh.F (positive
// area). Resizes W to n×c and fills it with the right-hand side: hat values Φ_B in the boundary
// rows, B = −L_IB Φ_B in the interior rows.
HarmonicSystem assembleHarmonicSystem(const geometry::CageMesh &mesh,
                                      const VertexAdjacency &adjacency, SupernodeTree tree,
                                      CageRowMatrix &W);

// Interior rows of W (its last A.rows() rows) ← L_II⁻¹ × themselves: one sparse Cholesky
// factorization, then one forward and one backward pass over the factor for all columns
// together, split over two threads when the system is large. Checks the factorization,
// finiteness and the relative residual. Errors: FactorizationFailed, SolveFailed, Cancelled.
std::optional<DeformError> solveHarmonicSystem(const HarmonicSystem &system, CageRowMatrix &W,
                                               double &relativeResidual,
                                               const std::function<bool()> &cancelled);

// Sparse Cholesky A = L Lᵀ by the multifrontal method over a separator tree: every supernode
// is assembled into a dense front (its columns plus the later rows they reach), factored with
// dense kernels, and passes its Schur complement up to its parent. The dense kernels run
// several times faster than a simplicial factorization's scalar loops on these meshes.
class MultifrontalCholesky {
public:
    // lower: n×n lower triangle in the tree's elimination order (see HarmonicSystem::A).
    // Returns false when a pivot is not positive (A not positive definite) or not finite.
    // Large trees factor the root's two subtrees on two threads.
    bool factor(const Eigen::SparseMatrix<double> &lower, const SupernodeTree &tree);

    // X ← A⁻¹ X for the n×width row-major block X at x with row stride `stride`. Large
    // systems solve the root's two subtrees on two threads.
    void solve(double *x, Eigen::Index stride, Eigen::Index width) const;

private:
    // Where one thread of the factorization keeps its results and its scratch.
    struct Workspace {
        std::vector<int> rows;      // the nodes' rows below their blocks, back to back
        std::vector<double> values; // the nodes' blocks of L, back to back
        // Schur complements waiting for their parent: in post-order a node's children are
        // the last complements pushed.
        std::vector<double> stack;
        std::vector<std::size_t> stackOffset;
        std::vector<int> mark, local; // per matrix row
        std::vector<int> collected;   // the rows of the node being assembled
        std::vector<double> front;
    };
    // Supernode k: columns [first, first + size) of L as one dense (size + below) × size
    // column-major block in its workspace's values; its rows are the block's own columns,
    // then `below` more (ascending) in its workspace's rows.
    struct Supernode {
        int first = 0, size = 0, below = 0, workspace = 0;
        std::size_t rowOffset = 0, valueOffset = 0;
    };

    // Rows of X for the solve. A thread that must not write the root's rows (position ≥
    // redirectFrom) sends its updates of them to `redirect` (width doubles per row) instead.
    struct Rows {
        double *x;
        Eigen::Index stride, width;
        double *redirect = nullptr;
        int redirectFrom = std::numeric_limits<int>::max();

        double *operator()(int position) const { return x + Eigen::Index(position) * stride; }
        double *target(int position) const
        {
            return position >= redirectFrom
                       ? redirect + Eigen::Index(position - redirectFrom) * width
                       : (*this)(position);
        }
    };
    void forward(const Supernode &node, const Rows &rows, CageRowMatrix &scratch) const;
    void backward(const Supernode &node, const Rows &rows, CageRowMatrix &scratch) const;

    bool factorNode(const Eigen::SparseMatrix<double> &lower, const SupernodeTree &tree,
                    std::size_t s, int workspace);
    // The rows of the node's front below its own columns (ascending) into ws.collected.
    void collectRows(const Eigen::SparseMatrix<double> &lower, const SupernodeTree::Node &node,
                     int stamp, Workspace &ws);
    // ws.front ← the m×m front: A's columns of the node and its children's complements.
    void assembleFront(const Eigen::SparseMatrix<double> &lower, const SupernodeTree::Node &node,
                       int m, Workspace &ws);
    const int *rowsOf(const Supernode &node) const
    {
        return m_workspaces[std::size_t(node.workspace)].rows.data() + node.rowOffset;
    }
    const double *blockOf(const Supernode &node) const
    {
        return m_workspaces[std::size_t(node.workspace)].values.data() + node.valueOffset;
    }

    std::vector<Supernode> m_nodes;
    std::vector<Workspace> m_workspaces;
    std::size_t m_split = 0; // first node of the root's second subtree (= size: no split)
};

// Solves A X = B (X: ni×c, row-major, resized): one sparse Cholesky factorization, then one
// forward and one backward pass over the factor for all columns together, split over two
// threads when the system is large. Checks info(), finiteness and the relative residual.
// Errors: FactorizationFailed, SolveFailed, Cancelled.
std::optional<DeformError> solveHarmonicSystem(const HarmonicSystem &system, CageRowMatrix &X,
                                               double &relativeResidual,
                                               const std::function<bool()> &cancelled);

inline DeformError cageError(DeformErrorCode code, std::string message)
{
    return DeformError{code, std::move(message)};
}

} // namespace finbook::deform::detail
