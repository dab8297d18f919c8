// drawTexturedMesh: exact fixed-point coverage (top-left rule), triangles drawn strip by strip
// and row span by row span (the pixels of a span: textured_span.h).
#include "textured_span.h"

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

namespace picture_detail {
namespace {

constexpr int kSubpixelBits = 8; // vertex positions are snapped to 1/256 px
constexpr std::int64_t kSubpixel = std::int64_t(1) << kSubpixelBits;
constexpr std::int64_t kHalfPixel = kSubpixel / 2;
// 2^21 px × 256 = 2^29: edge function products stay below 2^61, sums below 2^63.
constexpr double kMaxTargetCoordinate = double(1 << 21);
// Below these a second thread costs more than it saves.
constexpr int kMinBandRows = 64;
constexpr Eigen::Index kMinThreadedFaces = 64;
// Rows drawn together (drawStrips): 32 rows of a 1:1 picture's texels and of a 1920-px target
// take about 130 KB and 250 KB, within a core's L2 cache.
constexpr int kStripRows = 32;

struct MeshPoint {
    std::int64_t x = 0, y = 0; // target position in 1/256 px
    double fx = 0.0, fy = 0.0; // target position in px
    bool valid = false;
};

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

struct UvPlane {
    double u0, dudx, dudy, v0, dvdx, dvdy; // u(x, y) = u0 + x·dudx + y·dudy (target px)
};

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

// The faces drawn, bucketed by strips of kStripRows target rows: strip k holds, in the order of
// F, the valid faces whose box meets rows [k·kStripRows, (k+1)·kStripRows).
using FaceStrips = std::vector<std::vector<Eigen::Index>>;

FaceStrips faceStrips(const std::vector<MeshPoint> &points, const Eigen::MatrixX3i &F, int height)
{
    FaceStrips strips(std::size_t((height + kStripRows - 1) / kStripRows));
    const auto n = Eigen::Index(points.size());
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
        const int i = F(f, 0), j = F(f, 1), k = F(f, 2);
        if (i < 0 || j < 0 || k < 0 || i >= n || j >= n || k >= n)
            continue;
        const MeshPoint &a = points[std::size_t(i)], &b = points[std::size_t(j)],
                        &c = points[std::size_t(k)];
        if (!a.valid || !b.valid || !c.valid)
            continue;
        const std::int64_t top =
            std::max<std::int64_t>(0, -floorDiv(kHalfPixel - std::min({a.y, b.y, c.y}), kSubpixel));
        const std::int64_t bottom = std::min<std::int64_t>(
            height - 1, floorDiv(std::max({a.y, b.y, c.y}) - kHalfPixel, kSubpixel));
        for (std::int64_t strip = top / kStripRows; strip <= bottom / kStripRows && top <= bottom;
             ++strip)
            strips[std::size_t(strip)].push_back(f);
    }
    return strips;
}

// Draws the rows [band.bandTop, band.bandBottom) strip by strip: the texels and target pixels
// a strip's triangles touch stay in the cache while its neighbours are drawn (in the order of
// F, triangles far apart in the picture follow each other). Each pixel still sees its
// triangles in the order of F.
void drawStrips(const Raster &band, const FaceStrips &strips, const std::vector<MeshPoint> &points,
                const Eigen::MatrixX2d &uv, const Eigen::MatrixX3i &F)
{
    for (int strip = band.bandTop / kStripRows; strip * kStripRows < band.bandBottom; ++strip) {
        Raster r = band;
        r.bandTop = std::max(band.bandTop, strip * kStripRows);
        r.bandBottom = std::min(band.bandBottom, (strip + 1) * kStripRows);
        for (const Eigen::Index f : strips[std::size_t(strip)]) {
            const int i = F(f, 0), j = F(f, 1), k = F(f, 2);
            const double ua[2] = {uv(i, 0), uv(i, 1)}, ub[2] = {uv(j, 0), uv(j, 1)},
                         uc[2] = {uv(k, 0), uv(k, 1)};
            drawTriangle(r, points[std::size_t(i)], points[std::size_t(j)], points[std::size_t(k)],
                         ua, ub, uc);
        }
    }
}

} // namespace
} // namespace picture_detail

Eigen::MatrixX3i drawingOrder(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F)
{
    using picture_detail::kStripRows;
    std::vector<std::pair<std::pair<double, double>, Eigen::Index>> keys;
    keys.reserve(std::size_t(F.rows()));
    const auto n = V.rows();
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
        const int i = F(f, 0), j = F(f, 1), k = F(f, 2);
        if (i < 0 || j < 0 || k < 0 || i >= n || j >= n || k >= n || !V.row(i).allFinite() ||
            !V.row(j).allFinite() || !V.row(k).allFinite()) {
            keys.push_back({{std::numeric_limits<double>::infinity(), 0.0}, f});
            continue;
        }
        const double x = (V(i, 0) + V(j, 0) + V(k, 0)) / 3.0;
        const double y = (V(i, 1) + V(j, 1) + V(k, 1)) / 3.0;
        keys.push_back({{std::floor(y / kStripRows), x}, f});
    }
    std::stable_sort(keys.begin(), keys.end(),
                     [](const auto &a, const auto &b) { return a.first < b.first; });
    Eigen::MatrixX3i ordered(F.rows(), 3);
    for (std::size_t r = 0; r < keys.size(); ++r)
        ordered.row(Eigen::Index(r)) = F.row(keys[r].second);
    return ordered;
}

void drawTexturedMesh(QImage &target, const QTransform &view, const QImage &texture,
                      const Eigen::MatrixX2d &uv, const Eigen::MatrixX2d &V,
                      const Eigen::MatrixX3i &F, double opacity)
{
    using namespace picture_detail;
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
    const FaceStrips strips = faceStrips(points, F, r.height);
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
            std::thread helper([&] { drawStrips(lower, strips, points, uv, F); });
            drawStrips(upper, strips, points, uv, F);
            helper.join();
            return;
        } catch (const std::system_error &) { // no thread to be had: one pass, below
        }
    }
    r.bandTop = top;
    r.bandBottom = bottom;
    drawStrips(r, strips, points, uv, F);
}

} // namespace finbook::model
