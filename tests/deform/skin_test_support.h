// Meshes and skeletons for the skinning tests and the skin/bones benches.
//
// The skeleton extraction of the app lives elsewhere, so tests derive a plausible skeleton from
// the mesh itself: a "medial tree". Clearance = graph distance from the outline; a root at the
// vertex of largest clearance; then, repeatedly, the vertex farthest (along the mesh) from the
// tree so far is joined to it by the path that hugs the medial axis (edge cost length /
// (clearance + h)²). Each path is cut into bones of about equal length. Like a real skeleton it
// runs inside the shape along its limbs; unlike one it ignores all but the largest component.
#pragma once

#include "../geometry/geometry_test_support.h"

#include <finbook/geometry/embedding.h>
#include <finbook/geometry/object_mesh.h>

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <queue>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <random>
#include <vector>

namespace finbook::test {

struct TestSkeleton {
    Eigen::MatrixX2d joints;
    Eigen::VectorXi parent;
};

// Directory of the shared real data, empty when it is not there.
inline QString realDataDir()
{
    QString dir = qEnvironmentVariable("FINBOOK_DATA_DIR");
#ifdef FINBOOK_DATA_DIR
    if (dir.isEmpty())
        dir = QStringLiteral(FINBOOK_DATA_DIR);
#endif
    return !dir.isEmpty() && QDir(dir).exists() ? dir : QString();
}

// Every sketch and silhouette file under dir, sorted.
inline QStringList realDataFiles(const QString &dir)
{
    QStringList files;
    for (const char *sub : {"sketches", "silhouettes"}) {
        const QDir d(dir + QLatin1Char('/') + QLatin1String(sub));
        for (const QString &name : d.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
            files << d.filePath(name);
    }
    return files;
}

// A data file (Quick, Draw! strokes with a 3 px pen, or contours) meshed by buildObjectMesh;
// asStrokes: contours as the app imports them (contoursAsStrokes, a 3 px pen).
inline std::optional<geometry::ObjectMesh>
meshDataFile(const QString &path, const geometry::MeshOptions &options = {}, bool asStrokes = false)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return std::nullopt;
    const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
    const QJsonArray contours = json.value(QStringLiteral("contours")).toArray();
    std::vector<geometry::StrokeInput> strokes;
    if (json.contains(QStringLiteral("strokes")))
        for (const QJsonValue &stroke : json.value(QStringLiteral("strokes")).toArray())
            strokes.push_back({toMatrix(stroke.toArray()), 3.0});
    else if (asStrokes)
        for (Eigen::MatrixX2d &points : contoursAsStrokes(contours))
            strokes.push_back({std::move(points), 3.0});
    if (!strokes.empty()) {
        auto mesh = geometry::buildObjectMesh(strokes, options);
        return mesh ? std::optional(std::move(*mesh)) : std::nullopt;
    }
    if (contours.isEmpty())
        return std::nullopt;
    geometry::Polygon polygon;
    polygon.outer = toMatrix(contours[0].toArray());
    for (qsizetype i = 1; i < contours.size(); ++i)
        polygon.holes.push_back(toMatrix(contours[i].toArray()));
    auto mesh = geometry::buildObjectMesh(geometry::Region{polygon}, options);
    return mesh ? std::optional(std::move(*mesh)) : std::nullopt;
}

// Undirected edge graph of a triangle mesh with edge lengths, and which vertices lie on the
// outline (edges used by one triangle).
struct MeshGraph {
    std::vector<std::vector<std::pair<int, double>>> adjacent;
    std::vector<bool> boundary;
};

inline MeshGraph meshGraph(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F)
{
    MeshGraph g{std::vector<std::vector<std::pair<int, double>>>(std::size_t(V.rows())),
                std::vector<bool>(std::size_t(V.rows()), false)};
    std::vector<std::vector<std::pair<int, int>>> uses(std::size_t(V.rows())); // (other, count)
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const int a = std::min(F(t, k), F(t, (k + 1) % 3));
            const int b = std::max(F(t, k), F(t, (k + 1) % 3));
            auto &list = uses[std::size_t(a)];
            auto it = std::find_if(list.begin(), list.end(), [b](auto &e) { return e.first == b; });
            if (it == list.end())
                list.emplace_back(b, 1);
            else
                ++it->second;
        }
    }
    for (int a = 0; a < int(V.rows()); ++a) {
        for (const auto &[b, count] : uses[std::size_t(a)]) {
            const double length = (V.row(a) - V.row(b)).norm();
            g.adjacent[std::size_t(a)].emplace_back(b, length);
            g.adjacent[std::size_t(b)].emplace_back(a, length);
            if (count == 1)
                g.boundary[std::size_t(a)] = g.boundary[std::size_t(b)] = true;
        }
    }
    return g;
}

// Multi-source Dijkstra; cost(a, b, length) per edge. Returns distances (∞ = unreached) and
// fills `previous` (−1 at sources and unreached vertices).
inline std::vector<double> dijkstra(const MeshGraph &g, const std::vector<int> &sources,
                                    const std::function<double(int, int, double)> &cost,
                                    std::vector<int> *previous = nullptr)
{
    std::vector<double> distance(g.adjacent.size(), INFINITY);
    if (previous)
        previous->assign(g.adjacent.size(), -1);
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    for (const int s : sources) {
        distance[std::size_t(s)] = 0.0;
        queue.emplace(0.0, s);
    }
    while (!queue.empty()) {
        const auto [d, a] = queue.top();
        queue.pop();
        if (d > distance[std::size_t(a)])
            continue;
        for (const auto &[b, length] : g.adjacent[std::size_t(a)]) {
            const double nd = d + cost(a, b, length);
            if (nd < distance[std::size_t(b)]) {
                distance[std::size_t(b)] = nd;
                if (previous)
                    (*previous)[std::size_t(b)] = a;
                queue.emplace(nd, b);
            }
        }
    }
    return distance;
}

// Cuts a vertex path (positions) into `pieces` bones of equal arc length; returns the joints
// after the start.
inline std::vector<Eigen::Vector2d> cutPath(const std::vector<Eigen::Vector2d> &path, int pieces)
{
    std::vector<double> arc{0.0};
    for (std::size_t i = 1; i < path.size(); ++i)
        arc.push_back(arc.back() + (path[i] - path[i - 1]).norm());
    std::vector<Eigen::Vector2d> joints;
    std::size_t segment = 1;
    for (int k = 1; k <= pieces; ++k) {
        const double s = arc.back() * k / pieces;
        while (segment + 1 < path.size() && arc[segment] < s)
            ++segment;
        const double span = arc[segment] - arc[segment - 1];
        const double t = span > 0 ? std::clamp((s - arc[segment - 1]) / span, 0.0, 1.0) : 1.0;
        joints.push_back(path[segment - 1] + t * (path[segment] - path[segment - 1]));
    }
    return joints;
}

// The deepest vertex (largest clearance) of the component with the most vertices.
inline int medialRoot(const MeshGraph &g, const std::vector<double> &clearance)
{
    const auto edgeLength = [](int, int, double length) { return length; };
    int root = 0;
    std::size_t bestReach = 0;
    std::vector<bool> seen(g.adjacent.size(), false);
    for (int v = 0; v < int(g.adjacent.size()); ++v) {
        if (seen[std::size_t(v)])
            continue;
        const std::vector<double> d = dijkstra(g, {v}, edgeLength);
        std::size_t reached = 0;
        int deepest = v;
        for (std::size_t w = 0; w < d.size(); ++w) {
            if (std::isfinite(d[w])) {
                seen[w] = true;
                ++reached;
                if (clearance[w] > clearance[std::size_t(deepest)])
                    deepest = int(w);
            }
        }
        if (reached > bestReach) {
            bestReach = reached;
            root = deepest;
        }
    }
    return root;
}

// Grows the tree from `root`: each branch is the medial path from the tree to the vertex
// farthest from it (in px along that path). Returns the branches as point paths that start
// on the tree.
inline std::vector<std::vector<Eigen::Vector2d>>
medialBranches(const Eigen::MatrixX2d &V, const MeshGraph &g, const std::vector<double> &clearance,
               int root, int branches, double meanEdge)
{
    const auto medial = [&](int a, int b, double length) {
        const double c = 0.5 * (clearance[std::size_t(a)] + clearance[std::size_t(b)]) + meanEdge;
        return length / (c * c);
    };
    std::vector<int> tree{root};
    std::vector<std::vector<Eigen::Vector2d>> paths;
    for (int branch = 0; branch < branches; ++branch) {
        std::vector<int> previous;
        dijkstra(g, tree, medial, &previous);
        std::vector<double> along(std::size_t(V.rows()), -1.0);
        for (const int t : tree)
            along[std::size_t(t)] = 0.0;
        const std::function<double(int)> lengthTo = [&](int v) -> double {
            if (along[std::size_t(v)] >= 0.0)
                return along[std::size_t(v)];
            const int p = previous[std::size_t(v)];
            return along[std::size_t(v)] =
                       p < 0 ? -2.0 : lengthTo(p) + (V.row(v) - V.row(p)).norm();
        };
        int tip = -1;
        for (int v = 0; v < int(V.rows()); ++v) {
            if (lengthTo(v) > (tip < 0 ? 0.0 : along[std::size_t(tip)]))
                tip = v;
        }
        if (tip < 0 || along[std::size_t(tip)] < 3.0 * meanEdge)
            break;
        std::vector<Eigen::Vector2d> path;
        int v = tip;
        for (; previous[std::size_t(v)] >= 0; v = previous[std::size_t(v)]) {
            path.push_back(V.row(v).transpose());
            tree.push_back(v);
        }
        path.push_back(V.row(v).transpose());
        std::reverse(path.begin(), path.end());
        paths.push_back(path);
    }
    return paths;
}

inline double pathLength(const std::vector<Eigen::Vector2d> &path)
{
    double length = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i)
        length += (path[i] - path[i - 1]).norm();
    return length;
}

// The medial tree described at the top, with at most `branches` paths and about `bones` bones.
inline TestSkeleton medialTreeSkeleton(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                       int bones = 20, int branches = 5)
{
    const MeshGraph g = meshGraph(V, F);
    std::vector<int> outline;
    for (std::size_t v = 0; v < g.boundary.size(); ++v)
        if (g.boundary[v])
            outline.push_back(int(v));
    const std::vector<double> clearance =
        dijkstra(g, outline, [](int, int, double length) { return length; });
    double meanEdge = 0.0;
    for (Eigen::Index t = 0; t < F.rows(); ++t)
        meanEdge += (V.row(F(t, 0)) - V.row(F(t, 1))).norm() / double(F.rows());
    const int root = medialRoot(g, clearance);
    const auto paths = medialBranches(V, g, clearance, root, branches, meanEdge);
    double total = 0.0;
    for (const auto &path : paths)
        total += pathLength(path);
    std::vector<Eigen::Vector2d> joints{V.row(root).transpose()};
    std::vector<int> parent{-1};
    for (const auto &path : paths) {
        const int pieces =
            std::max(1, int(std::lround(bones * pathLength(path) / std::max(total, 1e-9))));
        // The branch hangs from the existing joint nearest to where its path meets the tree.
        int from = 0;
        for (std::size_t j = 0; j < joints.size(); ++j)
            if ((joints[j] - path.front()).norm() <
                (joints[std::size_t(from)] - path.front()).norm())
                from = int(j);
        for (const Eigen::Vector2d &joint : cutPath(path, pieces)) {
            joints.push_back(joint);
            parent.push_back(from);
            from = int(joints.size()) - 1;
        }
    }
    TestSkeleton s{Eigen::MatrixX2d(Eigen::Index(joints.size()), 2),
                   Eigen::Map<Eigen::VectorXi>(parent.data(), Eigen::Index(parent.size()))};
    for (std::size_t j = 0; j < joints.size(); ++j)
        s.joints.row(Eigen::Index(j)) = joints[j].transpose();
    return s;
}

// `count` points spread uniformly over random triangles, with their embedding.
inline geometry::Embedding randomEmbedding(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                           int count, Eigen::MatrixX2d &points, unsigned seed = 7)
{
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> pick(0, int(F.rows()) - 1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    geometry::Embedding e{Eigen::VectorXi(count), Eigen::MatrixX3d(count, 3), 0, 0};
    points.resize(count, 2);
    for (int p = 0; p < count; ++p) {
        double a = unit(random), b = unit(random);
        if (a + b > 1.0) {
            a = 1.0 - a;
            b = 1.0 - b;
        }
        e.I(p) = pick(random);
        e.B.row(p) << 1.0 - a - b, a, b;
        points.row(p) = e.B(p, 0) * V.row(F(e.I(p), 0)) + e.B(p, 1) * V.row(F(e.I(p), 1)) +
                        e.B(p, 2) * V.row(F(e.I(p), 2));
    }
    return e;
}

} // namespace finbook::test
