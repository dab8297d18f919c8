#include "skeleton_tree.h"

#include <finbook/geometry/skeleton/skeleton.h>

#include <algorithm>

namespace finbook::geometry {

int boneCount(const Skeleton &skeleton)
{
    return int((skeleton.parent.array() >= 0).count());
}

Eigen::VectorXi jointDegrees(const Skeleton &skeleton)
{
    Eigen::VectorXi degree = Eigen::VectorXi::Zero(skeleton.jointCount());
    for (int j = 0; j < skeleton.parent.size(); ++j) {
        if (skeleton.parent(j) >= 0) {
            ++degree(j);
            ++degree(skeleton.parent(j));
        }
    }
    return degree;
}

std::vector<JointKind> jointKinds(const Skeleton &skeleton)
{
    const Eigen::VectorXi degree = jointDegrees(skeleton);
    std::vector<JointKind> kinds;
    for (int j = 0; j < degree.size(); ++j) {
        const int d = degree(j);
        kinds.push_back(d == 0   ? JointKind::Isolated
                        : d == 1 ? JointKind::Terminal
                        : d == 2 ? JointKind::Inner
                                 : JointKind::Junction);
    }
    return kinds;
}

Eigen::VectorXd boneLengths(const Skeleton &skeleton)
{
    Eigen::VectorXd length = Eigen::VectorXd::Zero(skeleton.jointCount());
    for (int j = 0; j < skeleton.parent.size(); ++j) {
        if (skeleton.parent(j) >= 0)
            length(j) = (skeleton.joints.row(j) - skeleton.joints.row(skeleton.parent(j))).norm();
    }
    return length;
}

bool isValidSkeleton(const Skeleton &s)
{
    const Eigen::Index n = s.joints.rows();
    if (s.radius.size() != n || s.parent.size() != n || s.part.size() != n ||
        (!s.limbBase.empty() && Eigen::Index(s.limbBase.size()) != n))
        return false;
    if (!s.joints.allFinite() || !s.radius.allFinite() || (n > 0 && s.radius.minCoeff() < 0.0))
        return false;
    for (Eigen::Index j = 0; j < n; ++j) {
        if (s.parent(j) < -1 || s.parent(j) >= j || s.part(j) < 0)
            return false;
    }
    if (n == 0)
        return s.root == -1;
    return s.root >= 0 && s.root < n && s.parent(s.root) == -1;
}

std::vector<std::vector<int>> jointChildren(const Skeleton &skeleton)
{
    std::vector<std::vector<int>> children(std::size_t(skeleton.jointCount()));
    for (int j = 0; j < skeleton.parent.size(); ++j) {
        if (skeleton.parent(j) >= 0)
            children[std::size_t(skeleton.parent(j))].push_back(j);
    }
    return children;
}

namespace detail {

int JointGraph::add(const Eigen::Vector2d &p, double r, int partId)
{
    pos.push_back(p);
    radius.push_back(r);
    part.push_back(partId);
    adj.emplace_back();
    return size() - 1;
}

void JointGraph::connect(int a, int b)
{
    if (a == b)
        return;
    std::vector<int> &na = adj[std::size_t(a)];
    if (std::find(na.begin(), na.end(), b) == na.end()) {
        na.push_back(b);
        adj[std::size_t(b)].push_back(a);
    }
}

void JointGraph::disconnect(int a, int b)
{
    std::erase(adj[std::size_t(a)], b);
    std::erase(adj[std::size_t(b)], a);
}

JointGraph keptJoints(const JointGraph &graph, const std::vector<char> &keep, std::vector<int> &map)
{
    JointGraph out;
    map.assign(std::size_t(graph.size()), -1);
    for (int v = 0; v < graph.size(); ++v) {
        if (keep[std::size_t(v)])
            map[std::size_t(v)] = out.add(graph.pos[std::size_t(v)], graph.radius[std::size_t(v)],
                                          graph.part[std::size_t(v)]);
    }
    for (int v = 0; v < graph.size(); ++v) {
        for (int n : graph.adj[std::size_t(v)]) {
            if (map[std::size_t(v)] >= 0 && map[std::size_t(n)] >= 0)
                out.connect(map[std::size_t(v)], map[std::size_t(n)]);
        }
    }
    return out;
}

JointGraph toJointGraph(const Skeleton &skeleton)
{
    JointGraph graph;
    for (int j = 0; j < skeleton.jointCount(); ++j)
        graph.add(skeleton.joints.row(j).transpose(), skeleton.radius(j), skeleton.part(j));
    for (int j = 0; j < skeleton.jointCount(); ++j) {
        if (skeleton.parent(j) >= 0)
            graph.connect(j, skeleton.parent(j));
    }
    return graph;
}

namespace {
// Depth-first order of the tree of `root` (children by increasing index) with parents.
void visitTree(const JointGraph &graph, int root, std::vector<int> &order,
               std::vector<int> &parentOf, std::vector<char> &seen)
{
    std::vector<int> stack{root};
    seen[std::size_t(root)] = 1;
    parentOf[std::size_t(root)] = -1;
    while (!stack.empty()) {
        const int v = stack.back();
        stack.pop_back();
        order.push_back(v);
        std::vector<int> next;
        for (int n : graph.adj[std::size_t(v)]) {
            if (!seen[std::size_t(n)]) {
                seen[std::size_t(n)] = 1;
                parentOf[std::size_t(n)] = v;
                next.push_back(n);
            }
        }
        std::sort(next.begin(), next.end(), std::greater<>());
        stack.insert(stack.end(), next.begin(), next.end());
    }
}

std::vector<int> componentOf(const JointGraph &graph)
{
    std::vector<int> component(std::size_t(graph.size()), -1);
    for (int s = 0; s < graph.size(); ++s) {
        if (component[std::size_t(s)] >= 0)
            continue;
        std::vector<int> stack{s};
        component[std::size_t(s)] = s;
        while (!stack.empty()) {
            const int v = stack.back();
            stack.pop_back();
            for (int n : graph.adj[std::size_t(v)]) {
                if (component[std::size_t(n)] < 0) {
                    component[std::size_t(n)] = s;
                    stack.push_back(n);
                }
            }
        }
    }
    return component;
}
} // namespace

Skeleton orderedSkeleton(const JointGraph &graph, const std::vector<int> &roots, int characterRoot,
                         std::vector<int> *newIndex)
{
    const int n = graph.size();
    const std::vector<int> component = componentOf(graph);
    // The root of each component (indexed by its smallest joint).
    std::vector<int> rootOf(std::size_t(n), -1);
    for (int r : roots) {
        if (r >= 0 && r < n && rootOf[std::size_t(component[std::size_t(r)])] < 0)
            rootOf[std::size_t(component[std::size_t(r)])] = r;
    }
    std::vector<int> treeOrder;
    if (characterRoot >= 0 && characterRoot < n)
        treeOrder.push_back(component[std::size_t(characterRoot)]);
    for (int v = 0; v < n; ++v) {
        if (component[std::size_t(v)] == v && (treeOrder.empty() || treeOrder.front() != v))
            treeOrder.push_back(v);
    }
    std::vector<int> order, parentOf(std::size_t(n), -1);
    std::vector<char> seen(std::size_t(n), 0);
    for (int c : treeOrder) {
        int r = rootOf[std::size_t(c)] >= 0 ? rootOf[std::size_t(c)] : c;
        if (c == treeOrder.front() && characterRoot >= 0 && characterRoot < n)
            r = characterRoot;
        visitTree(graph, r, order, parentOf, seen);
    }
    std::vector<int> index(std::size_t(n), -1);
    for (int k = 0; k < n; ++k)
        index[std::size_t(order[std::size_t(k)])] = k;
    Skeleton s;
    s.joints.resize(n, 2);
    s.radius.resize(n);
    s.parent.resize(n);
    s.part.resize(n);
    for (int k = 0; k < n; ++k) {
        const std::size_t v = std::size_t(order[std::size_t(k)]);
        s.joints.row(k) = graph.pos[v].transpose();
        s.radius(k) = graph.radius[v];
        s.part(k) = graph.part[v];
        s.parent(k) = parentOf[v] >= 0 ? index[std::size_t(parentOf[v])] : -1;
    }
    s.root = n > 0 ? 0 : -1;
    if (newIndex)
        *newIndex = std::move(index);
    return s;
}

std::vector<int> skeletonRoots(const Skeleton &skeleton)
{
    std::vector<int> roots;
    if (skeleton.root >= 0)
        roots.push_back(skeleton.root);
    for (int j = 0; j < skeleton.parent.size(); ++j) {
        if (skeleton.parent(j) < 0 && j != skeleton.root)
            roots.push_back(j);
    }
    return roots;
}

} // namespace detail
} // namespace finbook::geometry
