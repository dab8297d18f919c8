// Two-level start for large meshes: the same shape meshed again with about a seventh of the
// vertices (its thinned outline's and about kCoarseShare inside), solved there first, and its
// triangles' rotations handed to the fine mesh's triangles before the fine passes. Coarse rotations
// of ~16 clusters (arap_coarse.cpp) leave a cold drag event at 20k vertices at 1.12× the converged
// energy: one rotation per cluster cannot bend smoothly. A real ARAP solve on ~2k vertices bends
// smoothly and costs about as much as three fine passes; the fine passes then only remove the
// short-wavelength error the coarse mesh cannot represent.
//
// The coarse mesh's pins: a coarse vertex that lies in a fine triangle whose corners are all
// pinned takes their targets' barycentric mix (a pinned band maps onto the coarse vertices
// inside it, exactly); a fine pin that no such coarse vertex represents nearby (a single pinned
// vertex, as the app's pins are) pins the coarse vertex nearest to it, moved onto the pin where
// the triangles around it allow (else at the same offset).
// Only the rotations cross over, and the fine global step that follows meets the fine pins
// exactly, so a coarse pin a little off only perturbs the start.
#include "arap_solver.h"

#include <finbook/geometry/mesh_boundary.h>
#include <finbook/geometry/object_mesh.h>
#include <finbook/geometry/polyline.h>
#include <finbook/geometry/region.h>
#include <finbook/geometry/simplicity.h>
#include <finbook/geometry/triangle_locator.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace finbook::deform::detail {
namespace {

// The coarse mesh aims at this fraction of the fine mesh's vertices, within these bounds; a
// coarse mesh that comes out above kMaxCoarseShare of them (thin drawings are nearly all
// outline, and the outline is not coarsened below what keeps it simple) is not used.
constexpr double kCoarseShare = 0.12;
constexpr int kMinCoarseVertices = 400;
constexpr int kMaxCoarseVertices = 4000;
constexpr double kMaxCoarseShare = 0.3;
// The size (bounding-box diagonal) the outline is meshed at.
constexpr double kCanonicalSize = 1000.0;

using geometry::signedArea;

// Keeps ring vertices at least `spacing` apart along the ring (always the first). Along the
// ring, not straight across as geometry::cleanPolyline measures: across, the two sides of a
// thin part fall within `spacing` of each other and lose their tip. With cleanPolyline the
// worst cold drag event of the 55 drawings at ~20k vertices went from 1.157× to 1.93× the
// converged energy (a tree sketch).
Eigen::MatrixX2d thinned(const Eigen::MatrixX2d &ring, double spacing)
{
    std::vector<Eigen::Index> kept{0};
    double run = 0.0;
    for (Eigen::Index i = 1; i < ring.rows(); ++i) {
        run += (ring.row(i) - ring.row(i - 1)).norm();
        if (run >= spacing) {
            kept.push_back(i);
            run = 0.0;
        }
    }
    if (kept.size() > 1 && (ring.row(kept.back()) - ring.row(0)).norm() < 0.5 * spacing)
        kept.pop_back();
    Eigen::MatrixX2d out(Eigen::Index(kept.size()), 2);
    for (std::size_t k = 0; k < kept.size(); ++k)
        out.row(Eigen::Index(k)) = ring.row(kept[k]);
    return out;
}

// The solved triangles' outline as a region: outer rings (positive area) with their holes,
// each ring thinned to `spacing` where that keeps its orientation (0: whole).
geometry::Region outline(const Eigen::MatrixX2d &V, const std::vector<Eigen::VectorXi> &loops,
                         double spacing)
{
    std::vector<Eigen::MatrixX2d> outers, holes;
    for (const Eigen::VectorXi &loop : loops) {
        Eigen::MatrixX2d ring(loop.size(), 2);
        for (Eigen::Index i = 0; i < loop.size(); ++i)
            ring.row(i) = V.row(loop(i));
        if (spacing > 0.0) {
            Eigen::MatrixX2d thin = thinned(ring, spacing);
            if (thin.rows() >= 3 && (signedArea(thin) > 0.0) == (signedArea(ring) > 0.0))
                ring = std::move(thin);
        }
        (signedArea(ring) > 0.0 ? outers : holes).push_back(std::move(ring));
    }
    geometry::Region region(outers.size());
    for (std::size_t k = 0; k < outers.size(); ++k)
        region[k].outer = outers[k];
    for (Eigen::MatrixX2d &hole : holes) { // into the smallest outer ring around it
        std::size_t best = region.size();
        double bestArea = INFINITY;
        for (std::size_t k = 0; k < outers.size(); ++k) {
            const double area = signedArea(outers[k]);
            if (area < bestArea &&
                geometry::regionContains({{outers[k], {}}}, hole(0, 0), hole(0, 1))) {
                best = k;
                bestArea = area;
            }
        }
        if (best == region.size())
            return {}; // a hole outside every outer ring: not an outline this can mesh
        region[best].holes.push_back(std::move(hole));
    }
    return region;
}

// Whether coarse vertex c can move to p with every triangle around it keeping at least a
// quarter of its area (counter-clockwise, as meshRegion makes them).
bool movable(const Eigen::MatrixX2d &Vc, const Eigen::MatrixX3i &Fc, const VertexRings &rings,
             Eigen::Index c, const Eigen::Vector2d &p)
{
    const auto doubleArea = [](const Eigen::Vector2d &a, const Eigen::Vector2d &b,
                               const Eigen::Vector2d &d) {
        return (b - a).x() * (d - a).y() - (b - a).y() * (d - a).x();
    };
    for (int i = rings.start[std::size_t(c)]; i < rings.start[std::size_t(c) + 1]; ++i) {
        const int t = rings.triangle[std::size_t(i)], r = rings.corner[std::size_t(i)];
        const Eigen::Vector2d a = Vc.row(Fc(t, (r + 1) % 3)), b = Vc.row(Fc(t, (r + 2) % 3));
        if (!(doubleArea(p, a, b) >= 0.25 * doubleArea(Vc.row(c).transpose(), a, b)))
            return false;
    }
    return true;
}

} // namespace

std::optional<TwoLevelBuild> buildTwoLevel(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                           const std::vector<Eigen::Index> &solvedTriangles,
                                           const Eigen::VectorXi &b, const ArapOptions &options)
{
    // The solved triangles, all turned counter-clockwise (y-up), as the outline wants them.
    const auto m = Eigen::Index(solvedTriangles.size());
    Eigen::MatrixX3i Fs(m, 3);
    std::vector<char> used(std::size_t(V.rows()), 0);
    for (Eigen::Index k = 0; k < m; ++k) {
        Eigen::Vector3i f = F.row(solvedTriangles[std::size_t(k)]);
        const Eigen::Vector2d e1 = V.row(f(1)) - V.row(f(0)), e2 = V.row(f(2)) - V.row(f(0));
        if (e1.x() * e2.y() - e1.y() * e2.x() < 0.0)
            std::swap(f(1), f(2));
        Fs.row(k) = f;
        for (int r = 0; r < 3; ++r)
            used[std::size_t(f(r))] = 1;
    }
    const auto fineVertices = double(std::count(used.begin(), used.end(), 1));
    geometry::MeshOptions mesh;
    mesh.targetVertices = int(std::clamp(kCoarseShare * fineVertices, double(kMinCoarseVertices),
                                         double(kMaxCoarseVertices)));
    mesh.maxVertices = int(kMaxCoarseShare * fineVertices);
    mesh.minEdge = 0.0; // the edge follows from the vertex count at any scale, not from pixels
    // Meshed at a fixed size: the mesher's tolerances are in pixels, and a drawing's mesh
    // should get the same coarse level whatever units it comes in.
    Eigen::Vector2d low = Eigen::Vector2d::Constant(INFINITY),
                    high = Eigen::Vector2d::Constant(-INFINITY);
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        if (used[std::size_t(v)]) {
            low = low.cwiseMin(V.row(v).transpose());
            high = high.cwiseMax(V.row(v).transpose());
        }
    }
    const double scale = kCanonicalSize / std::max((high - low).norm(), 1e-300);
    const Eigen::MatrixX2d Vn = (V.rowwise() - low.transpose()) * scale;
    const std::vector<Eigen::VectorXi> loops = geometry::boundaryLoops(Fs);
    geometry::Region region = outline(Vn, loops, 0.0);
    if (region.empty())
        return std::nullopt;
    const double edge = geometry::meshEdgeLength(geometry::regionArea(region),
                                                 geometry::regionPerimeter(region), mesh);
    // The outline thinned to about half the coarse edge (where it stays simple): kept whole,
    // a fine outline alone would be most of the coarse mesh's vertices.
    geometry::Region thin = outline(Vn, loops, 0.5 * edge);
    if (!thin.empty() && geometry::isSimple(thin, geometry::Touching::Forbidden))
        region = std::move(thin);
    auto coarse = geometry::meshRegion(region, mesh);
    if (!coarse || double(coarse->V.rows()) > kMaxCoarseShare * fineVertices)
        return std::nullopt;
    Eigen::MatrixX2d Vc = (coarse->V / scale).rowwise() + low.transpose();
    const Eigen::MatrixX3i &Fc = coarse->F;

    std::vector<char> pinned(std::size_t(V.rows()), 0);
    for (Eigen::Index e = 0; e < b.size(); ++e)
        pinned[std::size_t(b(e))] = 1;
    // Coarse vertices inside fully pinned fine triangles: barycentric targets.
    const geometry::TriangleLocator fine(V, Fs);
    TwoLevelBuild out;
    std::vector<Eigen::Vector3i> vertices;
    std::vector<Eigen::Vector3d> weights;
    std::vector<std::complex<double>> offsets;
    std::vector<int> coarsePins;
    std::vector<char> coarsePinned(std::size_t(Vc.rows()), 0);
    for (Eigen::Index c = 0; c < Vc.rows(); ++c) {
        const geometry::Location at = fine.locate(Vc.row(c).transpose());
        if (at.triangle < 0)
            continue;
        const Eigen::Vector3i f = Fs.row(at.triangle);
        if (!(pinned[std::size_t(f(0))] && pinned[std::size_t(f(1))] && pinned[std::size_t(f(2))]))
            continue;
        Eigen::Vector2d p = Eigen::Vector2d::Zero();
        for (int r = 0; r < 3; ++r)
            p += at.weights(r) * V.row(f(r)).transpose();
        vertices.push_back(f);
        weights.push_back(at.weights);
        offsets.emplace_back(Vc(c, 0) - p.x(), Vc(c, 1) - p.y());
        coarsePins.push_back(int(c));
        coarsePinned[std::size_t(c)] = 1;
    }
    // Fine pins no such coarse vertex represents: the nearest corner of the coarse triangle
    // they lie in, unless a corner of that triangle is pinned already.
    const geometry::TriangleLocator coarseLocator(Vc, Fc);
    std::vector<double> nearest(std::size_t(Vc.rows()), INFINITY);
    std::vector<int> nearestPin(std::size_t(Vc.rows()), -1);
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        if (!pinned[std::size_t(v)] || !used[std::size_t(v)])
            continue;
        const geometry::Location at = coarseLocator.locate(V.row(v).transpose());
        if (at.triangle < 0)
            return std::nullopt;
        const Eigen::Vector3i f = Fc.row(at.triangle);
        if (coarsePinned[std::size_t(f(0))] || coarsePinned[std::size_t(f(1))] ||
            coarsePinned[std::size_t(f(2))])
            continue;
        int corner = 0;
        at.weights.maxCoeff(&corner);
        const int c = f(corner);
        const double distance = (Vc.row(c) - V.row(v)).squaredNorm();
        if (distance < nearest[std::size_t(c)]) {
            nearest[std::size_t(c)] = distance;
            nearestPin[std::size_t(c)] = int(v);
        }
    }
    std::optional<VertexRings> rings; // built for the first such pin
    for (Eigen::Index c = 0; c < Vc.rows(); ++c) {
        const int v = nearestPin[std::size_t(c)];
        if (v < 0)
            continue;
        if (!rings)
            rings = vertexRings(Vc.rows(), Fc);
        if (movable(Vc, Fc, *rings, c, V.row(v).transpose()))
            Vc.row(c) = V.row(v); // the pin itself, so its target needs no offset
        vertices.emplace_back(v, v, v);
        weights.emplace_back(1.0, 0.0, 0.0);
        offsets.emplace_back(Vc(c, 0) - V(v, 0), Vc(c, 1) - V(v, 1));
        coarsePins.push_back(int(c));
    }
    const auto entries = Eigen::Index(coarsePins.size());
    Eigen::VectorXi bc = Eigen::Map<const Eigen::VectorXi>(coarsePins.data(), entries);
    ArapOptions coarseOptions = options;
    coarseOptions.method = ArapMethod::Refined;
    coarseOptions.dragBudgetMs = kTwoLevelBudgetShare * options.dragBudgetMs;
    coarseOptions.fixFlips = false; // only its rotations are used
    coarseOptions.followNearestComponent = false;
    coarseOptions.twoLevelVertices = 0; // a third level did not help (the 20k bar: 1.08×)
    auto level = arapPrecompute(Vc, Fc, bc, coarseOptions);
    // Every coarse triangle must be solved (a coarse part with fewer than two pins is not).
    if (!level || (*level)->triangles.rows() != Fc.rows())
        return std::nullopt;
    out.level = *level;
    out.entryVertices.resize(entries, 3);
    out.entryWeights.resize(entries, 3);
    out.entryOffset.resize(entries);
    for (Eigen::Index e = 0; e < entries; ++e) {
        out.entryVertices.row(e) = vertices[std::size_t(e)];
        out.entryWeights.row(e) = weights[std::size_t(e)];
        out.entryOffset(e) = offsets[std::size_t(e)];
    }
    return out;
}

bool attachTwoLevel(ArapPrecompute &d, const TwoLevelBuild &build, const std::vector<int> &internal)
{
    const Eigen::Index handles = d.handleEntry.size();
    Eigen::MatrixX3i entryHandles(build.entryVertices.rows(), 3);
    for (Eigen::Index e = 0; e < entryHandles.rows(); ++e) {
        for (int r = 0; r < 3; ++r) {
            const Eigen::Index h =
                Eigen::Index(internal[std::size_t(build.entryVertices(e, r))]) - d.freeCount;
            if (h < 0 || h >= handles)
                return false;
            entryHandles(e, r) = int(h);
        }
    }
    const ArapPrecompute &level = *build.level;
    Eigen::MatrixX2d rest(level.rest.size(), 2);
    rest.col(0) = level.rest.real();
    rest.col(1) = level.rest.imag();
    const geometry::TriangleLocator locator(rest, level.triangles);
    Eigen::VectorXi triangle(d.triangles.rows());
    for (Eigen::Index t = 0; t < d.triangles.rows(); ++t) {
        const Complex c =
            (d.rest(d.triangles(t, 0)) + d.rest(d.triangles(t, 1)) + d.rest(d.triangles(t, 2))) /
            3.0;
        triangle(t) = locator.locate(Eigen::Vector2d(c.real(), c.imag())).triangle;
        if (triangle(t) < 0)
            return false;
    }
    d.coarseLevel = build.level;
    d.coarseLevelTriangle = std::move(triangle);
    d.coarseLevelHandles = std::move(entryHandles);
    d.coarseLevelWeights = build.entryWeights;
    d.coarseLevelOffset = build.entryOffset;
    chooseDragPasses(d);
    return true;
}

bool twoLevelStart(const ArapPrecompute &d, Workspace &w)
{
    const ArapPrecompute &level = *d.coarseLevel;
    const auto targets = w.positions.segment(d.freeCount, d.handleEntry.size());
    Eigen::MatrixX2d bc(d.coarseLevelHandles.rows(), 2);
    for (Eigen::Index e = 0; e < bc.rows(); ++e) {
        Complex z = d.coarseLevelOffset(e);
        for (int r = 0; r < 3; ++r)
            z += d.coarseLevelWeights(e, r) * targets(d.coarseLevelHandles(e, r));
        bc.row(e) << z.real(), z.imag();
    }
    if (!solveCoarseLevel(level, bc, w.coarseLevelRotations))
        return false;
    const int *coarse = d.coarseLevelTriangle.data();
    for (Eigen::Index t = 0; t < d.triangles.rows(); ++t)
        w.rotations(t) = w.coarseLevelRotations(coarse[t]);
    globalStep(d, w);
    return true;
}

} // namespace finbook::deform::detail
