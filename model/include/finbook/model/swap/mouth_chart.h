// The mouth chart (issue 49): a swap set of the nine mouth shapes lip sync keys (Preston Blair's,
// as Rhubarb Lip Sync names them, lipsync/mouth_shape.h), each a simple drawing the animator
// redraws in their own style.
#pragma once

#include <finbook/model/document.h>

namespace finbook::model {

// Nine drawings named "A (M B P)" … "X (rest)" in MouthShape order, `width` canvas pixels wide
// around `centre`, drawn with `color` at pen width `penWidth`; every id allocated from `doc`.
// The drawings' outlines are closed, so Fill All colours each mouth's inside.
SwapSet mouthChart(Document &doc, QPointF centre, double width, QRgb color, float penWidth);

// The name mouthChart gives the drawing of shape `shape` (0 = A … 8 = X), and the shape a
// drawing of that name shows (-1 for another name): what lip sync keys by.
QString mouthChartName(int shape);
int mouthChartShape(const QString &drawingName);

} // namespace finbook::model
