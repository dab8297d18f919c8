#include "animator_rig.h"

#include "skeleton_contour.h"

#include <finbook/geometry/polyline.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace finbook::geometry::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;
// outlineTurning: within this share of its reach, reflex turns count against convex ones.
constexpr double kNetTurning = 0.5;
// The base of a limb: where the width has come down to within this fraction of the way from
// the body's inscribed radius to the limb's.
constexpr double kBaseDrop = 0.1;
// A limb is narrower than the body when its typical radius is below this fraction of the
// junction's; otherwise the junction itself is the base (a plus sign's arms).
constexpr double kNarrower = 0.8;
// The base is searched this many of the body's radii along the branch from the junction: the
// junction can sit deep in a long body (a horse's withers above its chest and foreleg), so the
// width drops well beyond its own disk. Measured with `finbook-bench limbs` (1: the base often
// in the chest, 3: at the top of the leg; README).
constexpr double kBaseReach = 3.0;
// Two branches from one junction run side by side when their ends lie within this angle
// (radians) of each other, seen from the junction.
constexpr double kSideBySide = kPi / 9.0;
// A limb longer than this many of its radii from its base gets a middle joint.
constexpr double kLongLimb = 6.0;
// A branch runs through a body when its thickest node is this many times its median width.
constexpr double kThickBody = 1.25;
// A limb has left the body where the outline lies within this many of its radii on both
// sides of it. A base where one side's outline lies farther, looked for within kSideAngle of
// the limb's direction as the Cut-out mode looks for a cut's ends (CutOutOptions::sideAngle,
// farReach), is still fused with the body on that side (a tail whose upper part is one with
// the rump); it moves out along the limb to where the outline comes in on both sides, across
// the limb (within kAcross of square to it) and within kSideAngle alike. The sector alone
// would take the outline behind a base near the body's edge for the limb's side.
constexpr double kFusedSide = 3.0;
constexpr double kSideAngle = 0.75 * kPi;
constexpr double kAcross = kPi / 6.0;

double cross2(const Eigen::Vector2d &a, const Eigen::Vector2d &b)
{
    return a.x() * b.y() - a.y() * b.x();
}

// Cumulative arc length along a node path.
std::vector<double> arcLengths(const DenseGraph &g, const std::vector<int> &nodes)
{
    std::vector<double> s(nodes.size(), 0.0);
    for (std::size_t i = 1; i < nodes.size(); ++i)
        s[i] = s[i - 1] + g.length(nodes[i - 1], nodes[i]);
    return s;
}

double median(std::vector<double> v)
{
    if (v.empty())
        return 0.0;
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
}

// The bend of the path at node i: the angle between the directions to the nodes `span` away
// (by arc length) on either side.
double bendAt(const DenseGraph &g, const std::vector<int> &nodes, const std::vector<double> &s,
              std::size_t i, double span)
{
    std::size_t a = i, b = i;
    while (a > 0 && s[i] - s[a] < span)
        --a;
    while (b + 1 < nodes.size() && s[b] - s[i] < span)
        ++b;
    if (a == i || b == i)
        return 0.0;
    const Eigen::Vector2d u = g.pos[std::size_t(nodes[i])] - g.pos[std::size_t(nodes[a])];
    const Eigen::Vector2d w = g.pos[std::size_t(nodes[b])] - g.pos[std::size_t(nodes[i])];
    return std::abs(std::atan2(cross2(u, w), u.dot(w)));
}

// How far the outline lies on either side of direction d at p: the nearest outline point
// within kSideAngle of d (sector) and the nearest hit of rays across d (square to it and
// kAcross either way), each the larger of its two sides (infinity when a side has none).
struct SideReach {
    double sector = 0.0, across = 0.0;
};

SideReach sideReach(const Polygon &contour, const Eigen::Vector2d &p, const Eigen::Vector2d &d)
{
    const Eigen::Vector2d u = d.normalized();
    const double none = std::numeric_limits<double>::infinity();
    double sector[2] = {none, none}, across[2] = {none, none};
    Eigen::Vector2d rays[2][3];
    for (int k = 0; k < 2; ++k)
        for (int r = 0; r < 3; ++r)
            rays[k][r] = Eigen::Rotation2Dd((k == 0 ? 0.5 : -0.5) * kPi + (r - 1) * kAcross) * u;
    const auto consider = [&](const Eigen::Vector2d &q) {
        const Eigen::Vector2d e = q - p;
        const double distance = e.norm(), angle = std::atan2(cross2(u, e), u.dot(e));
        if (distance > 0.0 && std::abs(angle) < kSideAngle)
            sector[angle > 0.0 ? 0 : 1] = std::min(sector[angle > 0.0 ? 0 : 1], distance);
    };
    for (const Eigen::MatrixX2d &ring : regionRings(Region{contour})) {
        const Eigen::Index n = ring.rows();
        for (Eigen::Index i = 0; i < n; ++i) {
            const Eigen::Vector2d a = ring.row(i).transpose();
            const Eigen::Vector2d b = ring.row((i + 1) % n).transpose(), e = b - a;
            consider(nearestOnSegment(p, a, b));
            consider(a);
            for (int k = 0; k < 2; ++k)
                for (const Eigen::Vector2d &ray : rays[k]) {
                    // p + t·ray = a + s·e
                    const double den = cross2(ray, e);
                    if (den == 0.0)
                        continue;
                    const double t = cross2(a - p, e) / den, s = cross2(a - p, ray) / den;
                    if (t > 0.0 && s >= 0.0 && s <= 1.0)
                        across[k] = std::min(across[k], t);
                }
        }
    }
    return {std::max(sector[0], sector[1]), std::max(across[0], across[1])};
}

} // namespace

double outlineTurning(const Polygon &contour, const Eigen::Vector2d &p, double reach)
{
    double best = 0.0, bestDistance = std::numeric_limits<double>::infinity();
    for (const Eigen::MatrixX2d &ring : regionRings(Region{contour})) {
        const Eigen::Index n = ring.rows();
        if (n < 3)
            continue;
        // Holes run the other way round: their convex corners (seen from inside the shape)
        // turn negatively.
        const double sign = signedArea(ring) >= 0.0 ? 1.0 : -1.0;
        double turning = 0.0, nearest = std::numeric_limits<double>::infinity();
        for (Eigen::Index i = 0; i < n; ++i) {
            const Eigen::Vector2d v = ring.row(i).transpose();
            const Eigen::Vector2d a = ring.row((i + n - 1) % n).transpose();
            const Eigen::Vector2d b = ring.row((i + 1) % n).transpose();
            nearest = std::min(nearest, pointSegmentDistance(p, v, b));
            if ((v - p).norm() > reach)
                continue;
            const Eigen::Vector2d u = v - a, w = b - v;
            const double angle = sign * std::atan2(cross2(u, w), u.dot(w));
            // Near the tip a reflex turn counts against the convex ones (the pen's round cap
            // standing out of a corner turns out and back in); further off, where a limb
            // leaves the body, it does not.
            turning += (v - p).norm() <= kNetTurning * reach ? angle : std::max(angle, 0.0);
        }
        if (nearest < bestDistance) {
            bestDistance = nearest;
            best = turning;
        }
    }
    return std::clamp(best, 0.0, 2.0 * kPi);
}

namespace {

// The nodes from `junction` out through its neighbour `first` up to (and including) the first
// node that is not an inner one, and the path's length.
std::vector<int> branchFrom(const DenseGraph &g, int junction, int first, double &length)
{
    std::vector<int> nodes{junction, first};
    length = g.length(junction, first);
    while (g.degree(nodes.back()) == 2 && nodes.size() <= std::size_t(g.size())) {
        const int at = nodes.back(), previous = nodes[nodes.size() - 2];
        const int next = g.adj[std::size_t(at)][0] != previous ? g.adj[std::size_t(at)][0]
                                                               : g.adj[std::size_t(at)][1];
        length += g.length(at, next);
        nodes.push_back(next);
    }
    return nodes;
}

// Whether every node of `path` lies within kInsideDisk inscribed radii of the polyline
// `along` (the radius interpolated along each of its edges): a prong inside the tube of
// another branch.
bool insideTube(const DenseGraph &g, const std::vector<int> &path, const std::vector<int> &along)
{
    for (const int n : path) {
        const Eigen::Vector2d &p = g.pos[std::size_t(n)];
        bool inside = false;
        for (std::size_t i = 0; i + 1 < along.size() && !inside; ++i) {
            const Eigen::Vector2d &a = g.pos[std::size_t(along[i])];
            const Eigen::Vector2d &b = g.pos[std::size_t(along[i + 1])];
            const Eigen::Vector2d ab = b - a;
            const double t = ab.squaredNorm() > 0.0
                                 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0)
                                 : 0.0;
            const double width = (1.0 - t) * g.clearance[std::size_t(along[i])] +
                                 t * g.clearance[std::size_t(along[i + 1])];
            inside = (a + t * ab - p).norm() <= kInsideDisk * width;
        }
        if (!inside)
            return false;
    }
    return true;
}

bool isCornerSpur(const DenseGraph &graph, const Region &contour, const std::vector<int> &path,
                  int junction)
{
    const double r = graph.clearance[std::size_t(junction)];
    const Eigen::Vector2d &c = graph.pos[std::size_t(junction)];
    double reach = 0.0, length = 0.0;
    std::vector<double> widths;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const int n = path[i];
        reach = std::max(reach,
                         (graph.pos[std::size_t(n)] - c).norm() + graph.clearance[std::size_t(n)]);
        widths.push_back(graph.clearance[std::size_t(n)]);
        length += graph.length(n, i + 1 < path.size() ? path[i + 1] : junction);
    }
    if (reach <= kInsideDisk * r)
        return true;
    if (length >= kSpurLength * r) {
        // A long prong running alongside a longer sibling that ends in a tip too, inside its
        // tube: the wide end of a tail splits the skeleton into two branches a radius apart,
        // one reaching a notch at a corner.
        const Eigen::Vector2d out = graph.pos[std::size_t(path.front())] - c;
        for (const int first : graph.adj[std::size_t(junction)]) {
            if (first == path.back())
                continue;
            double siblingLength = 0.0;
            const std::vector<int> sibling = branchFrom(graph, junction, first, siblingLength);
            const Eigen::Vector2d along = graph.pos[std::size_t(sibling.back())] - c;
            if (graph.degree(sibling.back()) == 1 && siblingLength > length &&
                std::abs(std::atan2(cross2(out, along), out.dot(along))) < kSideBySide &&
                insideTube(graph, path, sibling))
                return true;
        }
        return false;
    }
    const int tip = path.front();
    const int polygon = graph.polygon[std::size_t(tip)];
    if (polygon < 0 || std::size_t(polygon) >= contour.size())
        return false;
    // Around the tip, as far as the branch is wide: the whole cap of a limb.
    const double around = 2.0 * std::max({graph.clearance[std::size_t(tip)], median(widths), 1e-9});
    return outlineTurning(contour[std::size_t(polygon)], graph.pos[std::size_t(tip)], around) <
           kTipTurning;
}

} // namespace

void removeCornerSpurs(DenseGraph &graph, const Region &contour)
{
    // All spurs of a junction go at once: a box's two corner spurs at one end both go, where
    // one at a time would leave the second one part of a longer branch.
    for (;;) {
        std::vector<std::pair<int, std::vector<int>>> spurs; // junction, path
        for (int v = 0; v < graph.size(); ++v) {
            if (!graph.alive[std::size_t(v)] || graph.degree(v) != 1)
                continue;
            int junction = -1;
            std::vector<int> path = terminalPath(graph, v, junction);
            if (junction >= 0 && isCornerSpur(graph, contour, path, junction))
                spurs.emplace_back(junction, std::move(path));
        }
        if (spurs.empty())
            return;
        // A junction keeps its longest branch when every branch of it is a spur.
        std::sort(spurs.begin(), spurs.end(), [](const auto &a, const auto &b) {
            return a.first != b.first ? a.first < b.first : a.second.size() > b.second.size();
        });
        for (std::size_t i = 0; i < spurs.size();) {
            std::size_t end = i;
            while (end < spurs.size() && spurs[end].first == spurs[i].first)
                ++end;
            const bool all = int(end - i) >= graph.degree(spurs[i].first);
            for (std::size_t k = all ? i + 1 : i; k < end; ++k) {
                for (int n : spurs[k].second)
                    graph.removeNode(n);
            }
            i = end;
        }
    }
}

bool isJunctionCluster(const DenseGraph &graph, const Branch &branch)
{
    const int a = branch.nodes.front(), z = branch.nodes.back();
    return branch.length <
           std::max(graph.clearance[std::size_t(a)], graph.clearance[std::size_t(z)]);
}

namespace {

// limbJoints for nodes[0] the body end (a junction, or the thickest node of a branch between
// two tips or running through a body) and nodes.back() the tip: positions into `nodes`.
// The joints of a limb hanging from nodes.front(); *baseOut is the base among them (0: none).
// The base is the first node from the body that is narrow enough, or with `fromTip` the near
// end of the narrow run at the tip.
std::vector<int> limbJointsFrom(const DenseGraph &g, const std::vector<int> &nodes, int *baseOut,
                                bool fromTip, const Polygon *contour)
{
    *baseOut = 0;
    const int m = int(nodes.size());
    if (m < 3)
        return {};
    const std::vector<double> s = arcLengths(g, nodes);
    const double length = s.back();
    const double body = g.clearance[std::size_t(nodes.front())];
    std::vector<double> outer;
    for (int i = 1; i + 1 < m; ++i) {
        if (s[std::size_t(i)] >= std::max(body, length / 3.0))
            outer.push_back(g.clearance[std::size_t(nodes[std::size_t(i)])]);
    }
    const double limb =
        outer.empty() ? g.clearance[std::size_t(nodes[std::size_t(m - 2)])] : median(outer);
    std::vector<int> kept;
    int base = 0;
    if (limb < kNarrower * body) {
        const double level = limb + kBaseDrop * (body - limb);
        if (fromTip) {
            // The near end of the narrow run at the tip: the width on the body's side can dip
            // and rise again where the branch skirts the body's outline.
            for (int i = m - 2; i >= 1; --i) {
                if (g.clearance[std::size_t(nodes[std::size_t(i)])] > level)
                    break;
                base = i;
            }
        } else {
            for (int i = 1; i + 1 < m; ++i) {
                if (g.clearance[std::size_t(nodes[std::size_t(i)])] <= level ||
                    s[std::size_t(i)] >= kBaseReach * body) {
                    base = i;
                    break;
                }
            }
        }
        // Not inside the junction's own disk centre, and with a limb left beyond it.
        const auto leavesRoom = [&](int i) { return length - s[std::size_t(i)] >= 1.5 * limb; };
        if (base > 0 && (s[std::size_t(base)] < 0.5 * body || !leavesRoom(base)))
            base = 0;
        // Out along the limb to where the outline comes in on both sides.
        const auto reach = [&](int i) {
            int ahead = i + 1;
            while (ahead + 1 < m && s[std::size_t(ahead)] - s[std::size_t(i)] < 2.0 * limb)
                ++ahead;
            const Eigen::Vector2d &p = g.pos[std::size_t(nodes[std::size_t(i)])];
            const Eigen::Vector2d d = g.pos[std::size_t(nodes[std::size_t(ahead)])] - p;
            const double width = kFusedSide * g.clearance[std::size_t(nodes[std::size_t(i)])];
            const SideReach side = d.norm() > 0.0 ? sideReach(*contour, p, d) : SideReach{};
            return std::pair{side.sector <= width, side.sector <= width && side.across <= width};
        };
        if (base > 0 && contour && !reach(base).first) {
            for (int i = base + 1; i + 1 < m && leavesRoom(i); ++i) {
                if (reach(i).second) {
                    base = i;
                    break;
                }
            }
        }
        if (base > 0)
            kept.push_back(base);
    }
    *baseOut = base;
    const double limbLength = length - s[std::size_t(base)];
    if (limb > 0.0 && limbLength > kLongLimb * limb) {
        // The middle third of the limb: the sharpest bend if it bends, else the narrowest
        // place if it narrows, else half way.
        const double lo = s[std::size_t(base)] + limbLength / 3.0;
        const double hi = s[std::size_t(base)] + 2.0 * limbLength / 3.0;
        int bend = -1, narrow = -1, middle = -1;
        double bendAngle = 0.0, narrowest = std::numeric_limits<double>::infinity();
        for (int i = base + 1; i + 1 < m; ++i) {
            const double si = s[std::size_t(i)];
            if (si < lo || si > hi)
                continue;
            const double angle = bendAt(g, nodes, s, std::size_t(i), limb);
            if (angle > bendAngle) {
                bendAngle = angle;
                bend = i;
            }
            const double c = g.clearance[std::size_t(nodes[std::size_t(i)])];
            if (c < narrowest) {
                narrowest = c;
                narrow = i;
            }
            if (middle < 0 ||
                std::abs(si - 0.5 * (lo + hi)) < std::abs(s[std::size_t(middle)] - 0.5 * (lo + hi)))
                middle = i;
        }
        const int chosen = bendAngle > kPi / 12.0 ? bend : narrowest < 0.8 * limb ? narrow : middle;
        if (chosen > 0)
            kept.push_back(chosen);
    }
    return kept;
}

} // namespace

std::vector<int> limbJoints(const DenseGraph &g, const Branch &branch, std::vector<int> *bases,
                            const Region *contour)
{
    const std::vector<int> &nodes = branch.nodes;
    const int m = int(nodes.size());
    if (m < 3)
        return {};
    const int front = g.degree(nodes.front()), back = g.degree(nodes.back());
    std::vector<int> kept;
    // The limb hanging from nodes[from] out to the end `forward` points at (true: the back).
    const auto limbFrom = [&](int from, bool forward, bool fromTip) {
        const int step = forward ? 1 : -1;
        std::vector<int> path;
        for (int i = from; i >= 0 && i < m; i += step)
            path.push_back(nodes[std::size_t(i)]);
        int base = 0;
        const int polygon = g.polygon[std::size_t(nodes[std::size_t(from)])];
        const Polygon *outline = contour && polygon >= 0 && std::size_t(polygon) < contour->size()
                                     ? &(*contour)[std::size_t(polygon)]
                                     : nullptr;
        for (const int k : limbJointsFrom(g, path, &base, fromTip, outline))
            kept.push_back(from + step * k);
        if (base > 0 && bases)
            bases->push_back(from + step * base);
    };
    // The thickest node, and whether it is clearly thicker than the branch typically is (a
    // body along the branch).
    int thick = 0;
    std::vector<double> widths;
    for (int i = 0; i < m; ++i) {
        widths.push_back(g.clearance[std::size_t(nodes[std::size_t(i)])]);
        if (widths.back() > widths[std::size_t(thick)])
            thick = i;
    }
    const bool body = widths[std::size_t(thick)] >= kThickBody * median(widths);
    const bool inner = thick > 0 && thick < m - 1;
    if ((front >= 3 && back == 1) || (back >= 3 && front == 1)) {
        // From a junction to a tip. Where the branch runs through a body clearly thicker than
        // the junction (a loop round a hole broken at the tip: a guitar's neck in two strips),
        // the limb hangs from that body, not from the junction.
        const bool forward = front >= 3;
        const int junction = forward ? 0 : m - 1;
        if (body && inner &&
            widths[std::size_t(thick)] * kNarrower > widths[std::size_t(junction)]) {
            kept.push_back(thick);
            limbFrom(thick, forward, true);
        } else {
            limbFrom(junction, forward, false);
        }
    } else if (front == 1 && back == 1) {
        // Two tips: a body at one end or in the middle; each side of it is a limb from it.
        if (!body)
            return {};
        if (inner)
            kept.push_back(thick);
        limbFrom(thick, true, false);
        limbFrom(thick, false, false);
    }
    std::sort(kept.begin(), kept.end());
    return kept;
}

void trimTinyTips(DenseGraph &bones, const Contours &contours)
{
    for (int v = 0; v < bones.size(); ++v) {
        if (!bones.alive[std::size_t(v)] || bones.degree(v) != 1)
            continue;
        const int inner = bones.adj[std::size_t(v)].front();
        if (bones.degree(inner) != 2 ||
            bones.length(v, inner) >= 0.5 * bones.clearance[std::size_t(inner)])
            continue;
        const int outer = bones.adj[std::size_t(inner)][0] == v ? bones.adj[std::size_t(inner)][1]
                                                                : bones.adj[std::size_t(inner)][0];
        if (!contours.segmentInside(bones.polygon[std::size_t(v)], bones.pos[std::size_t(outer)],
                                    bones.pos[std::size_t(v)]))
            continue;
        bones.pos[std::size_t(inner)] = bones.pos[std::size_t(v)];
        bones.radius[std::size_t(inner)] = bones.radius[std::size_t(v)];
        bones.clearance[std::size_t(inner)] = bones.clearance[std::size_t(v)];
        bones.removeNode(v);
    }
}

void subdivideLongEdges(DenseGraph &graph)
{
    const int n = graph.size();
    for (int a = 0; a < n; ++a) {
        const std::vector<int> neighbours = graph.adj[std::size_t(a)];
        for (int b : neighbours) {
            if (b < a || !graph.alive[std::size_t(a)])
                continue;
            const double width =
                std::min(graph.clearance[std::size_t(a)], graph.clearance[std::size_t(b)]);
            const double length = graph.length(a, b);
            const int pieces = width > 0.0 ? int(std::min(64.0, std::floor(length / width))) : 1;
            if (pieces < 2)
                continue;
            graph.removeEdge(a, b);
            int previous = a;
            for (int k = 1; k < pieces; ++k) {
                const double t = double(k) / pieces;
                auto lerp = [&](const std::vector<double> &v) {
                    return (1.0 - t) * v[std::size_t(a)] + t * v[std::size_t(b)];
                };
                const int v = graph.addNode(
                    (1.0 - t) * graph.pos[std::size_t(a)] + t * graph.pos[std::size_t(b)],
                    lerp(graph.radius), lerp(graph.clearance), graph.polygon[std::size_t(a)]);
                graph.addEdge(previous, v);
                previous = v;
            }
            graph.addEdge(previous, b);
        }
    }
}

} // namespace finbook::geometry::detail
