// Strokes the model tests draw by hand: evenly spaced points on a straight line.
#pragma once

#include <finbook/model/types.h>

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

} // namespace finbook::testing
