// assembleCharacter (skeleton_connect.h): all parts in one joint graph, each join resolved
// against the graph as it stands (so two parts hanging from one bone split it twice).
#include "skeleton_tree.h"

#include <finbook/geometry/skeleton/skeleton_connect.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace finbook::geometry {
namespace {

using namespace detail;

// A child joint this close to its parent joint (relative to their radii) merges into it
// instead of hanging from it by a stub of a bone.
constexpr double kMergeFraction = 0.1;

GeometryError badJoin(const std::string &why)
{
    return GeometryError{GeometryErrorCode::InvalidIndex, "The parts cannot be joined: " + why};
}

struct Assembly {
    JointGraph graph;
    std::vector<char> alive;

    // The bone (a, b) of `part` nearest q and the parameter of q's projection; a == b for a
    // part without bones (its nearest joint).
    void nearest(int part, const Eigen::Vector2d &q, int &a, int &b, double &t) const
    {
        double best = std::numeric_limits<double>::infinity();
        a = b = -1;
        t = 0.0;
        for (int v = 0; v < graph.size(); ++v) {
            if (!alive[std::size_t(v)] || graph.part[std::size_t(v)] != part)
                continue;
            for (int n : graph.adj[std::size_t(v)]) {
                if (n < v || graph.part[std::size_t(n)] != part)
                    continue;
                const Eigen::Vector2d &p0 = graph.pos[std::size_t(v)];
                const Eigen::Vector2d d = graph.pos[std::size_t(n)] - p0;
                const double s = d.squaredNorm() > 0.0
                                     ? std::clamp((q - p0).dot(d) / d.squaredNorm(), 0.0, 1.0)
                                     : 0.0;
                const double dist = (q - (p0 + s * d)).norm();
                if (dist < best) {
                    best = dist;
                    a = v;
                    b = n;
                    t = s;
                }
            }
        }
        if (a >= 0)
            return;
        for (int v = 0; v < graph.size(); ++v) {
            if (alive[std::size_t(v)] && graph.part[std::size_t(v)] == part &&
                (graph.pos[std::size_t(v)] - q).norm() < best) {
                best = (graph.pos[std::size_t(v)] - q).norm();
                a = b = v;
            }
        }
    }

    // The joint of `part` where q attaches: the nearer end of the nearest bone, or a new
    // joint splitting it when q projects well inside.
    int attach(int part, const Eigen::Vector2d &q, double endFraction, bool &split)
    {
        int a = -1, b = -1;
        double t = 0.0;
        nearest(part, q, a, b, t);
        split = false;
        if (a == b)
            return a;
        if (t <= endFraction)
            return a;
        if (t >= 1.0 - endFraction)
            return b;
        const std::size_t ia = std::size_t(a), ib = std::size_t(b);
        const int added = graph.add((1.0 - t) * graph.pos[ia] + t * graph.pos[ib],
                                    (1.0 - t) * graph.radius[ia] + t * graph.radius[ib], part);
        alive.push_back(1);
        graph.disconnect(a, b);
        graph.connect(a, added);
        graph.connect(added, b);
        split = true;
        return added;
    }

    // Connects child below parent, or merges it into parent when they coincide; joins
    // resolved earlier that named the merged joint follow it.
    void hang(int child, int parent, std::vector<ResolvedJoin> &resolved)
    {
        const std::size_t c = std::size_t(child), p = std::size_t(parent);
        const double close = kMergeFraction * std::min(graph.radius[c], graph.radius[p]);
        if ((graph.pos[c] - graph.pos[p]).norm() > close) {
            graph.connect(parent, child);
            return;
        }
        const std::vector<int> neighbours = graph.adj[c];
        for (int n : neighbours) {
            graph.disconnect(child, n);
            graph.connect(parent, n);
        }
        alive[c] = 0;
        for (ResolvedJoin &r : resolved) {
            if (r.joint == child)
                r.joint = parent;
        }
    }
};

bool hasJoints(const std::vector<Skeleton> &parts, int p)
{
    return p >= 0 && std::size_t(p) < parts.size() && parts[std::size_t(p)].jointCount() > 0;
}

// Every part's joints and bones in one graph; offset[p] is part p's first joint.
Expected<Assembly, GeometryError> gather(const std::vector<Skeleton> &parts,
                                         std::vector<int> &offset)
{
    Assembly assembly;
    for (std::size_t p = 0; p < parts.size(); ++p) {
        const Skeleton &s = parts[p];
        if (!isValidSkeleton(s))
            return unexpected(badJoin("part " + std::to_string(p + 1) + " has no valid skeleton."));
        offset.push_back(assembly.graph.size());
        for (int j = 0; j < s.jointCount(); ++j)
            assembly.graph.add(s.joints.row(j).transpose(), s.radius(j), int(p));
        for (int j = 0; j < s.jointCount(); ++j) {
            if (s.parent(j) >= 0)
                assembly.graph.connect(offset.back() + j, offset.back() + s.parent(j));
        }
    }
    assembly.alive.assign(std::size_t(assembly.graph.size()), 1);
    return assembly;
}

// Tree roots in order of preference: the character root, the roots of parts that hang from
// nothing, then the others' (a hanging part's tree is its parent's, so theirs come last).
std::vector<int> preferredRoots(const std::vector<Skeleton> &parts, const std::vector<int> &offset,
                                const std::vector<char> &isChild, int rootPart)
{
    std::vector<int> roots;
    if (parts[std::size_t(rootPart)].root >= 0)
        roots.push_back(offset[std::size_t(rootPart)] + parts[std::size_t(rootPart)].root);
    for (int pass = 0; pass < 2; ++pass) {
        for (std::size_t p = 0; p < parts.size(); ++p) {
            if ((isChild[p] != 0) != (pass == 1))
                continue;
            for (int r : skeletonRoots(parts[p]))
                roots.push_back(offset[p] + r);
        }
    }
    return roots;
}

} // namespace

Expected<Character, GeometryError> assembleCharacter(const std::vector<Skeleton> &parts,
                                                     const std::vector<PartJoin> &joins,
                                                     int rootPart, const JoinOptions &options)
{
    if (!(options.endFraction >= 0.0 && options.endFraction < 0.5))
        return unexpected(GeometryError{GeometryErrorCode::InvalidOptions,
                                        "The join settings are out of range."});
    if (rootPart < 0 || std::size_t(rootPart) >= parts.size())
        return unexpected(badJoin("the character root is not one of the parts."));
    std::vector<int> offset;
    auto gathered = gather(parts, offset);
    if (!gathered)
        return unexpected(gathered.error());
    Assembly &assembly = *gathered;
    std::vector<int> group(parts.size());
    std::iota(group.begin(), group.end(), 0);
    auto find = [&](int v) {
        while (group[std::size_t(v)] != v)
            v = group[std::size_t(v)] = group[std::size_t(group[std::size_t(v)])];
        return v;
    };
    std::vector<char> isChild(parts.size(), 0);
    std::vector<ResolvedJoin> resolved;
    for (const PartJoin &join : joins) {
        if (!hasJoints(parts, join.child) || !hasJoints(parts, join.parent))
            return unexpected(badJoin("a join names a part without a skeleton."));
        if (!join.childAt.allFinite() || !join.parentAt.allFinite())
            return unexpected(
                GeometryError{GeometryErrorCode::InvalidOptions, "A join point is not a number."});
        if (join.child == rootPart || isChild[std::size_t(join.child)] ||
            find(join.child) == find(join.parent))
            return unexpected(badJoin("a part would hang from two places or from itself."));
        isChild[std::size_t(join.child)] = 1;
        group[std::size_t(find(join.child))] = find(join.parent);
        bool childSplit = false, parentSplit = false;
        const int c = assembly.attach(join.child, join.childAt, options.endFraction, childSplit);
        const int s = assembly.attach(join.parent, join.parentAt, options.endFraction, parentSplit);
        assembly.hang(c, s, resolved);
        resolved.push_back({join.child, join.parent,
                            parentSplit ? JoinKind::BoneSplit : JoinKind::JointConnect, s});
    }
    std::vector<int> map, liveRoots, index;
    const JointGraph compact = keptJoints(assembly.graph, assembly.alive, map);
    for (int r : preferredRoots(parts, offset, isChild, rootPart)) {
        if (map[std::size_t(r)] >= 0)
            liveRoots.push_back(map[std::size_t(r)]);
    }
    Character character;
    character.skeleton =
        orderedSkeleton(compact, liveRoots, liveRoots.empty() ? -1 : liveRoots.front(), &index);
    for (ResolvedJoin &r : resolved)
        r.joint = index[std::size_t(map[std::size_t(r.joint)])];
    character.joins = std::move(resolved);
    return character;
}

} // namespace finbook::geometry
