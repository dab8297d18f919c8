// Harmonic skinning weights: one factorization of the free block of a cotangent Laplacian,
// one back-substitution per bone.
#include "skeleton_internal.h"

#include <finbook/deform/skeleton/skinning_weights.h>

#include <Eigen/SparseCholesky>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace finbook::deform {
namespace {

using detail::makeError;
using SparseMatrix = Eigen::SparseMatrix<double>;

// Cotangent weights of edges whose opposite angles sum to more than π are negative, which
// would break the maximum principle (weights outside [0, 1]). Clamping them to this small
// positive value keeps an M-matrix and keeps every triangle edge connected, so no free vertex
// can be cut off from the bones (Delaunay meshes from geometry rarely need it).
constexpr double kMinEdgeWeight = 1e-2;

// Symmetric edge weights ½(cot α + cot β), upper triangle (row < column), clamped as above.
SparseMatrix edgeWeights(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F)
{
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(static_cast<std::size_t>(3 * F.rows()));
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const int o = F(t, k), i = F(t, (k + 1) % 3), j = F(t, (k + 2) % 3);
            const Eigen::Vector2d u = (V.row(i) - V.row(o)).transpose();
            const Eigen::Vector2d w = (V.row(j) - V.row(o)).transpose();
            const double cot = u.dot(w) / std::abs(u.x() * w.y() - u.y() * w.x());
            triplets.emplace_back(std::min(i, j), std::max(i, j), 0.5 * cot);
        }
    }
    SparseMatrix E(V.rows(), V.rows());
    E.setFromTriplets(triplets.begin(), triplets.end());
    for (Eigen::Index col = 0; col < E.outerSize(); ++col) {
        for (SparseMatrix::InnerIterator it(E, col); it; ++it)
            it.valueRef() = std::max(it.value(), kMinEdgeWeight);
    }
    return E;
}

struct HarmonicSystem {
    SparseMatrix L;        // free × free Laplacian block (both halves)
    Eigen::MatrixXd B;     // free × active: −L_fc · (boundary values)
    std::vector<int> free; // internal free index → vertex
    double norm = 0.0;     // ‖L‖∞
};

// `column` maps a handle joint to its column of B (−1 for handles holding no vertex).
HarmonicSystem assemble(const SparseMatrix &E, const Eigen::VectorXi &owner,
                        const std::vector<int> &column, int activeCount)
{
    HarmonicSystem s;
    std::vector<int> index(static_cast<std::size_t>(owner.size()), -1);
    for (Eigen::Index v = 0; v < owner.size(); ++v) {
        if (owner(v) < 0) {
            index[static_cast<std::size_t>(v)] = static_cast<int>(s.free.size());
            s.free.push_back(static_cast<int>(v));
        }
    }
    const auto n = static_cast<Eigen::Index>(s.free.size());
    s.B = Eigen::MatrixXd::Zero(n, activeCount);
    Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(n), rowSum = Eigen::VectorXd::Zero(n);
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(static_cast<std::size_t>(2 * E.nonZeros() + n));
    for (Eigen::Index col = 0; col < E.outerSize(); ++col) {
        for (SparseMatrix::InnerIterator it(E, col); it; ++it) {
            const int a = index[static_cast<std::size_t>(it.row())];
            const int b = index[static_cast<std::size_t>(it.col())];
            const double w = it.value();
            if (a >= 0)
                diagonal(a) += w;
            if (b >= 0)
                diagonal(b) += w;
            if (a >= 0 && b >= 0) {
                triplets.emplace_back(a, b, -w);
                triplets.emplace_back(b, a, -w);
                rowSum(a) += w;
                rowSum(b) += w;
            } else if (a >= 0 || b >= 0) {
                const int freeEnd = a >= 0 ? a : b;
                const int held = static_cast<int>(a >= 0 ? it.col() : it.row());
                s.B(freeEnd, column[static_cast<std::size_t>(owner(held))]) += w;
            }
        }
    }
    for (Eigen::Index i = 0; i < n; ++i)
        triplets.emplace_back(i, i, diagonal(i));
    s.L.resize(n, n);
    s.L.setFromTriplets(triplets.begin(), triplets.end());
    s.norm = n > 0 ? (diagonal + rowSum).maxCoeff() : 0.0;
    return s;
}

// Solves L X = B a few columns at a time so that cancellation is noticed between them.
std::optional<DeformError> solveColumns(const HarmonicSystem &s, Eigen::MatrixXd &X,
                                        double &residual, const std::function<bool()> &cancelled)
{
    Eigen::SimplicialLDLT<SparseMatrix> factor(s.L);
    if (factor.info() != Eigen::Success)
        return makeError(DeformErrorCode::FactorizationFailed,
                         "the skinning Laplacian could not be factorized");
    constexpr Eigen::Index kChunk = 8;
    X.resize(s.B.rows(), s.B.cols());
    for (Eigen::Index c = 0; c < s.B.cols(); c += kChunk) {
        if (cancelled && cancelled())
            return makeError(DeformErrorCode::Cancelled, "skinning weights cancelled");
        const Eigen::Index width = std::min(kChunk, s.B.cols() - c);
        X.middleCols(c, width) = factor.solve(s.B.middleCols(c, width));
    }
    if (!X.allFinite())
        return makeError(DeformErrorCode::SolveFailed, "the skinning weights are not finite");
    // The residual of the columns' sum: the solve is linear, so a bad column shows there, at
    // one sparse product instead of one per bone.
    const Eigen::VectorXd x = X.rowwise().sum(), b = s.B.rowwise().sum();
    residual = detail::relativeResidual(s.L * x - b, s.norm, x, b);
    if (!(residual <= detail::kResidualTolerance))
        return makeError(DeformErrorCode::SolveFailed,
                         "the skinning weights solve has a large residual");
    return std::nullopt;
}

// Rounding may leave weights a hair outside [0, 1] or rows summing to 1 ± ε: clamp and
// renormalize so callers can rely on both exactly (to the last bits). Every row has a positive
// sum: held rows contain a 1, free rows are a convex combination of held values.
void normalizeRows(Eigen::MatrixXd &W)
{
    W = W.cwiseMax(0.0).cwiseMin(1.0);
    const Eigen::VectorXd sum = W.rowwise().sum();
    W.array().colwise() /= sum.array().max(std::numeric_limits<double>::min());
}

// The skeleton's handles, restricted to `bones` when that is not empty.
Expected<Eigen::VectorXi, DeformError> chosenHandles(const Skeleton &skeleton,
                                                     const Eigen::VectorXi &bones)
{
    const Eigen::VectorXi all = skinningHandles(skeleton);
    if (bones.size() == 0)
        return all;
    std::vector<bool> wanted(static_cast<std::size_t>(skeleton.jointCount()), false);
    for (const int j : bones) {
        if (j < 0 || j >= skeleton.jointCount())
            return unexpected(makeError(DeformErrorCode::InvalidIndex,
                                        "bone " + std::to_string(j) + " does not exist"));
        wanted[static_cast<std::size_t>(j)] = true;
    }
    std::vector<int> chosen;
    for (const int j : all) {
        if (wanted[static_cast<std::size_t>(j)])
            chosen.push_back(j);
    }
    if (chosen.empty())
        return unexpected(makeError(DeformErrorCode::InvalidSkeleton, "no bone skins this mesh"));
    return Eigen::VectorXi(
        Eigen::Map<const Eigen::VectorXi>(chosen.data(), Eigen::Index(chosen.size())));
}

} // namespace

SkinningWeightsResult computeSkinningWeights(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                             const Skeleton &skeleton,
                                             const SkinningOptions &options,
                                             std::function<bool()> cancelled)
{
    if (auto error = detail::validateArapInput(V, F, Eigen::VectorXi()))
        return unexpected(*error);
    if (!(options.reach >= 0.0) || !std::isfinite(options.reach))
        return unexpected(makeError(DeformErrorCode::InvalidSkeleton,
                                    "the bones' reach must be a finite non-negative number"));
    if (!(options.jointFree >= 0.0) || !std::isfinite(options.jointFree) ||
        (options.jointRadius.size() != 0 &&
         (options.jointRadius.size() != skeleton.jointCount() || !options.jointRadius.allFinite() ||
          options.jointRadius.minCoeff() < 0.0)))
        return unexpected(makeError(DeformErrorCode::InvalidSkeleton,
                                    "the joint zones need one finite radius per joint"));
    if (double(V.rows()) * double(skeleton.jointCount()) > kMaxSkinningEntries)
        return unexpected(
            makeError(DeformErrorCode::InvalidSkeleton, "too many bones for a mesh of this size"));
    auto handles = chosenHandles(skeleton, options.bones);
    if (!handles)
        return unexpected(handles.error());
    auto weights = std::make_shared<SkinningWeights>();
    weights->handles = std::move(*handles);
    weights->owner = detail::skinningBoundary(V, F, skeleton, weights->handles, options.reach,
                                              options.jointRadius, options.jointFree);
    std::vector<int> column(static_cast<std::size_t>(skeleton.jointCount()), -1);
    std::vector<int> active;
    for (const int o : weights->owner) {
        if (o >= 0 && column[static_cast<std::size_t>(o)] < 0)
            column[static_cast<std::size_t>(o)] = 0;
    }
    for (std::size_t j = 0; j < column.size(); ++j) {
        if (column[j] == 0) {
            column[j] = static_cast<int>(active.size());
            active.push_back(static_cast<int>(j));
        }
    }
    weights->active = Eigen::Map<const Eigen::VectorXi>(active.data(), Eigen::Index(active.size()));
    if (cancelled && cancelled())
        return unexpected(makeError(DeformErrorCode::Cancelled, "skinning weights cancelled"));
    const HarmonicSystem system =
        assemble(edgeWeights(V, F), weights->owner, column, static_cast<int>(active.size()));
    Eigen::MatrixXd X;
    if (system.L.rows() > 0) {
        if (auto error = solveColumns(system, X, weights->relativeResidual, cancelled))
            return unexpected(*error);
    }
    weights->W = Eigen::MatrixXd::Zero(V.rows(), skeleton.jointCount());
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        if (weights->owner(v) >= 0)
            weights->W(v, weights->owner(v)) = 1.0;
    }
    // Column by column (W is column-major), then clamp and renormalize all rows at once.
    for (std::size_t k = 0; k < active.size(); ++k) {
        auto target = weights->W.col(active[k]);
        for (std::size_t i = 0; i < system.free.size(); ++i)
            target(system.free[i]) = X(Eigen::Index(i), Eigen::Index(k));
    }
    normalizeRows(weights->W);
    return std::shared_ptr<const SkinningWeights>(std::move(weights));
}

} // namespace finbook::deform
