#include "animator_rig.h"
#include "bone_graph.h"
#include "dense_graph.h"
#include "skeleton_contour.h"
#include "skeleton_tree.h"

#include <finbook/geometry/skeleton/skeleton_refine.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>

namespace finbook::geometry {
namespace {

using namespace detail;

DenseGraph fromRaw(const RawSkeleton &raw)
{
    DenseGraph graph;
    for (Eigen::Index v = 0; v < raw.nodes.rows(); ++v)
        graph.addNode(raw.nodes.row(v).transpose(), raw.radius(v), raw.clearance(v),
                      raw.polygon(v));
    for (Eigen::Index e = 0; e < raw.edges.rows(); ++e)
        graph.addEdge(raw.edges(e, 0), raw.edges(e, 1));
    return graph;
}

bool validRaw(const RawSkeleton &raw)
{
    const Eigen::Index n = raw.nodes.rows();
    if (raw.radius.size() != n || raw.clearance.size() != n || raw.polygon.size() != n)
        return false;
    if (!raw.nodes.allFinite() || !raw.radius.allFinite() || !raw.clearance.allFinite())
        return false;
    return raw.edges.size() == 0 || (raw.edges.minCoeff() >= 0 && raw.edges.maxCoeff() < n);
}

// Merges the two junctions of one junction–junction branch into the one with the larger
// clearance, unless a straight connection from there to the other's neighbours would leave
// the shape. False if it would.
bool mergeBranch(DenseGraph &g, const Branch &branch, const Contours &contours)
{
    const int a = branch.nodes.front(), z = branch.nodes.back();
    const int centre = g.clearance[std::size_t(a)] >= g.clearance[std::size_t(z)] ? a : z;
    const int other = centre == a ? z : a;
    const int inward =
        branch.nodes.size() > 2 ? branch.nodes[other == a ? 1 : branch.nodes.size() - 2] : centre;
    std::vector<int> outside;
    for (int n : g.adj[std::size_t(other)]) {
        if (n != inward)
            outside.push_back(n);
    }
    const int polygon = g.polygon[std::size_t(centre)];
    for (int n : outside) {
        if (!contours.boneFits(polygon, g.pos[std::size_t(centre)],
                               g.clearance[std::size_t(centre)], g.pos[std::size_t(n)],
                               g.clearance[std::size_t(n)]))
            return false;
    }
    for (int v : branch.nodes) {
        if (v != centre)
            g.removeNode(v);
    }
    for (int n : outside)
        g.addEdge(centre, n);
    return true;
}

// Junctions joined by a branch shorter than `distance` (or, with `clusters`, inside each
// other's inscribed disk) merge, shortest branch first, so clusters of junctions shrink to
// their widest one step by step; a merge that would take a bone outside is skipped.
void mergeJunctions(DenseGraph &g, double distance, bool clusters, const Contours &contours)
{
    if (!(distance > 0.0) && !clusters)
        return;
    std::vector<std::pair<int, int>> blocked;
    for (;;) {
        std::optional<Branch> shortest;
        for (Branch &b : extractBranches(g)) {
            const std::pair ends{std::min(b.nodes.front(), b.nodes.back()),
                                 std::max(b.nodes.front(), b.nodes.back())};
            if (b.nodes.size() < 2 || !isJunction(g, b.nodes.front()) ||
                !isJunction(g, b.nodes.back()) ||
                (b.length >= distance && !(clusters && isJunctionCluster(g, b))) ||
                std::find(blocked.begin(), blocked.end(), ends) != blocked.end())
                continue;
            if (!shortest || b.length < shortest->length)
                shortest = std::move(b);
        }
        if (!shortest)
            return;
        if (!mergeBranch(g, *shortest, contours))
            blocked.emplace_back(std::min(shortest->nodes.front(), shortest->nodes.back()),
                                 std::max(shortest->nodes.front(), shortest->nodes.back()));
    }
}

void prune(DenseGraph &g, double length)
{
    if (!(length > 0.0))
        return;
    removeTerminalBranches(g, [&](const std::vector<int> &, int, double l) { return l < length; });
}

int nearestJoint(const JointGraph &graph, const std::vector<int> &polygonOf, int polygon,
                 const Eigen::Vector2d &target)
{
    int best = -1;
    for (int j = 0; j < graph.size(); ++j) {
        if ((polygon < 0 || polygonOf[std::size_t(j)] == polygon) &&
            (best < 0 || (graph.pos[std::size_t(j)] - target).squaredNorm() <
                             (graph.pos[std::size_t(best)] - target).squaredNorm()))
            best = j;
    }
    return best;
}

Skeleton rooted(const DenseGraph &bones, const RawSkeleton &raw, const RefineOptions &options)
{
    JointGraph graph;
    std::vector<int> polygonOf, index(std::size_t(bones.size()), -1);
    for (int v = 0; v < bones.size(); ++v) {
        if (bones.alive[std::size_t(v)]) {
            index[std::size_t(v)] =
                graph.add(bones.pos[std::size_t(v)], bones.radius[std::size_t(v)], 0);
            polygonOf.push_back(bones.polygon[std::size_t(v)]);
        }
    }
    for (int v = 0; v < bones.size(); ++v) {
        for (int n : bones.adj[std::size_t(v)])
            graph.connect(index[std::size_t(v)], index[std::size_t(n)]);
    }
    const Eigen::Vector2d target =
        options.rootNear ? *options.rootNear : Eigen::Vector2d(raw.centroid.transpose());
    std::vector<int> roots;
    for (std::size_t p = 0; p < raw.contour.size(); ++p) {
        const Eigen::Vector2d c = regionCentroid(Region{raw.contour[p]}).transpose();
        roots.push_back(options.animatorRig ? thickestJoint(graph, polygonOf, int(p))
                                            : nearestJoint(graph, polygonOf, int(p), c));
    }
    const int root = options.rootNear || !options.animatorRig
                         ? nearestJoint(graph, polygonOf, -1, target)
                         : thickestJoint(graph, polygonOf, -1);
    if (options.animatorRig)
        joinPieces(graph, polygonOf, root, raw.contour);
    return orderedSkeleton(graph, roots, root);
}

// The joints still where a limb's base was put (clean-up after limbJoints may have merged or
// moved some: those are no longer bases). Left empty when there are none.
void markLimbBases(Skeleton &skeleton, const std::vector<Eigen::Vector2d> &bases)
{
    if (bases.empty() || skeleton.jointCount() == 0)
        return;
    std::vector<bool> flags(std::size_t(skeleton.jointCount()), false);
    bool any = false;
    for (int j = 0; j < skeleton.jointCount(); ++j) {
        if (skeleton.parent(j) < 0)
            continue; // a root has no bone into the body to leave out
        const Eigen::Vector2d p = skeleton.joints.row(j).transpose();
        for (const Eigen::Vector2d &b : bases) {
            if ((p - b).norm() <= 1e-9 * (1.0 + b.norm())) {
                flags[std::size_t(j)] = any = true;
                break;
            }
        }
    }
    if (any)
        skeleton.limbBase = std::move(flags);
}

bool validLength(double value)
{
    return value >= 0.0;
} // false for NaN

} // namespace

Expected<Skeleton, GeometryError> refineSkeleton(const RawSkeleton &raw,
                                                 const RefineOptions &options)
{
    if (!validLength(options.boneTolerance) || !validLength(options.mergeDistance) ||
        !validLength(options.pruneLength) || !validLength(options.collapseLength) ||
        (options.rootNear && !options.rootNear->allFinite()))
        return unexpected(GeometryError{GeometryErrorCode::InvalidOptions,
                                        "The skeleton refinement settings are out of range."});
    if (!validRaw(raw))
        return unexpected(GeometryError{GeometryErrorCode::InvalidIndex,
                                        "The stored skeleton is inconsistent; rebuild it."});
    // New bones (merges, collapses) keep at least the outline's simplification and erosion
    // away from it, so they stay inside the drawn shape too, not only inside raw.contour.
    const Contours contours(raw.contour, raw.tolerance + raw.erosion);
    DenseGraph graph = fromRaw(raw);
    prune(graph, options.pruneLength);
    if (options.animatorRig)
        removeCornerSpurs(graph, raw.contour);
    mergeJunctions(graph, options.mergeDistance, options.animatorRig, contours);
    ForcedJoints forced;
    std::vector<Eigen::Vector2d> bases; // where limbs leave the body
    if (options.animatorRig) {
        subdivideLongEdges(graph);
        forced = [&graph, &bases, &raw](const Branch &branch) {
            std::vector<int> at;
            std::vector<int> joints = limbJoints(graph, branch, &at, &raw.contour);
            for (const int i : at)
                bases.push_back(graph.pos[std::size_t(branch.nodes[std::size_t(i)])]);
            return joints;
        };
    }
    DenseGraph bones = bonesFromBranches(graph, options.boneTolerance, contours, forced);
    collapseShortBones(bones, options.collapseLength, options.animatorRig ? kTinyBone : 0.0,
                       contours);
    if (options.animatorRig)
        trimTinyTips(bones, contours);
    Skeleton skeleton = rooted(bones, raw, options);
    markLimbBases(skeleton, bases);
    return skeleton;
}

RefineRanges refineRanges(const RawSkeleton &raw)
{
    RefineRanges ranges;
    if (!validRaw(raw))
        return ranges;
    const DenseGraph graph = fromRaw(raw);
    double clearance = 0.0, jj = 0.0, terminal = 0.0, longest = 0.0;
    for (double c : graph.clearance)
        clearance = std::max(clearance, c);
    for (const Branch &b : extractBranches(graph)) {
        const bool ja = isJunction(graph, b.nodes.front()), jz = isJunction(graph, b.nodes.back());
        if (ja && jz)
            jj = std::max(jj, b.length);
        else if (ja || jz)
            terminal = std::max(terminal, b.length);
        longest = std::max(longest, b.length);
    }
    auto positive = [](double v) { return v > 0.0 ? v : 1.0; };
    ranges.boneTolerance = positive(clearance);
    ranges.mergeDistance = positive(jj);
    ranges.pruneLength = positive(terminal);
    ranges.collapseLength = positive(longest);
    return ranges;
}

Expected<Skeleton, GeometryError> skeletonize(const Region &region,
                                              const SkeletonOptions &skeletonOptions,
                                              const RefineOptions &refineOptions)
{
    const auto raw = rawSkeleton(region, skeletonOptions);
    if (!raw)
        return unexpected(raw.error());
    return refineSkeleton(*raw, refineOptions);
}

} // namespace finbook::geometry
