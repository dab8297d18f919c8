// Internal, CGAL: the Delaunay part of a cage mesh. Triangulates the strip between the cage
// and the lattice tiling (cage_lattice.h), or the whole cage when nothing is tiled, and
// refines it to the 20.7° shape bound and a size bound.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace finbook::geometry::detail {

struct StripInput {
    std::vector<Eigen::Vector2d> points; // every known vertex; ids below index this
    std::vector<int> ring;               // the cage boundary, subdivided, in order (closed)
    // Edges of the tiled region, tiled side on the left. They are constraints the refinement
    // must not split: a split would leave a vertex hanging in a lattice triangle's edge.
    std::vector<std::pair<int, int>> front;
    std::vector<int> loose; // further points to insert (deep lattice points in no triangle)
};

// A front edge refinement split after all: the vertices it put on it, from a to b.
struct FrontSplit {
    std::size_t front = 0; // index into StripInput::front
    std::vector<int> inner;
};

struct StripMesh {
    std::vector<Eigen::Vector2d> added;     // vertices refinement added; id = points.size() + k
    std::vector<Eigen::Vector3i> triangles; // strip triangles (ids), positive area
    std::vector<FrontSplit> splits;
};

// Refinement stops early (mesh valid, some triangles larger or skinnier) at vertexCap
// vertices. Errors: TriangulationFailed (CGAL threw, or the input was degenerate).
Expected<StripMesh, GeometryError> meshStrip(const StripInput &input, double maxEdge,
                                             long vertexCap);

} // namespace finbook::geometry::detail
