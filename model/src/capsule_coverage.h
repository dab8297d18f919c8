// Internal to render_wide_pen.cpp (no Qt): the union of round-capped segments ("capsules",
// what a round-capped, round-joined pen covers) as pixel coverage, by scanlines.
//
// QPainter fills such a union by rasterizing every capsule's outline, and its rasterizer keeps
// each row's cells in a sorted list: a row crossed by k outlines costs about k², so 20,000
// segments of a 200-pixel pen scribbled over a 1920 x 1080 frame took 97 s. Here each capsule
// only gives the interval it covers on each sample row it spans (computed exactly, wherever the
// capsule's centre line is, on the grid or off it), and the intervals are merged by counting
// into one row of samples. The work is at most samples × rows × (capsules + samples × width):
// a capsule costs at most the grid's height in rows whatever its width, and nothing grows
// with the number of capsules crossing a row beyond that.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace finbook::model {

struct Capsule {
    double ax = 0, ay = 0, bx = 0, by = 0; // centre line, in grid pixels (pixel x spans x..x+1)
    double radius = 0;                     // in grid pixels
};

// Samples per pixel along each axis: kCoverageSamples² samples give the antialiased edge
// (pixel coverage in steps of 1/16, QPainter's outline fill gives exact area coverage).
constexpr int kCoverageSamples = 4;

struct CoverageWork {
    std::int64_t spans = 0;   // capsule × sample-row intervals computed
    std::int64_t samples = 0; // samples swept
    std::int64_t total() const { return spans + samples; }
};

// Coverage 0..255 of each pixel of a width × height grid (row-major into `alpha`, resized) by
// the union of the capsules. Capsules with a non-finite value or no positive radius are skipped.
CoverageWork capsuleCoverage(std::span<const Capsule> capsules, int width, int height,
                             std::vector<std::uint8_t> &alpha);

} // namespace finbook::model
