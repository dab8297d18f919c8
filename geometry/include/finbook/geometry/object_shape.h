// The shape of an object: what meshing, skeletons and Fit Cage see. The union of the closed
// regions of its strokes (regions.h) and the strokes' bands (silhouette.h), so a drawing whose
// outline is left slightly open still gives a body, not a wire along the pen line. A tidy
// closed outline gives exactly its silhouette, except that a long, narrow slit of its own
// outline that the silhouette's closing filled (between an octopus's arms, the fingers of a
// hand, the turns of a coil) stays open, as the fill leaves it; the closing still bridges
// separate strokes and the slivers a sketchy stroke's end leaves.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>
#include <finbook/geometry/regions.h>
#include <finbook/geometry/silhouette.h>

#include <vector>

namespace finbook::geometry {

// Errors: those of silhouette() and computeRegions(). Promise: as silhouette() — simple up to
// touching points, outer rings positive, holes negative (kept only with HoleMode::KeepHoles),
// no NaN, every finite stroke point inside.
Expected<Region, GeometryError> objectShape(const std::vector<StrokeInput> &strokes,
                                            const SilhouetteOptions &silhouetteOptions = {},
                                            const RegionsOptions &regionsOptions = {});

} // namespace finbook::geometry
