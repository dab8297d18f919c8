// The shape of a picture: the outline of its pixels whose alpha reaches a threshold, traced by
// marching squares over the alpha values sampled at pixel centres.
//
// Pixel (i, j) covers [i, i+1] × [j, j+1] in picture pixels (y down, as on the canvas) and its
// alpha is sampled at its centre (i + 0.5, j + 0.5); outside the picture alpha is 0, so every
// outline closes. Where the outline crosses between two centres it is placed by interpolating
// alpha linearly to threshold − ½, so it follows an anti-aliased edge to a fraction of a pixel
// (a disc's outline lies on its circle within about a tenth of a pixel before simplification).
// A fully opaque picture's outline is its rectangle with each corner cut by ½ px along the
// diagonal; callers who want the exact rectangle use it directly (model's pictureShape).
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>
#include <finbook/geometry/region.h>

#include <cstdint>

namespace finbook::geometry {

struct AlphaOutlineOptions {
    int threshold = 128;   // a pixel is inside when its alpha ≥ threshold; 1..255
    double simplify = 0.5; // Douglas–Peucker tolerance in px; 0 keeps every crossing
    double minArea = 3.0;  // px²: outer loops and holes of smaller area are dropped
    long maxOutlinePoints = kMaxInputPoints; // refused beyond this (noise pictures)
};

// The largest picture side traceAlphaOutline accepts (the model refuses larger pictures first).
inline constexpr int kMaxAlphaSide = 65536;

// `alpha` points at the alpha of pixel (0, 0); pixel (x, y) is at
// alpha[y * rowStride + x * pixelStride] (pixelStride 4 reads one byte of 32-bit pixels).
// Returns polygons in the convention of region.h: outer rings with positive shoelace area,
// holes negative and strictly inside their outer ring, implicitly closed, no NaN. Rings come
// from different crossings and so never share a point before simplification; simplification
// may make two rings that passed within `simplify` px of each other touch or cross (a mesh
// takes the region through repairRegion, as buildObjectMesh(Region) does). An island inside
// a hole is its own polygon. An empty or fully transparent picture gives an empty region.
// Errors: InvalidOptions (threshold, simplify, minArea, strides, sizes, null alpha with a
// non-empty size), TooManyPoints (more crossings than maxOutlinePoints).
Expected<Region, GeometryError> traceAlphaOutline(const std::uint8_t *alpha, int width, int height,
                                                  long rowStride, int pixelStride = 1,
                                                  const AlphaOutlineOptions &options = {});

} // namespace finbook::geometry
