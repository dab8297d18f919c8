// Drawings the fill tests fill: outlines made of straight pen lines.
#pragma once

#include <finbook/model/commands.h>

#include <QPolygonF>

#include <cmath>
#include <memory>

namespace finbook::testing {

// A stroke along `corners` (in order), a point every `step` px, pressure 1.
inline model::StrokeDataPtr polylineStroke(const QPolygonF &corners, double step = 4.0,
                                           float width = 3.0f, QRgb color = 0xff000000)
{
    auto data = std::make_shared<model::StrokeData>();
    data->width = width;
    data->color = color;
    for (qsizetype i = 0; i + 1 < corners.size(); ++i) {
        const QPointF a = corners[i], b = corners[i + 1];
        const int n = std::max(1, int(std::ceil(std::hypot(b.x() - a.x(), b.y() - a.y()) / step)));
        for (int k = 0; k < n; ++k) {
            const QPointF p = a + (b - a) * (double(k) / n);
            data->points.push_back({float(p.x()), float(p.y()), 1.0f});
        }
    }
    data->points.push_back({float(corners.back().x()), float(corners.back().y()), 1.0f});
    return data;
}

inline QPolygonF squareCorners(QRectF r)
{
    return QPolygonF{r.topLeft(), r.topRight(), r.bottomRight(), r.bottomLeft(), r.topLeft()};
}

// A document with one frame whose object holds a closed square outline (one stroke). Returns
// the object's id; the undo stack is clear.
inline model::Id squareDocument(model::Document &doc, QRectF square = QRectF(100, 100, 100, 100))
{
    doc.undoStack()->push(new model::InsertFrameCommand(&doc, 0));
    const model::Id g = doc.frameAt(0).groups.at(0).id;
    doc.undoStack()->push(
        new model::AddStrokeCommand(&doc, g, polylineStroke(squareCorners(square))));
    doc.undoStack()->clear();
    return g;
}

} // namespace finbook::testing
