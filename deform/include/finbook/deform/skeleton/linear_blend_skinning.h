// Linear blend skinning: a point moves by the weighted average of its bones' rigid motions,
// x′ = Σ_j w_j T_j(x). Binding (weights of the points, only the bones that touch them) is done
// once per rest mesh / stroke set; skinning is the per-drag step and allocates nothing.
#pragma once

#include <finbook/deform/deform_error.h>
#include <finbook/deform/skeleton/skeleton.h>
#include <finbook/deform/skeleton/skinning_weights.h>
#include <finbook/geometry/embedding.h>

#include <Eigen/Core>

#include <optional>

namespace finbook::deform {

struct SkinBinding {
    Eigen::MatrixX2d rest;   // k×2 rest positions of the bound points
    Eigen::VectorXi bones;   // B handle joints (columns of SkinningWeights::W) that move them
    Eigen::MatrixXd weights; // k×B weights of those bones, rows in [0, 1] summing to 1
};

// The mesh vertices themselves: V n×2 as given to computeSkinningWeights.
SkinBinding bindVertices(const SkinningWeights &weights, const Eigen::MatrixX2d &V);

// Points embedded in the mesh (geometry::embed(V, F, points)): each point's weights are the
// barycentric blend of its triangle's vertex weights, its rest position the point itself (a
// non-finite point is bound at its embedded position instead, so skinning never gives NaN).
// V n×2 and F m×3 as given to computeSkinningWeights; embedding.I must index F (points.rows()
// entries). Errors: SizeMismatch, InvalidIndex.
Expected<SkinBinding, DeformError> bindPoints(const SkinningWeights &weights,
                                              const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                              const geometry::Embedding &embedding,
                                              const Eigen::MatrixX2d &points);

// out k×2 ← Σ_b weights(i, b) T_bones(b)(rest.row(i)). posed from forwardKinematics of the
// skeleton the weights were computed for. Allocation-free when out is already k×2.
// Errors: SizeMismatch (a bone beyond posed.transforms); out is then unchanged.
std::optional<DeformError> skin(const SkinBinding &binding, const PosedSkeleton &posed,
                                Eigen::MatrixX2d &out);

} // namespace finbook::deform
