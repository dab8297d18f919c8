// The shape of a picture object: what of a picture counts as "the object" when it is meshed.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>
#include <finbook/geometry/picture/alpha_outline.h>
#include <finbook/geometry/region.h>

#include <QImage>

#include <optional>

namespace finbook::model {

// True when every pixel of `image` has alpha 255 (an image without an alpha channel always).
bool isFullyOpaque(const QImage &image);

// `image` (any format) as Format_ARGB32_Premultiplied with its flat background made
// transparent: every pixel whose colour is within `tolerance` (0..255, on each of red, green and
// blue) of `background`'s is cleared; the others keep colour and alpha. The key is hard: an
// anti-aliased edge keeps the pixels that blend into the background beyond the tolerance.
QImage keyedOut(const QImage &image, QRgb background, int tolerance);

// The colour of a flat background `image` stands on, if it has one: it is fully opaque, its four
// corners are one colour (within 8 on each channel) and at least 80 % of its border pixels are
// that colour (within 16). What keyedOut() takes away when the user wants only the subject (a
// scan, a drawing exported on white). Nothing for a picture with transparency.
std::optional<QRgb> flatBackground(const QImage &image);

// The shape of a picture in its own pixels (y down, pixel (i, j) covers [i, i+1] × [j, j+1]):
// the exact rectangle [0, w] × [0, h] when it is fully opaque, otherwise the outline of its
// alpha (traceAlphaOutline, alpha_outline.h, with `options`). Region orientation as region.h.
// Errors: traceAlphaOutline's; an empty region for a null or fully transparent image.
Expected<geometry::Region, geometry::GeometryError>
pictureShape(const QImage &image, const geometry::AlphaOutlineOptions &options = {});

} // namespace finbook::model
