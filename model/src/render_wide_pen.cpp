#include "render_wide_pen.h"

#include <QPainterPath>
#include <QPolygonF>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace finbook::model {

namespace {
// Sutherland–Hodgman against one side of the rectangle: keeps the points where
// inside(p) >= 0 (a linear function), cutting the edges that cross.
template <class Side> QPolygonF cutBy(const QPolygonF &polygon, Side inside)
{
    QPolygonF kept;
    for (qsizetype i = 0; i < polygon.size(); ++i) {
        const QPointF p = polygon[i], q = polygon[(i + 1) % polygon.size()];
        const qreal dp = inside(p), dq = inside(q);
        if (dp >= 0)
            kept << p;
        if ((dp >= 0) != (dq >= 0))
            kept << p + (q - p) * (dp / (dp - dq));
    }
    return kept;
}

QPolygonF clipToRect(QPolygonF polygon, const QRectF &r)
{
    polygon = cutBy(polygon, [&](QPointF p) { return p.x() - r.left(); });
    polygon = cutBy(polygon, [&](QPointF p) { return r.right() - p.x(); });
    polygon = cutBy(polygon, [&](QPointF p) { return p.y() - r.top(); });
    return cutBy(polygon, [&](QPointF p) { return r.bottom() - p.y(); });
}

// Half-circle vertices enough for a quarter-pixel deviation at this device radius.
int arcSteps(qreal deviceRadius)
{
    if (deviceRadius <= 0.25)
        return 2;
    const qreal step = std::acos(std::max(-1.0, 1.0 - 0.25 / deviceRadius));
    return std::clamp(int(std::ceil(std::numbers::pi / step)), 2, 512);
}

// The capsule of a→b with radius r: a half circle around b facing away from a, one around a.
QPolygonF capsule(QPointF a, QPointF b, qreal r, int steps)
{
    const QPointF d = b - a;
    const qreal length = std::hypot(d.x(), d.y());
    const qreal angle = length > 0 ? std::atan2(d.y(), d.x()) : 0.0;
    QPolygonF polygon;
    polygon.reserve(2 * (steps + 1));
    for (const auto &[centre, start] :
         {std::pair{b, angle - std::numbers::pi / 2}, std::pair{a, angle + std::numbers::pi / 2}})
        for (int i = 0; i <= steps; ++i) {
            const qreal t = start + std::numbers::pi * i / steps;
            polygon << centre + QPointF(r * std::cos(t), r * std::sin(t));
        }
    return polygon;
}
} // namespace

void fillWideSegments(QPainter &painter, const std::vector<WideSegment> &segments,
                      const QRectF &visible, qreal scale)
{
    QPainterPath path;
    path.setFillRule(Qt::WindingFill);
    for (const WideSegment &s : segments) {
        const qreal r = s.width / 2;
        const QRectF reach = QRectF(s.a, s.b).normalized().adjusted(-r, -r, r, r);
        if (!reach.intersects(visible))
            continue;
        const QPolygonF cut = clipToRect(capsule(s.a, s.b, r, arcSteps(r * scale)), visible);
        if (cut.size() >= 3)
            path.addPolygon(cut);
    }
    if (path.isEmpty())
        return;
    painter.save();
    painter.setPen(Qt::NoPen);
    painter.drawPath(path);
    painter.restore();
}

} // namespace finbook::model
