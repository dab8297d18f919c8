// Cut-out joints: where to cut, which triangles lie past each cut, and the cut mesh with the
// vertices along the cuts copied per piece (cut_out.h).
#include "skeleton_internal.h"

#include <finbook/deform/skeleton/cut_out.h>
#include <finbook/geometry/mesh_boundary.h>
#include <finbook/geometry/polyline.h>
#include <finbook/geometry/region.h>

#include <queue>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <string>
#include <tuple>
#include <unordered_map>

namespace finbook::deform {
namespace {

using Vec = Eigen::Vector2d;

// Vertices this close to a cut (in inscribed radii of its joint) lie on it: a cut ending on an
// outline vertex passes through that vertex to round-off (its end is placed 1e-6 radii past).
constexpr double kOnCut = 1e-9;

double cross(const Vec &a, const Vec &b)
{
    return a.x() * b.y() - a.y() * b.x();
}

// Whether segments p–q and a–b share a point (touching counts).
bool segmentsMeet(const Vec &p, const Vec &q, const Vec &a, const Vec &b)
{
    const double d1 = cross(b - a, p - a), d2 = cross(b - a, q - a);
    const double d3 = cross(q - p, a - p), d4 = cross(q - p, b - p);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return true;
    const auto onSegment = [](const Vec &s, const Vec &e, const Vec &x) {
        return x.x() >= std::min(s.x(), e.x()) && x.x() <= std::max(s.x(), e.x()) &&
               x.y() >= std::min(s.y(), e.y()) && x.y() <= std::max(s.y(), e.y());
    };
    return (d1 == 0 && onSegment(a, b, p)) || (d2 == 0 && onSegment(a, b, q)) ||
           (d3 == 0 && onSegment(p, q, a)) || (d4 == 0 && onSegment(p, q, b));
}

// One key per undirected edge {a, b} of a mesh of n vertices.
long long edgeKey(Eigen::Index n, int a, int b)
{
    return (long long)std::min(a, b) * (long long)n + (long long)std::max(a, b);
}

struct MeshGraph {
    std::vector<std::pair<int, int>> boundary; // edges of one triangle
    std::vector<std::vector<int>> neighbours;  // vertex adjacency
    std::vector<Eigen::VectorXi> holes;        // outline loops running against the triangles
};

MeshGraph meshGraph(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F)
{
    const Eigen::Index n = V.rows();
    std::unordered_map<long long, int> count;
    count.reserve(std::size_t(F.rows()) * 3);
    MeshGraph g;
    g.neighbours.resize(std::size_t(n));
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const int a = F(t, k), b = F(t, (k + 1) % 3);
            if (count[edgeKey(n, a, b)]++ == 0) {
                g.neighbours[std::size_t(a)].push_back(b);
                g.neighbours[std::size_t(b)].push_back(a);
            }
        }
    }
    // The triangles' orientation (twice their signed area), against each loop's.
    double triangles = 0.0;
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        const Eigen::RowVector2d &a = V.row(F(t, 0));
        const Eigen::RowVector2d u = V.row(F(t, 1)) - a, w = V.row(F(t, 2)) - a;
        triangles += u.x() * w.y() - u.y() * w.x();
    }
    for (const Eigen::VectorXi &loop : geometry::boundaryLoops(F)) {
        for (Eigen::Index i = 0; i < loop.size(); ++i)
            g.boundary.emplace_back(loop(i), loop((i + 1) % loop.size()));
        if (geometry::signedArea(V(loop, Eigen::all)) * triangles < 0.0)
            g.holes.push_back(loop);
    }
    return g;
}

double angleOf(const Vec &v)
{
    return std::atan2(v.y(), v.x());
}

// The angle from `from` to `to`, counter-clockwise, in [0, 2π).
double ccw(double from, double to)
{
    const double d = std::fmod(to - from, 2.0 * M_PI);
    return d < 0.0 ? d + 2.0 * M_PI : d;
}

// The outline point nearest p in the counter-clockwise sector of directions from angle `from`
// spanning `span` (ends excluded): each outline edge's point nearest p, or an end of it, where
// that lies in the sector. Infinite distance where there is none.
struct Contact {
    double distance = std::numeric_limits<double>::infinity();
    Vec point = Vec::Zero();
};

Contact nearestInSector(const Eigen::MatrixX2d &V, const MeshGraph &g, const Vec &p, double from,
                        double span)
{
    Contact out;
    const auto consider = [&](const Vec &q) {
        const double distance = (q - p).norm();
        if (distance >= out.distance || distance == 0.0)
            return;
        const double turn = ccw(from, angleOf(q - p));
        if (turn > 0.0 && turn < span) {
            out.distance = distance;
            out.point = q;
        }
    };
    for (const auto &[a, b] : g.boundary) {
        const Vec s = V.row(a).transpose(), e = V.row(b).transpose();
        const Vec se = e - s;
        const double length2 = se.squaredNorm();
        const double t = length2 > 0.0 ? std::clamp((p - s).dot(se) / length2, 0.0, 1.0) : 0.0;
        consider(s + t * se);
        consider(s);
    }
    return out;
}

// Whether x lies in the limb's sector of the cut a → pivot → b: the one of the two angular
// sectors between the directions to a and to b that holds `outward`.
bool pastCut(const Vec &x, const Vec &pivot, const Vec &a, const Vec &b, const Vec &outward)
{
    const auto angle = angleOf;
    const double fromB = angle(b - pivot), span = ccw(fromB, angle(a - pivot));
    const bool outwardInside = ccw(fromB, angle(outward)) < span;
    return (ccw(fromB, angle(x - pivot)) < span) == outwardInside;
}

// The vertex of a triangle nearest `target` among those where `ok` holds, or −1.
int nearestWhere(const Eigen::MatrixX2d &V, const MeshGraph &g, const Vec &target,
                 const std::function<bool(const Vec &)> &ok)
{
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        if (g.neighbours[std::size_t(v)].empty())
            continue;
        const Vec p = V.row(v).transpose();
        const double d = (p - target).squaredNorm();
        if (d < bestDistance && ok(p)) {
            bestDistance = d;
            best = int(v);
        }
    }
    return best;
}

// A line across the shape that no flood crosses: where the skeleton's tree was cut open round
// a hole (a → middle → b, each end a hair past the outline).
struct Barrier {
    Vec a, middle, b;
    bool meets(const Vec &p, const Vec &q) const
    {
        return segmentsMeet(p, q, a, middle) || segmentsMeet(p, q, middle, b);
    }
};

// The vertices past the cut a → pivot → b (flooded from `seed` along edges that do not meet
// it nor a barrier), or empty when the flood reaches a vertex marked in `stop` (the cut does not
// separate). A vertex on the cut (within `onCut`) is not flooded through: a cut that ends on an
// outline vertex, such as the tip of the slit between two limbs, would otherwise leak round it
// along an edge leaving that vertex almost along the cut (an octopus arm whose slits end in a sharp
// V was left uncut, and its turn dragged the body with it).
std::vector<char> floodPast(const Eigen::MatrixX2d &V, const MeshGraph &g, const Vec &a,
                            const Vec &pivot, const Vec &b, int seed, const std::vector<char> &stop,
                            double onCut, const std::vector<Barrier> &barriers)
{
    const auto isOnCut = [&](const Vec &x) {
        return std::min(detail::squaredSegmentDistance(x, a, pivot),
                        detail::squaredSegmentDistance(x, pivot, b)) <= onCut * onCut;
    };
    std::vector<char> past(std::size_t(V.rows()), 0);
    std::vector<int> stack{seed};
    past[std::size_t(seed)] = 1;
    while (!stack.empty()) {
        const int v = stack.back();
        stack.pop_back();
        if (stop[std::size_t(v)])
            return {};
        const Vec p = V.row(v).transpose();
        for (const int u : g.neighbours[std::size_t(v)]) {
            const Vec q = V.row(u).transpose();
            if (past[std::size_t(u)] || segmentsMeet(p, q, a, pivot) ||
                segmentsMeet(p, q, pivot, b) || isOnCut(q) ||
                std::any_of(barriers.begin(), barriers.end(),
                            [&](const Barrier &line) { return line.meets(p, q); }))
                continue;
            past[std::size_t(u)] = 1;
            stack.push_back(u);
        }
    }
    return past;
}

// A ring's break: the straight skeleton of a shape with a hole runs round it in a loop, which
// the skeleton cuts open where the shape is thinnest (geometry::rawSkeleton), leaving a tip
// there that is no end of the shape. Such a tip has a joint within kRingGap of their inscribed
// radii (summed) of it through the mesh but kRingDetour times as far along the bones, and the
// loop the bones between them and that short way make goes round a hole. Each hole is broken
// once: at the pair closest for their radii. Measured on ../shared/data (finbook-bench
// limbs): the guitar's neck closes 0.9 radii apart, the deer's antlers 1.5 and 2.5; joints of
// the deer and an angel that are close through a wide part of the shape go round no hole.
constexpr double kRingGap = 3.0;
constexpr double kRingDetour = 3.0;

// The barriers across each ring's break, at its tip.
std::vector<Barrier> ringBreaks(const Eigen::MatrixX2d &V, const MeshGraph &g,
                                const Skeleton &skeleton, const Eigen::VectorXd &radius,
                                const std::vector<int> &nearestVertex,
                                const detail::ChildLists &children)
{
    std::vector<Barrier> out;
    const int count = skeleton.jointCount();
    if (g.holes.empty() || count < 3)
        return out;
    std::vector<std::vector<int>> bones(static_cast<std::size_t>(count));
    for (int j = 0; j < count; ++j)
        if (skeleton.parent(j) >= 0) {
            bones[std::size_t(j)].push_back(skeleton.parent(j));
            bones[std::size_t(skeleton.parent(j))].push_back(j);
        }
    const auto jointAt = [&](int j) { return Vec(skeleton.joints.row(j).transpose()); };
    struct Pair {
        double gap;
        int tip, beyond;
        std::vector<int> path; // the bones' way from tip to beyond
    };
    std::vector<Pair> pairs;
    for (int t = 0; t < count; ++t) {
        if (skeleton.parent(t) < 0 ||
            children.start[std::size_t(t) + 1] != children.start[std::size_t(t)] ||
            !(radius(t) > 0.0) || nearestVertex[std::size_t(t)] < 0)
            continue;
        // Along the bones from t to every joint, and the way back.
        std::vector<double> along(std::size_t(count), -1.0);
        std::vector<int> back(std::size_t(count), -1);
        along[std::size_t(t)] = 0.0;
        std::vector<int> stack{t};
        while (!stack.empty()) {
            const int j = stack.back();
            stack.pop_back();
            for (const int k : bones[std::size_t(j)])
                if (along[std::size_t(k)] < 0.0) {
                    along[std::size_t(k)] =
                        along[std::size_t(j)] + (jointAt(j) - jointAt(k)).norm();
                    back[std::size_t(k)] = j;
                    stack.push_back(k);
                }
        }
        double limit = 0.0;
        for (int o = 0; o < count; ++o)
            if (o != t && along[std::size_t(o)] >= 0.0 && radius(o) > 0.0)
                limit = std::max(limit, std::min(kRingGap * (radius(t) + radius(o)),
                                                 along[std::size_t(o)] / kRingDetour));
        if (limit <= 0.0)
            continue;
        // Through the mesh from t, as far as `limit`.
        std::vector<double> through(std::size_t(V.rows()), std::numeric_limits<double>::infinity());
        using Item = std::pair<double, int>;
        std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
        const int start = nearestVertex[std::size_t(t)];
        through[std::size_t(start)] = 0.0;
        queue.emplace(0.0, start);
        while (!queue.empty()) {
            const auto [d, v] = queue.top();
            queue.pop();
            if (d > through[std::size_t(v)])
                continue;
            for (const int u : g.neighbours[std::size_t(v)]) {
                const double next = d + (V.row(u) - V.row(v)).norm();
                if (next < through[std::size_t(u)] && next <= limit) {
                    through[std::size_t(u)] = next;
                    queue.emplace(next, u);
                }
            }
        }
        for (int o = 0; o < count; ++o) {
            const int v = o != t && radius(o) > 0.0 ? nearestVertex[std::size_t(o)] : -1;
            if (v < 0 || along[std::size_t(o)] < 0.0)
                continue;
            const double gap = through[std::size_t(v)] / (radius(t) + radius(o));
            if (gap > kRingGap || along[std::size_t(o)] < kRingDetour * through[std::size_t(v)])
                continue;
            Pair pair{gap, t, o, {}};
            for (int j = o; j >= 0; j = back[std::size_t(j)])
                pair.path.push_back(j);
            pairs.push_back(std::move(pair));
        }
    }
    std::sort(pairs.begin(), pairs.end(), [](const Pair &x, const Pair &y) {
        return x.gap != y.gap ? x.gap < y.gap
                              : std::tie(x.tip, x.beyond) < std::tie(y.tip, y.beyond);
    });
    std::vector<char> broken(g.holes.size(), 0);
    for (const Pair &pair : pairs) {
        geometry::Region loop{{Eigen::MatrixX2d(Eigen::Index(pair.path.size()), 2), {}}};
        for (std::size_t i = 0; i < pair.path.size(); ++i)
            loop[0].outer.row(Eigen::Index(i)) = jointAt(pair.path[i]).transpose();
        bool opens = false;
        for (std::size_t h = 0; h < g.holes.size(); ++h) {
            if (!geometry::regionContains(loop, V(g.holes[h](0), 0), V(g.holes[h](0), 1)))
                continue;
            opens = opens || !broken[h];
            broken[h] = 1;
        }
        if (!opens)
            continue;
        // Across the shape at a tip of the pair, which lies on the shape's medial axis: from the
        // outline nearest it to the nearest on the side facing away from that (where its
        // inscribed circle touches the outline on either side). At the tip whose two contacts
        // lie most nearly opposite: a branch running into the side of another is cut across
        // itself, not round the other's rounded end.
        std::optional<Barrier> across;
        double straightest = 2.0;
        for (const int j : {pair.tip, pair.beyond}) {
            if (children.start[std::size_t(j) + 1] != children.start[std::size_t(j)])
                continue;
            const Vec middle = jointAt(j);
            const Contact a = nearestInSector(V, g, middle, 0.0, 2.0 * M_PI);
            if (!std::isfinite(a.distance))
                continue;
            const Contact b =
                nearestInSector(V, g, middle, angleOf(a.point - middle) + 0.5 * M_PI, M_PI);
            if (!std::isfinite(b.distance))
                continue;
            const double cosine =
                (a.point - middle).normalized().dot((b.point - middle).normalized());
            if (cosine >= straightest)
                continue;
            straightest = cosine;
            const double margin = 1e-6 * radius(j);
            across = Barrier{Vec(a.point + margin * (a.point - middle).normalized()), middle,
                             Vec(b.point + margin * (b.point - middle).normalized())};
        }
        if (across)
            out.push_back(*across);
    }
    return out;
}

// Union–find over triangle corners.
int findRoot(std::vector<int> &up, int x)
{
    while (up[std::size_t(x)] != x) {
        up[std::size_t(x)] = up[std::size_t(up[std::size_t(x)])];
        x = up[std::size_t(x)];
    }
    return x;
}

// Slivers: where two cuts end on one outline point (the notch between a horse's ears), the
// triangles between them can belong to neither limb and be parted from the rest of their own
// piece, an island that no bone of its piece reaches, so it followed the nearest bone (an ear)
// as it turned. A connected part of a piece other than its largest that borders another piece
// and lies wholly near a cut (within one inscribed radius of its joint beyond its farther end)
// joins the piece it shares most edges with.
void joinSlivers(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F, const Skeleton &skeleton,
                 const Eigen::VectorXd &radius, CutMesh &out)
{
    const Eigen::Index n = V.rows(), m = F.rows();
    std::unordered_map<long long, std::vector<int>> edgeTriangles;
    edgeTriangles.reserve(std::size_t(3 * m));
    for (Eigen::Index t = 0; t < m; ++t)
        for (int k = 0; k < 3; ++k)
            edgeTriangles[edgeKey(n, F(t, k), F(t, (k + 1) % 3))].push_back(int(t));
    const auto nearACut = [&](const Vec &p) {
        return std::any_of(out.cuts.begin(), out.cuts.end(), [&](const JointCut &cut) {
            const Vec pivot = skeleton.joints.row(cut.joint).transpose();
            const double reach = std::max((cut.a - pivot).norm(), (cut.b - pivot).norm());
            return (p - pivot).norm() <= reach + radius(cut.joint);
        });
    };
    for (int round = 0; round < 4; ++round) {
        std::vector<int> up(static_cast<std::size_t>(m));
        std::iota(up.begin(), up.end(), 0);
        for (const auto &entry : edgeTriangles) {
            const std::vector<int> &triangles = entry.second;
            for (std::size_t i = 1; i < triangles.size(); ++i)
                if (out.piece(triangles[i]) == out.piece(triangles[0]))
                    up[std::size_t(findRoot(up, triangles[i]))] = findRoot(up, triangles[0]);
        }
        std::map<int, std::vector<int>> parts; // root → its triangles
        for (Eigen::Index t = 0; t < m; ++t)
            parts[findRoot(up, int(t))].push_back(int(t));
        std::map<int, std::size_t> largest; // piece → triangles of its largest part
        for (const auto &entry : parts) {
            std::size_t &size = largest[out.piece(entry.second.front())];
            size = std::max(size, entry.second.size());
        }
        std::vector<std::pair<std::vector<int>, int>> moves; // a sliver, the piece it joins
        for (const auto &entry : parts) {
            const std::vector<int> &triangles = entry.second;
            const int piece = out.piece(triangles.front());
            if (triangles.size() == largest[piece])
                continue;
            std::map<int, int> bordering; // other piece → shared edges
            bool sliver = true;
            for (std::size_t i = 0; i < triangles.size() && sliver; ++i) {
                const int t = triangles[i];
                for (int k = 0; k < 3 && sliver; ++k) {
                    sliver = nearACut(V.row(F(t, k)).transpose());
                    for (const int u : edgeTriangles.at(edgeKey(n, F(t, k), F(t, (k + 1) % 3))))
                        if (out.piece(u) != piece)
                            ++bordering[out.piece(u)];
                }
            }
            if (!sliver || bordering.empty())
                continue;
            const auto most =
                std::max_element(bordering.begin(), bordering.end(),
                                 [](const auto &a, const auto &b) { return a.second < b.second; });
            moves.emplace_back(triangles, most->first);
        }
        if (moves.empty())
            return;
        for (const auto &[triangles, piece] : moves)
            for (const int t : triangles)
                out.piece(t) = piece;
    }
}

} // namespace

Expected<CutMesh, DeformError> cutAtJoints(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                           const Skeleton &skeleton, const Eigen::VectorXd &radius,
                                           const CutOutOptions &options)
{
    if (radius.size() != skeleton.jointCount())
        return unexpected(detail::makeError(DeformErrorCode::SizeMismatch,
                                            "the joint radii do not match the skeleton"));
    const Eigen::Index n = V.rows();
    if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= n))
        return unexpected(detail::makeError(DeformErrorCode::InvalidIndex,
                                            "a triangle refers to a vertex that does not exist"));
    CutMesh out;
    out.V = V;
    out.F = F;
    out.source = Eigen::VectorXi::LinSpaced(n, 0, int(n) - 1);
    out.piece = Eigen::VectorXi::Constant(F.rows(), -1);
    if (n == 0 || F.rows() == 0)
        return out;
    const MeshGraph graph = meshGraph(V, F);
    const detail::ChildLists children = detail::childLists(skeleton.parent);
    // The mesh vertex nearest each joint, for the floods' stops.
    std::vector<int> nearestVertex(std::size_t(skeleton.jointCount()));
    for (Eigen::Index o = 0; o < skeleton.jointCount(); ++o)
        nearestVertex[std::size_t(o)] = nearestWhere(V, graph, skeleton.joints.row(o).transpose(),
                                                     [](const Vec &) { return true; });
    const std::vector<Barrier> barriers =
        ringBreaks(V, graph, skeleton, radius, nearestVertex, children);
    const auto subtreeOf = [&](int top) {
        std::vector<char> below(std::size_t(skeleton.jointCount()), 0);
        std::vector<int> pending{top};
        while (!pending.empty()) {
            const int c = pending.back();
            pending.pop_back();
            below[std::size_t(c)] = 1;
            for (int i = children.start[std::size_t(c)]; i < children.start[std::size_t(c) + 1];
                 ++i)
                pending.push_back(children.child[std::size_t(i)]);
        }
        return below;
    };
    const auto childCount = [&](int j) {
        return children.start[std::size_t(j) + 1] - children.start[std::size_t(j)];
    };
    // A limb: the chain of bones from `top` out to a tip, with no junction on it.
    const auto isChain = [&](int top) {
        for (int c = top;;) {
            const int count = childCount(c);
            if (count == 0)
                return true;
            if (count > 1)
                return false;
            c = children.child[std::size_t(children.start[std::size_t(c)])];
        }
    };
    struct Candidate {
        int child = -1;
        Vec a, b;
        std::vector<char> flooded;
        int size = 0;
    };
    // The vertices past the cut a → joint j → b towards `child`, or empty when that cut does
    // not separate: the flood from the child's side must reach no vertex just beside the
    // joint towards `others` (its other bones) and no joint outside the child's subtree (a cut
    // whose sides close round into a sharp V would otherwise take the whole body for the limb).
    const auto tryCut = [&](int j, int child, const Vec &a, const Vec &b,
                            const std::vector<Vec> &others) -> Candidate {
        const Vec pivot = skeleton.joints.row(j).transpose();
        const Vec outward = skeleton.joints.row(child).transpose() - pivot;
        const double r = radius(j);
        const auto past = [&](const Vec &x) { return pastCut(x, pivot, a, b, outward); };
        const int seed = nearestWhere(V, graph, pivot + 0.5 * r * outward.normalized(), past);
        if (seed < 0)
            return {};
        std::vector<char> stops(std::size_t(n), 0);
        for (const Vec &towards : others) {
            const int stop = nearestWhere(V, graph, pivot + 0.5 * r * towards.normalized(),
                                          [&](const Vec &x) { return !past(x); });
            if (stop < 0)
                return {};
            stops[std::size_t(stop)] = 1;
        }
        const std::vector<char> below = subtreeOf(child);
        const double reach = options.reach * r;
        for (Eigen::Index o = 0; o < skeleton.jointCount(); ++o) {
            const Vec at = skeleton.joints.row(o).transpose();
            if (below[std::size_t(o)] || (at - pivot).norm() <= reach)
                continue;
            const int v = nearestVertex[std::size_t(o)];
            if (v >= 0 && v != seed)
                stops[std::size_t(v)] = 1;
        }
        Candidate found{child, a, b,
                        floodPast(V, graph, a, pivot, b, seed, stops, kOnCut * r, barriers), 0};
        found.size = int(std::count(found.flooded.begin(), found.flooded.end(), char(1)));
        return found;
    };
    const auto commit = [&](int j, const Candidate &cut) {
        const Vec pivot = skeleton.joints.row(j).transpose();
        const Vec outward = skeleton.joints.row(cut.child).transpose() - pivot;
        const int index = int(out.cuts.size());
        bool any = false;
        for (Eigen::Index t = 0; t < F.rows(); ++t) {
            const int inside = cut.flooded[std::size_t(F(t, 0))] +
                               cut.flooded[std::size_t(F(t, 1))] +
                               cut.flooded[std::size_t(F(t, 2))];
            bool mine = inside == 3;
            if (inside == 1 || inside == 2) {
                const Vec c = (V.row(F(t, 0)) + V.row(F(t, 1)) + V.row(F(t, 2))).transpose() / 3.0;
                mine = pastCut(c, pivot, cut.a, cut.b, outward);
                // At a ring's break, only on the flooded side of it: a corner flooded and the
                // centroid not parted by the break.
                int flooded = 0;
                while (!cut.flooded[std::size_t(F(t, flooded))])
                    ++flooded;
                const Vec corner = V.row(F(t, flooded)).transpose();
                mine = mine &&
                       std::none_of(barriers.begin(), barriers.end(),
                                    [&](const Barrier &line) { return line.meets(c, corner); });
            }
            if (mine) {
                out.piece(t) = index;
                any = true;
            }
        }
        if (!any)
            return;
        double round2 = std::numeric_limits<double>::infinity();
        for (const auto &[s, e] : graph.boundary)
            round2 = std::min(round2, detail::squaredSegmentDistance(pivot, V.row(s).transpose(),
                                                                     V.row(e).transpose()));
        const double round = std::sqrt(round2);
        out.cuts.push_back({j, cut.child, cut.a, cut.b, std::isfinite(round) ? round : 0.0});
    };
    for (Eigen::Index k = 0; k < skeleton.jointCount(); ++k) {
        const int j = skeleton.order(k);
        const int parent = skeleton.parent(j);
        const auto js = std::size_t(j);
        const double r = radius(j);
        if (!(std::isfinite(r) && r > 0.0))
            continue;
        const Vec pivot = skeleton.joints.row(j).transpose();
        // A hair past the outline, so the outline edges a cut ends on count as crossed.
        const double margin = 1e-6 * r;
        const auto beyond = [&](const Vec &contact) {
            return Vec(contact + margin * (contact - pivot).normalized());
        };
        const double reach = options.reach * r;
        const auto within = [&](double a, double b) {
            return std::min(a, b) <= reach && std::max(a, b) <= options.farReach * r;
        };
        if (parent >= 0 && childCount(j) == 1) {
            const int child = children.child[std::size_t(children.start[js])];
            const Vec in = pivot - skeleton.joints.row(parent).transpose();
            const Vec outward = skeleton.joints.row(child).transpose() - pivot;
            if (in.norm() == 0.0 || outward.norm() == 0.0)
                continue;
            // The cut runs from the outline nearest the joint on one side of the child bone,
            // through the joint, to the nearest on the other: where the joint's inscribed
            // circle touches the outline, so the limb keeps a round end.
            const double at = angleOf(outward), side = options.sideAngle;
            const Contact a = nearestInSector(V, graph, pivot, at, side);
            const Contact b = nearestInSector(V, graph, pivot, at - side, side);
            if (!within(a.distance, b.distance))
                continue;
            const Candidate cut = tryCut(j, child, beyond(a.point), beyond(b.point), {-in});
            if (!cut.flooded.empty())
                commit(j, cut);
            continue;
        }
        if (childCount(j) < 2)
            continue;
        // A junction (or a root between two or more bones): each limb hanging from it is cut
        // between its bone and the neighbouring bones on either side.
        std::vector<Vec> bones; // from the joint to each neighbour: its children, then parent
        std::vector<int> ends;
        for (int i = children.start[js]; i < children.start[js + 1]; ++i) {
            const int c = children.child[std::size_t(i)];
            bones.push_back(skeleton.joints.row(c).transpose() - pivot);
            ends.push_back(c);
        }
        if (parent >= 0) {
            bones.push_back(skeleton.joints.row(parent).transpose() - pivot);
            ends.push_back(parent);
        }
        if (std::any_of(bones.begin(), bones.end(), [](const Vec &d) { return d.norm() == 0.0; }))
            continue;
        std::vector<Candidate> found;
        int limbs = 0;
        for (std::size_t i = 0; i + (parent >= 0 ? 1 : 0) < bones.size(); ++i) {
            if (!isChain(ends[i]))
                continue;
            ++limbs;
            // A limb already narrower at its first joint is cut there, where it leaves the
            // body, not again at the junction.
            if (childCount(ends[i]) == 1 && radius(ends[i]) < 0.8 * r)
                continue;
            const double at = angleOf(bones[i]);
            double left = 2.0 * M_PI, right = 2.0 * M_PI; // to the next bone each way
            for (std::size_t o = 0; o < bones.size(); ++o) {
                if (o == i)
                    continue;
                const double other = angleOf(bones[o]);
                left = std::min(left, ccw(at, other));
                right = std::min(right, ccw(other, at));
            }
            const Contact a = nearestInSector(V, graph, pivot, at, left);
            const Contact b = nearestInSector(V, graph, pivot, at - right, right);
            if (!within(a.distance, b.distance))
                continue;
            std::vector<Vec> others;
            for (std::size_t o = 0; o < bones.size(); ++o)
                if (o != i)
                    others.push_back(bones[o]);
            Candidate cut = tryCut(j, ends[i], beyond(a.point), beyond(b.point), others);
            if (!cut.flooded.empty())
                found.push_back(std::move(cut));
        }
        // At a root whose every bone is a limb, the heaviest stays as the body.
        if (parent < 0 && !found.empty() && limbs == int(bones.size()) &&
            int(found.size()) == limbs)
            found.erase(std::max_element(
                found.begin(), found.end(),
                [](const Candidate &x, const Candidate &y) { return x.size < y.size; }));
        for (const Candidate &cut : found)
            commit(j, cut);
    }
    if (out.cuts.empty())
        return out;
    joinSlivers(V, F, skeleton, radius, out);
    // Copies: corners of triangles of one piece that share an edge at a vertex stay one vertex.
    const Eigen::Index m = F.rows();
    std::vector<int> up(std::size_t(3 * m));
    std::iota(up.begin(), up.end(), 0);
    std::unordered_map<long long, std::pair<int, int>> firstCorner; // edge → (triangle, slot)
    firstCorner.reserve(std::size_t(3 * m));
    for (Eigen::Index t = 0; t < m; ++t) {
        for (int c = 0; c < 3; ++c) {
            const int a = F(t, c), b = F(t, (c + 1) % 3);
            const auto [it, fresh] =
                firstCorner.emplace(edgeKey(n, a, b), std::make_pair(int(t), c));
            if (fresh)
                continue;
            const auto [s, sc] = it->second;
            if (out.piece(s) != out.piece(t))
                continue;
            // Corner of a in s, corner of b in s.
            const int sa = F(s, sc) == a ? sc : (sc + 1) % 3;
            const int sb = F(s, sc) == b ? sc : (sc + 1) % 3;
            up[std::size_t(findRoot(up, int(3 * t + c)))] = findRoot(up, 3 * s + sa);
            up[std::size_t(findRoot(up, int(3 * t + (c + 1) % 3)))] = findRoot(up, 3 * s + sb);
        }
    }
    std::vector<int> classVertex(up.size(), -1);
    std::vector<char> used(std::size_t(n), 0);
    std::vector<int> extra;
    for (Eigen::Index t = 0; t < m; ++t) {
        for (int c = 0; c < 3; ++c) {
            const int root = findRoot(up, int(3 * t + c));
            int &vertex = classVertex[std::size_t(root)];
            if (vertex < 0) {
                const int original = F(t, c);
                if (!used[std::size_t(original)]) {
                    used[std::size_t(original)] = 1;
                    vertex = original;
                } else {
                    vertex = int(n + Eigen::Index(extra.size()));
                    extra.push_back(original);
                }
            }
            out.F(t, c) = vertex;
        }
    }
    out.V.conservativeResize(n + Eigen::Index(extra.size()), 2);
    out.source.conservativeResize(n + Eigen::Index(extra.size()));
    for (std::size_t e = 0; e < extra.size(); ++e) {
        out.V.row(n + Eigen::Index(e)) = V.row(extra[e]);
        out.source(n + Eigen::Index(e)) = extra[e];
    }
    // The pieces' outlines: the cut mesh's boundary loops (each vertex belongs to one piece).
    std::vector<int> pieceOf(std::size_t(out.V.rows()), -1);
    for (Eigen::Index t = 0; t < m; ++t)
        for (int c = 0; c < 3; ++c)
            pieceOf[std::size_t(out.F(t, c))] = out.piece(t);
    out.outlines.resize(out.cuts.size());
    const std::vector<Eigen::VectorXi> loops = geometry::boundaryLoops(out.F);
    for (const Eigen::VectorXi &loop : loops) {
        const int piece = pieceOf[std::size_t(loop(0))];
        if (piece >= 0)
            out.outlines[std::size_t(piece)].emplace_back(loop.data(), loop.data() + loop.size());
        else
            out.rootOutline.emplace_back(loop.data(), loop.data() + loop.size());
    }
    const Eigen::VectorXi bones = bonePieces(skeleton, out);
    out.parentPiece.assign(out.cuts.size(), -1);
    for (std::size_t c = 0; c < out.cuts.size(); ++c) {
        const int j = out.cuts[c].joint;
        out.parentPiece[c] = skeleton.parent(j) >= 0 ? bones(j) : -1;
    }
    return out;
}

Eigen::VectorXi bonePieces(const Skeleton &skeleton, const CutMesh &cut)
{
    std::vector<int> cutOf(std::size_t(skeleton.jointCount()), -1); // by the bone it starts
    for (std::size_t c = 0; c < cut.cuts.size(); ++c) {
        const int j = cut.cuts[c].child;
        if (j >= 0 && j < skeleton.jointCount())
            cutOf[std::size_t(j)] = int(c);
    }
    Eigen::VectorXi piece = Eigen::VectorXi::Constant(skeleton.jointCount(), -1);
    for (Eigen::Index k = 0; k < skeleton.jointCount(); ++k) {
        const int j = skeleton.order(k);
        const int p = skeleton.parent(j);
        if (p >= 0)
            piece(j) = cutOf[std::size_t(j)] >= 0 ? cutOf[std::size_t(j)] : piece(p);
    }
    return piece;
}

SkinningWeights cutOutWeights(const SkinningWeights &weights, const Skeleton &skeleton,
                              const CutMesh &cut)
{
    SkinningWeights out = weights;
    const Eigen::Index n = cut.V.rows();
    out.W.setZero(n, weights.W.cols());
    out.owner = Eigen::VectorXi::Constant(n, -1);
    const Eigen::VectorXi bones = bonePieces(skeleton, cut);
    // Each vertex's piece, from its triangles (all of one piece by construction).
    Eigen::VectorXi vertexPiece = Eigen::VectorXi::Constant(n, -1);
    for (Eigen::Index t = 0; t < cut.F.rows(); ++t)
        for (int c = 0; c < 3; ++c)
            vertexPiece(cut.F(t, c)) = cut.piece(t);
    // The first bone of each cut's piece (the bone leaving the cut joint).
    std::vector<int> firstBone(cut.cuts.size(), -1);
    for (std::size_t c = 0; c < cut.cuts.size(); ++c)
        firstBone[c] = cut.cuts[c].child;
    for (Eigen::Index v = 0; v < n; ++v) {
        const int source = cut.source(v);
        const int piece = vertexPiece(v);
        double sum = 0.0;
        for (Eigen::Index h = 0; h < weights.W.cols(); ++h) {
            if (h < bones.size() && bones(h) == piece) {
                out.W(v, h) = weights.W(source, h);
                sum += out.W(v, h);
            }
        }
        if (sum > 1e-12) {
            out.W.row(v) /= sum;
        } else {
            // All its weight lay on other pieces' bones: the nearest-by-weight bone of its own.
            int fallback = piece >= 0 ? firstBone[std::size_t(piece)] : -1;
            if (fallback < 0) {
                double best = -1.0;
                for (Eigen::Index h = 0; h < weights.W.cols(); ++h) {
                    if (h < bones.size() && bones(h) == piece && !skeleton.isRoot(h) &&
                        weights.W(source, h) > best) {
                        best = weights.W(source, h);
                        fallback = int(h);
                    }
                }
            }
            if (fallback >= 0)
                out.W(v, fallback) = 1.0;
            else
                out.W.row(v) = weights.W.row(source);
        }
        const int owner = weights.owner(source);
        out.owner(v) = owner >= 0 && owner < bones.size() && bones(owner) == piece ? owner : -1;
    }
    std::vector<int> active;
    for (const int h : weights.handles)
        if (out.W.col(h).cwiseAbs().maxCoeff() > 0.0)
            active.push_back(h);
    out.active = Eigen::Map<const Eigen::VectorXi>(active.data(), Eigen::Index(active.size()));
    return out;
}

} // namespace finbook::deform
