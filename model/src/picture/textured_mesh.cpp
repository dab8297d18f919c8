// drawTexturedMesh: exact fixed-point coverage (top-left rule) row span by row span, uv stepped
// in 16.16 fixed point along a span, bilinear premultiplied samples composited source-over.
#include <finbook/model/picture/textured_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

namespace finbook::model {

namespace {

constexpr int kSubpixelBits = 8; // vertex positions are snapped to 1/256 px
constexpr std::int64_t kSubpixel = std::int64_t(1) << kSubpixelBits;
constexpr std::int64_t kHalfPixel = kSubpixel / 2;
// 2^21 px × 256 = 2^29: edge function products stay below 2^61, sums below 2^63.
constexpr double kMaxTargetCoordinate = double(1 << 21);
// Below these a second thread costs more than it saves.
constexpr int kMinBandRows = 64;
constexpr Eigen::Index kMinThreadedFaces = 64;

struct MeshPoint {
    std::int64_t x = 0, y = 0; // target position in 1/256 px
    double fx = 0.0, fy = 0.0; // target position in px
    bool valid = false;
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

std::int64_t floorDiv(std::int64_t a, std::int64_t b) // b > 0
{
    const std::int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

// One edge P → Q of a triangle wound so that its inside has E > 0, where
// E(s) = (Q − P) × (s − P). The top-left rule is an integer bias: a pixel centre s is covered
// when E(s) + bias ≥ 0, bias 0 on top and left edges (E = 0 counts), −1 on the others (E must
// be > 0). With y down and this winding, a top edge runs in +x and a left edge in −y.
struct Edge {
    // At pixel X's centre on the row whose centre is sampleY (both in 1/256 px):
    // E + bias = dx·(sampleY − py) − dy·(X·256 + 128 − px) + bias = e0 + X·step. A row further
    // down adds dx·256 to e0. The bound on X this gives, floor(e0 / |step|), is walked from row
    // to row as a quotient and remainder (a division per edge, not per row), exactly.
    enum class Bound { Lower, Upper, Flat } bound;
    std::int64_t q = 0, r = 0;    // e0 = q·d + r, 0 ≤ r < d (Lower, Upper)
    std::int64_t d = 1;           // |step|
    std::int64_t qi = 0, ri = 0;  // dx·256 = qi·d + ri, 0 ≤ ri < d
    std::int64_t e0 = 0, inc = 0; // Flat: e0 itself, and its change per row

    Edge(const MeshPoint &from, const MeshPoint &to, std::int64_t sampleY)
    {
        const std::int64_t dx = to.x - from.x, dy = to.y - from.y;
        const std::int64_t bias = (dy < 0 || (dy == 0 && dx > 0)) ? 0 : -1;
        e0 = dx * (sampleY - from.y) - dy * (kHalfPixel - from.x) + bias;
        inc = dx * kSubpixel;
        const std::int64_t step = -dy * kSubpixel;
        bound = step > 0 ? Bound::Lower : step < 0 ? Bound::Upper : Bound::Flat;
        if (bound == Bound::Flat)
            return;
        d = step > 0 ? step : -step;
        q = floorDiv(e0, d);
        r = e0 - q * d;
        qi = floorDiv(inc, d);
        ri = inc - qi * d;
    }
    // Narrows [lo, hi] to the pixels of the current row this edge admits.
    void clip(std::int64_t &lo, std::int64_t &hi) const
    {
        if (bound == Bound::Lower)
            lo = std::max(lo, -q); // X ≥ ceil(−e0 / step) = −floor(e0 / step)
        else if (bound == Bound::Upper)
            hi = std::min(hi, q); // X ≤ floor(e0 / −step)
        else if (e0 < 0)
            hi = lo - 1;
    }
    void nextRow()
    {
        e0 += inc;
        q += qi;
        r += ri;
        if (r >= d) {
            r -= d;
            ++q;
        }
    }
};

// The target and texture as plain memory, and the triangle's affine uv on the target.
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

struct UvPlane {
    double u0, dudx, dudy, v0, dvdx, dvdy; // u(x, y) = u0 + x·dudx + y·dudy (target px)
};

// Bilinear sample at su, sv (16.16 texel coordinates relative to texel centres, u − ½, v − ½)
// with the neighbours clamped to the texture: for the half pixel along its border.
std::uint32_t sampleClamped(const Raster &r, std::int64_t su, std::int64_t sv)
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

// `r` by value: its fields are locals the compiler may keep in registers (the target's pixels
// are unsigned ints, which could otherwise alias the int fields of a Raster in memory).
// A triangle's uv in 32.32 fixed point relative to texel centres (u − ½, v − ½), as an
// affine function of the pixel (x, y) measured from the triangle's box corner (x0, y0):
// exact enough over any box (2^-32 texel per pixel of error), and a span starts with two
// integer multiplies instead of floating point and rounding.
struct FixedPlane {
    std::int64_t u, dudx, dudy, v, dvdx, dvdy; // at pixel (x0, y0)'s centre; per pixel
    std::int64_t x0, y0;
};

void drawSpan(const Raster r, const FixedPlane &p, int y, int x0, int x1)
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

// The plane in fixed point over the box [x0, x1] × [y0, y1]; false for a triangle whose uv
// runs out of range over its box (|uv| ≥ 2^24 texels, or a slope past 2^14 texels per pixel:
// more than a whole texture squeezed into a pixel, nothing to see), where the 32.32 products
// above could overflow; within range they stay below 2^58.
bool fixedPlane(const UvPlane &p, std::int64_t x0, std::int64_t y0, std::int64_t x1,
                std::int64_t y1, FixedPlane &f)
{
    constexpr double kOne = 4294967296.0; // 2^32
    constexpr double kMaxSlope = 16384.0, kMaxUv = double(1 << 24);
    const double extent = double(x1 - x0 + y1 - y0 + 2);
    for (const double slope : {p.dudx, p.dudy, p.dvdx, p.dvdy})
        if (!(std::abs(slope) <= kMaxSlope) || !(std::abs(slope) * extent < kMaxUv))
            return false;
    const double cx = double(x0) + 0.5, cy = double(y0) + 0.5;
    const double u = p.u0 + cx * p.dudx + cy * p.dudy, v = p.v0 + cx * p.dvdx + cy * p.dvdy;
    if (!(std::abs(u) < kMaxUv) || !(std::abs(v) < kMaxUv))
        return false;
    f = {std::llround((u - 0.5) * kOne),
         std::llround(p.dudx * kOne),
         std::llround(p.dudy * kOne),
         std::llround((v - 0.5) * kOne),
         std::llround(p.dvdx * kOne),
         std::llround(p.dvdy * kOne),
         x0,
         y0};
    return true;
}

// The affine map from target px to texture px over triangle abc; false when it has no area.
bool uvPlane(const MeshPoint &a, const MeshPoint &b, const MeshPoint &c, const double *ua,
             const double *ub, const double *uc, UvPlane &p)
{
    const double bx = b.fx - a.fx, by = b.fy - a.fy, cx = c.fx - a.fx, cy = c.fy - a.fy;
    const double det = bx * cy - by * cx;
    if (det == 0.0 || !std::isfinite(det))
        return false;
    const double du1 = ub[0] - ua[0], du2 = uc[0] - ua[0];
    const double dv1 = ub[1] - ua[1], dv2 = uc[1] - ua[1];
    p.dudx = (du1 * cy - du2 * by) / det;
    p.dudy = (du2 * bx - du1 * cx) / det;
    p.dvdx = (dv1 * cy - dv2 * by) / det;
    p.dvdy = (dv2 * bx - dv1 * cx) / det;
    p.u0 = ua[0] - a.fx * p.dudx - a.fy * p.dudy;
    p.v0 = ua[1] - a.fx * p.dvdx - a.fy * p.dvdy;
    return std::isfinite(p.dudx) && std::isfinite(p.dudy) && std::isfinite(p.dvdx) &&
           std::isfinite(p.dvdy) && std::isfinite(p.u0) && std::isfinite(p.v0);
}

void drawTriangle(const Raster &r, MeshPoint a, MeshPoint b, MeshPoint c, const double *ua,
                  const double *ub, const double *uc)
{
    const std::int64_t area2 = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (area2 == 0)
        return;
    if (area2 < 0) { // drawn whichever way it winds
        std::swap(b, c);
        std::swap(ub, uc);
    }
    // Pixels whose centre (px·256 + 128) can lie inside: the box, clipped to the target.
    const std::int64_t minX = std::min({a.x, b.x, c.x}), maxX = std::max({a.x, b.x, c.x});
    const std::int64_t minY = std::min({a.y, b.y, c.y}), maxY = std::max({a.y, b.y, c.y});
    const std::int64_t x0 = std::max<std::int64_t>(0, -floorDiv(kHalfPixel - minX, kSubpixel));
    const std::int64_t x1 =
        std::min<std::int64_t>(r.width - 1, floorDiv(maxX - kHalfPixel, kSubpixel));
    const std::int64_t y0 =
        std::max<std::int64_t>(r.bandTop, -floorDiv(kHalfPixel - minY, kSubpixel));
    const std::int64_t y1 =
        std::min<std::int64_t>(r.bandBottom - 1, floorDiv(maxY - kHalfPixel, kSubpixel));
    if (x0 > x1 || y0 > y1)
        return;
    UvPlane plane;
    FixedPlane fixed;
    if (!uvPlane(a, b, c, ua, ub, uc, plane) || !fixedPlane(plane, x0, y0, x1, y1, fixed))
        return;
    const std::int64_t sampleY = y0 * kSubpixel + kHalfPixel;
    Edge edges[3] = {Edge(a, b, sampleY), Edge(b, c, sampleY), Edge(c, a, sampleY)};
    for (std::int64_t y = y0; y <= y1; ++y) {
        std::int64_t lo = x0, hi = x1;
        for (Edge &e : edges) {
            e.clip(lo, hi);
            e.nextRow();
        }
        if (lo <= hi)
            drawSpan(r, fixed, int(y), int(lo), int(hi));
    }
}

std::vector<MeshPoint> mapVertices(const QTransform &view, const Eigen::MatrixX2d &V,
                                   const Eigen::MatrixX2d &uv)
{
    std::vector<MeshPoint> points(std::size_t(V.rows()));
    for (Eigen::Index i = 0; i < V.rows(); ++i) {
        if (!std::isfinite(uv(i, 0)) || !std::isfinite(uv(i, 1)))
            continue;
        const QPointF p = view.map(QPointF(V(i, 0), V(i, 1)));
        if (!(std::abs(p.x()) < kMaxTargetCoordinate) || !(std::abs(p.y()) < kMaxTargetCoordinate))
            continue; // NaN fails these too
        MeshPoint &m = points[std::size_t(i)];
        m.fx = p.x();
        m.fy = p.y();
        m.x = std::llround(p.x() * double(kSubpixel));
        m.y = std::llround(p.y() * double(kSubpixel));
        m.valid = true;
    }
    return points;
}

// The target rows the valid vertices span, [top, bottom), clipped to the target.
std::pair<int, int> coveredRows(const std::vector<MeshPoint> &points, int height)
{
    std::int64_t minY = std::numeric_limits<std::int64_t>::max(), maxY = -minY;
    for (const MeshPoint &p : points)
        if (p.valid) {
            minY = std::min(minY, p.y);
            maxY = std::max(maxY, p.y);
        }
    if (minY > maxY)
        return {0, 0};
    const std::int64_t top = std::max<std::int64_t>(0, -floorDiv(kHalfPixel - minY, kSubpixel));
    const std::int64_t bottom =
        std::min<std::int64_t>(height, floorDiv(maxY - kHalfPixel, kSubpixel) + 1);
    return {int(top), int(std::max(top, bottom))};
}

void drawFaces(const Raster &r, const std::vector<MeshPoint> &points, const Eigen::MatrixX2d &uv,
               const Eigen::MatrixX3i &F)
{
    const auto n = Eigen::Index(points.size());
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
        const int i = F(f, 0), j = F(f, 1), k = F(f, 2);
        if (i < 0 || j < 0 || k < 0 || i >= n || j >= n || k >= n)
            continue;
        const MeshPoint &a = points[std::size_t(i)], &b = points[std::size_t(j)],
                        &c = points[std::size_t(k)];
        if (!a.valid || !b.valid || !c.valid)
            continue;
        const double ua[2] = {uv(i, 0), uv(i, 1)}, ub[2] = {uv(j, 0), uv(j, 1)},
                     uc[2] = {uv(k, 0), uv(k, 1)};
        drawTriangle(r, a, b, c, ua, ub, uc);
    }
}

} // namespace

void drawTexturedMesh(QImage &target, const QTransform &view, const QImage &texture,
                      const Eigen::MatrixX2d &uv, const Eigen::MatrixX2d &V,
                      const Eigen::MatrixX3i &F, double opacity)
{
    if (target.isNull() || texture.isNull() || uv.rows() != V.rows() || !(opacity > 0.0))
        return;
    if (target.format() != QImage::Format_ARGB32_Premultiplied)
        target.convertTo(QImage::Format_ARGB32_Premultiplied);
    const QImage tex = texture.format() == QImage::Format_ARGB32_Premultiplied
                           ? texture
                           : texture.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    Raster r;
    r.target = reinterpret_cast<std::uint32_t *>(target.bits()); // detaches once, here
    r.targetStride = target.bytesPerLine() / 4;
    r.width = target.width();
    r.height = target.height();
    r.texture = reinterpret_cast<const std::uint32_t *>(tex.constBits());
    r.textureStride = tex.bytesPerLine() / 4;
    r.texWidth = tex.width();
    r.texHeight = tex.height();
    r.alpha = std::uint32_t(std::lround(std::min(opacity, 1.0) * 255.0));
    if (r.alpha == 0)
        return;
    const std::vector<MeshPoint> points = mapVertices(view, V, uv);
    const auto [top, bottom] = coveredRows(points, r.height);
    // Two bands of rows drawn at once: every pixel still sees the same triangles in the same
    // order, so the result is the same as drawn in one pass.
    if (bottom - top >= 2 * kMinBandRows && F.rows() >= kMinThreadedFaces &&
        std::thread::hardware_concurrency() >= 2) {
        Raster upper = r, lower = r;
        upper.bandTop = top;
        upper.bandBottom = lower.bandTop = (top + bottom) / 2;
        lower.bandBottom = bottom;
        try {
            std::thread helper([&] { drawFaces(lower, points, uv, F); });
            drawFaces(upper, points, uv, F);
            helper.join();
            return;
        } catch (const std::system_error &) { // no thread to be had: one pass, below
        }
    }
    r.bandTop = top;
    r.bandBottom = bottom;
    drawFaces(r, points, uv, F);
}

} // namespace finbook::model
