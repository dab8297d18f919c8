// Internal: free ends, touching ends and the closures that close faces (regions.h explains
// the rules). Works on the simplified strokes and grows the planar map as it accepts links.
#pragma once

#include "planar_map.h"
#include "stroke_soup.h"

#include <finbook/geometry/regions.h>

#include <vector>

namespace finbook::geometry::detail {

struct GapClosingResult {
    std::vector<GapClosure> closures;
    int freeEnds = 0;
};

// Inserts the strokes, the snaps of touching ends and the accepted closures into `map`; with
// `mouths`, then the mouths' chords.
GapClosingResult closeGaps(const StrokeSoup &soup, double closeGap, bool mouths, PlanarMap &map);

} // namespace finbook::geometry::detail
