// Internal to render.cpp: strokes whose pen is wider than a few dozen device pixels.
//
// QPainter strokes a polyline by building its whole outline, round joins of the pen's full
// radius included, and rasterizes it: a 2,000-pixel pen scribbling over the canvas took 22-37
// seconds a frame, nearly all of it spent on outline that is off the picture. Here each
// segment becomes its capsule (the hull of the pen's circles at both ends, which is what a
// round-capped, round-joined pen covers), cut to the visible rectangle before it is filled,
// so the rasterizer only sees what can be seen.
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

// Fills the union of the segments' capsules in the painter's brush, each capsule cut to
// `visible` (logical coordinates) first. `scale` is the painter's device pixels per unit.
void fillWideSegments(QPainter &painter, const std::vector<WideSegment> &segments,
                      const QRectF &visible, qreal scale);

} // namespace finbook::model
