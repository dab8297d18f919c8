// Layers of one object (issue 27): regions that overlap in the plane, an arm drawn over the
// body, inflate as separate height fields, each with its own zero-height outline, not as one
// merged blob. The planar map (regions.h) cuts the body where the arm's outline crosses it,
// so its faces are the body without the arm, the arm over the body and the arm beside it;
// inflating each face alone would pinch the body to height 0 along the arm's outline.
//
// A layer is the region one stroke closes by itself (its own faces, gaps closed as the
// drawing's are): the body's outline, the arm's. A face inflates as the topmost layer that
// holds it among the strokes on its boundary, topmost meaning drawn last (later strokes lie
// on top, as ink does): the arm over the body is the arm's, the body beside it the body's.
// A face no single stroke closes (an outline drawn in several strokes) is its own layer.
// The face's tones are then cut to the face (shade/tone_region.h).
#pragma once

#include <finbook/geometry/regions.h>

#include <vector>

namespace finbook::geometry {

struct Layer {
    int stroke = -1; // index into the input strokes
    Region region;   // the faces this stroke closes by itself
};

// One layer per input stroke that closes a region by itself, in stroke order. `closeGap` as
// the drawing's regions used (Regions::closeGap). Strokes whose regions cannot be computed
// give no layer. Cost: one planar map per stroke on a face's boundary.
std::vector<Layer> strokeLayers(const std::vector<StrokeInput> &strokes, double closeGap);

// The layer (index into `layers`) that face `face` of `regions` inflates as: the latest
// stroke on the face's boundary whose layer holds the face's seed; −1 when none does (the
// face is its own layer).
int faceLayer(const std::vector<Layer> &layers, const Regions &regions, int face);

// The region face `face` inflates as: the polygon of its layer's region around it (a stroke
// that crosses itself closes several), or the face's own polygon.
Region layerRegion(const std::vector<Layer> &layers, const Regions &regions, int face);

} // namespace finbook::geometry
