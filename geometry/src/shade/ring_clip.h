// Internal (shade/tone_region.h): tone rings cut to a fill outline of one ring without a
// polygon-boolean library. A tone is a few smooth rings of ~100 points and a fill's outline
// one ring of a few dozen; Clipper's sweep spent half of re-shading a posed frame on them.
// Here every crossing of the two outlines is found directly (boxes first), the pieces of
// each outline between crossings are kept where they lie inside the other, and they are
// chained into rings (Greiner–Hormann, forward only: both outlines wound positive, so the
// cut's outline runs forward along both). Rings that cross nothing are kept whole where they
// lie inside the other (a highlight inside the fill, or the whole fill inside a tone).
//
// General position only: where an outline touches the other, runs along it or passes through
// one of its vertices, or the pieces do not chain up, it gives up (false) and the caller
// clips with Clipper, as before.
#pragma once

#include <finbook/geometry/shade/shading.h>

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry::shade_detail {

// `rings` (count of them, non-zero rule, outer rings and holes wound oppositely, not crossing
// each other) cut to the ring `clip` (≥ 3 points, simple). On success the cut is appended to
// `out` (outer rings positive, holes negative, as Clipper gives them) and true is returned.
bool clipToRing(const std::vector<Eigen::Vector2d> *const *rings, std::size_t count,
                const std::vector<Eigen::Vector2d> &clip, Pieces &out);

} // namespace finbook::geometry::shade_detail
