#include "skeleton_tree.h"

#include <finbook/geometry/skeleton/skeleton_connect.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace finbook::geometry {
namespace {

using namespace detail;

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// The nearest point to q on a segment a–b: parameter t ∈ [0, 1] and distance.
double project(const Eigen::Vector2d &q, const Eigen::Vector2d &a, const Eigen::Vector2d &b,
               double &t)
{
    const Eigen::Vector2d ab = b - a;
    const double len2 = ab.squaredNorm();
    t = len2 > 0.0 ? std::clamp((q - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (q - (a + t * ab)).norm();
}

// Crossing point of segments a–b and c–d, if they cross.
std::optional<Eigen::Vector2d> crossing(const Eigen::Vector2d &a, const Eigen::Vector2d &b,
                                        const Eigen::Vector2d &c, const Eigen::Vector2d &d)
{
    const Eigen::Vector2d r = b - a, s = d - c;
    const double denom = r.x() * s.y() - r.y() * s.x();
    if (denom == 0.0)
        return std::nullopt;
    const Eigen::Vector2d ac = c - a;
    const double t = (ac.x() * s.y() - ac.y() * s.x()) / denom;
    const double u = (ac.x() * r.y() - ac.y() * r.x()) / denom;
    if (t < 0.0 || t > 1.0 || u < 0.0 || u > 1.0)
        return std::nullopt;
    return a + t * r;
}

// Cylinder–ball test of q against every bone of `parent` (or its joints' balls when it has
// no bones): the smallest distance / interpolated radius, and the point it projects to.
double depthIn(const Skeleton &parent, const Eigen::Vector2d &q, Eigen::Vector2d &at)
{
    double best = kUnbounded;
    auto consider = [&](double d, double r, const Eigen::Vector2d &p) {
        const double ratio = r > 0.0 ? d / r : (d > 0.0 ? kUnbounded : 0.0);
        if (ratio < best) {
            best = ratio;
            at = p;
        }
    };
    for (int j = 0; j < parent.jointCount(); ++j) {
        const int p = parent.parent(j);
        if (p < 0) {
            consider((q - parent.joints.row(j).transpose()).norm(), parent.radius(j),
                     parent.joints.row(j).transpose());
            continue;
        }
        const Eigen::Vector2d a = parent.joints.row(p).transpose(),
                              b = parent.joints.row(j).transpose();
        double t = 0.0;
        const double d = project(q, a, b, t);
        consider(d, (1.0 - t) * parent.radius(p) + t * parent.radius(j), a + t * (b - a));
    }
    return best;
}

struct Attachment {
    PartJoin join;
    double depth = kUnbounded;
};

Attachment bestJoin(int childPart, const Skeleton &child, int parentPart, const Skeleton &parent)
{
    std::vector<Eigen::Vector2d> points;
    // Crossings first: a child bone that runs through a parent bone attaches right there.
    for (int j = 0; j < child.jointCount(); ++j) {
        if (child.parent(j) < 0)
            continue;
        for (int k = 0; k < parent.jointCount(); ++k) {
            if (parent.parent(k) < 0)
                continue;
            if (const auto x = crossing(child.joints.row(child.parent(j)).transpose(),
                                        child.joints.row(j).transpose(),
                                        parent.joints.row(parent.parent(k)).transpose(),
                                        parent.joints.row(k).transpose()))
                points.push_back(*x);
        }
    }
    for (int j = 0; j < child.jointCount(); ++j)
        points.push_back(child.joints.row(j).transpose());
    Attachment best;
    for (const Eigen::Vector2d &q : points) {
        Eigen::Vector2d at;
        const double depth = depthIn(parent, q, at);
        if (depth <= 1.0 && depth < best.depth)
            best = {PartJoin{childPart, parentPart, q, at}, depth};
    }
    // The other way round: a parent joint inside a child bone (a wide part laid over the end
    // of a thin one) joins them too, at that joint.
    for (int k = 0; k < parent.jointCount(); ++k) {
        const Eigen::Vector2d q = parent.joints.row(k).transpose();
        Eigen::Vector2d at;
        const double depth = depthIn(child, q, at);
        if (depth <= 1.0 && depth < best.depth)
            best = {PartJoin{childPart, parentPart, at, q}, depth};
    }
    return best;
}

} // namespace

std::optional<PartJoin> findJoin(int childPart, const Skeleton &child, int parentPart,
                                 const Skeleton &parent)
{
    const Attachment c = bestJoin(childPart, child, parentPart, parent);
    if (!(c.depth <= 1.0))
        return std::nullopt;
    return c.join;
}

std::vector<PartJoin> findJoins(const std::vector<Skeleton> &parts, int rootPart)
{
    std::vector<PartJoin> joins;
    if (rootPart < 0 || std::size_t(rootPart) >= parts.size())
        return joins;
    std::vector<char> attached(parts.size(), 0);
    attached[std::size_t(rootPart)] = 1;
    for (;;) {
        Attachment best;
        for (std::size_t c = 0; c < parts.size(); ++c) {
            for (std::size_t p = 0; p < parts.size() && !attached[c]; ++p) {
                if (!attached[p])
                    continue;
                const Attachment candidate = bestJoin(int(c), parts[c], int(p), parts[p]);
                if (candidate.depth < best.depth)
                    best = candidate;
            }
        }
        if (!(best.depth <= 1.0))
            return joins;
        attached[std::size_t(best.join.child)] = 1;
        joins.push_back(best.join);
    }
}

} // namespace finbook::geometry
