// The vector eraser's geometry: which parts of a polyline stay when a disc is swept along a
// path across it. Pure, Qt-free, and linear in the polyline (a bounding-box test rejects the
// segments far from the rub before any exact work).
#pragma once

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry {

// A place on a polyline: segment `segment` (0 .. n-2) at fraction `t` (0..1) from its first
// point. A one-point polyline has only {0, 0}.
struct PolylinePlace {
    Eigen::Index segment = 0;
    double t = 0.0;
    friend bool operator==(const PolylinePlace &, const PolylinePlace &) = default;
};

// A part of the polyline that stays, from `from` to `to` along it (from before to).
struct KeptSpan {
    PolylinePlace from;
    PolylinePlace to;
};

struct EraseResult {
    bool touched = false;       // false: the rub missed, nothing changes
    std::vector<KeptSpan> kept; // in order along the polyline; empty when all of it goes
};

// Erases from the polyline P (n×2, n ≥ 1) everything within `radius` + reach of the rub path
// E (m×2, m ≥ 1; one row is a single dab), where reach(k) (n, ≥ 0; e.g. half the drawn width
// at point k) lets the eraser take a thick line as soon as it touches its edge; a segment
// uses the mean of its two ends. Non-finite input rows never count as covered. Each kept span
// ends exactly where the centre line enters the erased area.
EraseResult erasePolyline(const Eigen::MatrixX2d &P, const Eigen::VectorXd &reach,
                          const Eigen::MatrixX2d &E, double radius);

} // namespace finbook::geometry
