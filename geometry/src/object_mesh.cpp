#include "cdt_mesher.h"
#include "mesh_cleanup.h"

#include <finbook/geometry/mesh_boundary.h>
#include <finbook/geometry/object_mesh.h>
#include <finbook/geometry/object_shape.h>
#include <finbook/geometry/simplicity.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace finbook::geometry {
namespace {

// Vertex count of a refined mesh with size bound S, fitted on disks and thin bands:
// N ≈ kAreaFactor·A/S² + kBoundaryFactor·P/S (interior vertices fill the area, boundary
// vertices line the outline).
constexpr double kAreaFactor = 2.0;
constexpr double kBoundaryFactor = 0.8;

double edgeForVertexCount(double area, double perimeter, double vertices)
{
    const double a = kAreaFactor * area, b = kBoundaryFactor * perimeter;
    // Positive root of a·u² + b·u − N = 0 for u = 1/S.
    const double u = (-b + std::sqrt(b * b + 4.0 * a * vertices)) / (2.0 * a);
    return 1.0 / u;
}

bool validOptions(const MeshOptions &options)
{
    return std::isfinite(options.density) && options.density > 0.0 && options.density <= 100.0 &&
           options.targetVertices >= 3 && options.maxVertices >= options.targetVertices &&
           std::isfinite(options.minEdge) && options.minEdge >= 0.0;
}

Expected<TriMesh, GeometryError> toTriMesh(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F)
{
    TriMesh mesh;
    mesh.reserve(std::size_t(V.rows()), std::size_t(F.rows() + V.rows()), std::size_t(F.rows()));
    std::vector<TriMesh::VertexHandle> handles;
    handles.reserve(std::size_t(V.rows()));
    for (Eigen::Index v = 0; v < V.rows(); ++v)
        handles.push_back(mesh.add_vertex(TriMesh::Point(V(v, 0), V(v, 1), 0.0)));
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
        const TriMesh::FaceHandle face =
            mesh.add_face(handles[std::size_t(F(f, 0))], handles[std::size_t(F(f, 1))],
                          handles[std::size_t(F(f, 2))]);
        if (!face.is_valid())
            return unexpected(GeometryError{GeometryErrorCode::TriangulationFailed,
                                            "The mesh has a non-manifold spot OpenMesh cannot "
                                            "store; try a slightly different outline."});
    }
    return mesh;
}

} // namespace

double meshEdgeLength(double area, double perimeter, const MeshOptions &options)
{
    if (!(area > 0.0) || !validOptions(options))
        return options.minEdge > 0.0 ? options.minEdge : 1.0;
    const double target = edgeForVertexCount(area, perimeter, options.targetVertices);
    const double ceiling = edgeForVertexCount(area, perimeter, options.maxVertices);
    return std::max({target / options.density, ceiling, options.minEdge});
}

Expected<ObjectMesh, GeometryError> meshRegion(const Region &region, const MeshOptions &options)
{
    if (!validOptions(options))
        return unexpected(GeometryError{GeometryErrorCode::InvalidOptions,
                                        "Mesh density must be in (0, 100], target vertices at "
                                        "least 3 and not above the maximum, minimum edge ≥ 0."});
    if (!isSimple(region, Touching::AllowedAtPoints))
        return unexpected(GeometryError{GeometryErrorCode::NotSimple,
                                        "The outline crosses or touches itself; repair it "
                                        "(repairRegion) before meshing."});
    const double area = regionArea(region);
    if (!(area > 0.0) || !std::isfinite(area))
        return unexpected(
            GeometryError{GeometryErrorCode::DegenerateRegion, "The outline encloses no area."});
    const double edge = meshEdgeLength(area, regionPerimeter(region), options);
    // Dense outlines bring their own vertices on top of the estimate; the cap only guards
    // against runaway refinement.
    const long cap = 2L * options.maxVertices + 2L * regionVertexCount(region);
    auto raw = detail::refineRegion(region, edge, cap);
    if (!raw)
        return unexpected(raw.error());
    detail::dropDegenerate(raw->V, raw->F);
    detail::splitNonManifoldVertices(raw->V, raw->F);
    if (raw->F.rows() == 0)
        return unexpected(GeometryError{GeometryErrorCode::DegenerateRegion,
                                        "The outline is too thin to hold a triangle."});
    auto mesh = toTriMesh(raw->V, raw->F);
    if (!mesh)
        return unexpected(mesh.error());
    return ObjectMesh{std::move(*mesh), std::move(raw->V), std::move(raw->F), region};
}

Expected<ObjectMesh, GeometryError> objectMeshFrom(const Eigen::MatrixX2d &V,
                                                   const Eigen::MatrixX3i &F)
{
    const auto degenerate = [](const char *what) {
        return unexpected(GeometryError{GeometryErrorCode::DegenerateRegion, what});
    };
    if (F.rows() == 0 || V.rows() < 3)
        return degenerate("The mesh has no triangles.");
    if (!V.allFinite() || F.minCoeff() < 0 || F.maxCoeff() >= V.rows())
        return degenerate("The mesh refers to vertices it does not have.");
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
        const Eigen::RowVector2d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
        const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
        if (!(area > 0.0))
            return degenerate("The mesh has a triangle without area or turned over.");
    }
    auto mesh = toTriMesh(V, F);
    if (!mesh)
        return unexpected(mesh.error());
    // Outer loops (positive area) become polygons; each hole goes to the smallest outer loop
    // that holds its first vertex.
    std::vector<Eigen::MatrixX2d> holes;
    Region region;
    for (const Eigen::VectorXi &loop : boundaryLoops(F)) {
        Eigen::MatrixX2d ring(loop.size(), 2);
        for (Eigen::Index i = 0; i < loop.size(); ++i)
            ring.row(i) = V.row(loop(i));
        if (regionArea({Polygon{ring, {}}}) > 0.0)
            region.push_back(Polygon{std::move(ring), {}});
        else
            holes.push_back(std::move(ring));
    }
    for (Eigen::MatrixX2d &hole : holes) {
        Polygon *home = nullptr;
        double homeArea = std::numeric_limits<double>::infinity();
        for (Polygon &polygon : region) {
            const double area = regionArea({Polygon{polygon.outer, {}}});
            if (area < homeArea &&
                regionContains({Polygon{polygon.outer, {}}}, hole(0, 0), hole(0, 1))) {
                home = &polygon;
                homeArea = area;
            }
        }
        if (home)
            home->holes.push_back(std::move(hole));
    }
    return ObjectMesh{std::move(*mesh), V, F, std::move(region)};
}

Expected<ObjectMesh, GeometryError> buildObjectMesh(const std::vector<StrokeInput> &strokes,
                                                    const MeshOptions &options)
{
    auto region = objectShape(strokes, options.silhouette, options.regions);
    if (!region)
        return unexpected(region.error());
    return meshRegion(*region, options);
}

Expected<ObjectMesh, GeometryError> buildObjectMesh(const Region &region,
                                                    const MeshOptions &options)
{
    auto repaired = repairRegion(region, options.repair);
    if (!repaired)
        return unexpected(repaired.error());
    return meshRegion(*repaired, options);
}

} // namespace finbook::geometry
