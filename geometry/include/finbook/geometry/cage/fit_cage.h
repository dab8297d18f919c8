// Fit Cage: a coarse cage around an object in one step.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>
#include <finbook/geometry/region.h>
#include <finbook/geometry/regions.h>
#include <finbook/geometry/silhouette.h>
#include <finbook/geometry/stroke_input.h>

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry {

struct FitCageOptions {
    // About this many corners: the result has at most this many (a few more only where the
    // shape forces sharp corners to be squared off). In [kMinFitCorners, kMaxFitCorners].
    int corners = 16;
    // px: the object's outline is grown by this much first, and every point that must be
    // contained ends up at least margin / 2 inside the cage. In [0, 1e4].
    double margin = 8.0;
    SilhouetteOptions silhouette; // for the strokes overload
    RegionsOptions regions;       // for the strokes overload (object_shape.h)
};

inline constexpr int kMinFitCorners = 3;
inline constexpr int kMaxFitCorners = 1000;

// A simple polygon (positive orientation, passes checkCage) around `shape` — its outer rings
// grown by options.margin, bridged into one outline where the shape has several parts, and
// simplified to about options.corners corners by Douglas–Peucker, then pushed outward by the
// simplification tolerance — that contains every finite row of `mustContain` (k×2) at least
// margin / 2 from its edges; verified, and grown until it does (a simplified convex hull is
// the last resort, which always does). Holes of `shape` are ignored; `shape` may be empty
// when mustContain is not (the cage then wraps the points alone).
// Errors: EmptyInput (no finite point in shape and mustContain), CoordinateOutOfRange,
// TooManyPoints, InvalidOptions, ClippingFailed (reported, never thrown).
Expected<Eigen::MatrixX2d, GeometryError> fitCage(const Region &shape,
                                                  const Eigen::MatrixX2d &mustContain,
                                                  const FitCageOptions &options = {});

// objectShape(strokes, options.silhouette, options.regions), then the cage around it that
// contains every finite stroke point. Errors: those of objectShape() and of the Region overload.
Expected<Eigen::MatrixX2d, GeometryError> fitCage(const std::vector<StrokeInput> &strokes,
                                                  const FitCageOptions &options = {});

} // namespace finbook::geometry
