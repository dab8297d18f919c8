// The pixel side of drawTexturedMesh (textured_mesh.h): bilinear premultiplied samples of the
// texture composited source-over along one span of a target row. Private to the model.
#pragma once

#include <QtGlobal>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define FINBOOK_TEXTURE_AVX2 1
#endif

#include <algorithm>
#include <cstdint>

namespace finbook::model::picture_detail {

// Which pixel kernel the spans are drawn with (drawSpanWith's groups); all give the same pixels
// bit for bit.
enum class SpanKernel { Scalar, Sse2, Avx2 };

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
    SpanKernel kernel;
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

#if defined(__SSE2__)
// scalePixel on 16-bit lanes: x · a / 255 rounded, lane by lane (x, a ≤ 255).
inline __m128i scale16(__m128i x, __m128i a)
{
    const __m128i t = _mm_mullo_epi16(x, a);
    return _mm_srli_epi16(
        _mm_add_epi16(_mm_add_epi16(t, _mm_srli_epi16(t, 8)), _mm_set1_epi16(128)), 8);
}

// The texel at the top left of each of N neighbouring pixels' samples (u, v at the first,
// 32.32 relative to texel centres; du, dv per pixel): a lane past the span (from `count` on)
// takes the first's, a texel that exists.
template <int N>
[[gnu::always_inline]] inline void texelsOf(const Raster &r, std::int64_t u, std::int64_t v,
                                            std::int64_t du, std::int64_t dv, int count,
                                            const std::uint32_t *(&texel)[N])
{
    texel[0] = r.texture + (v >> 32) * r.textureStride + (u >> 32);
    for (int i = 1; i < N; ++i)
        texel[i] = i < count
                       ? r.texture + ((v + i * dv) >> 32) * r.textureStride + ((u + i * du) >> 32)
                       : texel[0];
}

// Stores the first `count` (1..4) pixels of `pixels`, and nothing past them: no read of the
// target, which a pass that only overwrites should not wait for.
inline void storePixels(std::uint32_t *out, __m128i pixels, int count)
{
    if (count == 4) {
        _mm_storeu_si128(reinterpret_cast<__m128i *>(out), pixels);
        return;
    }
    if (count & 2) {
        _mm_storel_epi64(reinterpret_cast<__m128i *>(out), pixels);
        out += 2;
        pixels = _mm_srli_si128(pixels, 8);
    }
    if (count & 1)
        *out = std::uint32_t(_mm_cvtsi128_si32(pixels));
}

// A triangle's steps for drawFour: u and v as 32.32 per pixel, and the low words of 0..3 steps.
struct FourSteps {
    std::int64_t du, dv;
    __m128i lowU, lowV; // 32-bit lanes: (i · du) mod 2^32, (i · dv) mod 2^32 for i = 0..3
    __m128i opacity;    // 16-bit lanes
};

inline FourSteps fourSteps(const FixedPlane &p, std::uint32_t alpha)
{
    const auto du = std::uint32_t(p.dudx), dv = std::uint32_t(p.dvdx);
    return {p.dudx, p.dvdx, _mm_setr_epi32(0, int(du), int(2 * du), int(3 * du)),
            _mm_setr_epi32(0, int(dv), int(2 * dv), int(3 * dv)), _mm_set1_epi16(short(alpha))};
}

// Sum of the four neighbours of two pixels (16-bit lanes: pixel i's channels, then pixel j's)
// weighted by w00..w11 (16-bit lanes, each pixel's weight four times), divided by 256.
inline __m128i bilinearPair(const std::uint32_t *pi, const std::uint32_t *pj, qsizetype stride,
                            __m128i w00, __m128i w10, __m128i w01, __m128i w11)
{
    const __m128i zero = _mm_setzero_si128();
    const __m128i top = _mm_unpacklo_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(pi)),
                                           _mm_loadl_epi64(reinterpret_cast<const __m128i *>(pj)));
    const __m128i bottom =
        _mm_unpacklo_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(pi + stride)),
                           _mm_loadl_epi64(reinterpret_cast<const __m128i *>(pj + stride)));
    __m128i sum = _mm_mullo_epi16(_mm_unpacklo_epi8(top, zero), w00);
    sum = _mm_add_epi16(sum, _mm_mullo_epi16(_mm_unpackhi_epi8(top, zero), w10));
    sum = _mm_add_epi16(sum, _mm_mullo_epi16(_mm_unpacklo_epi8(bottom, zero), w01));
    sum = _mm_add_epi16(sum, _mm_mullo_epi16(_mm_unpackhi_epi8(bottom, zero), w11));
    return _mm_srli_epi16(sum, 8); // weights sum to 256: no lane passes 255 · 256
}

// Four neighbouring pixels whose samples all lie inside the texture's interior (u, v at the
// first, 32.32 relative to texel centres), sampled and composited at once. The same weights,
// sums and roundings as sampleInterior, scalePixel and the source-over of drawOne, so the same
// pixels bit for bit: a clear source leaves the target as it was (x · 255 / 255 rounds back to x)
// and an opaque one replaces it.
[[gnu::always_inline]] inline void drawFour(const Raster &r, std::uint32_t *out, std::int64_t u,
                                            std::int64_t v, const FourSteps &steps, int count)
{
    const std::uint32_t *texel[4];
    texelsOf(r, u, v, steps.du, steps.dv, count, texel);
    // The weights are bits 24..31 of u and v: exact in wrapping 32-bit arithmetic.
    const __m128i wx =
        _mm_srli_epi32(_mm_add_epi32(_mm_set1_epi32(int(std::uint32_t(u))), steps.lowU), 24);
    const __m128i wy =
        _mm_srli_epi32(_mm_add_epi32(_mm_set1_epi32(int(std::uint32_t(v))), steps.lowV), 24);
    const __m128i w11 =
        _mm_srli_epi32(_mm_add_epi32(_mm_mullo_epi16(wx, wy), _mm_set1_epi32(128)), 8);
    const __m128i w10 = _mm_sub_epi32(wx, w11), w01 = _mm_sub_epi32(wy, w11);
    const __m128i w00 =
        _mm_sub_epi32(_mm_add_epi32(_mm_set1_epi32(256), w11), _mm_add_epi32(wx, wy));
    // Each pixel's weight in four 16-bit lanes: pixels 0, 1 in the low halves, 2, 3 in the high.
    const __m128i left = _mm_packs_epi32(w00, w10), right = _mm_packs_epi32(w01, w11);
    const __m128i l0 = _mm_unpacklo_epi16(left, left), l1 = _mm_unpackhi_epi16(left, left);
    const __m128i r0 = _mm_unpacklo_epi16(right, right), r1 = _mm_unpackhi_epi16(right, right);
    __m128i first = bilinearPair(texel[0], texel[1], r.textureStride, _mm_unpacklo_epi32(l0, l0),
                                 _mm_unpacklo_epi32(l1, l1), _mm_unpacklo_epi32(r0, r0),
                                 _mm_unpacklo_epi32(r1, r1));
    __m128i second = bilinearPair(texel[2], texel[3], r.textureStride, _mm_unpackhi_epi32(l0, l0),
                                  _mm_unpackhi_epi32(l1, l1), _mm_unpackhi_epi32(r0, r0),
                                  _mm_unpackhi_epi32(r1, r1));
    if (r.alpha != 255) {
        first = scale16(first, steps.opacity);
        second = scale16(second, steps.opacity);
    }
    __m128i result = _mm_packus_epi16(first, second);
    // The span's bytes in a byte mask, and whether its pixels are all opaque or all clear.
    const int lanes = count == 4 ? 0xffff : (1 << (4 * count)) - 1;
    const int opaque = _mm_movemask_epi8(_mm_cmpeq_epi8(result, _mm_set1_epi8(char(-1))));
    const __m128i zero = _mm_setzero_si128();
    if ((opaque & 0x8888 & lanes) != (0x8888 & lanes)) {
        if ((_mm_movemask_epi8(_mm_cmpeq_epi8(result, zero)) & lanes) == lanes)
            return; // all clear: the target as it was
        const __m128i under = _mm_loadu_si128(reinterpret_cast<const __m128i *>(out));
        const __m128i full = _mm_set1_epi16(255);
        const auto over = [&](__m128i s, __m128i d) {
            const __m128i a = _mm_shufflehi_epi16(_mm_shufflelo_epi16(s, 0xff), 0xff);
            return _mm_add_epi16(s, scale16(d, _mm_sub_epi16(full, a)));
        };
        result = _mm_packus_epi16(over(first, _mm_unpacklo_epi8(under, zero)),
                                  over(second, _mm_unpackhi_epi8(under, zero)));
    }
    storePixels(out, result, count);
}
#endif

#if defined(FINBOOK_TEXTURE_AVX2)
// drawFour eight pixels at a time where the processor has AVX2: pixels 0-3 in the low 128-bit
// lane and 4-7 in the high one, each lane doing exactly what drawFour does.
struct EightSteps {
    std::int64_t du, dv;
    __m256i lowU, lowV;
    __m256i opacity;
};

__attribute__((target("avx2"))) inline EightSteps eightSteps(const FixedPlane &p,
                                                             std::uint32_t alpha)
{
    const auto du = std::uint32_t(p.dudx), dv = std::uint32_t(p.dvdx);
    const __m256i ramp = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    return {p.dudx, p.dvdx, _mm256_mullo_epi32(ramp, _mm256_set1_epi32(int(du))),
            _mm256_mullo_epi32(ramp, _mm256_set1_epi32(int(dv))), _mm256_set1_epi16(short(alpha))};
}

__attribute__((target("avx2"))) inline __m256i scale16(__m256i x, __m256i a)
{
    const __m256i t = _mm256_mullo_epi16(x, a);
    return _mm256_srli_epi16(
        _mm256_add_epi16(_mm256_add_epi16(t, _mm256_srli_epi16(t, 8)), _mm256_set1_epi16(128)), 8);
}

// Texels p, p + 1 of two pixels side by side in one 128-bit lane's low and high halves.
__attribute__((target("avx2"))) inline __m128i texelPairs(const std::uint32_t *pi,
                                                          const std::uint32_t *pj)
{
    return _mm_unpacklo_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(pi)),
                              _mm_loadl_epi64(reinterpret_cast<const __m128i *>(pj)));
}

// bilinearPair for pixels (i, j) in the low lane and (k, l) in the high lane.
__attribute__((target("avx2"))) inline __m256i bilinearPairs(const std::uint32_t *const *t,
                                                             qsizetype stride, __m256i w00,
                                                             __m256i w10, __m256i w01, __m256i w11)
{
    const __m256i zero = _mm256_setzero_si256();
    const __m256i top = _mm256_set_m128i(texelPairs(t[2], t[3]), texelPairs(t[0], t[1]));
    const __m256i bottom = _mm256_set_m128i(texelPairs(t[2] + stride, t[3] + stride),
                                            texelPairs(t[0] + stride, t[1] + stride));
    __m256i sum = _mm256_mullo_epi16(_mm256_unpacklo_epi8(top, zero), w00);
    sum = _mm256_add_epi16(sum, _mm256_mullo_epi16(_mm256_unpackhi_epi8(top, zero), w10));
    sum = _mm256_add_epi16(sum, _mm256_mullo_epi16(_mm256_unpacklo_epi8(bottom, zero), w01));
    sum = _mm256_add_epi16(sum, _mm256_mullo_epi16(_mm256_unpackhi_epi8(bottom, zero), w11));
    return _mm256_srli_epi16(sum, 8);
}

// Source-over in 16-bit lanes: s + d · (255 − s's alpha) / 255.
__attribute__((target("avx2"))) inline __m256i over(__m256i s, __m256i d)
{
    const __m256i a = _mm256_shufflehi_epi16(_mm256_shufflelo_epi16(s, 0xff), 0xff);
    return _mm256_add_epi16(s, scale16(d, _mm256_sub_epi16(_mm256_set1_epi16(255), a)));
}

[[gnu::always_inline]] __attribute__((target("avx2"))) inline void
drawEight(const Raster &r, std::uint32_t *out, std::int64_t u, std::int64_t v,
          const EightSteps &steps, int count)
{
    const __m256i wx = _mm256_srli_epi32(
        _mm256_add_epi32(_mm256_set1_epi32(int(std::uint32_t(u))), steps.lowU), 24);
    const __m256i wy = _mm256_srli_epi32(
        _mm256_add_epi32(_mm256_set1_epi32(int(std::uint32_t(v))), steps.lowV), 24);
    const std::uint32_t *texel[8];
    texelsOf(r, u, v, steps.du, steps.dv, count, texel);
    const __m256i w11 =
        _mm256_srli_epi32(_mm256_add_epi32(_mm256_mullo_epi16(wx, wy), _mm256_set1_epi32(128)), 8);
    const __m256i w10 = _mm256_sub_epi32(wx, w11), w01 = _mm256_sub_epi32(wy, w11);
    const __m256i w00 =
        _mm256_sub_epi32(_mm256_add_epi32(_mm256_set1_epi32(256), w11), _mm256_add_epi32(wx, wy));
    const __m256i left = _mm256_packs_epi32(w00, w10), right = _mm256_packs_epi32(w01, w11);
    const __m256i l0 = _mm256_unpacklo_epi16(left, left), l1 = _mm256_unpackhi_epi16(left, left);
    const __m256i r0 = _mm256_unpacklo_epi16(right, right),
                  r1 = _mm256_unpackhi_epi16(right, right);
    const std::uint32_t *const firstTexels[4] = {texel[0], texel[1], texel[4], texel[5]};
    const std::uint32_t *const secondTexels[4] = {texel[2], texel[3], texel[6], texel[7]};
    __m256i first = bilinearPairs(firstTexels, r.textureStride, _mm256_unpacklo_epi32(l0, l0),
                                  _mm256_unpacklo_epi32(l1, l1), _mm256_unpacklo_epi32(r0, r0),
                                  _mm256_unpacklo_epi32(r1, r1));
    __m256i second = bilinearPairs(secondTexels, r.textureStride, _mm256_unpackhi_epi32(l0, l0),
                                   _mm256_unpackhi_epi32(l1, l1), _mm256_unpackhi_epi32(r0, r0),
                                   _mm256_unpackhi_epi32(r1, r1));
    if (r.alpha != 255) {
        first = scale16(first, steps.opacity);
        second = scale16(second, steps.opacity);
    }
    __m256i result = _mm256_packus_epi16(first, second);
    // The span's bytes in a byte mask, and whether its pixels are all opaque or all clear.
    const std::uint32_t lanes = count == 8 ? 0xffffffffu : (1u << (4 * count)) - 1;
    const auto opaque =
        std::uint32_t(_mm256_movemask_epi8(_mm256_cmpeq_epi8(result, _mm256_set1_epi8(char(-1)))));
    const __m256i zero = _mm256_setzero_si256();
    if ((opaque & 0x88888888u & lanes) != (0x88888888u & lanes)) {
        const auto clear = std::uint32_t(_mm256_movemask_epi8(_mm256_cmpeq_epi8(result, zero)));
        if ((clear & lanes) == lanes)
            return; // all clear: the target as it was
        const __m256i under = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(out));
        result = _mm256_packus_epi16(over(first, _mm256_unpacklo_epi8(under, zero)),
                                     over(second, _mm256_unpackhi_epi8(under, zero)));
    }
    if (count == 8) {
        _mm256_storeu_si256(reinterpret_cast<__m256i *>(out), result);
        return;
    }
    __m128i low = _mm256_castsi256_si128(result);
    if (count & 4) {
        _mm_storeu_si128(reinterpret_cast<__m128i *>(out), low);
        out += 4;
        low = _mm256_extracti128_si256(result, 1);
    }
    storePixels(out, low, count & 3);
}
#endif

// The scalar pixel: pixel x of a span whose sample is (u, v), 32.32 relative to texel centres.
inline void drawOne(const Raster &r, std::uint32_t *out, std::int64_t u, std::int64_t v)
{
    const std::int64_t su = u >> 16, sv = v >> 16;
    // In 16.16: u ∈ [0, w] ⇔ su ∈ [−½, w − ½]; inside [0, w − 1) all four texels exist.
    std::uint32_t s = 0;
    if (std::uint64_t(su) < std::uint64_t(r.texWidth - 1) << 16 &&
        std::uint64_t(sv) < std::uint64_t(r.texHeight - 1) << 16) {
        s = sampleInterior(r.texture + (sv >> 16) * r.textureStride + (su >> 16), r.textureStride,
                           std::uint32_t(su >> 8) & 0xff, std::uint32_t(sv >> 8) & 0xff);
    } else if (su >= -32768 && sv >= -32768 && su <= std::int64_t(r.texWidth) * 65536 - 32768 &&
               sv <= std::int64_t(r.texHeight) * 65536 - 32768) {
        s = sampleClamped(r, su, sv);
    } // else outside the texture's rectangle: transparent
    if (r.alpha != 255)
        s = scalePixel(s, r.alpha);
    const std::uint32_t a = s >> 24;
    if (a == 255)
        *out = s;
    else if (s != 0)
        *out = s + scalePixel(*out, 255 - a);
}

// No wide path: every pixel by drawOne.
struct OneByOne {
    static constexpr int kPixels = 0;
    OneByOne(const FixedPlane &, std::uint32_t) {}
    void draw(const Raster &, std::uint32_t *, std::int64_t, std::int64_t, int) const {}
};

#if defined(__SSE2__)
struct FourAtOnce {
    static constexpr int kPixels = 4;
    FourSteps steps;
    FourAtOnce(const FixedPlane &p, std::uint32_t alpha)
        : steps(fourSteps(p, alpha))
    {}
    [[gnu::always_inline]] void draw(const Raster &r, std::uint32_t *out, std::int64_t u,
                                     std::int64_t v, int count) const
    {
        drawFour(r, out, u, v, steps, count);
    }
};
#endif

#if defined(FINBOOK_TEXTURE_AVX2)
struct EightAtOnce {
    static constexpr int kPixels = 8;
    EightSteps steps;
    __attribute__((target("avx2"))) EightAtOnce(const FixedPlane &p, std::uint32_t alpha)
        : steps(eightSteps(p, alpha))
    {}
    __attribute__((target("avx2"))) void draw(const Raster &r, std::uint32_t *out, std::int64_t u,
                                              std::int64_t v, int count) const
    {
        drawEight(r, out, u, v, steps, count);
    }
};

inline bool hasAvx2()
{
    static const bool yes = __builtin_cpu_supports("avx2");
    return yes;
}
#endif

// Draws pixels x0..x1 of row y, `Group::kPixels` neighbouring pixels at once wherever all of
// them sample inside the texture's interior (everywhere when `inside`: the whole triangle
// does), the others one by one. `r` by value: its fields are locals the compiler may keep in
// registers (the target's pixels are unsigned ints, which could otherwise alias the int fields
// of a Raster in memory).
template <class Group>
[[gnu::always_inline]] inline void drawSpanWith(const Raster r, const FixedPlane &p, int y, int x0,
                                                int x1, const Group &group, bool inside)
{
    const std::int64_t dx = x0 - p.x0, dy = y - p.y0;
    std::int64_t u = p.u + dx * p.dudx + dy * p.dudy, v = p.v + dx * p.dvdx + dy * p.dvdy;
    const auto innerU = std::uint64_t(r.texWidth - 1) << 16, innerV = std::uint64_t(r.texHeight - 1)
                                                                      << 16;
    const auto interior = [&](std::int64_t uu, std::int64_t vv) {
        return std::uint64_t(uu >> 16) < innerU && std::uint64_t(vv >> 16) < innerV;
    };
    std::uint32_t *out = r.target + qsizetype(y) * r.targetStride;
    for (int x = x0; x <= x1;) {
        // A group of up to kPixels pixels, the last one of a span cut short at its end (the
        // wide kernels read a whole group of the target to composite, so it stays inside the
        // row; they write only the span's pixels). The interior is a box and
        // u, v are linear along the span: when the first and the last of a group sample inside
        // it, so do those between.
        if constexpr (Group::kPixels > 0) {
            const int count = std::min(Group::kPixels, x1 - x + 1);
            if (x + Group::kPixels <= r.width &&
                (inside || (interior(u, v) &&
                            interior(u + (count - 1) * p.dudx, v + (count - 1) * p.dvdx)))) {
                group.draw(r, out + x, u, v, count);
                x += count;
                u += count * p.dudx;
                v += count * p.dvdx;
                continue;
            }
        }
        drawOne(r, out + x, u, v);
        ++x;
        u += p.dudx;
        v += p.dvdx;
    }
}

// The widest kernel this build and processor have.
inline SpanKernel widestSpanKernel()
{
#if defined(FINBOOK_TEXTURE_AVX2)
    if (hasAvx2())
        return SpanKernel::Avx2;
#endif
#if defined(__SSE2__)
    return SpanKernel::Sse2;
#else
    return SpanKernel::Scalar;
#endif
}

} // namespace finbook::model::picture_detail
