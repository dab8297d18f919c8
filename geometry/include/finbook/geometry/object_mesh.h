// Quality triangle mesh of an object: from its strokes (via objectShape()) or from a Region.
//
// Constrained Delaunay triangulation of the region refined by CGAL's Delaunay mesher with the
// domain marked by nesting depth (holes and the space between lobes stay empty), shape bound
// 0.125 (minimum angle ≈ 20.7°) and a size bound from the target vertex count.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>
#include <finbook/geometry/polygon_repair.h>
#include <finbook/geometry/region.h>
#include <finbook/geometry/regions.h>
#include <finbook/geometry/silhouette.h>
#include <finbook/geometry/stroke_input.h>
#include <finbook/geometry/tri_mesh.h>

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry {

struct MeshOptions {
    // Edge length scales with 1/density: 2 halves the edges (about 4× the vertices).
    double density = 1.0; // in (0, 100]
    // Vertices aimed for at density 1, whatever the object's size: ARAP cost stays
    // predictable, and a full-canvas character gets edges of roughly 10–20 px.
    int targetVertices = 1500;
    // Ceiling: the edge length is raised until the estimate fits (absurd densities, huge
    // regions). Refinement itself stops at 2 × maxVertices + the outline's vertices; a mesh
    // stopped there is valid but may keep a few triangles below the 20° minimum angle.
    int maxVertices = 30000;
    double minEdge = 1.0; // px: small objects are not refined below this
    SilhouetteOptions silhouette;
    RegionsOptions regions; // closed regions fill the shape (object_shape.h)
    RepairOptions repair;   // for the Region overload
};

// V: n×2 vertex positions (canvas px). F: m×3 vertex indices, every triangle with positive
// shoelace area (counter-clockwise in y-up math axes, see region.h), no zero-area triangles,
// every vertex referenced. Row i of V is vertex i of `mesh`, row j of F is face j of `mesh`.
// Several connected components (lobes) are normal. `region` is the outline that was meshed.
struct ObjectMesh {
    TriMesh mesh;
    Eigen::MatrixX2d V;
    Eigen::MatrixX3i F;
    Region region;
};

// objectShape(strokes, options.silhouette, options.regions), then meshRegion. Errors: those of
// objectShape().
Expected<ObjectMesh, GeometryError> buildObjectMesh(const std::vector<StrokeInput> &strokes,
                                                    const MeshOptions &options = {});

// repairRegion(region, options.repair), then meshRegion. Errors: those of repairRegion().
Expected<ObjectMesh, GeometryError> buildObjectMesh(const Region &region,
                                                    const MeshOptions &options = {});

// Meshes a region whose rings do not cross: isSimple(region, Touching::AllowedAtPoints),
// as silhouette() and repairRegion() promise.
// Errors: NotSimple, DegenerateRegion (no area), InvalidOptions, TriangulationFailed.
Expected<ObjectMesh, GeometryError> meshRegion(const Region &region,
                                               const MeshOptions &options = {});

// An ObjectMesh from a triangle mesh made elsewhere (a picture object's texture mesh, saved with
// it): `region` is the mesh's boundary, each outer loop a polygon holding the hole loops that lie
// inside it. Errors: DegenerateRegion when F is empty, has an index outside V or a triangle of
// zero or negative area; TriangulationFailed when OpenMesh cannot store it (non-manifold).
Expected<ObjectMesh, GeometryError> objectMeshFrom(const Eigen::MatrixX2d &V,
                                                   const Eigen::MatrixX3i &F);

// The CGAL size bound (longest edge, px) meshRegion uses for this area and perimeter.
double meshEdgeLength(double area, double perimeter, const MeshOptions &options);

} // namespace finbook::geometry
