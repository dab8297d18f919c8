#include "stroke_hit.h"

#include <finbook/geometry/object_shape.h>
#include <finbook/geometry/region.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/render.h>
#include <finbook/model/stroke_input.h>

#include <algorithm>
#include <cmath>

namespace finbook::ui {

qreal distanceToSegment(const QPointF &p, const QPointF &a, const QPointF &b)
{
    const QPointF ab = b - a;
    const qreal len2 = QPointF::dotProduct(ab, ab);
    qreal t = len2 > 0 ? QPointF::dotProduct(p - a, ab) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    const QPointF d = p - (a + t * ab);
    return std::hypot(d.x(), d.y());
}

namespace {

// Distance between two segments in the plane (0 when they cross).
qreal segmentDistance(const QLineF &s, const QLineF &t)
{
    QPointF crossing;
    if (s.intersects(t, &crossing) == QLineF::BoundedIntersection)
        return 0.0;
    return std::min(
        {distanceToSegment(s.p1(), t.p1(), t.p2()), distanceToSegment(s.p2(), t.p1(), t.p2()),
         distanceToSegment(t.p1(), s.p1(), s.p2()), distanceToSegment(t.p2(), s.p1(), s.p2())});
}

QPointF toPoint(const model::StrokePoint &p)
{
    return QPointF(p.x, p.y);
}

} // namespace

QRectF strokeBounds(const std::vector<model::StrokePoint> &points, float width)
{
    if (points.empty())
        return {};
    float minX = points[0].x, maxX = minX, minY = points[0].y, maxY = minY;
    for (const model::StrokePoint &p : points) {
        minX = std::min(minX, p.x);
        maxX = std::max(maxX, p.x);
        minY = std::min(minY, p.y);
        maxY = std::max(maxY, p.y);
    }
    const qreal pad = std::max(0.5f, width / 2);
    return QRectF(QPointF(minX, minY), QPointF(maxX, maxY)).adjusted(-pad, -pad, pad, pad);
}

bool strokeTouched(const std::vector<model::StrokePoint> &points, float width, const QLineF &path,
                   qreal tolerance)
{
    if (points.empty())
        return false;
    const qreal reach = tolerance + std::max(0.5f, width / 2);
    const QRectF sweep =
        QRectF(path.p1(), path.p2()).normalized().adjusted(-reach, -reach, reach, reach);
    if (!sweep.intersects(strokeBounds(points, width)))
        return false;
    if (points.size() == 1)
        return distanceToSegment(toPoint(points[0]), path.p1(), path.p2()) <= reach;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const QLineF seg(toPoint(points[i]), toPoint(points[i + 1]));
        const qreal r =
            tolerance +
            std::max(0.5f, width * std::max(points[i].pressure, points[i + 1].pressure) / 2);
        if (segmentDistance(seg, path) <= r)
            return true;
    }
    return false;
}

qreal fractionInside(const std::vector<model::StrokePoint> &points, const QPolygonF &polygon)
{
    if (points.empty() || polygon.size() < 3)
        return 0.0;
    const QRectF box = polygon.boundingRect();
    std::size_t inside = 0;
    for (const model::StrokePoint &p : points) {
        const QPointF q = toPoint(p);
        if (box.contains(q) && polygon.containsPoint(q, Qt::OddEvenFill))
            ++inside;
    }
    return qreal(inside) / qreal(points.size());
}

model::Id strokeAt(const model::Frame &frame, const QPointF &p, qreal tolerance)
{
    const QLineF here(p, p);
    for (auto g = frame.groups.rbegin(); g != frame.groups.rend(); ++g) {
        if (!isEditable(*g))
            continue;
        for (std::size_t i = g->strokes.size(); i-- > 0;) {
            const model::Stroke &s = g->strokes[i];
            if (s.data &&
                strokeTouched(model::displayedPoints(*g, i), s.data->width, here, tolerance))
                return s.id;
        }
    }
    return model::kNoId;
}

bool insideShape(const model::StrokeGroup &g, double closeGap, QPointF pos)
{
    if (model::pictureShowsAt(g, pos))
        return true;
    std::vector<geometry::StrokeInput> inputs;
    double left = HUGE_VAL, top = HUGE_VAL, right = -HUGE_VAL, bottom = -HUGE_VAL;
    for (std::size_t s = 0; s < g.strokes.size(); ++s) {
        const auto &points = model::displayedPoints(g, s);
        if (points.empty())
            continue;
        for (const model::StrokePoint &p : points) {
            left = std::min(left, double(p.x));
            right = std::max(right, double(p.x));
            top = std::min(top, double(p.y));
            bottom = std::max(bottom, double(p.y));
        }
        inputs.push_back(model::strokeInput(points, g.strokes[s].data->width));
    }
    // Cheap refusal first: the shape never reaches far beyond the points.
    const double reach = 32.0;
    if (inputs.empty() || !(pos.x() >= left - reach && pos.x() <= right + reach &&
                            pos.y() >= top - reach && pos.y() <= bottom + reach))
        return false;
    const auto region = geometry::objectShape(
        inputs, {}, geometry::RegionsOptions{closeGap >= 0.0 ? closeGap : -1.0});
    return region && geometry::regionContains(*region, pos.x(), pos.y());
}

} // namespace finbook::ui
