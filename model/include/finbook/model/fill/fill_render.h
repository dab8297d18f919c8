// Fills as every renderer draws them (the canvas, thumbnails, onion skin, playback, each export
// format): one item per fill, its faces as the object shows now (posed where it is posed), to be
// drawn under the object's strokes.
#pragma once

#include <finbook/model/render.h>
#include <finbook/model/shade/fill_shading.h>

#include <QPainterPath>

#include <functional>
#include <optional>
#include <vector>

namespace finbook::model {

struct FillItem {
    QPainterPath path; // canvas pixels, non-zero (winding) rule
    QRgb color = 0;    // after options: the onion-skin tint, lighter than the strokes'
    int fill = -1;     // the index of the object's fill it paints (a socket: the limb's)
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
// then each cut piece with the fills clipped to its outline and its own runs (joined across a
// cut by an arc on the piece above, cutOutSeam, or else the run across goes with the deeper
// piece), so a limb turned over the body
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
// The index of the fill that `layers` show at canvas point p (the topmost fill item holding
// it), or -1.
int shownFillAt(const std::vector<PaintLayer> &layers, QPointF p);

// Where posed stroke `stroke` of a cut-out pose crosses a cut between its points i and i + 1
// and both pieces turned rigidly: each piece's part of the line ends where it met the cut at
// rest (its point nearest the joint: the cut runs from the joint to the outline's nearest
// point), and an arc round the joint joins the two ends, as a cut-out puppet's round joint is
// drawn. `arc` runs from point i's piece's end to point i + 1's; `cut` is the deeper piece's
// cut, whose socket (centre `joint`) the arc goes round. nullopt where the line is drawn
// straight across (a piece that bent, no round end, no cut there).
struct CutOutSeam {
    std::size_t cut = 0;
    QPointF joint;
    std::vector<StrokePoint> arc;
};
std::optional<CutOutSeam> cutOutSeam(const StrokeGroup &group, std::size_t stroke, std::size_t i);

// What bakedStrokes does with the parts of lines a piece above hides: drops them (the SVG
// export draws what shows), or keeps them unseen (kHiddenLineColor: drawn by no renderer,
// bounding no region), so that each line stays whole and the loop it closed still inflates as
// one (Apply Pose).
enum class HiddenLines { Drop, KeepUnseen };

// The strokes Apply Pose makes of `group`'s pose: posedStrokes (a cut-out pose's lines go round
// the joints), with what the pose hid cut away: the parts of a piece's lines that a piece
// drawn over it covers with its fills (paintLayers: the body's outline under a limb turned over
// it), cut where the cover begins, so the baked drawing shows what the pose showed. A stroke
// cut so becomes several strokes in its place, in order along it (each part begins where the
// one before ends), its first part that shows with its id, the others with ids from `newId`;
// the hidden parts are left out or kept unseen as `hidden` says (a stroke hidden whole too).
// Any other pose: as posedStrokes. `closeGap`: the document's Close gaps, as the pose was
// painted with.
std::vector<Stroke> bakedStrokes(const StrokeGroup &group, double closeGap,
                                 const std::function<Id()> &newId,
                                 HiddenLines hidden = HiddenLines::Drop);
// The same with the group's paintLayers already made with `settings` (the SVG export paints
// them too).
std::vector<Stroke> bakedStrokes(const StrokeGroup &group, const std::vector<PaintLayer> &layers,
                                 const DocumentSettings &settings, const std::function<Id()> &newId,
                                 HiddenLines hidden = HiddenLines::Drop);

// Paints one item: its path, then its tones (the canvas raster draws its own way).
void paintFill(QPainter &painter, const FillItem &fill);

// A layer's fills (`fills`, back to front) as the renderers paint them: the flat fills of one
// colour joined into one path wherever that changes nothing else, so that two fills of one
// colour meeting along a line of no ink (Fill All's fills either side of a closed gap; Apply
// Pose's cut-out closers) paint as one. Painted apart, each covered the pixels of their shared
// edge in part, and the paper showed through as a light seam. A fill joins the last earlier
// one of its colour that no fill of another colour painted between them overlaps (their
// boxes); fills with tones stay as they are. Only an object at rest (`group`): its fills are
// faces of one arrangement, which never overlap, so joined paths cover each pixel as painted
// apart; a posed object's pieces and sockets overlap, and a path of overlapping parts of
// either turning would leave holes where they meet.
std::vector<FillItem> paintedFills(const StrokeGroup &group, const std::vector<FillItem> &fills);

// Whether any object of the frame that `options` shows has fills (false when options leave
// fills out).
bool frameHasFills(const Frame &frame, const RenderOptions &options = {});

// The alpha a tinted fill gets against a tinted stroke (onion skin): the shape reads, the ink
// stays on top.
constexpr double kTintedFillAlpha = 0.35;

} // namespace finbook::model
