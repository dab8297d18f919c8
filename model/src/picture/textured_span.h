// The pixel side of drawTexturedMesh (textured_mesh.h): bilinear premultiplied samples of the
// texture composited source-over along one span of a target row. Private to the model.
#pragma once

#include <QtGlobal>

#include <algorithm>
#include <cstdint>

namespace finbook::model::picture_detail {

// The target and the texture as plain memory.
struct Raster {
    std::uint32_t *target;
    qsizetype targetStride; // in pixels
    int width, height;
    const std::uint32_t *texture;
    qsizetype textureStride;
    int texWidth, texHeight;
    std::uint32_t alpha;     // opacity, 0..255
    int bandTop, bandBottom; // the rows [bandTop, bandBottom) this pass may draw
};

// Per channel (x·a + y·b) / 256 for a + b = 256, two channels per multiply.
inline std::uint32_t lerpPixel(std::uint32_t x, std::uint32_t a, std::uint32_t y, std::uint32_t b)
{
    std::uint32_t t = (x & 0xff00ffu) * a + (y & 0xff00ffu) * b;
    t = (t >> 8) & 0xff00ffu;
    x = ((x >> 8) & 0xff00ffu) * a + ((y >> 8) & 0xff00ffu) * b;
    return (x & 0xff00ff00u) | t;
}

// Per channel x · a / 255, rounded (a in 0..255).
inline std::uint32_t scalePixel(std::uint32_t x, std::uint32_t a)
{
    std::uint32_t t = (x & 0xff00ffu) * a;
    t = ((t + ((t >> 8) & 0xff00ffu) + 0x800080u) >> 8) & 0xff00ffu;
    x = ((x >> 8) & 0xff00ffu) * a;
    x = (x + ((x >> 8) & 0xff00ffu) + 0x800080u) & 0xff00ff00u;
    return x | t;
}

// Bilinear sample at su, sv (16.16 texel coordinates relative to texel centres, u − ½, v − ½)
// with the neighbours clamped to the texture: for the half pixel along its border.
inline std::uint32_t sampleClamped(const Raster &r, std::int64_t su, std::int64_t sv)
{
    const std::int64_t fx = su >> 16, fy = sv >> 16;
    const auto wx = std::uint32_t((su >> 8) & 0xff), wy = std::uint32_t((sv >> 8) & 0xff);
    const int x0 = int(std::clamp<std::int64_t>(fx, 0, r.texWidth - 1));
    const int x1 = int(std::clamp<std::int64_t>(fx + 1, 0, r.texWidth - 1));
    const int y0 = int(std::clamp<std::int64_t>(fy, 0, r.texHeight - 1));
    const int y1 = int(std::clamp<std::int64_t>(fy + 1, 0, r.texHeight - 1));
    const std::uint32_t *row0 = r.texture + qsizetype(y0) * r.textureStride;
    const std::uint32_t *row1 = r.texture + qsizetype(y1) * r.textureStride;
    const std::uint32_t top = lerpPixel(row0[x0], 256 - wx, row0[x1], wx);
    const std::uint32_t bottom = lerpPixel(row1[x0], 256 - wx, row1[x1], wx);
    return lerpPixel(top, 256 - wy, bottom, wy);
}

// A pixel's four channels spread to 16 bits each (0x00AA00GG00RR00BB order: A, G | R, B).
inline std::uint64_t spread(std::uint32_t p)
{
    return std::uint64_t(p & 0xff00ffu) | (std::uint64_t(p & 0xff00ff00u) << 24);
}

// Bilinear sample between texel `p` and its right, lower and lower-right neighbours: one
// weighted sum of the four spread texels (weights summing to 256, so 255 · 256 fits a lane).
inline std::uint32_t sampleInterior(const std::uint32_t *p, qsizetype stride, std::uint32_t wx,
                                    std::uint32_t wy)
{
    if ((wx | wy) == 0) // on a texel centre (the rest pose): the texel itself
        return p[0];
    const std::uint32_t w11 = (wx * wy + 128) >> 8, w10 = wx - w11, w01 = wy - w11;
    const std::uint32_t w00 = 256 - wx - wy + w11;
    const std::uint64_t sum = spread(p[0]) * w00 + spread(p[1]) * w10 + spread(p[stride]) * w01 +
                              spread(p[stride + 1]) * w11;
    const std::uint64_t lanes = (sum >> 8) & 0x00ff00ff00ff00ffull;
    return std::uint32_t(lanes & 0xff00ffu) | (std::uint32_t(lanes >> 24) & 0xff00ff00u);
}

// A triangle's uv in 32.32 fixed point relative to texel centres (u − ½, v − ½), as an
// affine function of the pixel (x, y) measured from the triangle's box corner (x0, y0):
// exact enough over any box (2^-32 texel per pixel of error), and a span starts with two
// integer multiplies instead of floating point and rounding.
struct FixedPlane {
    std::int64_t u, dudx, dudy, v, dvdx, dvdy; // at pixel (x0, y0)'s centre; per pixel
    std::int64_t x0, y0;
};

// Draws pixels x0..x1 of row y. `r` by value: its fields are locals the compiler may keep in
// registers (the target's pixels are unsigned ints, which could otherwise alias the int fields
// of a Raster in memory).
inline void drawSpan(const Raster r, const FixedPlane &p, int y, int x0, int x1)
{
    const std::int64_t dx = x0 - p.x0, dy = y - p.y0;
    std::int64_t u = p.u + dx * p.dudx + dy * p.dudy, v = p.v + dx * p.dvdx + dy * p.dvdy;
    // In 16.16: u ∈ [0, w] ⇔ su ∈ [−½, w − ½]; inside [0, w − 1) all four texels exist.
    const std::int64_t minS = -32768, maxU = std::int64_t(r.texWidth) * 65536 - 32768,
                       maxV = std::int64_t(r.texHeight) * 65536 - 32768;
    const auto innerU = std::uint64_t(r.texWidth - 1) << 16, innerV = std::uint64_t(r.texHeight - 1)
                                                                      << 16;
    std::uint32_t *out = r.target + qsizetype(y) * r.targetStride;
    for (int x = x0; x <= x1; ++x, u += p.dudx, v += p.dvdx) {
        const std::int64_t su = u >> 16, sv = v >> 16;
        std::uint32_t s;
        if (std::uint64_t(su) < innerU && std::uint64_t(sv) < innerV) {
            s = sampleInterior(r.texture + (sv >> 16) * r.textureStride + (su >> 16),
                               r.textureStride, std::uint32_t(su >> 8) & 0xff,
                               std::uint32_t(sv >> 8) & 0xff);
        } else if (su < minS || sv < minS || su > maxU || sv > maxV) {
            continue; // outside the texture's rectangle: transparent
        } else {
            s = sampleClamped(r, su, sv);
        }
        if (r.alpha != 255)
            s = scalePixel(s, r.alpha);
        const std::uint32_t a = s >> 24;
        if (a == 255)
            out[x] = s;
        else if (s != 0)
            out[x] = s + scalePixel(out[x], 255 - a);
    }
}

} // namespace finbook::model::picture_detail
