// Painting frames with QPainter (QtGui only): shared by the canvas, timeline thumbnails,
// onion skin and `finbook export`, so every place draws a stroke the same way.
#pragma once

#include <finbook/model/document.h>

#include <QImage>
#include <QPainter>

#include <optional>

namespace finbook::model {

struct RenderOptions {
    bool paintBackground = true;
    qreal opacity = 1.0;
    std::optional<QColor> tint; // onion skin: every stroke in this colour
    bool showHidden = false;
};

// Paints one stroke with its pressure-varying width. Consecutive samples whose widths round
// to the same quarter pixel are drawn as one polyline, which keeps 50k-point frames fast.
void paintStroke(QPainter &painter, const std::vector<StrokePoint> &points, QRgb color,
                 float width);

// Paints the objects of a frame (deformed pose where an object has one) in canvas
// coordinates; the painter's transform maps canvas to device.
void paintFrame(QPainter &painter, const Frame &frame, const DocumentSettings &settings,
                const RenderOptions &options = {});

// The points an object shows now: its solved pose if it has pins, else its rest strokes.
const std::vector<StrokePoint> &displayedPoints(const StrokeGroup &group, std::size_t stroke);

// The object's strokes as they show now, ids kept: a posed object's strokes get new data
// holding their posed points; an unposed object's strokes are returned as they are (shared).
std::vector<Stroke> posedStrokes(const StrokeGroup &group);

// Renders a frame antialiased at `size` (the canvas scaled to fit, aspect kept).
QImage renderFrame(const Frame &frame, const DocumentSettings &settings, QSize size,
                   const RenderOptions &options = {});

} // namespace finbook::model
