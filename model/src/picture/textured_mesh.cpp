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

// Whether every pixel a triangle covers samples inside the texture's interior (where all four
// bilinear neighbours exist, u ∈ [½, w − ½)), with a margin for the pixel centres its snapped
// corners admit beyond the exact triangle and for rounding: then its spans skip the test.
bool samplesInside(const Raster &r, const UvPlane &p, const double *ua, const double *ub,
                   const double *uc)
{
    const double marginU = 0.01 + (std::abs(p.dudx) + std::abs(p.dudy)) / 64.0;
    const double marginV = 0.01 + (std::abs(p.dvdx) + std::abs(p.dvdy)) / 64.0;
    for (const double *t : {ua, ub, uc})
        if (!(t[0] >= 0.5 + marginU && t[0] <= r.texWidth - 0.5 - marginU &&
              t[1] >= 0.5 + marginV && t[1] <= r.texHeight - 0.5 - marginV))
            return false;
    return true;
}

// Draws triangle abc over the rows [r.bandTop, r.bandBottom), its spans by Group.
template <class Group>
[[gnu::always_inline]] inline void drawTriangle(const Raster &r, MeshPoint a, MeshPoint b,
                                                MeshPoint c, const double *ua, const double *ub,
                                                const double *uc)
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
    const Group group(fixed, r.alpha);
    const bool inside = samplesInside(r, plane, ua, ub, uc);
    for (std::int64_t y = y0; y <= y1; ++y) {
        std::int64_t lo = x0, hi = x1;
        for (Edge &e : edges) {
            e.clip(lo, hi);
            e.nextRow();
        }
        if (lo <= hi)
            drawSpanWith(r, fixed, int(y), int(lo), int(hi), group, inside);
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
// F, the valid faces whose box meets rows [k·kStripRows, (k+1)·kStripRows); and the work each
// strip costs, estimated in pixels (each face's area shared out over its rows, plus a cost per
// face and per span).
struct FaceStrips {
    std::vector<std::vector<Eigen::Index>> faces;
    std::vector<double> work;
};

FaceStrips faceStrips(const std::vector<MeshPoint> &points, const Eigen::MatrixX3i &F, int height)
{
    constexpr double kFaceCost = 40.0, kSpanCost = 6.0; // in pixels drawn, measured roughly
    const auto count = std::size_t((height + kStripRows - 1) / kStripRows);
    FaceStrips strips{std::vector<std::vector<Eigen::Index>>(count), std::vector<double>(count)};
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
        if (top > bottom)
            continue;
        const double area =
            0.5 * std::abs((b.fx - a.fx) * (c.fy - a.fy) - (b.fy - a.fy) * (c.fx - a.fx));
        const double perRow = area / double(bottom - top + 1);
        for (std::int64_t strip = top / kStripRows; strip <= bottom / kStripRows; ++strip) {
            const std::int64_t rows = std::min(bottom, (strip + 1) * kStripRows - 1) -
                                      std::max(top, strip * kStripRows) + 1;
            strips.faces[std::size_t(strip)].push_back(f);
            strips.work[std::size_t(strip)] += kFaceCost + double(rows) * (perRow + kSpanCost);
        }
    }
    return strips;
}

// The row that splits the rows [top, bottom) into two bands of about the same work.
int balancedSplit(const FaceStrips &strips, int top, int bottom)
{
    const int first = top / kStripRows, last = (bottom - 1) / kStripRows;
    double total = 0.0;
    for (int s = first; s <= last; ++s)
        total += strips.work[std::size_t(s)];
    double done = 0.0;
    int split = (top + bottom) / 2;
    for (int s = first; s <= last; ++s) {
        const double work = strips.work[std::size_t(s)];
        if (work > 0.0 && done + work >= total / 2.0) { // within strip s, in proportion
            split = s * kStripRows + int(std::lround(kStripRows * (total / 2.0 - done) / work));
            break;
        }
        done += work;
    }
    return std::clamp(split, top + 1, bottom - 1);
}

// The cache lines a strip will read: its triangles' texels (the box of their uv) and target
// pixels (the box of their corners), fetched into the cache a few at a time while the strip
// before it is drawn, so that they are not waited for one miss at a time.
class StripPrefetch {
public:
    StripPrefetch(const Raster &r, const std::vector<Eigen::Index> &faces,
                  const std::vector<MeshPoint> &points, const Eigen::MatrixX2d &uv,
                  const Eigen::MatrixX3i &F, int top, int bottom)
        : r_(r)
    {
        double u0 = kHuge, u1 = -kHuge, v0 = kHuge, v1 = -kHuge, x0 = kHuge, x1 = -kHuge;
        for (const Eigen::Index f : faces)
            for (int c = 0; c < 3; ++c) {
                const int i = F(f, c);
                u0 = std::min(u0, uv(i, 0));
                u1 = std::max(u1, uv(i, 0));
                v0 = std::min(v0, uv(i, 1));
                v1 = std::max(v1, uv(i, 1));
                x0 = std::min(x0, points[std::size_t(i)].fx);
                x1 = std::max(x1, points[std::size_t(i)].fx);
            }
        if (faces.empty())
            return;
        texLeft_ = int(std::clamp(std::floor(u0) - 1.0, 0.0, double(r.texWidth - 1)));
        texRight_ = int(std::clamp(std::ceil(u1) + 1.0, 0.0, double(r.texWidth - 1)));
        texRow_ = int(std::clamp(std::floor(v0) - 1.0, 0.0, double(r.texHeight - 1)));
        texBottom_ = int(std::clamp(std::ceil(v1) + 1.0, 0.0, double(r.texHeight - 1)));
        left_ = int(std::clamp(std::floor(x0) - 1.0, 0.0, double(r.width - 1)));
        right_ = int(std::clamp(std::ceil(x1) + 1.0, 0.0, double(r.width - 1)));
        row_ = top;
        bottom_ = bottom - 1;
        const int targetLines = (bottom_ - row_ + 1) * ((right_ - left_) / 16 + 2);
        const int textureLines = (texBottom_ - texRow_ + 1) * ((texRight_ - texLeft_) / 16 + 2);
        // A box of uv much larger than the strip (a turned or shrunk picture) holds mostly
        // texels the strip never reads: those are left to the processor.
        if (textureLines > 4 * targetLines + 64)
            texBottom_ = texRow_ - 1;
        lines_ = targetLines + (texBottom_ >= texRow_ ? textureLines : 0);
    }
    int lines() const { return lines_; }
    // Fetches the next n lines (texture rows first, then target rows).
    void fetch(int n)
    {
        for (; n > 0 && texRow_ <= texBottom_; --n) {
            __builtin_prefetch(
                r_.texture + qsizetype(texRow_) * r_.textureStride + texLeft_ + texAt_, 0, 2);
            if (advance(texAt_, texLeft_, texRight_))
                ++texRow_;
        }
        for (; n > 0 && row_ <= bottom_; --n) {
            __builtin_prefetch(r_.target + qsizetype(row_) * r_.targetStride + left_ + at_, 1, 2);
            if (advance(at_, left_, right_))
                ++row_;
        }
    }

private:
    static constexpr double kHuge = 1e300;
    // Steps to the next line (16 pixels on) of a row of pixels [left, right], its last pixel
    // last; true when the row is done.
    static bool advance(int &at, int left, int right)
    {
        if (left + at >= right) {
            at = 0;
            return true;
        }
        at = std::min(at + 16, right - left);
        return false;
    }
    const Raster &r_;
    int texLeft_ = 0, texRight_ = -1, texRow_ = 0, texBottom_ = -1, texAt_ = 0;
    int left_ = 0, right_ = -1, row_ = 0, bottom_ = -1, at_ = 0;
    int lines_ = 0;
};

// Draws the rows [band.bandTop, band.bandBottom) strip by strip, spans by Group: the texels and
// target pixels a strip's triangles touch stay in the cache while its neighbours are drawn (in the
// order of F, triangles far apart in the picture follow each other). Each pixel still sees its
// triangles in the order of F.
template <class Group>
[[gnu::always_inline]] inline void
drawStripsWith(const Raster &band, const FaceStrips &strips, const std::vector<MeshPoint> &points,
               const Eigen::MatrixX2d &uv, const Eigen::MatrixX3i &F)
{
    const int first = band.bandTop / kStripRows;
    for (int strip = first; strip * kStripRows < band.bandBottom; ++strip) {
        Raster r = band;
        r.bandTop = std::max(band.bandTop, strip * kStripRows);
        r.bandBottom = std::min(band.bandBottom, (strip + 1) * kStripRows);
        const auto &faces = strips.faces[std::size_t(strip)];
        const int nextTop = (strip + 1) * kStripRows;
        StripPrefetch next(band,
                           nextTop < band.bandBottom ? strips.faces[std::size_t(strip + 1)]
                                                     : std::vector<Eigen::Index>(),
                           points, uv, F, nextTop, std::min(band.bandBottom, nextTop + kStripRows));
        const int perFace = faces.empty() ? 0 : next.lines() / int(faces.size()) + 1;
        for (const Eigen::Index f : faces) {
            next.fetch(perFace);
            const int i = F(f, 0), j = F(f, 1), k = F(f, 2);
            const double ua[2] = {uv(i, 0), uv(i, 1)}, ub[2] = {uv(j, 0), uv(j, 1)},
                         uc[2] = {uv(k, 0), uv(k, 1)};
            drawTriangle<Group>(r, points[std::size_t(i)], points[std::size_t(j)],
                                points[std::size_t(k)], ua, ub, uc);
        }
    }
}

#if defined(FINBOOK_TEXTURE_AVX2)
__attribute__((target("avx2"))) void drawStripsAvx2(const Raster &band, const FaceStrips &strips,
                                                    const std::vector<MeshPoint> &points,
                                                    const Eigen::MatrixX2d &uv,
                                                    const Eigen::MatrixX3i &F)
{
    drawStripsWith<EightAtOnce>(band, strips, points, uv, F);
}
#endif

// drawStripsWith the kernel band.kernel names.
void drawStrips(const Raster &band, const FaceStrips &strips, const std::vector<MeshPoint> &points,
                const Eigen::MatrixX2d &uv, const Eigen::MatrixX3i &F)
{
    switch (band.kernel) {
    case SpanKernel::Avx2:
#if defined(FINBOOK_TEXTURE_AVX2)
        drawStripsAvx2(band, strips, points, uv, F);
        return;
#endif
    case SpanKernel::Sse2:
#if defined(__SSE2__)
        drawStripsWith<FourAtOnce>(band, strips, points, uv, F);
        return;
#endif
    case SpanKernel::Scalar:
        break;
    }
    drawStripsWith<OneByOne>(band, strips, points, uv, F);
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

bool texturedMeshKernelAvailable(TexturedMeshKernel kernel)
{
    using picture_detail::SpanKernel;
    const SpanKernel widest = picture_detail::widestSpanKernel();
    switch (kernel) {
    case TexturedMeshKernel::Automatic:
    case TexturedMeshKernel::Scalar:
        return true;
    case TexturedMeshKernel::Sse2:
        return widest != SpanKernel::Scalar;
    case TexturedMeshKernel::Avx2:
        return widest == SpanKernel::Avx2;
    }
    return false;
}

void drawTexturedMesh(QImage &target, const QTransform &view, const QImage &texture,
                      const Eigen::MatrixX2d &uv, const Eigen::MatrixX2d &V,
                      const Eigen::MatrixX3i &F, double opacity, TexturedMeshKernel kernel)
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
    r.kernel = widestSpanKernel();
    if (kernel == TexturedMeshKernel::Scalar)
        r.kernel = SpanKernel::Scalar;
    else if (kernel == TexturedMeshKernel::Sse2 && texturedMeshKernelAvailable(kernel))
        r.kernel = SpanKernel::Sse2;
    const std::vector<MeshPoint> points = mapVertices(view, V, uv);
    const FaceStrips strips = faceStrips(points, F, r.height);
    const auto [top, bottom] = coveredRows(points, r.height);
    // Two bands of rows of about the same work drawn at once: every pixel still sees the same
    // triangles in the same order, so the result is the same as drawn in one pass.
    if (bottom - top >= 2 * kMinBandRows && F.rows() >= kMinThreadedFaces &&
        std::thread::hardware_concurrency() >= 2) {
        Raster upper = r, lower = r;
        upper.bandTop = top;
        upper.bandBottom = lower.bandTop = balancedSplit(strips, top, bottom);
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
