// Strokes the model tests draw by hand: evenly spaced points on a straight line or round a
// square.
#pragma once

#include <finbook/model/types.h>

#include <QImage>

#include <memory>

namespace finbook::testing {

// `points` ≥ 2 points from `from` to `to`, pressure 1, the given width.
inline model::StrokeDataPtr lineStroke(QPointF from, QPointF to, int points, float width)
{
    auto data = std::make_shared<model::StrokeData>();
    data->width = width;
    for (int i = 0; i < points; ++i) {
        const QPointF p = from + (to - from) * (double(i) / (points - 1));
        data->points.push_back({float(p.x()), float(p.y()), 1.0f});
    }
    return data;
}

// A closed square outline (the last point is the first) from `corner` to `corner` + (side,
// side), `perSide` points a side, pressure 1: the object a pen draws round a solid tile.
inline model::StrokeDataPtr squareOutline(QPointF corner, double side, int perSide, float width)
{
    auto data = std::make_shared<model::StrokeData>();
    data->width = width;
    const QPointF corners[] = {corner, corner + QPointF(side, 0), corner + QPointF(side, side),
                               corner + QPointF(0, side), corner};
    for (int edge = 0; edge < 4; ++edge)
        for (int i = 0; i < perSide; ++i) {
            const QPointF p =
                corners[edge] + (corners[edge + 1] - corners[edge]) * (double(i) / perSide);
            data->points.push_back({float(p.x()), float(p.y()), 1.0f});
        }
    data->points.push_back(data->points.front());
    return data;
}

// The centre of the dark pixels of `image` (x < 0 when there are none): where a dot of ink
// landed in a rendered picture.
inline QPointF darkCentre(const QImage &image)
{
    double sx = 0, sy = 0, n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (qGray(image.pixel(x, y)) < 100) {
                sx += x + 0.5;
                sy += y + 0.5;
                n += 1;
            }
    return n > 0 ? QPointF(sx / n, sy / n) : QPointF(-1, -1);
}

} // namespace finbook::testing
