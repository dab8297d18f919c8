#include "arap_solver.h"

#include <finbook/deform/arap.h>

#include <future>
#include <system_error>
#include <vector>

namespace finbook::deform {
namespace {

using detail::Complex;
using detail::makeError;

// Which vertices are solved for, which are pinned handles and which just follow their
// component (see the header for the internal numbering these lists become).
struct Classification {
    std::vector<int> freeVertices, handleVertices, handleEntries, rigidVertices, rigidEntries;
    std::vector<int> pinnedVertices;
    std::vector<Eigen::Index> solvedTriangles;
    Eigen::VectorXi label;    // component per (original) vertex
    std::vector<bool> pinned; // per component: has at least one pinned vertex
};

Classification classify(Eigen::Index n, const Eigen::MatrixX3i &F, const Eigen::VectorXi &b)
{
    int componentCount = 0;
    Classification c;
    c.label = detail::componentLabels(n, F, componentCount);
    const Eigen::VectorXi &label = c.label;
    std::vector<int> lastEntry(static_cast<std::size_t>(n), -1);
    for (Eigen::Index e = 0; e < b.size(); ++e)
        lastEntry[b(e)] = static_cast<int>(e);
    std::vector<int> pinCount(componentCount, 0), componentEntry(componentCount, -1);
    for (int v = 0; v < n; ++v) {
        if (lastEntry[v] < 0)
            continue;
        c.pinnedVertices.push_back(v);
        ++pinCount[label(v)];
        componentEntry[label(v)] = lastEntry[v];
    }
    for (int v = 0; v < n; ++v) {
        const int component = label(v);
        if (pinCount[component] < 2) {
            c.rigidVertices.push_back(v);
            c.rigidEntries.push_back(pinCount[component] == 1 ? componentEntry[component] : -1);
        } else if (lastEntry[v] >= 0) {
            c.handleVertices.push_back(v);
            c.handleEntries.push_back(lastEntry[v]);
        } else {
            c.freeVertices.push_back(v);
        }
    }
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        if (pinCount[label(F(t, 0))] >= 2)
            c.solvedTriangles.push_back(t);
    }
    c.pinned.resize(std::size_t(componentCount));
    for (int k = 0; k < componentCount; ++k)
        c.pinned[std::size_t(k)] = pinCount[k] > 0;
    return c;
}

// Step 2's matrix H00 over the free vertices (upper triangle, free-local numbering): the
// edge-weighted Laplacian summed per triangle, Σ w on the diagonal and −w per edge, with the
// weights of `cotangent` (see edgeWeights). Entries whose weights cancel stay in the pattern.
Eigen::SparseMatrix<double> freeLaplacian(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                          const Classification &c,
                                          const std::vector<int> &freeLocal, bool cotangent)
{
    const auto nf = static_cast<int>(c.freeVertices.size());
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(c.solvedTriangles.size() * 6);
    for (const Eigen::Index t : c.solvedTriangles) {
        Complex z[3];
        for (int r = 0; r < 3; ++r)
            z[r] = Complex(V(F(t, r), 0), V(F(t, r), 1));
        double w[3];
        detail::edgeWeights(z, cotangent, w);
        for (int r = 0; r < 3; ++r) {
            for (int s = r; s < 3; ++s) {
                const int i = freeLocal[F(t, r)], j = freeLocal[F(t, s)];
                if (i < 0 || j < 0)
                    continue;
                // Vertex r's two edges are opposite the other two corners; edge (r, s) is
                // opposite the third.
                const double value = r == s ? w[(r + 1) % 3] + w[(r + 2) % 3] : -w[3 - r - s];
                entries.emplace_back(std::min(i, j), std::max(i, j), value);
            }
        }
    }
    Eigen::SparseMatrix<double> upper(nf, nf);
    upper.setFromTriplets(entries.begin(), entries.end());
    return upper;
}

// AMD on the free-vertex adjacency, computed once and shared by G00 and H00 (same pattern).
// Stores H00 pre-permuted and the factors' shared symbolic analysis in d and returns the free
// vertices in elimination order.
std::vector<int> fillReducingOrder(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                   const Classification &c, const std::vector<int> &freeLocal,
                                   ArapPrecompute &d)
{
    const Eigen::SparseMatrix<double> laplacian =
        freeLaplacian(V, F, c, freeLocal, d.options.method == ArapMethod::Refined);
    const auto nf = static_cast<int>(c.freeVertices.size());
    const std::vector<int> order = supernodalOrder(laplacian);
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse(nf);
    for (int k = 0; k < nf; ++k)
        inverse.indices()(k) = order[std::size_t(k)];
    Eigen::SparseMatrix<double> permuted(nf, nf);
    permuted = laplacian.selfadjointView<Eigen::Upper>().twistedBy(inverse.inverse());
    std::vector<int> ordered(static_cast<std::size_t>(nf));
    for (int k = 0; k < nf; ++k)
        ordered[k] = c.freeVertices[inverse.indices()(k)];
    // Both halves are kept: the factorization reads the lower one, the per-event residual
    // check whole rows (= columns). Permuted columns come out unsorted, and G00 is built on
    // this pattern through an assignment that needs sorted indices: a double transpose sorts.
    d.stepTwoMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>(permuted);
    d.stepTwoNorm = detail::selfAdjointNorm(d.stepTwoMatrix);
    d.factorPattern =
        analyzeSupernodal(nf, d.stepTwoMatrix.outerIndexPtr(), d.stepTwoMatrix.innerIndexPtr());
    return ordered;
}

// Fills order, handle/rigid bookkeeping and rest positions; returns original → internal.
std::vector<int> numberVertices(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                const Eigen::VectorXi &b, const Classification &c,
                                ArapPrecompute &d)
{
    const Eigen::Index n = V.rows();
    std::vector<int> freeLocal(static_cast<std::size_t>(n), -1);
    for (std::size_t k = 0; k < c.freeVertices.size(); ++k)
        freeLocal[c.freeVertices[k]] = static_cast<int>(k);
    const std::vector<int> ordered = fillReducingOrder(V, F, c, freeLocal, d);

    d.freeCount = static_cast<Eigen::Index>(ordered.size());
    d.order.resize(n);
    int next = 0;
    for (const auto *list : {&ordered, &c.handleVertices, &c.rigidVertices}) {
        for (const int v : *list)
            d.order(next++) = v;
    }
    std::vector<int> internal(static_cast<std::size_t>(n));
    d.rest.resize(n);
    for (int k = 0; k < n; ++k) {
        internal[d.order(k)] = k;
        d.rest(k) = Complex(V(d.order(k), 0), V(d.order(k), 1));
    }
    d.handleEntry = Eigen::Map<const Eigen::VectorXi>(c.handleEntries.data(),
                                                      Eigen::Index(c.handleEntries.size()));
    d.rigidEntry = Eigen::Map<const Eigen::VectorXi>(c.rigidEntries.data(),
                                                     Eigen::Index(c.rigidEntries.size()));
    d.pinnedVertices = Eigen::Map<const Eigen::VectorXi>(c.pinnedVertices.data(),
                                                         Eigen::Index(c.pinnedVertices.size()));
    d.pinEntryCount = b.size();
    d.entryRest.resize(b.size());
    for (Eigen::Index e = 0; e < b.size(); ++e)
        d.entryRest(e) = Complex(V(b(e), 0), V(b(e), 1));
    const Eigen::Index solved = d.freeCount + d.handleEntry.size();
    if (solved > 0) {
        const Eigen::VectorXd x = d.rest.head(solved).real(), y = d.rest.head(solved).imag();
        d.objectSize = std::hypot(x.maxCoeff() - x.minCoeff(), y.maxCoeff() - y.minCoeff());
    }
    Eigen::VectorXi internalLabel(n);
    for (Eigen::Index k = 0; k < n; ++k)
        internalLabel(k) = c.label(d.order(k));
    detail::buildFollowers(internalLabel, c.pinned, d);
    return internal;
}

} // namespace

ArapPrecomputeResult arapPrecompute(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                    const Eigen::VectorXi &b, const ArapOptions &options,
                                    std::function<bool()> cancelled)
{
    const auto stop = [&cancelled] { return cancelled && cancelled(); };
    const auto cancelledError = [] {
        return unexpected(makeError(DeformErrorCode::Cancelled, "precompute was cancelled"));
    };
    if (auto error = detail::validateArapInput(V, F, b))
        return unexpected(std::move(*error));
    if (stop())
        return cancelledError();
    auto d = std::make_shared<ArapPrecompute>();
    d->options = options;
    const Classification c = classify(V.rows(), F, b);
    if (stop())
        return cancelledError();
    // A large mesh's coarse level is meshed and precomputed on a thread of its own meanwhile.
    std::future<std::optional<detail::TwoLevelBuild>> twoLevel;
    if (options.method == ArapMethod::Refined && options.twoLevelVertices > 0 &&
        c.freeVertices.size() + c.handleVertices.size() >= std::size_t(options.twoLevelVertices)) {
        // Only a faster start: without a thread, or when building it fails, there is none.
        try {
            twoLevel =
                std::async(std::launch::async, [&]() -> std::optional<detail::TwoLevelBuild> {
                    try {
                        return detail::buildTwoLevel(V, F, c.solvedTriangles, b, options);
                    } catch (...) {
                        return std::nullopt;
                    }
                });
        } catch (const std::system_error &) {
        }
    }
    const std::vector<int> internal = numberVertices(V, F, b, c, *d);
    if (stop())
        return cancelledError();
    // H00 is factored while G00 is assembled, and the drag set-up (see
    // ArapFactorization::finish) done while G00 is factored.
    detail::ArapFactorization factorization(*d);
    detail::assembleArapSystems(V, F, c.solvedTriangles, internal, *d);
    if (auto error = factorization.finish(cancelled))
        return unexpected(std::move(*error));
    if (twoLevel.valid()) {
        if (const auto build = twoLevel.get())
            detail::attachTwoLevel(*d, *build, internal);
    }
    return std::shared_ptr<const ArapPrecompute>(std::move(d));
}

} // namespace finbook::deform
