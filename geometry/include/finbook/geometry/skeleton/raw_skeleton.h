// Stage one of the automatic skeleton (Ma et al. 2021, "RealSkel", in 2D): an object's
// silhouette → its cleaned interior straight skeleton, dense and with radii, from which
// refineSkeleton() (skeleton_refine.h) makes bones.
//
// Per polygon of the region: the outline is eroded by a quarter of the simplification
// tolerance (this opens points where rings touch, so CGAL gets the strictly simple input it
// needs), simplified by Douglas–Peucker to a vertex budget (the straight skeleton costs ~n²),
// jittered by ~1e-7 of its size with a hash of the coordinates (exact symmetry makes CGAL
// 5–50× slower; the jitter is deterministic, so equal input gives equal output), then
// skeletonised by CGAL's interior straight skeleton, holes included. Bisectors that touch the
// outline are dropped, edges shorter than a quarter of the local radius collapse (shortest
// first), loops around holes are cut where the shape is thinnest, and side branches that do
// not reach out of their junction's inscribed disk (outline noise) are removed. If CGAL gives
// up on a polygon, two coarser, differently jittered outlines are tried; a polygon that still
// fails gets no skeleton (the others do).
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>
#include <finbook/geometry/region.h>

#include <Eigen/Core>

#include <functional>

namespace finbook::geometry {

// Returns true when the caller no longer wants the result; polled between stages and inside
// CGAL's event loop, so a stale request stops within a fraction of a millisecond.
using CancelCallback = std::function<bool()>;

struct SkeletonOptions {
    // Vertices per polygon for the straight skeleton, whose cost grows ~n² (CPU time measured
    // on a 2-core machine: ~2.5 ms at 64 vertices, ~8 ms at 150; exactly symmetric outlines
    // such as regular stars cost about twice that even jittered). The Douglas–Peucker
    // tolerance grows from simplifyTolerance until a polygon has at most targetVertices, but
    // not past a quarter of the polygon's mean half-width (area / perimeter), so thin parts
    // and detailed shapes keep their outline, unless it would then have more than
    // maxVertices: the hard bound. Within maxVertices, vertices whose removal would move the
    // outline by more than a quarter of the local half-width are kept too (tentacle tips,
    // antennae, thin wavy limbs: issue 21).
    // 8 ≤ targetVertices ≤ maxVertices ≤ 1000.
    int targetVertices = 64;
    int maxVertices = 150;
    // Douglas–Peucker tolerance (px) to start from; 0 picks 0.25 % of the region's diagonal
    // (at least 0.05 px, at most 1 px).
    double simplifyTolerance = 0.0;
    CancelCallback cancelled;
};

// The cleaned dense skeleton: a forest (one tree per polygon, cycles cut). Refinement is a
// pure function of this value, so it is what a document keeps to re-run the sliders.
//   nodes      N×2  skeleton vertices (px)
//   radius     N    inscribed distance of the outline: CGAL's event time, capped by the
//                   distance to the contour (the event time overshoots next to reflex
//                   corners, e.g. a palm between two fingers), plus the erosion
//   clearance  N    distance to `contour`, what bones are kept within (≥ radius − erosion)
//   polygon    N    index into `contour` of the polygon each node lies in
//   edges      E×2  node index pairs, E = N − (number of trees)
//   contour         the simplified, eroded outline the skeleton was built from
//   centroid        area centroid of the input region (the default root is the joint nearest)
struct RawSkeleton {
    Eigen::MatrixX2d nodes;
    Eigen::VectorXd radius;
    Eigen::VectorXd clearance;
    Eigen::VectorXi polygon;
    Eigen::MatrixX2i edges;
    Region contour;
    Eigen::RowVector2d centroid = Eigen::RowVector2d::Zero();
    double erosion = 0.0;     // px the outline was eroded by
    double tolerance = 0.0;   // px: the Douglas–Peucker tolerance that met the budget
    long polygonVertices = 0; // vertices of `contour` (what CGAL saw)
    bool degenerate = false;  // true: no area; a one-joint or one-bone fallback
};

// Needs: a region (silhouette.h, or contours as given: rings may touch, cross or repeat
// points; orientation is taken from the sign convention of region.h).
// Errors: EmptyInput (no finite point), CoordinateOutOfRange, TooManyPoints, InvalidOptions,
// ClippingFailed, SkeletonFailed (CGAL gave up on every polygon, retries included), Cancelled.
// Degenerate input (one point, a straight line, a zero-area scribble, a region that the
// erosion empties) is not an error: the result has one node, or two nodes and one edge along
// the points' principal axis, and `degenerate` set. Promise: everything finite.
Expected<RawSkeleton, GeometryError> rawSkeleton(const Region &region,
                                                 const SkeletonOptions &options = {});

} // namespace finbook::geometry
