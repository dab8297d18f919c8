#include "skeleton_internal.h"

#include <finbook/deform/skeleton/linear_blend_skinning.h>

#include <string>
#include <vector>

namespace finbook::deform {
namespace {

using detail::makeError;

// Drops the columns no bound point uses, so skinning visits only bones that matter.
SkinBinding compact(Eigen::MatrixX2d rest, const Eigen::MatrixXd &full,
                    const Eigen::VectorXi &candidates)
{
    std::vector<int> used;
    for (const int j : candidates) {
        if (full.rows() > 0 && full.col(j).maxCoeff() > 0.0)
            used.push_back(j);
    }
    SkinBinding binding{std::move(rest),
                        Eigen::Map<const Eigen::VectorXi>(used.data(), Eigen::Index(used.size())),
                        Eigen::MatrixXd(full.rows(), Eigen::Index(used.size()))};
    for (std::size_t b = 0; b < used.size(); ++b)
        binding.weights.col(Eigen::Index(b)) = full.col(used[b]);
    return binding;
}

} // namespace

SkinBinding bindVertices(const SkinningWeights &weights, const Eigen::MatrixX2d &V)
{
    return compact(V, weights.W, weights.active);
}

Expected<SkinBinding, DeformError> bindPoints(const SkinningWeights &weights,
                                              const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                              const geometry::Embedding &embedding,
                                              const Eigen::MatrixX2d &points)
{
    const Eigen::Index k = points.rows();
    if (embedding.I.size() != k || embedding.B.rows() != k || V.rows() != weights.W.rows())
        return unexpected(
            makeError(DeformErrorCode::SizeMismatch,
                      "the embedding or the mesh does not match the points or weights"));
    const Eigen::Index n = weights.W.rows();
    Eigen::MatrixXd full = Eigen::MatrixXd::Zero(k, weights.W.cols());
    Eigen::MatrixX2d rest(k, 2);
    for (Eigen::Index i = 0; i < k; ++i) {
        const int t = embedding.I(i);
        if (t < 0 || t >= F.rows() || (F.row(t).array() < 0).any() || (F.row(t).array() >= n).any())
            return unexpected(makeError(DeformErrorCode::InvalidIndex,
                                        "point " + std::to_string(i) +
                                            " is embedded in a triangle that does not exist"));
        Eigen::Vector2d embedded = Eigen::Vector2d::Zero();
        for (int c = 0; c < 3; ++c) {
            const double b = embedding.B(i, c);
            full.row(i) += b * weights.W.row(F(t, c));
            embedded += b * V.row(F(t, c)).transpose();
        }
        if (points.row(i).allFinite())
            rest.row(i) = points.row(i);
        else
            rest.row(i) = embedded.transpose();
    }
    return compact(std::move(rest), full, weights.active);
}

std::optional<DeformError> skin(const SkinBinding &binding, const PosedSkeleton &posed,
                                Eigen::MatrixX2d &out)
{
    const auto transforms = static_cast<Eigen::Index>(posed.transforms.size());
    if (binding.weights.rows() != binding.rest.rows() ||
        binding.weights.cols() != binding.bones.size())
        return makeError(DeformErrorCode::SizeMismatch, "the skin binding is inconsistent");
    for (const int j : binding.bones) {
        if (j < 0 || j >= transforms)
            return makeError(DeformErrorCode::SizeMismatch,
                             "the pose has fewer bones than the skinning weights");
    }
    const Eigen::Index k = binding.rest.rows();
    out.resize(k, 2);
    out.setZero();
    const auto x = binding.rest.col(0).array(), y = binding.rest.col(1).array();
    // Column by column: each bone's transform is applied to all points as one vectorized
    // expression; no temporaries are materialized.
    for (Eigen::Index b = 0; b < binding.bones.size(); ++b) {
        const BoneTransform &T = posed.transforms[static_cast<std::size_t>(binding.bones(b))];
        const auto w = binding.weights.col(b).array();
        out.col(0).array() += w * (T(0, 0) * x + T(0, 1) * y + T(0, 2));
        out.col(1).array() += w * (T(1, 0) * x + T(1, 1) * y + T(1, 2));
    }
    return std::nullopt;
}

} // namespace finbook::deform
