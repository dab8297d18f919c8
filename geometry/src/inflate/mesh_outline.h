// The outline of a triangle mesh as the inflation sees it: its boundary edges, oriented by
// their triangles so the shape lies to the left, and an inward direction at every outline
// vertex. Internal to geometry/src/inflate.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry::inflate_detail {

// B boundary edges and K outline vertices.
//   a, e        B×2  edge start and direction (end − start); the shape is on the left of e
//   inward      B×2  unit left normal of each edge (into the shape)
//   invLength2  B    1 / |e|² (0 for a zero-length edge, which then only counts as a point)
//   ends        B×2  rows of the edge's start and end in `points`
//   points      K×2  outline vertex positions
//   bisector    K×2  unit inward direction at each outline vertex
//   edgeIn      K    the edge ending at each vertex, edgeOut the one starting there; −1 where
//   edgeOut          several do (outlines touching at a pinched vertex)
//   normal      K×2  unit inward normal of the outline at each vertex, smoothed along it
//                    (smoothOutlineNormals; the bisector until then)
//   slot        n    per mesh vertex: its row in `points`, or −1 off the outline
struct MeshOutline {
    Eigen::MatrixX2d a, e, inward;
    Eigen::VectorXd invLength2;
    Eigen::MatrixX2i ends;
    Eigen::MatrixX2d points, bisector;
    Eigen::VectorXi edgeIn, edgeOut;
    Eigen::MatrixX2d normal;
    std::vector<int> slot;

    long edgeCount() const { return long(a.rows()); }
};

// Boundary edges are directed triangle edges whose reverse no triangle has. F must index V.
MeshOutline meshOutline(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F);

// Sets outline.normal to the average of the edge normals along the outline within `window`
// (px) of each vertex on either side, weighted by length and falling linearly to 0 at the
// window's end; the two edges at the vertex always count fully. A drawn outline is sampled by
// a polygon whose corners (pixel steps, pen jitter, the mesher's splits) are not part of the
// shape: the inflation grows its balls along these normals and lights with them, so detail
// below the mesh's resolution neither dents the surface nor streaks the shading.
void smoothOutlineNormals(MeshOutline &outline, double window);

} // namespace finbook::geometry::inflate_detail
