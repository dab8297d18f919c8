// Hit tests against what the canvas shows: displayed points (the solved pose for pinned
// objects), in canvas coordinates. Hidden objects are never hit; locked ones are skipped by
// callers that edit.
#pragma once

#include <finbook/model/types.h>

#include <QLineF>
#include <QPolygonF>
#include <QRectF>

#include <vector>

namespace finbook::ui {

// Distance from `p` to the segment a–b (a point when a == b).
qreal distanceToSegment(const QPointF &p, const QPointF &a, const QPointF &b);

// True when the swept segment `path` passes within `tolerance` of the stroke's outline.
bool strokeTouched(const std::vector<model::StrokePoint> &points, float width, const QLineF &path,
                   qreal tolerance);

// Fraction (0..1) of the points that lie inside `polygon`.
qreal fractionInside(const std::vector<model::StrokePoint> &points, const QPolygonF &polygon);

// Bounds of points padded by half the width; a null rect for no points.
QRectF strokeBounds(const std::vector<model::StrokePoint> &points, float width);

// Objects a tool may edit: visible and unlocked.
inline bool isEditable(const model::StrokeGroup &group)
{
    return group.visible && !group.locked;
}

// Whether `pos` lies inside the object's shape as shown: its regions closed at `closeGap` (the
// document's Close gaps) and ink (geometry/object_shape.h), so a click in the middle of an outline
// counts before any mesh exists, even where the outline was left slightly open. The Pin and Bone
// tools both ask this.
bool insideShape(const model::StrokeGroup &group, double closeGap, QPointF pos);

// The topmost stroke of an editable object within `tolerance` of `p`, or kNoId.
model::Id strokeAt(const model::Frame &frame, const QPointF &p, qreal tolerance);

} // namespace finbook::ui
