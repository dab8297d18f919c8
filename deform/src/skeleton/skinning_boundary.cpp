// Boundary conditions of the harmonic skinning weights: which vertices each bone holds.
#include "skeleton_internal.h"

#include <finbook/deform/skeleton/skinning_weights.h>

#include <limits>
#include <vector>

namespace finbook::deform {
namespace {

struct Segment {
    Eigen::Vector2d a, b;
};

std::vector<Segment> handleSegments(const Skeleton &skeleton, const Eigen::VectorXi &handles)
{
    std::vector<Segment> segments;
    segments.reserve(static_cast<std::size_t>(handles.size()));
    for (const int j : handles) {
        const int p = skeleton.parent(j);
        const Eigen::Vector2d tip = skeleton.joints.row(j).transpose();
        segments.push_back(
            {p < 0 ? tip : Eigen::Vector2d(skeleton.joints.row(p).transpose()), tip});
    }
    return segments;
}

double meanEdgeLength(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F)
{
    double sum = 0.0;
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        for (int k = 0; k < 3; ++k)
            sum += (V.row(F(t, (k + 1) % 3)) - V.row(F(t, k))).norm();
    }
    return F.rows() > 0 ? sum / double(3 * F.rows()) : 0.0;
}

// A handle that holds no vertex (a bone shorter than the mesh's edges, or one outside the mesh)
// takes the vertex nearest to it that is not another handle's only vertex, so every bone moves
// something and skinning sees it.
void giveEveryHandleAVertex(const Eigen::MatrixX2d &V, const std::vector<Segment> &segments,
                            Eigen::VectorXi &owner)
{
    std::vector<int> count(segments.size(), 0);
    for (const int o : owner) {
        if (o >= 0)
            ++count[static_cast<std::size_t>(o)];
    }
    for (std::size_t h = 0; h < segments.size(); ++h) {
        if (count[h] > 0)
            continue;
        int best = -1;
        double bestDistance = std::numeric_limits<double>::infinity();
        for (Eigen::Index v = 0; v < V.rows(); ++v) {
            const int o = owner(v);
            if (o >= 0 && count[static_cast<std::size_t>(o)] <= 1)
                continue;
            const double d =
                detail::squaredSegmentDistance(V.row(v).transpose(), segments[h].a, segments[h].b);
            if (d < bestDistance) {
                bestDistance = d;
                best = static_cast<int>(v);
            }
        }
        if (best < 0)
            continue;
        if (owner(best) >= 0)
            --count[static_cast<std::size_t>(owner(best))];
        owner(best) = static_cast<int>(h);
        count[h] = 1;
    }
}

// Vertices within jointFree × radius of a joint where two or more bones meet are left free.
void freeJointZones(const Eigen::MatrixX2d &V, const Skeleton &skeleton,
                    const Eigen::VectorXd &jointRadius, double jointFree, Eigen::VectorXi &owner)
{
    if (!(jointFree > 0.0) || jointRadius.size() != skeleton.jointCount())
        return;
    std::vector<int> degree(static_cast<std::size_t>(skeleton.jointCount()), 0);
    for (Eigen::Index j = 0; j < skeleton.jointCount(); ++j) {
        if (skeleton.parent(j) >= 0) {
            ++degree[static_cast<std::size_t>(j)];
            ++degree[static_cast<std::size_t>(skeleton.parent(j))];
        }
    }
    for (Eigen::Index j = 0; j < skeleton.jointCount(); ++j) {
        const double r = jointFree * jointRadius(j);
        if (degree[static_cast<std::size_t>(j)] < 2 || !(r > 0.0))
            continue;
        for (Eigen::Index v = 0; v < V.rows(); ++v) {
            if ((V.row(v) - skeleton.joints.row(j)).squaredNorm() < r * r)
                owner(v) = -1;
        }
    }
}

} // namespace

Eigen::VectorXi skinningHandles(const Skeleton &skeleton)
{
    std::vector<bool> hasChild(static_cast<std::size_t>(skeleton.jointCount()), false);
    for (const int p : skeleton.parent) {
        if (p >= 0)
            hasChild[static_cast<std::size_t>(p)] = true;
    }
    std::vector<int> handles;
    for (Eigen::Index j = 0; j < skeleton.jointCount(); ++j) {
        if (!skeleton.isRoot(j) || !hasChild[static_cast<std::size_t>(j)])
            handles.push_back(static_cast<int>(j));
    }
    return Eigen::Map<const Eigen::VectorXi>(handles.data(), Eigen::Index(handles.size()));
}

// Works in handle positions 0 … H−1 internally and returns joint indices.
Eigen::VectorXi detail::skinningBoundary(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                         const Skeleton &skeleton, const Eigen::VectorXi &handles,
                                         double reachEdges, const Eigen::VectorXd &jointRadius,
                                         double jointFree)
{
    const std::vector<Segment> segments = handleSegments(skeleton, handles);
    const double reach = reachEdges * meanEdgeLength(V, F);
    const double reach2 = reach * reach;
    Eigen::VectorXi owner = Eigen::VectorXi::Constant(V.rows(), -1);
    Eigen::VectorXi nearest(V.rows());
    Eigen::VectorXd nearestDistance(V.rows());
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        const Eigen::Vector2d p = V.row(v).transpose();
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t h = 0; h < segments.size(); ++h) {
            const double d = detail::squaredSegmentDistance(p, segments[h].a, segments[h].b);
            if (d < best) {
                best = d;
                nearest(v) = static_cast<int>(h);
            }
        }
        nearestDistance(v) = best;
        if (best <= reach2)
            owner(v) = nearest(v);
    }
    freeJointZones(V, skeleton, jointRadius, jointFree, owner);
    giveEveryHandleAVertex(V, segments, owner);
    // A component no bone reaches would make the Laplacian singular: its vertex nearest to a
    // bone is fixed to that bone, so the whole component follows it.
    int componentCount = 0;
    const Eigen::VectorXi component = detail::componentLabels(V.rows(), F, componentCount);
    std::vector<int> closest(static_cast<std::size_t>(componentCount), -1);
    std::vector<bool> held(static_cast<std::size_t>(componentCount), false);
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        const auto c = static_cast<std::size_t>(component(v));
        held[c] = held[c] || owner(v) >= 0;
        if (closest[c] < 0 || nearestDistance(v) < nearestDistance(closest[c]))
            closest[c] = static_cast<int>(v);
    }
    for (std::size_t c = 0; c < held.size(); ++c) {
        if (!held[c])
            owner(closest[c]) = nearest(closest[c]);
    }
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        if (owner(v) >= 0)
            owner(v) = handles(owner(v));
    }
    return owner;
}

} // namespace finbook::deform

namespace finbook::deform {

SkinningWeights withJointZones(const SkinningWeights &weights, const Eigen::MatrixX2d &V,
                               const Skeleton &skeleton, const Eigen::VectorXd &jointRadius,
                               double jointFree)
{
    SkinningWeights out = weights;
    if (weights.owner.size() != V.rows() || !jointRadius.allFinite())
        return out;
    Eigen::VectorXi zoned = weights.owner;
    freeJointZones(V, skeleton, jointRadius, jointFree, zoned);
    std::vector<int> held(static_cast<std::size_t>(skeleton.jointCount()), 0);
    for (const int o : zoned) {
        if (o >= 0)
            ++held[static_cast<std::size_t>(o)];
    }
    // A bone all of whose vertices lie in joint zones keeps one, the nearest to its middle,
    // as the weights' boundary would give it (giveEveryHandleAVertex): it must move something.
    std::vector<int> keep(held.size(), -1);
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        const int o = weights.owner(v);
        if (o < 0 || o >= skeleton.jointCount() || held[static_cast<std::size_t>(o)] > 0)
            continue;
        const int p = skeleton.parent(o) >= 0 ? skeleton.parent(o) : o;
        const Eigen::RowVector2d middle = 0.5 * (skeleton.joints.row(o) + skeleton.joints.row(p));
        int &k = keep[static_cast<std::size_t>(o)];
        if (k < 0 || (V.row(v) - middle).squaredNorm() < (V.row(k) - middle).squaredNorm())
            k = static_cast<int>(v);
    }
    for (const int k : keep) {
        if (k >= 0)
            zoned(k) = weights.owner(k);
    }
    out.owner = zoned;
    return out;
}

} // namespace finbook::deform
