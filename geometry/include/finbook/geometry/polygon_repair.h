// Repair arbitrary rings (self-crossing, touching, wrongly oriented, duplicated points) into a
// Region whose rings do not cross, which meshRegion() accepts.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>
#include <finbook/geometry/region.h>

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry {

enum class FillRule {
    EvenOdd, // inside = crossed an odd number of times; orientation does not matter
    NonZero, // inside = winding number ≠ 0; self-crossing loops are filled
};

struct RepairOptions {
    // How the rings of one polygon combine; separate polygons are always unioned.
    FillRule fillRule = FillRule::EvenOdd;
    // Convex corners are rounded to this radius (px) by a morphological opening, because an
    // input angle below ~60° keeps the quality mesher from reaching its 20° minimum angle
    // near that corner. Parts thinner than 2 × cornerRadius disappear. 0 disables.
    double cornerRadius = 1.0;
    // Douglas–Peucker tolerance (px), applied to the input rings (pixel outlines carry many
    // redundant points) and to the result, unless that would make rings cross.
    double simplifyTolerance = 0.25;
};

// All rings together form one polygon, combined by options.fillRule. Rings are m×2 (any
// orientation, implicitly closed); non-finite rows are dropped.
// Errors: EmptyInput (nothing finite), CoordinateOutOfRange, TooManyPoints, InvalidOptions,
// DegenerateRegion (no area left), ClippingFailed (should never happen; reported, not thrown).
// Promise: isSimple(result, Touching::AllowedAtPoints), outer rings positive, holes negative
// (region.h).
Expected<Region, GeometryError> repairRings(const std::vector<Eigen::MatrixX2d> &rings,
                                            const RepairOptions &options = {});

// Each polygon's outer ring and holes combine by options.fillRule, polygons are unioned.
Expected<Region, GeometryError> repairRegion(const Region &region,
                                             const RepairOptions &options = {});

} // namespace finbook::geometry
