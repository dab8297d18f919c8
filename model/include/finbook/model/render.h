// Painting frames with QPainter (QtGui only): shared by the canvas, timeline thumbnails,
// onion skin and `finbook export`, so every place draws a stroke the same way.
#pragma once

#include <finbook/model/document.h>

#include <QImage>
#include <QPainter>

#include <functional>
#include <optional>

namespace finbook::model {

struct RenderOptions {
    bool paintBackground = true;
    qreal opacity = 1.0;
    std::optional<QColor> tint; // onion skin: every stroke in this colour
    bool showHidden = false;
    // False: shaded fills are painted flat in their colour, without working out their tones
    // (a cheaper picture, for thumbnails over their budget).
    bool shading = true;
    // False: only the strokes are painted (the cheapest picture: its cost follows the points).
    bool fills = true;
    // Painted on the page after its background, clipped to it, under the drawing (the
    // reference picture of thumbnails and exports). Empty: nothing.
    std::function<void(QPainter &)> underlay;
    // renderFrame: the page seen through this camera (the picture is the shot, the
    // background all over it). Empty: the page as it is.
    std::optional<CameraState> camera;
};

// Liang–Barsky: cuts segment a→b to the part inside `r`; false when none of it is (or it is
// not finite). An end inside `r` comes back exactly as it was. `t0`, `t1` (optional) get where
// the kept part starts and ends along the original segment (0..1).
bool clipSegment(QPointF &a, QPointF &b, const QRectF &r, double *t0 = nullptr,
                 double *t1 = nullptr);

// Paints one stroke with its pressure-varying width. Consecutive samples whose widths round
// to the same quarter pixel are drawn as one polyline, which keeps 50k-point frames fast.
// Only what the painter can show is drawn: segments are clipped to the device (and the
// painter's clip) plus the pen's reach, so a point far off the canvas costs no more than
// one on it. Pens several dozen device pixels wide are filled as the union of their segments'
// capsules, and a long scribble whose outlines would crowd QPainter's rows (any pen) as a
// coverage mask of the device, so its cost is bounded by the frame, not by its overlap.
// Non-finite points and widths are skipped.
void paintStroke(QPainter &painter, const std::vector<StrokePoint> &points, QRgb color,
                 float width);

// One stroke to paint: the points shown (rest or pose), the colour after options (tint; the
// alpha may carry extra coats, see paintList), the nominal width.
struct PaintItem {
    const std::vector<StrokePoint> *points = nullptr; // into the frame: valid while it is
    QRgb color = 0;
    float width = 0.0f;
    int coats = 1; // how many references of the same stroke this item stands for
};

// The strokes of a frame in painting order (back to front), with options applied. A stroke
// referenced several times in the frame (the same points, colour and width: a pasted copy in
// place, or a crafted file referencing one stroke thousands of times) is one item at its last
// place whose alpha is what its coats add up to (exact inside the stroke, within a grey level
// at its edges), so painting a frame costs what its distinct strokes cost.
std::vector<PaintItem> paintList(const Frame &frame, const RenderOptions &options = {});
// The same for one object's strokes (a frame with fills is painted object by object, each
// object's fills under its strokes: fill/fill_render.h).
std::vector<PaintItem> paintList(const StrokeGroup &group, const RenderOptions &options = {});

// Paints the objects of a frame (deformed pose where an object has one) in canvas
// coordinates; the painter's transform maps canvas to device. Each object's fills go under
// its strokes (settings.closeGap decides its regions).
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

// Rows [top, top + rows) of renderFrame(frame, settings, size, options): a huge frame can be
// rendered band by band (export) without an image of its full size. Needs 0 <= top and
// rows >= 0; a null image when even the band cannot be allocated.
QImage renderFrameBand(const Frame &frame, const DocumentSettings &settings, QSize size, int top,
                       int rows, const RenderOptions &options = {});

} // namespace finbook::model
