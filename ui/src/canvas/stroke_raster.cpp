#include "stroke_raster.h"

#include <finbook/model/picture/picture_object.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#endif

#include <finbook/model/fill/fill_render.h>

#include <QPainter>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <thread>

namespace finbook::ui {

namespace {
constexpr int kTile = 8;

// Thinnest radius drawn at full strength, in device pixels; thinner strokes fade instead.
constexpr float kMinRadius = 0.5f;
// Coverage (0..255) of the pixel centred at (px, py), relative to the segment start, by a
// capsule from (0, 0) radius ar to (dx, dy) radius ar + dr; inv = 1 / |d|² (0 for a dot).
inline std::uint8_t coverage(float px, float py, float dx, float dy, float inv, float ar, float dr)
{
    const float t = std::clamp((px * dx + py * dy) * inv, 0.0f, 1.0f);
    const float ex = px - t * dx, ey = py - t * dy;
    const float r = ar + t * dr;
    const float d = std::sqrt(ex * ex + ey * ey);
    // A pixel-wide box filter across the edge; hairlines fade with their width.
    const float c = std::clamp(std::max(r, kMinRadius) + 0.5f - d, 0.0f, 1.0f);
    const float fade = std::min(1.0f, r / kMinRadius);
    return std::uint8_t(c * fade * 255.0f + 0.5f);
}

// Every channel of a premultiplied ARGB pixel times a/255, rounded (the classic two-lane trick).
inline QRgb byteMul(QRgb x, std::uint32_t a)
{
    std::uint32_t t = (x & 0xff00ffu) * a;
    t = ((t + ((t >> 8) & 0xff00ffu) + 0x800080u) >> 8) & 0xff00ffu;
    std::uint32_t u = ((x >> 8) & 0xff00ffu) * a;
    u = (u + ((u >> 8) & 0xff00ffu) + 0x800080u) & 0xff00ff00u;
    return u | t;
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define FINBOOK_RASTER_AVX2 1
// coverage() eight pixels at a time where the processor has AVX2 (asked once at run time): a
// pen line's capsule is a few pixels wide, so most rows take one step instead of two or three.
// Same arithmetic as the SSE path, only wider.
__attribute__((target("avx2"))) void coverSpansAvx2(const CoverSpan *spans, std::size_t count,
                                                    float dxf, float dyf, float invf, float arf,
                                                    float drf)
{
    const __m256 zero = _mm256_setzero_ps(), one = _mm256_set1_ps(1.0f);
    const __m256 dx = _mm256_set1_ps(dxf), dy = _mm256_set1_ps(dyf), inv = _mm256_set1_ps(invf);
    const __m256 ar = _mm256_set1_ps(arf), dr = _mm256_set1_ps(drf);
    const __m256 minR = _mm256_set1_ps(kMinRadius), invMinR = _mm256_set1_ps(1.0f / kMinRadius);
    const __m256 half = _mm256_set1_ps(0.5f), scale = _mm256_set1_ps(255.0f);
    const __m256 tiny = _mm256_set1_ps(1e-12f), eight = _mm256_set1_ps(8.0f);
    const __m256 lanes = _mm256_set_ps(7, 6, 5, 4, 3, 2, 1, 0);
    for (std::size_t s = 0; s < count; ++s) {
        const CoverSpan &span = spans[s];
        const __m256 py = _mm256_set1_ps(span.py), pyDy = _mm256_mul_ps(py, dy);
        __m256 px = _mm256_add_ps(_mm256_set1_ps(span.px0), lanes);
        int i = 0;
        for (; i + 8 <= span.n; i += 8, px = _mm256_add_ps(px, eight)) {
            __m256 t = _mm256_mul_ps(_mm256_add_ps(_mm256_mul_ps(px, dx), pyDy), inv);
            t = _mm256_min_ps(_mm256_max_ps(t, zero), one);
            const __m256 ex = _mm256_sub_ps(px, _mm256_mul_ps(t, dx));
            const __m256 ey = _mm256_sub_ps(py, _mm256_mul_ps(t, dy));
            const __m256 r = _mm256_add_ps(ar, _mm256_mul_ps(t, dr));
            const __m256 d2 =
                _mm256_max_ps(_mm256_add_ps(_mm256_mul_ps(ex, ex), _mm256_mul_ps(ey, ey)), tiny);
            const __m256 d = _mm256_mul_ps(d2, _mm256_rsqrt_ps(d2));
            __m256 c = _mm256_sub_ps(_mm256_add_ps(_mm256_max_ps(r, minR), half), d);
            c = _mm256_min_ps(_mm256_max_ps(c, zero), one);
            const __m256 fade = _mm256_min_ps(one, _mm256_mul_ps(r, invMinR));
            const __m256i v = _mm256_cvttps_epi32(
                _mm256_add_ps(_mm256_mul_ps(_mm256_mul_ps(c, fade), scale), half));
            const __m128i words =
                _mm_packs_epi32(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
            const __m128i bytes = _mm_packus_epi16(words, _mm_setzero_si128());
            const __m128i old = _mm_loadl_epi64(reinterpret_cast<const __m128i *>(span.row + i));
            _mm_storel_epi64(reinterpret_cast<__m128i *>(span.row + i), _mm_max_epu8(bytes, old));
        }
        for (; i < span.n; ++i) // at the clip's right edge only
            span.row[i] = std::max(
                span.row[i], coverage(span.px0 + float(i), span.py, dxf, dyf, invf, arf, drf));
    }
}

// x · a / 255 per byte, rounded as byteMul does, for sixteen 16-bit lanes.
__attribute__((target("avx2"))) inline __m256i mulDiv255(__m256i x, __m256i a)
{
    const __m256i t = _mm256_mullo_epi16(x, a);
    return _mm256_srli_epi16(
        _mm256_add_epi16(_mm256_add_epi16(t, _mm256_srli_epi16(t, 8)), _mm256_set1_epi16(0x80)), 8);
}

// composite() for eight pixels whose coverage is `mask`: the same sums as its scalar loop
// (source-over, or with `replace` the colour replacing what it covers), on eight lanes; pixels
// of coverage 0 come out unchanged. Clears the mask.
__attribute__((target("avx2"))) void blendEightAvx2(QRgb *dst, std::uint8_t *mask, QRgb src,
                                                    bool replace)
{
    const __m256i zero = _mm256_setzero_si256();
    const __m256i coverage = _mm256_mullo_epi32(
        _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(mask))),
        _mm256_set1_epi32(0x01010101));
    const __m256i colour = _mm256_set1_epi32(int(src));
    // The source at each pixel's coverage.
    const __m256i s = _mm256_packus_epi16(
        mulDiv255(_mm256_unpacklo_epi8(colour, zero), _mm256_unpacklo_epi8(coverage, zero)),
        mulDiv255(_mm256_unpackhi_epi8(colour, zero), _mm256_unpackhi_epi8(coverage, zero)));
    // What is left of the destination: 255 − the source's alpha (or − the coverage).
    const __m256i alphaBytes =
        _mm256_set_epi8(15, 15, 15, 15, 11, 11, 11, 11, 7, 7, 7, 7, 3, 3, 3, 3, 15, 15, 15, 15, 11,
                        11, 11, 11, 7, 7, 7, 7, 3, 3, 3, 3);
    const __m256i keep = _mm256_xor_si256(replace ? coverage : _mm256_shuffle_epi8(s, alphaBytes),
                                          _mm256_set1_epi8(char(0xff)));
    const __m256i d = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(dst));
    const __m256i kept = _mm256_packus_epi16(
        mulDiv255(_mm256_unpacklo_epi8(d, zero), _mm256_unpacklo_epi8(keep, zero)),
        mulDiv255(_mm256_unpackhi_epi8(d, zero), _mm256_unpackhi_epi8(keep, zero)));
    _mm256_storeu_si256(reinterpret_cast<__m256i *>(dst), _mm256_add_epi8(s, kept));
    std::memset(mask, 0, 8);
}

bool hasAvx2()
{
    static const bool yes = __builtin_cpu_supports("avx2");
    return yes;
}
#endif

#if defined(__SSE2__)
// coverage() four pixels at a time for one capsule: its constants broadcast once (per capsule,
// not per row), then cover() max-combines a row's pixels into row[0..n) and returns how many
// it did (a multiple of four).
struct CapsuleSse {
    __m128 dx, dy, inv, ar, dr;
    CapsuleSse(float dx_, float dy_, float inv_, float ar_, float dr_)
        : dx(_mm_set1_ps(dx_))
        , dy(_mm_set1_ps(dy_))
        , inv(_mm_set1_ps(inv_))
        , ar(_mm_set1_ps(ar_))
        , dr(_mm_set1_ps(dr_))
    {}
    int cover(std::uint8_t *row, int n, float px0, float py) const
    {
        const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
        const __m128 minR = _mm_set1_ps(kMinRadius), invMinR = _mm_set1_ps(1.0f / kMinRadius);
        const __m128 half = _mm_set1_ps(0.5f), scale = _mm_set1_ps(255.0f);
        const __m128 tiny = _mm_set1_ps(1e-12f);
        const __m128 vpy = _mm_set1_ps(py), pyDy = _mm_mul_ps(vpy, dy);
        __m128 px = _mm_add_ps(_mm_set1_ps(px0), _mm_set_ps(3, 2, 1, 0));
        int i = 0;
        for (; i + 4 <= n; i += 4, px = _mm_add_ps(px, _mm_set1_ps(4.0f))) {
            __m128 t = _mm_mul_ps(_mm_add_ps(_mm_mul_ps(px, dx), pyDy), inv);
            t = _mm_min_ps(_mm_max_ps(t, zero), one);
            const __m128 ex = _mm_sub_ps(px, _mm_mul_ps(t, dx));
            const __m128 ey = _mm_sub_ps(vpy, _mm_mul_ps(t, dy));
            const __m128 r = _mm_add_ps(ar, _mm_mul_ps(t, dr));
            // d = d² / √d² with the fast reciprocal root (relative error below 4e-4: a
            // thousandth of a pixel here, far under one step of coverage).
            const __m128 d2 = _mm_max_ps(_mm_add_ps(_mm_mul_ps(ex, ex), _mm_mul_ps(ey, ey)), tiny);
            const __m128 d = _mm_mul_ps(d2, _mm_rsqrt_ps(d2));
            __m128 c = _mm_sub_ps(_mm_add_ps(_mm_max_ps(r, minR), half), d);
            c = _mm_min_ps(_mm_max_ps(c, zero), one);
            const __m128 fade = _mm_min_ps(one, _mm_mul_ps(r, invMinR));
            const __m128i v =
                _mm_cvttps_epi32(_mm_add_ps(_mm_mul_ps(_mm_mul_ps(c, fade), scale), half));
            const __m128i bytes = _mm_packus_epi16(_mm_packs_epi32(v, v), _mm_setzero_si128());
            std::uint32_t old;
            std::memcpy(&old, row + i, 4);
            const auto packed =
                std::uint32_t(_mm_cvtsi128_si32(_mm_max_epu8(bytes, _mm_cvtsi32_si128(int(old)))));
            std::memcpy(row + i, &packed, 4);
        }
        return i;
    }
};
#endif

} // namespace

StrokeRaster::StrokeRaster(QImage *image, const QRect &deviceClip, const QTransform &toDevice,
                           std::vector<std::uint8_t> recycledMask)
    : m_bits(image->bits())
    , m_stride(image->bytesPerLine())
    , m_clip(deviceClip.intersected(image->rect()))
    , m_toDevice(toDevice)
    , m_xx(float(toDevice.m11()))
    , m_xy(float(toDevice.m21()))
    , m_yx(float(toDevice.m12()))
    , m_yy(float(toDevice.m22()))
    , m_scale(float(std::sqrt(std::abs(toDevice.determinant()))))
    , m_ox(float(toDevice.dx()))
    , m_oy(float(toDevice.dy()))
    , m_width(std::max(0, m_clip.width()))
    , m_height(std::max(0, m_clip.height()))
    , m_tilesX((m_width + kTile - 1) / kTile)
#if defined(FINBOOK_RASTER_AVX2)
    , m_wide(hasAvx2())
#endif
{
    const int tilesY = (m_height + kTile - 1) / kTile;
    m_mask = std::move(recycledMask);
    if (m_mask.size() < std::size_t(m_width) * std::size_t(m_height))
        m_mask.assign(std::size_t(m_width) * std::size_t(m_height), 0);
    m_touched.assign(std::size_t(m_tilesX) * std::size_t(tilesY), 0);
}

void StrokeRaster::drawParallel(QImage *image, const QRect &deviceClip, const QTransform &toDevice,
                                const std::function<void(StrokeRaster &)> &draw)
{
    const QRect clip = deviceClip.intersected(image->rect());
    if (clip.isEmpty())
        return;
    // Horizontal bands share no pixel, so each keeps the strokes' order exactly. The
    // rasterizers are built here: QImage::bits() detaches and must not run in the workers.
    const int bands = std::clamp(int(std::thread::hardware_concurrency()), 1, 4);
    const int step = (clip.height() + bands - 1) / bands;
    // Masks are kept between calls (a fresh megabyte costs page faults on every repaint);
    // they come back all zero because composite() clears every pixel a stroke touched.
    static std::vector<std::vector<std::uint8_t>> pool;
    std::vector<std::unique_ptr<StrokeRaster>> rasters;
    for (int top = clip.top(); top <= clip.bottom(); top += step) {
        const QRect band(clip.left(), top, clip.width(), std::min(step, clip.bottom() + 1 - top));
        std::vector<std::uint8_t> mask;
        if (rasters.size() < pool.size())
            mask = std::move(pool[rasters.size()]);
        rasters.push_back(std::make_unique<StrokeRaster>(image, band, toDevice, std::move(mask)));
    }
    std::vector<std::thread> workers;
    for (std::size_t b = 1; b < rasters.size(); ++b)
        workers.emplace_back([&draw, raster = rasters[b].get()] { draw(*raster); });
    draw(*rasters.front());
    for (std::thread &w : workers)
        w.join();
    pool.resize(std::max(pool.size(), rasters.size()));
    for (std::size_t b = 0; b < rasters.size(); ++b)
        pool[b] = std::move(rasters[b]->m_mask);
}

void StrokeRaster::drawFrame(const model::Frame &frame, const model::RenderOptions &options,
                             const model::DocumentSettings &settings)
{
    const qreal opacity = std::clamp(options.opacity, 0.0, 1.0);
    if (opacity <= 0)
        return;
    // A ghost: the frame into a layer at full strength, then the layer once at its opacity
    // (drawFrame's header says why).
    const bool layered = (options.tint || opacity < 1.0) && m_width > 0 && m_height > 0;
    if (layered) {
        // All zero: new, or cleared where the last frame used it (flushGhost), so the onion
        // skin's several frames clear what they drew rather than the whole band each.
        if (m_ghost.size() != std::size_t(m_width) * std::size_t(m_height))
            m_ghost.assign(std::size_t(m_width) * std::size_t(m_height), 0);
        m_ghostActive = true;
        m_ghostReplace = options.tint.has_value();
        m_ghostBox = QRect();
    }
    const qreal itemOpacity = layered ? 1.0 : opacity;
    // paintList folds repeated references of one stroke into one item, as paintFrame does.
    if (!model::frameHasFills(frame, options) && !model::frameHasPictures(frame, options)) {
        for (const model::PaintItem &item : model::paintList(frame, options))
            drawStroke(*item.points, item.color, item.width, itemOpacity);
    } else {
        for (const model::StrokeGroup &group : frame.groups) {
            if (group.picture && (group.visible || options.showHidden))
                drawPicture(group, options.tint, itemOpacity);
            for (const model::PaintLayer &layer : model::paintLayers(group, settings, options)) {
                for (const model::FillItem &fill : model::paintedFills(group, layer.fills)) {
                    drawFill(fill.path, fill.color, itemOpacity);
                    for (const model::ToneItem &tone : fill.tones)
                        drawFill(tone.path, tone.color, itemOpacity);
                }
                for (const model::PaintItem &item : layer.strokes)
                    drawStroke(*item.points, item.color, item.width, itemOpacity);
            }
        }
    }
    if (layered)
        flushGhost(opacity);
}

void StrokeRaster::drawPicture(const model::StrokeGroup &group, const std::optional<QColor> &tint,
                               qreal opacity)
{
    if (m_clip.isEmpty() || opacity <= 0)
        return;
    const QTransform view = m_toDevice * QTransform::fromTranslate(-m_clip.left(), -m_clip.top());
    if (m_ghostActive) {
        // Into the ghost layer (clip-relative), which flushGhost lays on the image.
        QImage ghost(reinterpret_cast<uchar *>(m_ghost.data()), m_width, m_height,
                     qsizetype(m_width) * 4, QImage::Format_ARGB32_Premultiplied);
        model::drawPicture(ghost, view, group, 1.0, tint);
        const QRectF shown = view.mapRect(model::shownPictureBounds(group));
        if (std::isfinite(shown.left()) && std::isfinite(shown.right()) &&
            std::isfinite(shown.top()) && std::isfinite(shown.bottom()))
            m_ghostBox |=
                shown.toAlignedRect().adjusted(-1, -1, 1, 1) & QRect(0, 0, m_width, m_height);
        return;
    }
    // Straight into this band of the image: a picture over its own rows, no scratch copy.
    QImage band(m_bits + qsizetype(m_clip.top()) * m_stride + qsizetype(m_clip.left()) * 4, m_width,
                m_height, m_stride, QImage::Format_ARGB32_Premultiplied);
    model::drawPicture(band, view, group, opacity, tint);
}

void StrokeRaster::flushGhost(qreal opacity)
{
    const auto a = std::uint32_t(std::lround(255.0 * std::clamp(opacity, 0.0, 1.0)));
    for (int y = m_ghostBox.top(); y <= m_ghostBox.bottom(); ++y) {
        QRgb *src = m_ghost.data() + std::size_t(y) * std::size_t(m_width);
        auto *dst = reinterpret_cast<QRgb *>(m_bits + qsizetype(y + m_clip.top()) * m_stride) +
                    m_clip.left();
        for (int x = m_ghostBox.left(); x <= m_ghostBox.right(); ++x) {
            if (!src[x])
                continue;
            const QRgb s = byteMul(src[x], a);
            dst[x] = s + byteMul(dst[x], 255 - qAlpha(s)); // source-over, premultiplied
            src[x] = 0;
        }
    }
    m_ghostActive = false;
    m_ghostBox = QRect();
}

void StrokeRaster::prepareFills(const model::Frame &frame, const model::RenderOptions &options,
                                const model::DocumentSettings &settings)
{
    for (const model::StrokeGroup &group : frame.groups)
        model::fillList(group, settings, options);
}

void StrokeRaster::drawFill(const QPainterPath &path, QRgb color, qreal opacity)
{
    if (path.isEmpty() || m_clip.isEmpty() || opacity <= 0 || qAlpha(color) == 0)
        return;
    const QPainterPath device = m_toDevice.map(path);
    const QRect box =
        device.boundingRect().toAlignedRect().adjusted(-1, -1, 1, 1).intersected(m_clip);
    if (box.isEmpty())
        return;
    // QPainter's coverage in a scratch mask the size of the fill's part of this band, then
    // into the band's mask, so it composites exactly as a stroke does.
    QImage coverage(box.size(), QImage::Format_Alpha8);
    coverage.fill(0);
    {
        QPainter p(&coverage);
        p.setRenderHint(QPainter::Antialiasing, true);
        p.translate(-box.topLeft());
        p.fillPath(device, QColor(0, 0, 0, 255));
    }
    for (int y = 0; y < box.height(); ++y) {
        const uchar *src = coverage.constScanLine(y);
        std::uint8_t *row = m_mask.data() +
                            std::size_t(box.top() + y - m_clip.top()) * std::size_t(m_width) +
                            std::size_t(box.left() - m_clip.left());
        for (int x = 0; x < box.width(); ++x)
            row[x] = std::max(row[x], std::uint8_t(src[x]));
    }
    touch(box.left() - m_clip.left(), box.top() - m_clip.top(), box.right() - m_clip.left(),
          box.bottom() - m_clip.top());
    composite(color, opacity);
}

void StrokeRaster::drawStroke(const std::vector<model::StrokePoint> &points, QRgb color,
                              float width, qreal opacity)
{
    if (points.empty() || m_clip.isEmpty() || opacity <= 0 || qAlpha(color) == 0)
        return;
    // paintStroke's widths, kept finite and sane whatever the file or the tablet says.
    const auto radius = [&](const model::StrokePoint &p) {
        float r = width * p.pressure / 2;
        if (!(r > 0.125f)) // also NaN
            r = 0.125f;
        return std::min(r, model::kMaxStrokeWidth / 2) * m_scale;
    };
    // Segments are cut to the clip plus the widest pen first: a point millions of pixels away
    // (or at 1e30, past what an int holds) costs no more than one on the canvas.
    // The same pass finds the stroke's extent: a stroke wholly beside this band (half of them,
    // for each of two bands) is left before its segments are looked at.
    float widest = 0.0f;
    float minX = points.front().x, maxX = minX, minY = points.front().y, maxY = minY;
    for (const model::StrokePoint &p : points) {
        widest = std::max(widest, radius(p));
        minX = std::min(minX, p.x);
        maxX = std::max(maxX, p.x);
        minY = std::min(minY, p.y);
        maxY = std::max(maxY, p.y);
    }
    const double reach = double(std::max(widest, kMinRadius)) + 2.0;
    const QRectF clip = QRectF(m_clip).adjusted(-reach, -reach, reach, reach);
    const double left = clip.left(), right = clip.right(), top = clip.top(), bottom = clip.bottom();
    // The extent's box on the device: each of its sides at the corner the transform takes
    // farthest that way. (NaN extents compare false and fall through to the per-segment checks.)
    const auto span = [](float m, float lo, float hi) {
        return m >= 0 ? std::pair(m * lo, m * hi) : std::pair(m * hi, m * lo);
    };
    const auto [xFromX0, xFromX1] = span(m_xx, minX, maxX);
    const auto [xFromY0, xFromY1] = span(m_xy, minY, maxY);
    const auto [yFromX0, yFromX1] = span(m_yx, minX, maxX);
    const auto [yFromY0, yFromY1] = span(m_yy, minY, maxY);
    if (double(yFromX1 + yFromY1 + m_oy) < top || double(yFromX0 + yFromY0 + m_oy) > bottom ||
        double(xFromX1 + xFromY1 + m_ox) < left || double(xFromX0 + xFromY0 + m_ox) > right)
        return;
    const auto inside = [&](const QPointF &p) {
        return p.x() >= left && p.x() <= right && p.y() >= top && p.y() <= bottom;
    };
    const auto device = [&](const model::StrokePoint &p) {
        return QPointF(double(m_xx * p.x + m_xy * p.y + m_ox),
                       double(m_yx * p.x + m_yy * p.y + m_oy));
    };
    if (points.size() == 1) {
        const QPointF at = device(points.front());
        if (clip.contains(at)) {
            const float r = radius(points.front());
            capsule(float(at.x()), float(at.y()), r, float(at.x()), float(at.y()), r);
        }
    }
    for (std::size_t i = 1; i < points.size(); ++i) {
        QPointF a = device(points[i - 1]), b = device(points[i]);
        double t0 = 0, t1 = 1;
        // Most segments lie wholly inside or wholly beside the band: no cut to make.
        if (!(inside(a) && inside(b))) {
            if ((a.y() < top && b.y() < top) || (a.y() > bottom && b.y() > bottom) ||
                (a.x() < left && b.x() < left) || (a.x() > right && b.x() > right))
                continue;
            if (!model::clipSegment(a, b, clip, &t0, &t1))
                continue;
        }
        const float ar = radius(points[i - 1]), br = radius(points[i]);
        capsule(float(a.x()), float(a.y()), ar + float(t0) * (br - ar), float(b.x()), float(b.y()),
                ar + float(t1) * (br - ar));
    }
    composite(color, opacity);
}

void StrokeRaster::touch(int x0, int y0, int x1, int y1)
{
    for (int ty = y0 / kTile; ty <= y1 / kTile; ++ty)
        for (int tx = x0 / kTile; tx <= x1 / kTile; ++tx) {
            const int t = ty * m_tilesX + tx;
            if (!m_touched[std::size_t(t)]) {
                m_touched[std::size_t(t)] = 1;
                m_tiles.push_back(t);
            }
        }
}

void StrokeRaster::capsule(float ax, float ay, float ar, float bx, float by, float br)
{
    if (!std::isfinite(ax) || !std::isfinite(ay) || !std::isfinite(bx) || !std::isfinite(by))
        return;
    // Coverage ends half a pixel outside the radius.
    const float reach = std::max({ar, br, kMinRadius}) + 0.5f;
    // Only pixels whose centre (x + 0.5) lies nearer than `reach`: the rest get no coverage.
    const int x0 = std::max(m_clip.left(), int(std::ceil(std::min(ax, bx) - reach - 0.5f)));
    const int x1 = std::min(m_clip.right(), int(std::floor(std::max(ax, bx) + reach - 0.5f)));
    const int y0 = std::max(m_clip.top(), int(std::ceil(std::min(ay, by) - reach - 0.5f)));
    const int y1 = std::min(m_clip.bottom(), int(std::floor(std::max(ay, by) + reach - 0.5f)));
    if (x0 > x1 || y0 > y1)
        return;
    const float dx = bx - ax, dy = by - ay, dr = br - ar;
    const float len2 = dx * dx + dy * dy;
    const float inv = len2 > 1e-12f ? 1.0f / len2 : 0.0f;
    const bool slanted = std::abs(dy) > 1e-6f;
    const float invDy = slanted ? 1.0f / dy : 0.0f;
    // A capsule at most eight pixels wide (a pen line's segment) takes one vector step a row
    // whatever part of the row it reaches: its box is covered row by row, with no narrowing.
    const bool narrow = m_wide && x1 - x0 < 8 && x0 + 7 <= m_clip.right();
    // A small or narrow capsule marks its box's tiles at once; a long one marks, row by row,
    // only the tiles it reaches.
    const bool box = narrow || ((x1 - x0) < 2 * kTile && (y1 - y0) < 2 * kTile);
    if (box)
        touch(x0 - m_clip.left(), y0 - m_clip.top(), x1 - m_clip.left(), y1 - m_clip.top());
    for (int y = y0; y <= y1; ++y) {
        const float cy = float(y) + 0.5f;
        int rx0 = x0, n = 8;
        if (!narrow) {
            // Only the columns the capsule can reach in this row: the part of the segment
            // within `reach` of the row, widened by `reach`. A long diagonal then costs its
            // length times its width, not its bounding box (a zigzag across the canvas cost the
            // canvas per segment).
            float lo = std::min(ax, bx), hi = std::max(ax, bx);
            if (slanted) {
                float t0 = (cy - reach - ay) * invDy, t1 = (cy + reach - ay) * invDy;
                if (t0 > t1)
                    std::swap(t0, t1);
                t0 = std::max(t0, 0.0f);
                t1 = std::min(t1, 1.0f);
                if (t0 > t1)
                    continue;
                lo = std::min(ax + t0 * dx, ax + t1 * dx);
                hi = std::max(ax + t0 * dx, ax + t1 * dx);
            }
            rx0 = std::max(x0, int(std::ceil(lo - reach - 0.5f)));
            const int rx1 = std::min(x1, int(std::floor(hi + reach - 0.5f)));
            if (rx0 > rx1)
                continue;
            if (!box)
                touch(rx0 - m_clip.left(), y - m_clip.top(), rx1 - m_clip.left(), y - m_clip.top());
            // Whole groups of eight (or four) for the vector loops: pixels past rx1 lie beyond
            // the reach, so they get zero coverage and leave the mask (and the untouched tiles)
            // as they were; at the clip's right edge, just the pixels there are.
            const int group = m_wide ? 8 : 4;
            n = (rx1 - rx0 + group) & ~(group - 1);
            if (rx0 + n - 1 > m_clip.right())
                n = rx1 - rx0 + 1;
        }
        m_spans.push_back({m_mask.data() + std::size_t(y - m_clip.top()) * std::size_t(m_width) +
                               std::size_t(rx0 - m_clip.left()),
                           float(rx0) + 0.5f - ax, cy - ay, n});
    }
#if defined(FINBOOK_RASTER_AVX2)
    if (m_wide) {
        coverSpansAvx2(m_spans.data(), m_spans.size(), dx, dy, inv, ar, dr);
        m_spans.clear();
        return;
    }
#endif
#if defined(__SSE2__)
    const CapsuleSse sse(dx, dy, inv, ar, dr);
#endif
    for (const CoverSpan &span : m_spans) {
        int i = 0;
#if defined(__SSE2__)
        i = sse.cover(span.row, span.n, span.px0, span.py);
#endif
        for (; i < span.n; ++i)
            span.row[i] =
                std::max(span.row[i], coverage(span.px0 + float(i), span.py, dx, dy, inv, ar, dr));
    }
    m_spans.clear();
}

void StrokeRaster::composite(QRgb color, qreal opacity)
{
    // The source at full coverage: premultiplied, opacity folded into alpha.
    const int alpha = int(std::lround(qAlpha(color) * std::clamp(opacity, 0.0, 1.0)));
    const QRgb src = byteMul(qPremultiply(qRgba(qRed(color), qGreen(color), qBlue(color), 255)),
                             std::uint32_t(alpha));
    const bool ghost = m_ghostActive;
    const bool opaque = qAlpha(src) == 255;

    for (int t : m_tiles) {
        m_touched[std::size_t(t)] = 0;
        const int tx = (t % m_tilesX) * kTile, ty = (t / m_tilesX) * kTile;
        const int xEnd = std::min(tx + kTile, m_width), yEnd = std::min(ty + kTile, m_height);
        if (ghost)
            m_ghostBox |= QRect(QPoint(tx, ty), QPoint(xEnd - 1, yEnd - 1));
        for (int y = ty; y < yEnd; ++y) {
            std::uint8_t *mask = m_mask.data() + std::size_t(y) * std::size_t(m_width);
            if (xEnd - tx == kTile) { // most tile rows of a thin stroke are empty
                std::uint64_t word;
                std::memcpy(&word, mask + tx, sizeof word);
                if (!word)
                    continue;
            }
            auto *dst =
                ghost ? m_ghost.data() + std::size_t(y) * std::size_t(m_width)
                      : reinterpret_cast<QRgb *>(m_bits + qsizetype(y + m_clip.top()) * m_stride) +
                            m_clip.left();
#if defined(FINBOOK_RASTER_AVX2)
            if (m_wide && xEnd - tx == kTile) {
                blendEightAvx2(dst + tx, mask + tx, src, ghost && m_ghostReplace);
                continue;
            }
#endif
            for (int x = tx; x < xEnd; ++x) {
                const std::uint32_t m = mask[x];
                if (!m)
                    continue;
                mask[x] = 0;
                if (m == 255 && opaque) { // covered by an opaque colour: the colour
                    dst[x] = src;
                    continue;
                }
                const QRgb s = m == 255 ? src : byteMul(src, m);
                if (ghost && m_ghostReplace) // this item's colour where it covers, whole
                    dst[x] = s + byteMul(dst[x], 255 - m);
                else
                    dst[x] = s + byteMul(dst[x], 255 - qAlpha(s)); // source-over, premultiplied
            }
        }
    }
    m_tiles.clear();
}

} // namespace finbook::ui
