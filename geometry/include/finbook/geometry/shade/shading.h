// Shading from an inflated normal field (issue 27): a light fixed in screen space, a ramp of
// tones (cel) or a smooth one, an optional rim light, and the tone regions as polygons, so
// every renderer (QPainter, SVG) draws the same few filled shapes.
//
// Axes are the inflation's (inflate/inflation.h): x right, y down (canvas px), z toward the
// viewer. Shading is computed on the inflated rest mesh and posed with the drawing: pose.h
// moves the mesh and rotates its normals by the pose's local rotation; the light is then
// applied to the posed normals, so a bent arm keeps its shading and the light stays put.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry {

// The direction toward the light (unit): `azimuthDegrees` counter-clockwise on screen from
// the right (90 = from above, 180 = from the left), `elevationDegrees` above the drawing's
// plane (90 = straight from the viewer). Non-finite angles give the default (135°, 45°).
Eigen::Vector3d lightDirection(double azimuthDegrees, double elevationDegrees);

// Lambert term per vertex: max(0, n · light), in [0, 1]. normals n×3 unit (rows), light unit.
Eigen::VectorXd diffuseTerm(const Eigen::MatrixX3d &normals, const Eigen::Vector3d &light);

// Rim light per vertex, in [0, 1]: how far the surface turns away from the viewer (1 − n_z)
// on the side away from the light (a back light's rim on the shadow side): 0 facing the
// viewer or facing the light, near 1 on the outline opposite the light.
Eigen::VectorXd rimTerm(const Eigen::MatrixX3d &normals, const Eigen::Vector3d &light);

// Convex pieces of the triangles (V n×2, F m×3) where the linear interpolation of `value`
// (n) is ≥ threshold: whole triangles where all three corners are, clipped ones (3 to 4
// corners) where some are. Together they cover exactly the super-level set; pieces keep the
// orientation of their triangle. Triangles with a non-finite corner are left out.
struct Pieces {
    std::vector<Eigen::Vector2d> points;
    std::vector<int> starts{0}; // piece k is points[starts[k], starts[k + 1])
    int count() const { return int(starts.size()) - 1; }
};
Pieces superLevelPieces(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                        const Eigen::VectorXd &value, double threshold);

} // namespace finbook::geometry
