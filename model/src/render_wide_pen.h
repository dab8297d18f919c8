// Internal to render.cpp: strokes whose pen is wider than a few dozen device pixels, and
// scribbles of any pen whose outlines crowd the rows (outlineFillIsCrowded).
//
// QPainter strokes a polyline by building its whole outline, round joins of the pen's full
// radius included, and rasterizes it: a 2,000-pixel pen scribbling over the canvas took 22-37
// seconds a frame, nearly all of it spent on outline that is off the picture. Here each
// segment becomes its capsule (the hull of the pen's circles at both ends, which is what a
// round-capped, round-joined pen covers), cut to the visible rectangle before it is filled,
// so the rasterizer only sees what can be seen.
//
// That outline fill still costs about k² on a row that k capsule outlines cross: a 200-pixel
// pen scribbling 20,000 points over a 1920 x 1080 frame took 97 s. When that estimate is large
// next to the frame's pixels, the union is rasterized by scanlines into a coverage mask instead
// (capsule_coverage.h), whose cost is bounded by the frame whatever the pen, and the mask is
// painted as an image. Each segment keeps its own width on both paths.
#pragma once

#include <QPainter>
#include <QRectF>

#include <vector>

namespace finbook::model {

// Pens at least this wide on the device take the capsule path.
constexpr qreal kWidePenPixels = 48.0;

struct WideSegment {
    QPointF a, b;
    qreal width = 0; // logical units, like the pen's
};

enum class WidePenFill {
    Automatic, // the coverage mask where the outline fill is estimated to cost much more
    Outline,   // QPainter fills the capsules' outlines
    Coverage,  // scanline coverage mask (needs a transform without shear; else Outline)
};

// What a fill handed on: outline vertices to QPainter, or work of the coverage mask.
struct WidePenWork {
    WidePenFill used = WidePenFill::Outline;
    qint64 outlineVertices = 0;
    qint64 coverageWork = 0; // CoverageWork::total()
};

// Whether QPainter's outline fill would cost far more than a coverage mask of the frame. Its
// rasterizer keeps each row's outline cells in a sorted list, so a row crossed k times costs
// about k², at least (Σ rows crossed)² / rows in all. `rowsCrossed` sums the device rows each
// segment's outline crosses (its height plus the pen's, at most `rows`); `pixels` is the
// frame's. Holds for long scribbles whatever the pen: a 10-pixel pen over 20,000 random
// points took 265 s a frame.
bool outlineFillIsCrowded(double rowsCrossed, double rows, double pixels);

// Fills the union of the segments' capsules in the painter's brush, each capsule cut to
// `visible` (logical coordinates) first. `scale` is the painter's device pixels per unit.
WidePenWork fillWideSegments(QPainter &painter, const std::vector<WideSegment> &segments,
                             const QRectF &visible, qreal scale,
                             WidePenFill fill = WidePenFill::Automatic);

} // namespace finbook::model
