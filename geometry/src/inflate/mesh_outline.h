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
//   convex      K    1 where the outline turns toward the shape (a convex corner) at a vertex
//                    with one edge in and one out, else 0 (reflex, straight, or pinched)
//   turnCos     K    cos of the angle between the edge in and the edge out (−1 if pinched)
//   slot        n    per mesh vertex: its row in `points`, or −1 off the outline
struct MeshOutline {
    Eigen::MatrixX2d a, e, inward;
    Eigen::VectorXd invLength2;
    Eigen::MatrixX2i ends;
    Eigen::MatrixX2d points, bisector;
    Eigen::VectorXi convex;
    Eigen::VectorXd turnCos;
    std::vector<int> slot;

    long edgeCount() const { return long(a.rows()); }
};

// Boundary edges are directed triangle edges whose reverse no triangle has. F must index V.
MeshOutline meshOutline(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F);

} // namespace finbook::geometry::inflate_detail
