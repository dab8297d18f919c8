// The root at the thickest part and separate pieces of one object joined (issue 21).
#include "animator_rig.h"
#include "skeleton_contour.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace finbook::geometry::detail {
namespace {

// Pieces nearer than this many radii (the thicker piece's widest) are joined.
constexpr double kPieceReach = 1.0;

double segmentPointT(const Eigen::Vector2d &p, const Eigen::Vector2d &a, const Eigen::Vector2d &b)
{
    const Eigen::Vector2d ab = b - a;
    const double l2 = ab.squaredNorm();
    return l2 > 0.0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
}

// Per polygon of `contour`, its widest inscribed radius where its bones run: the joints' radii,
// and the clearance sampled along each bone of that polygon (an ellipse's medial axis has
// joints only at its ends, where the radius is a fraction of the middle's: a cow's body drawn
// as an ellipse measured half as thick as it is, and a leg under its far end was left alone).
std::vector<double> widestRadii(const JointGraph &graph, const std::vector<int> &polygonOf,
                                const Region &contour)
{
    constexpr int kSamples = 8; // per bone
    std::vector<double> widest(contour.size(), 0.0);
    std::vector<std::optional<ContourIndex>> index(contour.size());
    for (int j = 0; j < graph.size(); ++j) {
        const int p = polygonOf[std::size_t(j)];
        if (p < 0 || std::size_t(p) >= contour.size())
            continue;
        double &w = widest[std::size_t(p)];
        w = std::max(w, graph.radius[std::size_t(j)]);
        for (int n : graph.adj[std::size_t(j)]) {
            if (n < j || polygonOf[std::size_t(n)] != p)
                continue;
            auto &at = index[std::size_t(p)];
            if (!at)
                at.emplace(Polygon{contour[std::size_t(p)].outer, contour[std::size_t(p)].holes});
            for (int k = 1; k < kSamples; ++k) {
                const double t = double(k) / kSamples;
                const Eigen::Vector2d q =
                    graph.pos[std::size_t(j)] +
                    t * (graph.pos[std::size_t(n)] - graph.pos[std::size_t(j)]);
                if (at->inside(q))
                    w = std::max(w, at->distance(q));
            }
        }
    }
    return widest;
}

// Where two pieces' outer outlines come closest: a point on each (vertex to edge, both ways;
// the pieces of one region never cross, so no crossing test is needed).
struct Contact {
    Eigen::Vector2d onChild = Eigen::Vector2d::Zero(), onParent = Eigen::Vector2d::Zero();
    double distance = std::numeric_limits<double>::infinity();
};

Contact closestContact(const Polygon &child, const Polygon &parent)
{
    Contact out;
    const auto scan = [&](const Eigen::MatrixX2d &from, const Eigen::MatrixX2d &to,
                          bool fromChild) {
        const Eigen::Index n = to.rows();
        for (Eigen::Index i = 0; i < from.rows(); ++i) {
            const Eigen::Vector2d p = from.row(i).transpose();
            for (Eigen::Index k = 0; k < n; ++k) {
                const Eigen::Vector2d a = to.row(k).transpose(),
                                      b = to.row((k + 1) % n).transpose();
                const Eigen::Vector2d q = nearestOnSegment(p, a, b);
                const double d = (q - p).norm();
                if (d < out.distance) {
                    out.distance = d;
                    out.onChild = fromChild ? p : q;
                    out.onParent = fromChild ? q : p;
                }
            }
        }
    };
    scan(child.outer, parent.outer, true);
    scan(parent.outer, child.outer, false);
    return out;
}

// The contact of `piece` (a polygon of `contour`) with each piece that has an attached joint
// (distance +inf for the others and for itself): measured once per join, for nearlyTouches and
// aimAtContact.
std::vector<Contact> contactsWithAttached(const std::vector<int> &polygonOf,
                                          const std::vector<char> &attached, int piece,
                                          const Region &contour)
{
    std::vector<Contact> out(contour.size());
    std::vector<char> reached(contour.size(), 0);
    for (std::size_t j = 0; j < polygonOf.size(); ++j) {
        const int p = polygonOf[j];
        if (attached[j] && p >= 0 && std::size_t(p) < contour.size())
            reached[std::size_t(p)] = 1;
    }
    for (std::size_t p = 0; p < contour.size(); ++p)
        if (reached[p] && int(p) != piece)
            out[p] = closestContact(contour[std::size_t(piece)], contour[p]);
    return out;
}

// Whether `piece` touches or nearly touches a piece with an attached joint: their outlines
// within kPieceReach of the thicker piece's widest radius (widestRadii).
bool nearlyTouches(const std::vector<Contact> &contacts, int piece,
                   const std::vector<double> &widest)
{
    for (std::size_t p = 0; p < contacts.size(); ++p)
        if (contacts[p].distance <= kPieceReach * std::max(widest[std::size_t(piece)], widest[p]))
            return true;
    return false;
}

} // namespace

int thickestJoint(const JointGraph &graph, const std::vector<int> &polygonOf, int polygon)
{
    // The largest disk; an inner joint nearly as thick (90 %) wins over a tip.
    int best = -1, bestInner = -1;
    for (int j = 0; j < graph.size(); ++j) {
        if (polygon >= 0 && polygonOf[std::size_t(j)] != polygon)
            continue;
        if (best < 0 || graph.radius[std::size_t(j)] > graph.radius[std::size_t(best)])
            best = j;
        if (graph.adj[std::size_t(j)].size() >= 2 &&
            (bestInner < 0 || graph.radius[std::size_t(j)] > graph.radius[std::size_t(bestInner)]))
            bestInner = j;
    }
    if (bestInner >= 0 &&
        graph.radius[std::size_t(bestInner)] >= 0.9 * graph.radius[std::size_t(best)])
        return bestInner;
    return best;
}

namespace {

// A piece that nearly touches the attached ones hangs where it comes closest to them, not by
// whichever of its joints lies nearest some attached bone: a cow's legs drawn as lines under
// its body each hang from the body's bone above them, not one from the next along the belly
// (a bone through the air between them), and a tree's trunk line from the crown it meets.
// `child` becomes the joint of its tree nearest that contact, and from–to (at bestT) the bone
// of the attached piece it comes closest to nearest the contact there. Left as it is when no
// attached piece's outline was measured (contacts: contactsWithAttached).
void aimAtContact(const JointGraph &graph, const std::vector<int> &polygonOf,
                  const std::vector<char> &attached, const std::vector<Contact> &contacts,
                  int &child, int &from, int &to, double &bestT)
{
    // The child's tree (its free joints connected to it).
    std::vector<char> inTree(std::size_t(graph.size()), 0);
    std::vector<int> stack{child}, tree;
    inTree[std::size_t(child)] = 1;
    while (!stack.empty()) {
        const int v = stack.back();
        stack.pop_back();
        tree.push_back(v);
        for (int n : graph.adj[std::size_t(v)])
            if (!attached[std::size_t(n)] && !inTree[std::size_t(n)]) {
                inTree[std::size_t(n)] = 1;
                stack.push_back(n);
            }
    }
    // The attached piece whose outline comes closest.
    Contact best;
    int parentPiece = -1;
    for (std::size_t p = 0; p < contacts.size(); ++p)
        if (contacts[p].distance < best.distance) {
            best = contacts[p];
            parentPiece = int(p);
        }
    if (parentPiece < 0)
        return;
    // The bone (or lone joint) of that piece nearest the contact on its side.
    double nearest = std::numeric_limits<double>::infinity();
    int a0 = -1, b0 = -1;
    double t0 = 0.0;
    for (int a = 0; a < graph.size(); ++a) {
        if (!attached[std::size_t(a)] || polygonOf[std::size_t(a)] != parentPiece)
            continue;
        const auto consider = [&](int b) {
            const Eigen::Vector2d &pa = graph.pos[std::size_t(a)], &pb = graph.pos[std::size_t(b)];
            const double t = segmentPointT(best.onParent, pa, pb);
            const double d = (best.onParent - (pa + t * (pb - pa))).norm();
            if (d < nearest) {
                nearest = d;
                a0 = a;
                b0 = b;
                t0 = t;
            }
        };
        consider(a);
        for (int b : graph.adj[std::size_t(a)])
            if (b > a && attached[std::size_t(b)] && polygonOf[std::size_t(b)] == parentPiece)
                consider(b);
    }
    if (a0 < 0)
        return;
    int hangBy = child;
    double closest = std::numeric_limits<double>::infinity();
    for (int j : tree) {
        const double d = (graph.pos[std::size_t(j)] - best.onChild).norm();
        if (d < closest) {
            closest = d;
            hangBy = j;
        }
    }
    // Near a tip of that piece (a body's end), hang from the tip itself: a split there would
    // leave a stub of the body beyond the new joint, a spur.
    if (a0 != b0) {
        const double length = (graph.pos[std::size_t(b0)] - graph.pos[std::size_t(a0)]).norm();
        for (const auto &[end, t] : {std::pair{a0, 0.0}, std::pair{b0, 1.0}})
            if (graph.adj[std::size_t(end)].size() == 1 &&
                std::abs(t0 - t) * length <= graph.radius[std::size_t(end)])
                t0 = t;
    }
    child = hangBy;
    from = a0;
    to = b0;
    bestT = t0;
}

} // namespace

void joinPieces(JointGraph &graph, std::vector<int> &polygonOf, int root, const Region &contour)
{
    if (root < 0 || root >= graph.size())
        return;
    std::vector<char> attached(std::size_t(graph.size()), 0);
    auto attachTree = [&](int from) {
        std::vector<int> stack{from};
        attached[std::size_t(from)] = 1;
        while (!stack.empty()) {
            const int v = stack.back();
            stack.pop_back();
            for (int n : graph.adj[std::size_t(v)]) {
                if (!attached[std::size_t(n)]) {
                    attached[std::size_t(n)] = 1;
                    stack.push_back(n);
                }
            }
        }
    };
    attachTree(root);
    // Measured once: a joint split into a bone below takes the bone's own radius there.
    const std::vector<double> widest = widestRadii(graph, polygonOf, contour);
    for (;;) {
        // The free joint nearest to an attached bone (or lone attached joint).
        double best = std::numeric_limits<double>::infinity(), bestT = 0.0;
        int child = -1, from = -1, to = -1;
        for (int c = 0; c < graph.size(); ++c) {
            if (attached[std::size_t(c)])
                continue;
            const Eigen::Vector2d &p = graph.pos[std::size_t(c)];
            for (int a = 0; a < graph.size(); ++a) {
                if (!attached[std::size_t(a)])
                    continue;
                auto consider = [&](int b) {
                    const Eigen::Vector2d &pa = graph.pos[std::size_t(a)];
                    const Eigen::Vector2d &pb = graph.pos[std::size_t(b)];
                    const double t = segmentPointT(p, pa, pb);
                    const double d = (p - (pa + t * (pb - pa))).norm();
                    if (d < best) {
                        best = d;
                        bestT = t;
                        child = c;
                        from = a;
                        to = b;
                    }
                };
                consider(a);
                for (int b : graph.adj[std::size_t(a)]) {
                    if (b > a)
                        consider(b);
                }
            }
        }
        if (child < 0)
            return;
        // A piece without an outline to measure is joined, as before, where it is nearest.
        const int piece = polygonOf[std::size_t(child)];
        bool near = true;
        if (piece >= 0 && std::size_t(piece) < contour.size()) {
            const std::vector<Contact> contacts =
                contactsWithAttached(polygonOf, attached, piece, contour);
            near = nearlyTouches(contacts, piece, widest);
            if (near)
                aimAtContact(graph, polygonOf, attached, contacts, child, from, to, bestT);
        }
        attachTree(child);
        if (!near)
            continue; // a tree of its own; the pieces near it hang from it
        int hang = bestT < 0.5 ? from : to;
        const double length = (graph.pos[std::size_t(to)] - graph.pos[std::size_t(from)]).norm();
        const double fromEnd = std::min(bestT, 1.0 - bestT) * length;
        if (from != to && fromEnd > 0.5 * std::min(graph.radius[std::size_t(from)],
                                                   graph.radius[std::size_t(to)])) {
            // A bone split: a new joint where the piece's nearest point projects.
            const Eigen::Vector2d at =
                graph.pos[std::size_t(from)] +
                bestT * (graph.pos[std::size_t(to)] - graph.pos[std::size_t(from)]);
            const double r = (1.0 - bestT) * graph.radius[std::size_t(from)] +
                             bestT * graph.radius[std::size_t(to)];
            hang = graph.add(at, r, graph.part[std::size_t(from)]);
            polygonOf.push_back(polygonOf[std::size_t(from)]);
            attached.push_back(1);
            graph.disconnect(from, to);
            graph.connect(from, hang);
            graph.connect(hang, to);
        }
        graph.connect(hang, child);
    }
}

} // namespace finbook::geometry::detail
