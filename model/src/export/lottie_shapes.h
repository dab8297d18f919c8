// Internal: Finbook's strokes and fills as the closed Bézier paths a Lottie file holds.
//
// Lottie strokes have one width; Finbook's follow the pen's pressure. A stroke is therefore
// written as a filled outline (non-zero rule) that is exact by construction rather than a
// boolean union: the stroke is cut into runs at its sharp turns, and each run's outline is its
// left offset forward, a half circle around its last sample, its right offset back and a half
// circle around its first sample. Inside a run the offsets meet at mitres, which a run's limits
// keep short (turns up to 40°) and free of swallowtails (a mitre's setback stays within 45 % of
// each neighbouring segment); at a cut both runs end in a half circle around the shared sample,
// so together they make the round join the canvas paints. Runs also end every 32 samples (or
// 256 px): rlottie's rasterizer drops stretches of a long thin outline painted at once, so an
// exporter paints short runs one by one. Every run winds the same way and the
// offsets of a run never run backwards, so wherever runs or parts of one run overlap the
// winding number is positive and the non-zero rule fills it once: a loop keeps its hole, a
// stroke crossing itself stays solid.
//
// The outline's vertex count depends only on the sample count and where the stroke is cut, so
// the same stroke posed from frame to frame keeps one vertex layout and can be keyframed.
#pragma once

#include <finbook/model/types.h>

#include <QPainterPath>
#include <QPointF>

#include <vector>

namespace finbook::model {

// One closed cubic Bézier path: vertices with their in and out tangents relative to them.
struct BezierPath {
    std::vector<QPointF> vertices, in, out;
    friend bool operator==(const BezierPath &, const BezierPath &) = default;
};

// The stroke's outline as runs (see above), with the widths paintStroke paints (each segment
// as wide as its end sample says, in quarter pixels; a lone sample: at least half a pixel).
// Non-finite samples are left out. Empty when no sample is finite.
// Samples that lie within 0.1 px (in place and in radius) of the line through the samples kept
// around them are left out (Douglas–Peucker); with `rest` (the same stroke at rest, as many
// points), which samples are kept is decided on it, so every pose keeps the same ones.
std::vector<BezierPath> strokeOutline(const std::vector<StrokePoint> &points, float width,
                                      const std::vector<StrokePoint> *rest = nullptr);

// A fill's faces: one straight-sided path per ring of `path` (curves flattened), as the path
// winds, so holes stay holes under the non-zero rule. Rings of fewer than 3 points are left out.
std::vector<BezierPath> areaOutline(const QPainterPath &path);

} // namespace finbook::model
