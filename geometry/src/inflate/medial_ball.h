// The medial ball through a point of the shape: from the nearest outline point b, the disc
// that touches the outline at b and grows along the outline's inward normal there until it
// meets the outline elsewhere. Internal to geometry/src/inflate; see inflation.h.
#pragma once

#include "mesh_outline.h"
#include "outline_grid.h"

#include <Eigen/Core>

namespace finbook::geometry::inflate_detail {

struct MedialBall {
    Eigen::RowVector2d centre;    // m = b + r·n
    Eigen::RowVector2d direction; // n, unit, into the shape
    double depth = 0.0;           // d = |p − b|
    double radius = 0.0;          // r ≥ 0; 0 for outline vertices (not searched)
    double height = 0.0;          // sqrt(r² − |p − m|²), 0 on the outline
};

// When a point where a growing ball touches the outline stops it: if, seen from the ball's
// centre, it lies at least the contact angle from b (cos ≤ minCos) and at least minChord (px)
// from b, or if it lies across from b (cos ≤ kOppositeCos: a thin part's other side, a
// spike's), however near.
struct ContactRule {
    double minCos = 0.5;
    double minChord = 0.0;
};
inline constexpr double kOppositeCos = -0.7071; // 135°

// p is a mesh vertex; grid is built on outline; slot is its row in outline.points or −1
// (meshOutline). `tolerance` is a length (px) below which points coincide, relative to the
// drawing's size. `rule`: from InflateOptions (contactAngleDegrees, outlineSmoothing).
MedialBall medialBall(const MeshOutline &outline, const OutlineGrid &grid,
                      const Eigen::RowVector2d &p, int slot, double tolerance,
                      const ContactRule &rule);

} // namespace finbook::geometry::inflate_detail
