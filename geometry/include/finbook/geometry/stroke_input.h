// One pen stroke as the geometry layer sees it.
#pragma once

#include <Eigen/Core>

namespace finbook::geometry {

// points: n×2 canvas pixels (x right, y down), drawing order. n may be 1 (a dot); rows may
// repeat or be non-finite: non-finite rows are dropped, repeats ignored.
// width: pen width in pixels, finite and in [0, kMaxPenWidth].
struct StrokeInput {
    Eigen::MatrixX2d points;
    double width = 3.0;
};

} // namespace finbook::geometry
