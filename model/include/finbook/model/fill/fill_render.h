// Fills as every renderer draws them (the canvas, thumbnails, onion skin, playback, each export
// format): one item per fill, its faces as the object shows now (posed where it is posed), to be
// drawn under the object's strokes.
#pragma once

#include <finbook/model/render.h>
#include <finbook/model/shade/fill_shading.h>

#include <QPainterPath>

namespace finbook::model {

struct FillItem {
    QPainterPath path; // canvas pixels, non-zero (winding) rule
    QRgb color = 0;    // after options: the onion-skin tint, lighter than the strokes'
    // A shaded fill's tone regions (shade/fill_shading.h), drawn over `path` in this order.
    // They follow the fill's faces and end on its outline, under the ink.
    std::vector<ToneItem> tones;
};

// The fills of one object, back to front, flat. Empty for an object without fills.
std::vector<FillItem> fillList(const StrokeGroup &group, double closeGap,
                               const RenderOptions &options = {});
// The same with shaded fills' tones lit by the document's light (settings.closeGap decides
// the regions). Tinted fills (onion skin) stay flat.
std::vector<FillItem> fillList(const StrokeGroup &group, const DocumentSettings &settings,
                               const RenderOptions &options = {});

// An object as the renderers paint it, back to front: usually one layer (its fills, then its
// strokes). A cut-out pose (DeformedStrokes::pieces) gives one layer per piece, each over the
// ones before: the roots' piece with every fill and the strokes' runs that stayed with it,
// then each cut piece with the fills clipped to its outline and its own runs (the run across
// a cut goes with the deeper piece: the limb's round end), so a limb turned over the body
// hides the body's lines under it, as a cut-out puppet's paper limb does. A piece that moved
// rigidly (DeformedStrokes::motions) takes the rest fills moved with it, so no twist of the
// posed fills opens a hole in it; each cut's socket (its round joint) is painted in the limb's
// fill on the layer of the piece above it, over that layer's fills.
struct PaintLayer {
    std::vector<FillItem> fills;
    std::vector<PaintItem> strokes;             // may point into runs
    std::vector<std::vector<StrokePoint>> runs; // pieces of strokes split at the cuts
    PaintLayer() = default;
    PaintLayer(const PaintLayer &) = delete; // strokes point into runs
    PaintLayer &operator=(const PaintLayer &) = delete;
    PaintLayer(PaintLayer &&) = default;
    PaintLayer &operator=(PaintLayer &&) = default;
};
std::vector<PaintLayer> paintLayers(const StrokeGroup &group, const DocumentSettings &settings,
                                    const RenderOptions &options = {});

// Paints one item: its path, then its tones (the canvas raster draws its own way).
void paintFill(QPainter &painter, const FillItem &fill);

// Whether any object of the frame that `options` shows has fills.
bool frameHasFills(const Frame &frame, const RenderOptions &options = {});

// The alpha a tinted fill gets against a tinted stroke (onion skin): the shape reads, the ink
// stays on top.
constexpr double kTintedFillAlpha = 0.35;

} // namespace finbook::model
