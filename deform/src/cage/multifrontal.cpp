#include "harmonic_internal.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <thread>

namespace finbook::deform::detail {
namespace {

using Block = Eigen::Map<Eigen::MatrixXd, 0, Eigen::OuterStride<>>;
using ConstBlock = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>>;
using RowBlock = Eigen::Map<CageRowMatrix, 0, Eigen::OuterStride<>>;

// Fronts with at least this many eliminated columns use Eigen's blocked dense kernels; below,
// plain loops win because the per-call overhead of the blocked kernels dominates.
constexpr int kBlockedColumns = 24;
// Likewise for the solve: nodes with this many columns use a triangular solve and a product.
constexpr int kBlockedSolveColumns = 8;
// Below this many unknowns a second thread costs more to start than it saves.
constexpr std::size_t kParallelUnknowns = 3000;
// Likewise for the solve, in unknowns × right-hand sides.
constexpr Eigen::Index kParallelSolveWork = 40000;

// Eliminates the first ns columns of the m×m front (column-major, lower triangle): on return
// they hold L's columns and the trailing (m − ns)² block the Schur complement.
bool partialCholesky(double *front, int m, int ns)
{
    if (ns >= kBlockedColumns) {
        Block f(front, m, m, Eigen::OuterStride<>(m));
        auto f11 = f.topLeftCorner(ns, ns);
        Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(f11);
        if (llt.info() != Eigen::Success || !f11.diagonal().allFinite() ||
            !(f11.diagonal().minCoeff() > 0.0))
            return false;
        const int nu = m - ns;
        if (nu > 0) {
            auto f21 = f.bottomLeftCorner(nu, ns);
            f11.triangularView<Eigen::Lower>().transpose().solveInPlace<Eigen::OnTheRight>(f21);
            f.bottomRightCorner(nu, nu).selfadjointView<Eigen::Lower>().rankUpdate(f21, -1.0);
        }
        return true;
    }
    for (int j = 0; j < ns; ++j) { // right-looking, one column at a time
        double *cj = front + std::size_t(j) * std::size_t(m);
        if (!(cj[j] > 0.0) || !std::isfinite(cj[j]))
            return false;
        const double pivot = std::sqrt(cj[j]);
        cj[j] = pivot;
        const double inverse = 1.0 / pivot;
        for (int i = j + 1; i < m; ++i)
            cj[i] *= inverse;
        for (int k = j + 1; k < m; ++k) {
            const double l = cj[k];
            if (l == 0.0) // separators are not always fully coupled
                continue;
            double *ck = front + std::size_t(k) * std::size_t(m);
            for (int i = k; i < m; ++i)
                ck[i] -= l * cj[i];
        }
    }
    return true;
}

} // namespace

void MultifrontalCholesky::collectRows(const Eigen::SparseMatrix<double> &lower,
                                       const SupernodeTree::Node &node, int stamp, Workspace &ws)
{
    // Gathered apart: appending to ws.rows while reading a child's rows from it could move them.
    const int last = node.first + node.size;
    ws.collected.clear();
    const auto add = [&](int r) {
        if (r >= last && ws.mark[std::size_t(r)] != stamp) {
            ws.mark[std::size_t(r)] = stamp;
            ws.collected.push_back(r);
        }
    };
    for (int j = node.first; j < last; ++j)
        for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it)
            add(int(it.row()));
    for (const int child : node.children) {
        const Supernode &c = m_nodes[std::size_t(child)];
        const int *rows = rowsOf(c);
        for (int k = 0; k < c.below; ++k)
            add(rows[k]);
    }
    std::sort(ws.collected.begin(), ws.collected.end());
}

void MultifrontalCholesky::assembleFront(const Eigen::SparseMatrix<double> &lower,
                                         const SupernodeTree::Node &node, int m, Workspace &ws)
{
    ws.front.assign(std::size_t(m) * std::size_t(m), 0.0);
    double *front = ws.front.data();
    const auto at = [&](int row, int col) -> double & {
        return front[std::size_t(col) * std::size_t(m) + std::size_t(row)];
    };
    for (int j = node.first; j < node.first + node.size; ++j)
        for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it)
            at(ws.local[std::size_t(it.row())], ws.local[std::size_t(j)]) += it.value();
    for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
        const Supernode &c = m_nodes[std::size_t(*child)];
        Workspace &from = m_workspaces[std::size_t(c.workspace)];
        const int *rows = rowsOf(c);
        const auto k = std::size_t(c.below);
        const double *u = from.stack.data() + from.stackOffset.back();
        for (std::size_t b = 0; b < k; ++b) { // extend-add the child's Schur complement
            const int col = ws.local[std::size_t(rows[b])];
            for (std::size_t a = b; a < k; ++a)
                at(ws.local[std::size_t(rows[a])], col) += u[b * k + a];
        }
        from.stack.resize(from.stackOffset.back());
        from.stackOffset.pop_back();
    }
}

bool MultifrontalCholesky::factorNode(const Eigen::SparseMatrix<double> &lower,
                                      const SupernodeTree &tree, std::size_t s, int workspace)
{
    Workspace &ws = m_workspaces[std::size_t(workspace)];
    const SupernodeTree::Node &node = tree.nodes[s];
    collectRows(lower, node, int(s), ws);
    const std::size_t rowBegin = ws.rows.size();
    ws.rows.insert(ws.rows.end(), ws.collected.begin(), ws.collected.end());
    const int ns = node.size, nu = int(ws.collected.size()), m = ns + nu;
    for (int k = 0; k < ns; ++k)
        ws.local[std::size_t(node.first + k)] = k;
    for (int k = 0; k < nu; ++k)
        ws.local[std::size_t(ws.collected[std::size_t(k)])] = ns + k;
    assembleFront(lower, node, m, ws);
    const double *front = ws.front.data();
    if (!partialCholesky(ws.front.data(), m, ns))
        return false;
    m_nodes[s] = {node.first, ns, nu, workspace, rowBegin, ws.values.size()};
    ws.values.insert(ws.values.end(), front,
                     front + std::ptrdiff_t(std::size_t(m) * std::size_t(ns)));
    // The Schur complement waits on the stack for the parent.
    ws.stackOffset.push_back(ws.stack.size());
    ws.stack.resize(ws.stack.size() + std::size_t(nu) * std::size_t(nu));
    double *u = ws.stack.data() + ws.stackOffset.back();
    for (int b = 0; b < nu; ++b)
        for (int a = b; a < nu; ++a)
            u[std::size_t(b) * std::size_t(nu) + std::size_t(a)] =
                front[std::size_t(ns + b) * std::size_t(m) + std::size_t(ns + a)];
    return true;
}

bool MultifrontalCholesky::factor(const Eigen::SparseMatrix<double> &lower,
                                  const SupernodeTree &tree)
{
    const std::size_t count = tree.nodes.size();
    const auto n = std::size_t(lower.rows());
    m_nodes.assign(count, {});
    // The root's last child's subtree goes to a second thread when it is big enough: in
    // post-order it is the contiguous node range ending just before the root.
    std::size_t split = count;
    if (count > 0 && tree.nodes.back().children.size() == 2 && n >= kParallelUnknowns) {
        split = std::size_t(tree.nodes.back().children.front()) + 1;
    }
    m_split = split;
    m_workspaces.assign(split < count ? 2 : 1, {});
    for (Workspace &ws : m_workspaces) {
        ws.mark.assign(n, -1);
        ws.local.assign(n, -1);
        ws.values.reserve(std::size_t(lower.nonZeros()) * 12 / m_workspaces.size());
    }
    if (split == count) {
        for (std::size_t s = 0; s < count; ++s)
            if (!factorNode(lower, tree, s, 0))
                return false;
        return true;
    }
    bool helperOk = true;
    std::exception_ptr failure;
    std::thread helper([&] {
        try {
            for (std::size_t s = split; s + 1 < count && helperOk; ++s)
                helperOk = factorNode(lower, tree, s, 1);
        } catch (...) {
            failure = std::current_exception();
        }
    });
    bool ok = true;
    for (std::size_t s = 0; s < split && ok; ++s)
        ok = factorNode(lower, tree, s, 0);
    helper.join();
    if (failure)
        std::rethrow_exception(failure);
    return ok && helperOk && factorNode(lower, tree, count - 1, 0);
}

void MultifrontalCholesky::forward(const Supernode &node, const Rows &rows,
                                   CageRowMatrix &scratch) const
{
    const int ns = node.size, nu = node.below, m = ns + nu;
    const int *below = rowsOf(node);
    const double *L = blockOf(node);
    const Eigen::Index width = rows.width;
    if (ns >= kBlockedSolveColumns) {
        // The node's rows of X are consecutive: one triangular solve and one product.
        RowBlock xs(rows(node.first), ns, width, Eigen::OuterStride<>(rows.stride));
        const ConstBlock l(L, m, ns, Eigen::OuterStride<>(m));
        l.topRows(ns).triangularView<Eigen::Lower>().solveInPlace(xs);
        if (nu == 0)
            return;
        scratch.noalias() = l.bottomRows(nu) * xs;
        for (int a = 0; a < nu; ++a) {
            double *xa = rows.target(below[a]);
            const double *t = scratch.data() + Eigen::Index(a) * width;
            for (Eigen::Index k = 0; k < width; ++k)
                xa[k] -= t[k];
        }
        return;
    }
    for (int j = 0; j < ns; ++j) {
        const double *lj = L + std::size_t(j) * std::size_t(m);
        double *xj = rows(node.first + j);
        const double inverse = 1.0 / lj[j];
        for (Eigen::Index k = 0; k < width; ++k)
            xj[k] *= inverse;
        for (int i = j + 1; i < m; ++i) {
            const double l = lj[i];
            if (l == 0.0)
                continue;
            double *xi = i < ns ? rows(node.first + i) : rows.target(below[i - ns]);
            for (Eigen::Index k = 0; k < width; ++k)
                xi[k] -= l * xj[k];
        }
    }
}

void MultifrontalCholesky::backward(const Supernode &node, const Rows &rows,
                                    CageRowMatrix &scratch) const
{
    const int ns = node.size, nu = node.below, m = ns + nu;
    const int *below = rowsOf(node);
    const double *L = blockOf(node);
    const Eigen::Index width = rows.width;
    if (ns >= kBlockedSolveColumns) {
        RowBlock xs(rows(node.first), ns, width, Eigen::OuterStride<>(rows.stride));
        const ConstBlock l(L, m, ns, Eigen::OuterStride<>(m));
        if (nu > 0) {
            scratch.resize(nu, width);
            for (int a = 0; a < nu; ++a)
                std::copy_n(rows(below[a]), width, scratch.data() + Eigen::Index(a) * width);
            xs.noalias() -= l.bottomRows(nu).transpose() * scratch;
        }
        l.topRows(ns).triangularView<Eigen::Lower>().transpose().solveInPlace(xs);
        return;
    }
    for (int j = ns - 1; j >= 0; --j) {
        const double *lj = L + std::size_t(j) * std::size_t(m);
        double *xj = rows(node.first + j);
        for (int i = j + 1; i < m; ++i) {
            const double l = lj[i];
            if (l == 0.0)
                continue;
            const double *xi = rows(i < ns ? node.first + i : below[i - ns]);
            for (Eigen::Index k = 0; k < width; ++k)
                xj[k] -= l * xi[k];
        }
        const double inverse = 1.0 / lj[j];
        for (Eigen::Index k = 0; k < width; ++k)
            xj[k] *= inverse;
    }
}

void MultifrontalCholesky::solve(double *x, Eigen::Index stride, Eigen::Index width) const
{
    CageRowMatrix scratch;
    const Rows rows{x, stride, width};
    const std::size_t count = m_nodes.size();
    const bool parallel =
        m_split < count && Eigen::Index(m_nodes.back().first) * width >= kParallelSolveWork;
    if (!parallel) {
        for (const Supernode &node : m_nodes) // L y = b, children first
            forward(node, rows, scratch);
        for (auto it = m_nodes.rbegin(); it != m_nodes.rend(); ++it) // Lᵀ x = y, parents first
            backward(*it, rows, scratch);
        return;
    }
    // The root's two subtrees on two threads. Forward, both update the root's rows: the
    // helper's updates go to a buffer of its own, added once both are done. Backward, they
    // only read the root's rows.
    const int rootFirst = m_nodes.back().first;
    const auto rootRows = Eigen::Index(m_nodes.back().size);
    CageRowMatrix buffer = CageRowMatrix::Zero(rootRows, width);
    const Rows helperRows{x, stride, width, buffer.data(), rootFirst};
    const auto run = [&](const std::function<void(CageRowMatrix &)> &mine,
                         const std::function<void(CageRowMatrix &)> &theirs) {
        std::exception_ptr failure;
        std::thread helper([&] {
            try {
                CageRowMatrix own;
                theirs(own);
            } catch (...) {
                failure = std::current_exception();
            }
        });
        mine(scratch);
        helper.join();
        if (failure)
            std::rethrow_exception(failure);
    };
    run(
        [&](CageRowMatrix &s) {
            for (std::size_t k = 0; k < m_split; ++k)
                forward(m_nodes[k], rows, s);
        },
        [&](CageRowMatrix &s) {
            for (std::size_t k = m_split; k + 1 < count; ++k)
                forward(m_nodes[k], helperRows, s);
        });
    for (Eigen::Index a = 0; a < rootRows; ++a) {
        double *xa = rows(rootFirst + int(a));
        for (Eigen::Index k = 0; k < width; ++k)
            xa[k] += buffer(a, k);
    }
    forward(m_nodes.back(), rows, scratch);
    backward(m_nodes.back(), rows, scratch);
    run(
        [&](CageRowMatrix &s) {
            for (std::size_t k = m_split; k-- > 0;)
                backward(m_nodes[k], rows, s);
        },
        [&](CageRowMatrix &s) {
            for (std::size_t k = count - 1; k-- > m_split;)
                backward(m_nodes[k], rows, s);
        });
}

} // namespace finbook::deform::detail
