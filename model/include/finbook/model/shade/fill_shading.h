// Shaded fills (issue 27): the tone regions a shaded fill draws over its flat colour, from the
// inflated shape of each of its faces, computed once in the object's rest space and posed with
// the drawing (geometry/shade/pose.h: the posed normals are the rest ones turned by the pose's
// local rotation), then lit by the document's light, which stays fixed on screen.
//
// Every renderer (canvas, thumbnails, onion skin when asked, playback, raster exports, SVG)
// gets the same tone paths through fillList (fill/fill_render.h). Both the rest inflation and
// the posed tones are caches keyed by content (the face's regions object, the pose's shared
// points, the light, the shading, the colour), never undo state; safe on any thread.
#pragma once

#include <finbook/model/fill/fill_regions.h>
#include <finbook/model/types.h>

#include <QPainterPath>

#include <vector>

namespace finbook::model {

// One tone region: polygons (non-zero rule) in canvas px, drawn over the fill in this colour.
struct ToneItem {
    QPainterPath path;
    QRgb color = 0;
};

// Where the ramps change tone, on the Lambert term max(0, n · light) in [0, 1].
constexpr double kShadowBelow = 0.3;    // cel: shadow under this
constexpr double kHighlightAbove = 0.8; // three tones: highlight from this
constexpr int kSmoothLevels = 8;        // smooth: this many bands from shadow to highlight
constexpr double kRimFrom = 0.6;        // rim light where geometry::rimTerm reaches this

// The ramp's colours for a fill colour (alpha kept).
QRgb shadowTone(QRgb color);
QRgb highlightTone(QRgb color);
QRgb rimTone(QRgb color);
// The colour a shaded fill is laid down in before its tones: its own, or the shadow for the
// smooth ramp (whose bands then lighten it).
QRgb baseTone(QRgb color, const FillShading &shading);

// The tones of face `face` of `group`'s regions as it shows now (back to front), for a fill
// of `color` shaded as `shading`, under the light of `settings`, clipped to `facePath` (the
// face as shown: regions->displayedPath(group, face)). Empty when the shading is off or the
// face cannot be inflated (then the fill shows flat).
std::vector<ToneItem> faceTones(const StrokeGroup &group, const ObjectRegionsPtr &regions, int face,
                                const QPainterPath &facePath, const FillShading &shading,
                                QRgb color, const DocumentSettings &settings);

// About how many shading-mesh vertices painting `frame` inflates (each shaded fill of a shown
// object meshes at least one face at its object's mesh density): a price to check before
// painting, as the work and memory of shading grow with it.
qint64 shadingVertexEstimate(const Frame &frame);

} // namespace finbook::model
