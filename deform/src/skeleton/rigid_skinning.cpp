#include "skeleton_internal.h"

#include <finbook/deform/skeleton/rigid_skinning.h>

#include <vector>

namespace finbook::deform {

namespace {

// V, F valid and weights.owner of V's size.
Eigen::VectorXi pinsOf(const SkinningWeights &weights, const Eigen::MatrixX2d &V,
                       const Eigen::MatrixX3i &F)
{
    int componentCount = 0;
    const Eigen::VectorXi component = detail::componentLabels(V.rows(), F, componentCount);
    std::vector<bool> pinned(static_cast<std::size_t>(V.rows()), false);
    std::vector<int> first(static_cast<std::size_t>(componentCount), -1);
    std::vector<int> count(static_cast<std::size_t>(componentCount), 0);
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        if (weights.owner(v) < 0)
            continue;
        const auto c = static_cast<std::size_t>(component(v));
        pinned[static_cast<std::size_t>(v)] = true;
        if (first[c] < 0)
            first[c] = static_cast<int>(v);
        ++count[c];
    }
    // With one pin ARAP can only translate a component; the farthest vertex as a second pin
    // lets it turn with its bone (LBS gives that vertex the bone's full motion there).
    std::vector<int> farthest(static_cast<std::size_t>(componentCount), -1);
    std::vector<double> distance(static_cast<std::size_t>(componentCount), -1.0);
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        const auto c = static_cast<std::size_t>(component(v));
        if (count[c] != 1)
            continue;
        const double d = (V.row(v) - V.row(first[c])).squaredNorm();
        if (d > distance[c]) {
            distance[c] = d;
            farthest[c] = static_cast<int>(v);
        }
    }
    for (const int v : farthest) {
        if (v >= 0)
            pinned[static_cast<std::size_t>(v)] = true;
    }
    std::vector<int> pins;
    for (std::size_t v = 0; v < pinned.size(); ++v) {
        if (pinned[v])
            pins.push_back(static_cast<int>(v));
    }
    return Eigen::Map<const Eigen::VectorXi>(pins.data(), Eigen::Index(pins.size()));
}

std::optional<DeformError> validate(const SkinningWeights &weights, const Eigen::MatrixX2d &V,
                                    const Eigen::MatrixX3i &F)
{
    if (weights.W.rows() != V.rows() || weights.owner.size() != V.rows())
        return detail::makeError(DeformErrorCode::SizeMismatch,
                                 "the skinning weights belong to another mesh");
    return detail::validateArapInput(V, F, Eigen::VectorXi());
}

} // namespace

Expected<Eigen::VectorXi, DeformError>
rigidSkinPins(const SkinningWeights &weights, const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F)
{
    if (auto error = validate(weights, V, F))
        return unexpected(*error);
    return pinsOf(weights, V, F);
}

RigidSkinningResult rigidSkinPrecompute(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                        const SkinningWeights &weights, const ArapOptions &options,
                                        std::function<bool()> cancelled)
{
    if (auto error = validate(weights, V, F))
        return unexpected(*error);
    auto rig = std::make_shared<RigidSkinning>();
    rig->pinVertices = pinsOf(weights, V, F);
    auto arap = arapPrecompute(V, F, rig->pinVertices, options, std::move(cancelled));
    if (!arap)
        return unexpected(arap.error());
    rig->arap = *arap;
    Eigen::MatrixX2d pinRest(rig->pinVertices.size(), 2);
    Eigen::MatrixXd pinWeights(rig->pinVertices.size(), weights.W.cols());
    for (Eigen::Index k = 0; k < rig->pinVertices.size(); ++k) {
        pinRest.row(k) = V.row(rig->pinVertices(k));
        pinWeights.row(k) = weights.W.row(rig->pinVertices(k));
    }
    SkinningWeights pinSubset{pinWeights, Eigen::VectorXi(), weights.handles, weights.active, 0.0};
    rig->pins = bindVertices(pinSubset, pinRest);
    return std::shared_ptr<const RigidSkinning>(std::move(rig));
}

Expected<ArapSolveReport, DeformError>
rigidSkinSolve(const RigidSkinning &rig, const PosedSkeleton &posed, Eigen::MatrixX2d &U)
{
    thread_local Eigen::MatrixX2d targets;
    if (auto error = skin(rig.pins, posed, targets))
        return unexpected(*error);
    return arapSolve(*rig.arap, targets, U);
}

} // namespace finbook::deform
