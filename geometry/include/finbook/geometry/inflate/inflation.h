// Inflation of an object's shape (issue 27): a rounded height field over its triangle mesh,
// with a normal per vertex, the surface that shading lights and that the 3D export writes.
//
// Model: medial balls along the outline's normals. For a mesh vertex p, let b be the nearest
// point of the mesh outline, d = |p − b| and n the inward normal there. The largest disc that
// touches the outline at b has its centre m = b + r·n on the medial axis; r (the medial
// radius) is found in closed form as the smallest r at which that disc touches the outline
// elsewhere. The height and normal are the ball's:
//     h = sqrt(r² − |p − m|²)  (= sqrt(d (2r − d)) when p lies on the ray from b along n),
//     normal = (p − m, h) / r.
// So h is 0 exactly on the outline with a horizontal normal (vertical tangent), h reaches r
// on the medial axis with a vertical normal, and every cross-section is a circular arc: a disc
// gives the hemisphere sqrt(R² − ρ²), a capsule or strip a round tube. This is the limit of
// RealSkel's general cylinders around bones and balls at joints when the bones follow the
// medial axis exactly, so it needs no skeleton: a refined skeleton's bones are simplified
// and pruned, and their radii would not meet the outline (h ≠ 0 there, or gaps between
// cylinders). The smooth alternative, sqrt of a Poisson solution (Ink-and-Ray, Monster Mash),
// cannot be round for both a disc and a strip (their aspect ratios differ by √2) and needs a
// sparse solve; this one is per vertex, needs no solver and cannot fail to converge.
//
// The outline is a polygon sampling a drawn curve (pixel steps, pen jitter, the mesher's
// splits), and a polygon's medial axis has a branch at every convex vertex: read literally,
// the balls near each vertex shrink and the surface ripples with the sampling. So n is the
// outline's normal smoothed over about one mesh edge (InflateOptions::outlineSmoothing) and
// interpolated along each edge like a Phong normal, and a contact stops the ball only if,
// seen from its centre, it lies at least the contact angle (InflateOptions::
// contactAngleDegrees) and the smoothing length away from b, or across from b (≥ 135°: a
// thin part's other side), in the spirit of the λ-medial axis. Where the smoothed direction
// misses p (a reflex corner's wedge, a notch), the ball along the exact ray from b through p
// is grown too and the higher of the two kept, as in a union of balls. Corners sharper than
// the angle at the smoothing's scale keep their crease.
//
// Cost: per vertex, the outline edges within 2r of b (a uniform grid finds them nearest
// first): O(n · B) at worst, for n vertices and B outline edges; the grid makes thin parts
// cheap. This inflates one mesh as one height field; overlapping regions of one object (an
// arm drawn over the body) are layered by inflating each layer's region separately
// (inflate/layers.h: strokeLayers, layerRegion), which the shading and the 3D export do.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>
#include <finbook/geometry/object_mesh.h>

#include <Eigen/Core>

namespace finbook::geometry {

struct InflateOptions {
    // A point where the ball touches the outline stops it only if it lies at least this angle
    // (degrees, seen from the ball's centre) from the point the ball grows from (and at least
    // the smoothing length, unless across from it). Corners that turn less are read as a
    // smoothly sampled curve, sharper ones keep their medial branch.
    double contactAngleDegrees = 60.0; // in (0, 180)
    // Length along the outline over which its normals are averaged, and below which contacts
    // are ignored, in mean mesh edge lengths: detail below the mesh's resolution is not shape.
    // 0 reads the polygon literally (corners' bisectors, every contact).
    double outlineSmoothing = 1.0; // in [0, 100]
};

// One value per vertex of the inflated mesh (n rows): the given mesh with every chord (an
// interior edge joining two outline vertices, across a part one triangle wide) split at its
// midpoint, so the surface does not pinch to height 0 along it.
//   V        n×2  canvas px (x right, y down): the given vertices in their order, then one
//                 per chord (n = the given count when there is no chord)
//   F        m×3  triangles, positive shoelace area (object_mesh.h); the given ones where no
//                 chord was split
//   height   n    h ≥ 0, exactly 0 on the outline, ≤ radius
//   normal   n×3  unit; columns x, y along the canvas axes, z the height axis, toward the
//                 viewer (so the frame (x, y, z) is left-handed; flip y for a right-handed one)
//   depth    n    d, distance to the outline (0 on it)
//   radius   n    r, radius of the ball through the vertex; 0 on the outline (the height is
//                 0 and the normal horizontal there whatever r is, so it is not searched)
//   outline  n    1 for vertices on the mesh outline (on a boundary edge), else 0
// A vertex no triangle uses is not part of the shape: height, depth and radius 0, normal
// (0, 0, 1).
struct Inflation {
    Eigen::MatrixX2d V;
    Eigen::MatrixX3i F;
    Eigen::VectorXd height;
    Eigen::MatrixX3d normal;
    Eigen::VectorXd depth;
    Eigen::VectorXd radius;
    Eigen::VectorXi outline;
};

// Inflates the mesh (V, F) over its own outline: the boundary edges of F, oriented by the
// triangles, so holes and separate lobes need no extra input.
// Errors: EmptyInput (no vertex or no triangle), NonFiniteInput (NaN or infinite coordinate),
// CoordinateOutOfRange (beyond kMaxCoordinate), InvalidIndex (a triangle names a missing
// vertex or repeats one), DegenerateRegion (a triangle of zero or negative area, or no
// outline), InvalidOptions (an option outside its range). Promise: every value finite,
// normals unit. A pure function of its arguments (no shared state): safe to run on a worker
// thread and concurrently.
Expected<Inflation, GeometryError> inflateMesh(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                               const InflateOptions &options = {});

// inflateMesh(mesh.V, mesh.F, options).
Expected<Inflation, GeometryError> inflateObjectMesh(const ObjectMesh &mesh,
                                                     const InflateOptions &options = {});

// meshRegion(region, meshOptions), then inflateMesh. Errors: those of both.
Expected<Inflation, GeometryError> inflateRegion(const Region &region,
                                                 const MeshOptions &meshOptions = {},
                                                 const InflateOptions &options = {});

// ∫ h dA over the mesh with h linear on each triangle (px³): the volume above the plane.
double inflatedVolume(const Inflation &inflation);

} // namespace finbook::geometry
