// The silhouette of a stroke group: the filled area an artist means by "this object".
//
// Every stroke is widened to a band of radius width/2 + margin (round caps and joins, so a
// one-point stroke becomes a disk), the bands are united, gaps up to `gap` px wide are bridged
// by a morphological closing (dilate by gap/2, unite, erode by gap/2), and areas enclosed by
// the strokes are filled. Parts drawn further apart than `gap` stay separate polygons (lobes).
// Every finite stroke point lies inside the result, more than width/2 + margin − (0.2 px +
// simplifyTolerance) from its boundary (chords of the round caps, thinning of dense strokes
// and simplification of the outline each cut in a little), and in any case more than
// 0.7 × (width/2 + margin).
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>
#include <finbook/geometry/region.h>
#include <finbook/geometry/stroke_input.h>

#include <vector>

namespace finbook::geometry {

enum class HoleMode {
    // Everything enclosed by strokes is inside: a closed outline becomes a filled shape, a
    // face's eyes do not punch holes. What OpenToonz and MonsterMash do; the default.
    FillEnclosed,
    // Enclosed areas wider than the gap stay holes (a ring drawn as concentric strokes keeps
    // its middle open; so does a single closed outline). Narrower ones are closed.
    KeepHoles,
};

struct SilhouetteOptions {
    double margin = 2.0; // px added around the pen's edge; ≥ 0
    double gap = 8.0;    // px: gaps up to this wide between strokes are bridged; ≥ 0
    HoleMode holes = HoleMode::FillEnclosed;
    // Douglas–Peucker tolerance (px) on the outline; capped at a fifth of the thinnest
    // stroke's radius (width/2 + margin) so stroke points stay well inside.
    double simplifyTolerance = 0.4;
};

// Errors: EmptyInput (no strokes, no finite point), InvalidWidth, InvalidOptions,
// CoordinateOutOfRange, TooManyPoints, DegenerateRegion (zero width and zero margin),
// ClippingFailed (should never happen; reported instead of thrown).
// Promise: isSimple(result, Touching::AllowedAtPoints), outer rings positive and holes negative
// (region.h), no NaN.
Expected<Region, GeometryError> silhouette(const std::vector<StrokeInput> &strokes,
                                           const SilhouetteOptions &options = {});

} // namespace finbook::geometry
