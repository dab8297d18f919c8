// Tone regions as clean polygons (issue 27's shading): the set where a per-vertex value is at
// least a threshold, bounded by its contour traced through the mesh (marching triangles: the
// crossing on each edge found by linear interpolation, the crossings chained triangle to
// triangle into closed rings together with the parts of the mesh outline inside the set),
// the contour smoothed, and the result clipped to the fill's region.
//
// The contour of a piecewise linear field turns at every mesh edge it crosses, by an angle
// that depends on how the triangles happen to lie: on a coarse shading mesh it zigzags. A few
// Taubin (λ|μ) smoothing steps on the contour's own vertices (never on the mesh outline or
// its ends there) take the zigzag out without shrinking a closed contour. The mesh is posed
// by another map than the region it shades (shade/pose.h versus the region's anchors), and
// inflated as its layer (an arm's whole loop), so the rings are clipped to that region
// (non-zero rule): a tone never spills past its fill. A region of one ring is cut directly
// where the two outlines cross (src/shade/ring_clip.h; most of re-shading's cost went to the
// polygon boolean before); holes, or outlines that touch rather than cross, go to Clipper.
#pragma once

#include <finbook/geometry/shade/shading.h>

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry {

// Edge structure of a triangle mesh, computed once per rest mesh and reused for every
// threshold and pose. For triangle f and corner k, edge (F(f, k), F(f, k + 1 mod 3)):
//   edge       m×3  its undirected edge number (0 … edgeCount − 1)
//   neighbour  m×3  the triangle across it, −1 on the outline
struct MeshEdges {
    Eigen::MatrixX3i edge;
    Eigen::MatrixX3i neighbour;
    int edgeCount = 0;
};
MeshEdges meshEdges(const Eigen::MatrixX3i &F);

struct ToneOptions {
    int smoothingSteps = 3; // Taubin λ|μ pairs on the contour (0: the raw contour)
};

// The closed rings (as Pieces: ring k is points[starts[k], starts[k + 1])) of the set where
// `value` ≥ threshold over the mesh (V n×2, F m×3 with positive area, `edges` = meshEdges(F)),
// outer rings and holes wound oppositely (draw with the non-zero rule), clipped to `clip`
// (rings, non-zero rule) unless `clip` is empty. Triangles with a non-finite corner or value
// are left out. Empty when nothing reaches the threshold.
Pieces toneRegion(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F, const MeshEdges &edges,
                  const Eigen::VectorXd &value, double threshold,
                  const std::vector<Eigen::MatrixX2d> &clip, const ToneOptions &options = {});

// Signed area of rings (shoelace, summed): the area a non-zero fill covers when the rings do
// not overlap.
double ringsArea(const Pieces &rings);

} // namespace finbook::geometry
