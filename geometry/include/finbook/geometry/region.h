// Planar regions: polygons with holes, the output of the silhouette and the input of meshing.
//
// Orientation convention (used throughout finbook::geometry): orientation is the sign of the
// shoelace area  A = 1/2 Σ (x_i y_{i+1} − x_{i+1} y_i)  computed on the coordinates exactly as
// given. Outer rings and triangles have A > 0, holes A < 0. In y-up math axes that is
// counter-clockwise; on the y-down canvas it *looks* clockwise on screen. This matches the
// silhouettes in shared/data ("outer positive in y-down coordinates").
#pragma once

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry {

// A ring is m×2, implicitly closed (the first point is not repeated at the end).
struct Polygon {
    Eigen::MatrixX2d outer;              // A > 0
    std::vector<Eigen::MatrixX2d> holes; // each A < 0, strictly inside outer
};

// Disjoint polygons (separate lobes of one object stay separate polygons).
using Region = std::vector<Polygon>;

// Signed area of all rings (outer positive, holes negative): the covered area.
double regionArea(const Region &region);

// Total length of all ring boundaries.
double regionPerimeter(const Region &region);

// All rings of the region, outer first per polygon.
std::vector<Eigen::MatrixX2d> regionRings(const Region &region);

// Number of ring vertices in total.
long regionVertexCount(const Region &region);

// Whether (x, y) lies inside the region: inside an outer ring and in none of its holes (the
// even-odd rule over every ring). Points exactly on a boundary may go either way.
bool regionContains(const Region &region, double x, double y);

} // namespace finbook::geometry
