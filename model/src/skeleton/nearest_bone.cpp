// Nearest rest bone: a bounding-volume tree searched nearest first (see nearest_bone.h). Both
// the build and the search are loops over explicit stacks: nothing here recurses, whatever
// the skeleton a file holds.
#include "nearest_bone.h"

#include <QLineF>

#include <algorithm>
#include <cmath>
#include <limits>

namespace finbook::model::join_detail {

namespace {
constexpr int kLeafBones = 8;

// Whether (d, j) comes before (bestD, bestJ): nearer, or as near with a lower index (the scan
// keeps the first of equals). An infinite or NaN distance never wins, as in the scan.
bool better(double d, int j, double bestD, int bestJ)
{
    return d < bestD || (d == bestD && bestJ >= 0 && j < bestJ);
}

// A lower bound of the distance the scan computes from p to any bone in the box. The exact
// distance to a box is at most the exact distance to a bone in it; the computed distance of a
// bone may be a few rounding errors below its exact one, so the bound gives way by far more.
double lowerBound(QPointF p, double x0, double y0, double x1, double y1)
{
    const double dx = std::max({x0 - p.x(), 0.0, p.x() - x1});
    const double dy = std::max({y0 - p.y(), 0.0, p.y() - y1});
    // hypot's care is needed only where the squares would overflow.
    const double d = dx < 1e150 && dy < 1e150 ? std::sqrt(dx * dx + dy * dy) : std::hypot(dx, dy);
    const double scale = std::max({std::abs(p.x()), std::abs(p.y()), std::abs(x0), std::abs(x1),
                                   std::abs(y0), std::abs(y1), 1.0});
    return d * (1.0 - 1e-9) - 1e-9 * scale;
}
} // namespace

std::pair<double, double> project(QPointF p, QPointF a, QPointF b)
{
    const QPointF d = b - a;
    const double len2 = QPointF::dotProduct(d, d);
    const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, d) / len2, 0.0, 1.0) : 0.0;
    return {t, QLineF(p, a + t * d).length()};
}

NearestBone nearestByScan(const SkeletonRig &rig, QPointF p, std::int64_t &work)
{
    NearestBone best;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < rig.joints.size(); ++j) {
        const int parent = rig.parent[j];
        if (parent < 0)
            continue;
        const auto [t, d] = project(p, rig.joints[std::size_t(parent)], rig.joints[j]);
        if (d < bestDistance) {
            bestDistance = d;
            best = {int(j), t};
        }
    }
    work += std::int64_t(rig.joints.size());
    return best;
}

BoneIndex::BoneIndex(const SkeletonRig &rig)
    : m_rig(rig)
{
    for (std::size_t j = 0; j < rig.joints.size(); ++j)
        if (rig.parent[j] >= 0)
            m_bones.push_back(int(j));
    if (m_bones.empty())
        return;
    const auto centre = [&rig](int j, int axis) {
        const QPointF a = rig.joints[std::size_t(rig.parent[std::size_t(j)])],
                      b = rig.joints[std::size_t(j)];
        return axis == 0 ? a.x() / 2 + b.x() / 2 : a.y() / 2 + b.y() / 2;
    };
    m_nodes.reserve(2 * m_bones.size() / kLeafBones + 2);
    m_nodes.push_back(Node{0, 0, 0, 0, 0, int(m_bones.size())});
    std::vector<int> open{0};
    while (!open.empty()) {
        const int at = open.back();
        open.pop_back();
        Node node = m_nodes[std::size_t(at)];
        node.x0 = node.y0 = std::numeric_limits<double>::infinity();
        node.x1 = node.y1 = -std::numeric_limits<double>::infinity();
        double cx0 = node.x0, cy0 = node.y0, cx1 = node.x1, cy1 = node.y1;
        for (int k = node.begin; k < node.end; ++k) {
            const int j = m_bones[std::size_t(k)];
            for (const QPointF q : {rig.joints[std::size_t(rig.parent[std::size_t(j)])],
                                    rig.joints[std::size_t(j)]}) {
                node.x0 = std::min(node.x0, q.x());
                node.x1 = std::max(node.x1, q.x());
                node.y0 = std::min(node.y0, q.y());
                node.y1 = std::max(node.y1, q.y());
            }
            const double cx = centre(j, 0), cy = centre(j, 1);
            cx0 = std::min(cx0, cx);
            cx1 = std::max(cx1, cx);
            cy0 = std::min(cy0, cy);
            cy1 = std::max(cy1, cy);
        }
        if (node.end - node.begin > kLeafBones) {
            const int axis = cx1 - cx0 >= cy1 - cy0 ? 0 : 1;
            const int middle = node.begin + (node.end - node.begin) / 2;
            std::nth_element(m_bones.begin() + node.begin, m_bones.begin() + middle,
                             m_bones.begin() + node.end, [&](int a, int b) {
                                 const double ca = centre(a, axis), cb = centre(b, axis);
                                 return ca < cb || (ca == cb && a < b);
                             });
            node.left = int(m_nodes.size());
            m_nodes.push_back(Node{0, 0, 0, 0, node.begin, middle});
            node.right = int(m_nodes.size());
            m_nodes.push_back(Node{0, 0, 0, 0, middle, node.end});
            open.push_back(node.left);
            open.push_back(node.right);
        }
        m_nodes[std::size_t(at)] = node;
    }
}

NearestBone BoneIndex::nearest(QPointF p, std::int64_t &work) const
{
    NearestBone best;
    double bestDistance = std::numeric_limits<double>::infinity();
    if (m_nodes.empty())
        return best;
    const auto boundOf = [&](int n) {
        const Node &node = m_nodes[std::size_t(n)];
        const double bound = lowerBound(p, node.x0, node.y0, node.x1, node.y1);
        return std::isnan(bound) ? -std::numeric_limits<double>::infinity() : bound;
    };
    // Depth-first, the nearer child first, skipping what cannot win or tie.
    std::vector<std::pair<double, int>> open{{boundOf(0), 0}}; // lower bound, node
    while (!open.empty()) {
        const auto [bound, n] = open.back();
        open.pop_back();
        ++work;
        if (bound > bestDistance)
            continue; // every bone in it is farther than the best: none can win or tie
        const Node &node = m_nodes[std::size_t(n)];
        if (node.left >= 0) {
            const double left = boundOf(node.left), right = boundOf(node.right);
            if (left <= right) {
                open.push_back({right, node.right});
                open.push_back({left, node.left});
            } else {
                open.push_back({left, node.left});
                open.push_back({right, node.right});
            }
            continue;
        }
        for (int k = node.begin; k < node.end; ++k) {
            const int j = m_bones[std::size_t(k)];
            const auto [t, d] = project(p, m_rig.joints[std::size_t(m_rig.parent[std::size_t(j)])],
                                        m_rig.joints[std::size_t(j)]);
            if (better(d, j, bestDistance, best.joint)) {
                bestDistance = d;
                best = {j, t};
            }
        }
        work += 2 * (node.end - node.begin); // a bone costs about two nodes
    }
    return best;
}

} // namespace finbook::model::join_detail
