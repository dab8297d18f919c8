// Drawing helpers shared by the Cage tool and the cage overlay.
#pragma once

#include <QPolygonF>
#include <QTransform>

#include <vector>

namespace finbook::ui {

// Canvas points in widget coordinates.
inline QPolygonF mappedPolygon(const QTransform &canvasToWidget, const std::vector<QPointF> &points)
{
    QPolygonF poly;
    poly.reserve(qsizetype(points.size()));
    for (QPointF p : points)
        poly << canvasToWidget.map(p);
    return poly;
}

} // namespace finbook::ui
