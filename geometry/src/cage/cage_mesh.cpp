#include "cage_lattice.h"
#include "cage_strip_mesher.h"

#include <finbook/geometry/cage/cage_mesh.h>
#include <finbook/geometry/cage/cage_polygon.h>
#include <finbook/geometry/polyline.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace finbook::geometry {
namespace {

// Lattice spacing relative to maxEdge: strip triangles reach from the cage to the lattice, so
// the lattice is a little finer than the size bound to leave them room.
constexpr double kLatticeRatio = 0.9;
// Lattice vertices closer than this × spacing to the cage are left to the strip. Above the
// lattice triangles' circumradius (1/√3 ≈ 0.577) kept triangles stay inside the cage; a little
// more gives the mesher room to meet the angle bound. (Wider strips, or a row of lattice
// triangles handed to CGAL unconstrained, measured slower: CGAL's time is the strip's.)
constexpr double kClearanceRatio = 0.75;
// Rounds of taking lattice vertices out when refinement split an edge of the tiled region;
// after that the whole cage is meshed by CGAL alone.
constexpr int kMaxShrinkRounds = 4;

GeometryError meshError(GeometryErrorCode code, std::string message)
{
    return GeometryError{code, std::move(message)};
}

double perimeter(const Eigen::MatrixX2d &corners)
{
    return polylineLength(corners, true);
}

// Vertices meshCage makes at lattice spacing h: the lattice's density 2/(√3 h²) over the area,
// plus the boundary and the strip's extra row, both about perimeter / h.
double estimateVertices(double area, double length, double h)
{
    return 2.0 / std::sqrt(3.0) * area / (h * h) + 1.2 * length / h;
}

struct Ring {
    std::vector<Eigen::Vector2d> points; // corners first (id = corner index), then the splits
    std::vector<int> ids;                // the boundary in order
};

// Each cage edge in equal pieces no longer than h.
Ring subdivide(const Eigen::MatrixX2d &corners, double h)
{
    Ring ring;
    const Eigen::Index c = corners.rows();
    for (Eigen::Index e = 0; e < c; ++e)
        ring.points.emplace_back(corners.row(e).transpose());
    for (Eigen::Index e = 0; e < c; ++e) {
        const Eigen::Vector2d a = corners.row(e), b = corners.row((e + 1) % c);
        const long pieces = std::max(1L, long(std::ceil((b - a).norm() / h)));
        ring.ids.push_back(int(e));
        for (long k = 1; k < pieces; ++k) {
            ring.ids.push_back(int(ring.points.size()));
            ring.points.push_back(a + (double(k) / double(pieces)) * (b - a));
        }
    }
    return ring;
}

struct RawCageMesh {
    std::vector<Eigen::Vector2d> points;
    std::vector<Eigen::Vector3i> triangles;
    std::size_t stripEnd = 0;     // triangles [0, stripEnd) come from the strip mesher
    std::size_t latticeBegin = 0; // points [latticeBegin, latticeEnd) are lattice vertices
    std::size_t latticeEnd = 0;
    std::size_t ringEnd = 0;    // points [0, ringEnd) are corners and their subdivisions
    std::size_t addedBegin = 0; // points from here on were added by refinement
};

// Per kept lattice triangle: the vertex refinement put at the midpoint of each of its edges
// (edge e joins corner e and corner e + 1), −1 where the edge is whole.
using EdgeMidpoints = std::vector<std::array<int, 3>>;

// Splits of the tiled region's edges at their midpoints are patched (see addLatticeTriangles).
// Any other split (two or more points on one edge, or one off the midpoint) takes the
// triangle's vertices out of the tiling instead; returns false when it had to.
bool findMidpoints(const detail::CageLattice::Tiling &tiling, const detail::StripInput &input,
                   const detail::StripMesh &strip, double h, detail::CageLattice &lattice,
                   EdgeMidpoints &midpoints)
{
    midpoints.clear(); // empty: nothing split
    if (!strip.splits.empty())
        midpoints.assign(tiling.triangles.size(), {-1, -1, -1});
    const auto position = [&](int id) -> const Eigen::Vector2d & {
        return std::size_t(id) < input.points.size()
                   ? input.points[std::size_t(id)]
                   : strip.added[std::size_t(id) - input.points.size()];
    };
    bool patchable = true;
    for (const detail::FrontSplit &split : strip.splits) {
        const int t = tiling.frontTriangle[split.front];
        const Eigen::Vector3i &tri = tiling.triangles[std::size_t(t)];
        const int a = tiling.front[split.front].first, b = tiling.front[split.front].second;
        const int e = tri[0] == a ? 0 : (tri[1] == a ? 1 : 2);
        const Eigen::Vector2d middle =
            0.5 * (tiling.points[std::size_t(a)] + tiling.points[std::size_t(b)]);
        if (split.inner.size() == 1 &&
            (position(split.inner.front()) - middle).norm() <= 1e-9 * h) {
            midpoints[std::size_t(t)][std::size_t(e)] = split.inner.front();
            continue;
        }
        for (int k = 0; k < 3; ++k)
            lattice.exclude(tiling.cells[std::size_t(tri[k])]);
        patchable = false;
    }
    return patchable;
}

// Appends the lattice triangles to raw (ids shifted by offset). A triangle with split edges is
// replaced by the triangles of its edge midpoints (red–green refinement: angles ≥ 30°); those
// go before raw.stripEnd, so that the boundary walk sees both sides of the split edges.
void addLatticeTriangles(const detail::CageLattice::Tiling &tiling, const EdgeMidpoints &midpoints,
                         int offset, RawCageMesh &raw)
{
    for (std::size_t t = 0; t < midpoints.size(); ++t) {
        const std::array<int, 3> &m = midpoints[t];
        const int splits = int(m[0] >= 0) + int(m[1] >= 0) + int(m[2] >= 0);
        if (splits == 0)
            continue;
        const Eigen::Vector3i v = tiling.triangles[t] + Eigen::Vector3i::Constant(offset);
        if (splits == 3) {
            raw.triangles.emplace_back(v[0], m[0], m[2]);
            raw.triangles.emplace_back(m[0], v[1], m[1]);
            raw.triangles.emplace_back(m[2], m[1], v[2]);
            raw.triangles.emplace_back(m[0], m[1], m[2]);
            continue;
        }
        // Rotate so that edge 0 is the split one (one split) or the whole one (two splits).
        int e = 0;
        while ((m[std::size_t(e)] >= 0) != (splits == 1))
            ++e;
        const int a = v[e], b = v[(e + 1) % 3], c = v[(e + 2) % 3];
        if (splits == 1) {
            raw.triangles.emplace_back(a, m[std::size_t(e)], c);
            raw.triangles.emplace_back(m[std::size_t(e)], b, c);
        } else {
            const int bc = m[std::size_t((e + 1) % 3)], ca = m[std::size_t((e + 2) % 3)];
            raw.triangles.emplace_back(a, b, bc);
            raw.triangles.emplace_back(a, bc, ca);
            raw.triangles.emplace_back(bc, c, ca);
        }
    }
    raw.stripEnd = raw.triangles.size();
    raw.triangles.reserve(raw.triangles.size() + tiling.triangles.size());
    for (std::size_t t = 0; t < tiling.triangles.size(); ++t)
        if (midpoints.empty() ||
            (midpoints[t][0] < 0 && midpoints[t][1] < 0 && midpoints[t][2] < 0))
            raw.triangles.push_back(tiling.triangles[t] + Eigen::Vector3i::Constant(offset));
}

Expected<RawCageMesh, GeometryError> meshParts(const Eigen::MatrixX2d &corners, double maxEdge,
                                               long vertexCap)
{
    const double h = kLatticeRatio * maxEdge;
    const Ring ring = subdivide(corners, h);
    detail::CageLattice lattice(corners, h, kClearanceRatio * h);
    for (int round = 0; round <= kMaxShrinkRounds; ++round) {
        const bool tiled = round < kMaxShrinkRounds;
        detail::CageLattice::Tiling tiling;
        if (tiled)
            tiling = lattice.tiling();
        detail::StripInput input;
        input.points = ring.points;
        input.ring = ring.ids;
        const int offset = int(input.points.size());
        input.points.insert(input.points.end(), tiling.points.begin(), tiling.points.end());
        for (const auto &[a, b] : tiling.front)
            input.front.emplace_back(a + offset, b + offset);
        for (std::size_t k = tiling.usedCount; k < tiling.points.size(); ++k)
            input.loose.push_back(int(k) + offset);
        auto strip = detail::meshStrip(input, maxEdge, vertexCap);
        if (!strip)
            return unexpected(strip.error());
        EdgeMidpoints midpoints;
        if (!findMidpoints(tiling, input, *strip, h, lattice, midpoints))
            continue;
        RawCageMesh raw;
        raw.points = std::move(input.points);
        raw.latticeBegin = std::size_t(offset);
        raw.latticeEnd = std::size_t(offset) + tiling.usedCount;
        raw.ringEnd = ring.points.size();
        raw.addedBegin = raw.points.size();
        raw.points.insert(raw.points.end(), strip->added.begin(), strip->added.end());
        raw.triangles = std::move(strip->triangles);
        addLatticeTriangles(tiling, midpoints, offset, raw);
        return raw;
    }
    return unexpected(
        meshError(GeometryErrorCode::TriangulationFailed, "Meshing the cage did not converge."));
}

// The cage's boundary, walked counter-clockwise from corner 0: the strip triangles' edges with
// only one triangle. Only points on the cage can end such an edge (the tiled region's edges
// join lattice vertices), so only edges between those are looked at.
Expected<std::vector<int>, GeometryError> boundaryWalk(const RawCageMesh &raw)
{
    const auto onCage = [&](int v) {
        return std::size_t(v) < raw.ringEnd || std::size_t(v) >= raw.addedBegin;
    };
    struct HalfEdge {
        long long key; // the unordered edge
        int from, to;
    };
    std::vector<HalfEdge> halfEdges;
    for (std::size_t t = 0; t < raw.stripEnd; ++t) {
        for (int k = 0; k < 3; ++k) {
            const int a = raw.triangles[t][k], b = raw.triangles[t][(k + 1) % 3];
            if (onCage(a) && onCage(b))
                halfEdges.push_back(
                    {(static_cast<long long>(std::min(a, b)) << 32) | std::max(a, b), a, b});
        }
    }
    std::sort(halfEdges.begin(), halfEdges.end(),
              [](const HalfEdge &x, const HalfEdge &y) { return x.key < y.key; });
    std::vector<int> next(raw.points.size(), -1);
    std::size_t count = 0;
    for (std::size_t i = 0; i < halfEdges.size();) {
        std::size_t j = i + 1;
        while (j < halfEdges.size() && halfEdges[j].key == halfEdges[i].key)
            ++j;
        if (j == i + 1) { // one triangle only: on the cage
            if (next[std::size_t(halfEdges[i].from)] >= 0)
                return unexpected(meshError(GeometryErrorCode::TriangulationFailed,
                                            "The cage mesh's boundary branches."));
            next[std::size_t(halfEdges[i].from)] = halfEdges[i].to;
            ++count;
        }
        i = j;
    }
    std::vector<int> walk{0};
    while (walk.size() <= count) {
        const int to = next[std::size_t(walk.back())];
        if (to < 0)
            break;
        if (to == 0)
            return walk.size() == count
                       ? Expected<std::vector<int>, GeometryError>(std::move(walk))
                       : unexpected(meshError(GeometryErrorCode::TriangulationFailed,
                                              "The cage mesh's boundary is not one loop."));
        walk.push_back(to);
    }
    return unexpected(meshError(GeometryErrorCode::TriangulationFailed,
                                "The cage mesh's boundary is not closed."));
}

struct BoundaryEntry {
    int vertex, edge;
    double t;
};

// Edge and parameter of every boundary vertex but the corners, from the corners the walk passes
// before and after it; sorted by edge, then parameter.
Expected<std::vector<BoundaryEntry>, GeometryError> boundaryEntries(const Eigen::MatrixX2d &corners,
                                                                    const RawCageMesh &raw,
                                                                    const std::vector<int> &walk)
{
    const int c = int(corners.rows());
    std::vector<int> cornerAt; // positions of the corners along the walk
    for (std::size_t k = 0; k < walk.size(); ++k)
        if (walk[k] < c)
            cornerAt.push_back(int(k));
    if (int(cornerAt.size()) != c)
        return unexpected(meshError(GeometryErrorCode::TriangulationFailed,
                                    "A corner of the cage is missing from its mesh's boundary."));
    std::vector<BoundaryEntry> boundary;
    for (int s = 0; s < c; ++s) {
        const int from = walk[std::size_t(cornerAt[std::size_t(s)])];
        const int to = walk[std::size_t(cornerAt[std::size_t((s + 1) % c)])];
        // Walked counter-clockwise: a clockwise cage's edges come backwards.
        const int edge = to == (from + 1) % c ? from : (from == (to + 1) % c ? to : -1);
        if (edge < 0)
            return unexpected(meshError(GeometryErrorCode::TriangulationFailed,
                                        "The cage mesh's boundary skips a corner."));
        const Eigen::Vector2d a = corners.row(edge),
                              ab = corners.row((edge + 1) % c) - a.transpose();
        const int end = s + 1 < c ? cornerAt[std::size_t(s + 1)] : int(walk.size());
        for (int k = cornerAt[std::size_t(s)] + 1; k < end; ++k) {
            const int v = walk[std::size_t(k)];
            const double t =
                std::clamp((raw.points[std::size_t(v)] - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
            boundary.push_back({v, edge, t});
        }
    }
    std::sort(boundary.begin(), boundary.end(), [](const BoundaryEntry &x, const BoundaryEntry &y) {
        return x.edge != y.edge ? x.edge < y.edge : x.t < y.t;
    });
    return boundary;
}

// The mesh with its vertices in CageMesh's order: corners, boundary entries, the rest.
CageMesh orderVertices(const Eigen::MatrixX2d &corners, const RawCageMesh &raw,
                       const std::vector<BoundaryEntry> &boundary)
{
    const int c = int(corners.rows());
    std::vector<int> newIndex(raw.points.size(), -1);
    CageMesh mesh;
    mesh.cornerCount = c;
    mesh.boundaryCount = c + Eigen::Index(boundary.size());
    mesh.boundaryEdge.resize(mesh.boundaryCount);
    mesh.boundaryParameter.resize(mesh.boundaryCount);
    int next = 0;
    for (int v = 0; v < c; ++v) {
        newIndex[std::size_t(v)] = next;
        mesh.boundaryEdge(next) = v;
        mesh.boundaryParameter(next++) = 0.0;
    }
    for (const BoundaryEntry &entry : boundary) {
        newIndex[std::size_t(entry.vertex)] = next;
        mesh.boundaryEdge(next) = entry.edge;
        mesh.boundaryParameter(next++) = entry.t;
    }
    std::vector<char> referenced(raw.points.size(), 0);
    for (const Eigen::Vector3i &t : raw.triangles)
        for (int k = 0; k < 3; ++k)
            referenced[std::size_t(t[k])] = 1;
    for (std::size_t v = 0; v < raw.points.size(); ++v) {
        if (referenced[v] && newIndex[v] < 0) {
            newIndex[v] = next++;
            mesh.latticeVertices += v >= raw.latticeBegin && v < raw.latticeEnd ? 1 : 0;
        }
    }
    mesh.V.resize(next, 2);
    for (std::size_t v = 0; v < raw.points.size(); ++v)
        if (newIndex[v] >= 0)
            mesh.V.row(newIndex[v]) = raw.points[v].transpose();
    for (int v = 0; v < c; ++v) // exactly as given, whatever CGAL did with them
        mesh.V.row(v) = corners.row(v);
    mesh.F.resize(Eigen::Index(raw.triangles.size()), 3);
    for (std::size_t t = 0; t < raw.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            mesh.F(Eigen::Index(t), k) = newIndex[std::size_t(raw.triangles[t][k])];
    return mesh;
}

} // namespace

double cageVertexEstimate(const Eigen::MatrixX2d &corners, double maxEdge)
{
    if (checkCage(corners) || !std::isfinite(maxEdge) || !(maxEdge > 0.0))
        return 0.0;
    return estimateVertices(std::abs(signedArea(corners)), perimeter(corners),
                            kLatticeRatio * maxEdge);
}

double cageEdgeLength(const Eigen::MatrixX2d &corners, long targetVertices)
{
    if (checkCage(corners) || targetVertices < 3)
        return 0.0;
    // estimateVertices(h) = a/h² + b/h = target, solved for x = 1/h.
    const double a = 2.0 / std::sqrt(3.0) * std::abs(signedArea(corners));
    const double b = 1.2 * perimeter(corners);
    const double target = double(targetVertices);
    const double x = (-b + std::sqrt(b * b + 4.0 * a * target)) / (2.0 * a);
    return 1.0 / (kLatticeRatio * x);
}

Expected<CageMesh, GeometryError> meshCage(const Eigen::MatrixX2d &corners, double maxEdge)
{
    if (auto error = checkCage(corners))
        return unexpected(std::move(*error));
    if (!std::isfinite(maxEdge) || !(maxEdge > 0.0))
        return unexpected(meshError(GeometryErrorCode::InvalidOptions,
                                    "The cage mesh's edge length must be a positive number."));
    const double estimate = estimateVertices(std::abs(signedArea(corners)), perimeter(corners),
                                             kLatticeRatio * maxEdge);
    if (!(estimate <= double(kMaxCageMeshVertices)))
        return unexpected(meshError(GeometryErrorCode::InvalidOptions,
                                    "The cage mesh would be too fine; choose a longer edge."));
    const long cap = 2 * long(estimate) + 4 * corners.rows() + 1000;
    auto raw = meshParts(corners, maxEdge, cap);
    if (!raw)
        return unexpected(raw.error());
    auto walk = boundaryWalk(*raw);
    if (!walk)
        return unexpected(walk.error());
    auto boundary = boundaryEntries(corners, *raw, *walk);
    if (!boundary)
        return unexpected(boundary.error());
    return orderVertices(corners, *raw, *boundary);
}

} // namespace finbook::geometry
