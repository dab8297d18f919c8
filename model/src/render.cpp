// Painting strokes and frames with QPainter, at a cost bounded by what is on the canvas.
//
// Two kinds of tiny files used to cost minutes: a point millions of pixels off the canvas
// (QPainter's stroker builds the whole outline of a segment whatever the clip), and one
// stroke referenced thousands of times (each reference painted again). So segments are
// clipped to what the painter can show before QPainter sees them, and references to the
// same points in one frame are painted once (paintList). Wide pens and long scribbles, whose
// outlines QPainter fills at a cost growing with their overlap, go through render_wide_pen.h.
#include "render_wide_pen.h"

#include <finbook/model/fill/fill_render.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/render.h>
#include <finbook/model/scene/shot.h>

#include <QPainterPath>
#include <QVarLengthArray>

#include <algorithm>
#include <cmath>
#include <span>
#include <tuple>
#include <unordered_map>

namespace finbook::model {

namespace {
// Width buckets of a quarter pixel: invisible steps, but long runs for the polyline fast path.
int widthBucket(float width, float pressure)
{
    const float w = width * pressure * 4.0f;
    // QPen refuses widths of 32768 and more (and draws 1 pixel instead): stay below.
    return std::isfinite(w) ? int(std::lround(std::clamp(w, 0.0f, 4.0f * kMaxStrokeWidth))) : 0;
}

void paintDot(QPainter &painter, const QPointF &p, qreal width)
{
    painter.setPen(Qt::NoPen);
    painter.drawEllipse(p, width / 2, width / 2);
}

bool isFinite(const StrokePoint &p)
{
    return std::isfinite(p.x) && std::isfinite(p.y);
}

// Polylines of equal width, handed to QPainter as they fill up.
class RunPainter {
public:
    RunPainter(QPainter &painter, QPen pen)
        : m_painter(painter)
        , m_pen(std::move(pen))
    {}
    ~RunPainter() { flush(); }

    void segment(const QPointF &a, const QPointF &b, int bucket)
    {
        if (!m_run.isEmpty() && (bucket != m_bucket || m_run.back() != a))
            flush();
        if (m_run.isEmpty()) {
            m_run.append(a);
            m_bucket = bucket;
        }
        m_run.append(b);
    }
    void flush()
    {
        if (m_run.size() >= 2) {
            m_pen.setWidthF(std::max(0.25, m_bucket / 4.0));
            m_painter.setPen(m_pen);
            m_painter.drawPolyline(m_run.constData(), int(m_run.size()));
        }
        m_run.clear();
    }

private:
    QPainter &m_painter;
    QPen m_pen;
    QVarLengthArray<QPointF, 256> m_run;
    int m_bucket = 0;
};

// The largest width a stroke can have, for the clip margin.
float widestPen(const std::vector<StrokePoint> &points, float width)
{
    float widest = 0.25f;
    for (const StrokePoint &p : points)
        if (std::isfinite(p.pressure))
            widest = std::max(widest, width * std::clamp(p.pressure, 0.0f, 1.0f));
    return std::isfinite(widest) ? widest : 0.25f;
}

// Where the painter can draw, in its logical coordinates: the device (and the clip, if any)
// mapped back. Empty when there is no device or the transform cannot be inverted.
QRectF paintableRect(const QPainter &painter)
{
    const QPaintDevice *device = painter.device();
    if (!device)
        return {};
    bool invertible = false;
    const QTransform toLogical = painter.combinedTransform().inverted(&invertible);
    if (!invertible)
        return {};
    QRectF rect = toLogical.mapRect(QRectF(0, 0, device->width(), device->height()));
    if (painter.hasClipping())
        rect = rect.intersected(painter.clipBoundingRect());
    return rect;
}

// Whether the stroke's outlines cross the visible rows so often that QPainter would spend far
// more on them than a coverage mask of the frame (a long scribble: render_wide_pen.h).
bool crowdsTheRows(const std::vector<StrokePoint> &points, float width, const QRectF &paintable,
                   qreal scale)
{
    const double rows = paintable.height() * scale;
    const double pixels = paintable.width() * scale * rows;
    if (!outlineFillIsCrowded(double(points.size()) * rows, rows, pixels))
        return false; // even if every segment crossed every row
    double crossed = 0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        const StrokePoint &from = points[i - 1], &to = points[i];
        if (!isFinite(from) || !isFinite(to))
            continue;
        const double reach = std::max(0.25, widthBucket(width, to.pressure) / 4.0) / 2;
        const double top = std::max(paintable.top(), double(std::min(from.y, to.y)) - reach);
        const double bottom = std::min(paintable.bottom(), double(std::max(from.y, to.y)) + reach);
        if (top < bottom)
            crossed += (bottom - top) * scale;
    }
    return outlineFillIsCrowded(crossed, rows, pixels);
}

// The alpha that `coats` layers of `alpha` (0..1) give when painted over each other.
qreal coatedAlpha(qreal alpha, int coats)
{
    return 1.0 - std::pow(1.0 - std::clamp(alpha, 0.0, 1.0), coats);
}
} // namespace

namespace {
// Liang–Barsky from `a` along a→b.
bool clipFrom(QPointF &a, QPointF &b, const QRectF &r, double &t0, double &t1)
{
    t0 = 0.0;
    t1 = 1.0;
    const double dx = b.x() - a.x(), dy = b.y() - a.y();
    if (!std::isfinite(dx) || !std::isfinite(dy))
        return false;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.x() - r.left(), r.right() - a.x(), a.y() - r.top(), r.bottom() - a.y()};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0)
                return false;
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0.0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 > t1)
            return false;
    }
    const QPointF from = a;
    if (t0 > 0.0)
        a = QPointF(from.x() + t0 * dx, from.y() + t0 * dy);
    if (t1 < 1.0)
        b = QPointF(from.x() + t1 * dx, from.y() + t1 * dy);
    return true;
}

double distanceTo(const QPointF &p, const QPointF &c)
{
    return std::abs(p.x() - c.x()) + std::abs(p.y() - c.y());
}
} // namespace

bool clipSegment(QPointF &a, QPointF &b, const QRectF &r, double *t0Out, double *t1Out)
{
    // The cuts are measured from the end nearer the rectangle: from a point near 1e30, t × d
    // loses every digit that matters there (1 - 1e-28 is 1), and the piece drawn pointed the
    // wrong way or vanished. From the near end the cuts are small multiples of d, exact enough.
    const bool flip = distanceTo(b, r.center()) < distanceTo(a, r.center());
    double t0 = 0.0, t1 = 1.0;
    if (flip ? !clipFrom(b, a, r, t0, t1) : !clipFrom(a, b, r, t0, t1))
        return false;
    if (flip)
        std::tie(t0, t1) = std::pair(1.0 - t1, 1.0 - t0);
    if (t0Out)
        *t0Out = t0;
    if (t1Out)
        *t1Out = t1;
    return true;
}

void paintStroke(QPainter &painter, const std::vector<StrokePoint> &points, QRgb color, float width)
{
    if (points.empty() || !(width > 0.0f) || !std::isfinite(width))
        return;
    width = std::min(width, kMaxStrokeWidth); // what a file may hold; wider strains QPainter
    const QRectF paintable = paintableRect(painter);
    if (paintable.isEmpty())
        return;
    // Caps and antialiasing reach half a pen plus a device pixel or two past a segment.
    const qreal scale =
        std::max(1e-9, std::sqrt(std::abs(painter.combinedTransform().determinant())));
    const qreal margin = widestPen(points, width) / 2 + 2.0 / scale;
    const QRectF clip = paintable.adjusted(-margin, -margin, margin, margin);
    const QColor c = QColor::fromRgba(color);
    painter.setBrush(c);
    if (points.size() == 1) {
        const StrokePoint &p = points.front();
        const QPointF at(p.x, p.y);
        if (isFinite(p) && clip.contains(at))
            paintDot(painter, at, std::max(0.5f, width * std::clamp(p.pressure, 0.0f, 1.0f)));
        return;
    }
    if (widestPen(points, width) * scale >= kWidePenPixels ||
        crowdsTheRows(points, width, paintable, scale)) {
        std::vector<WideSegment> segments;
        for (std::size_t i = 1; i < points.size(); ++i) {
            const StrokePoint &from = points[i - 1], &to = points[i];
            QPointF a(from.x, from.y), b(to.x, to.y);
            if (isFinite(from) && isFinite(to) && clipSegment(a, b, clip))
                segments.push_back({a, b, std::max(0.25, widthBucket(width, to.pressure) / 4.0)});
        }
        const qreal edge = 2.0 / scale; // antialiasing reaches a pixel past the picture
        fillWideSegments(painter, segments, paintable.adjusted(-edge, -edge, edge, edge), scale);
        return;
    }
    RunPainter runs(painter, QPen(c, 1.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    for (std::size_t i = 1; i < points.size(); ++i) {
        const StrokePoint &from = points[i - 1], &to = points[i];
        if (!isFinite(from) || !isFinite(to)) {
            runs.flush();
            continue;
        }
        QPointF a(from.x, from.y), b(to.x, to.y);
        const QPointF end = b;
        if (!clipSegment(a, b, clip)) {
            runs.flush();
            continue;
        }
        runs.segment(a, b, widthBucket(width, to.pressure));
        if (b != end) // left the clip: the next piece starts a new run
            runs.flush();
    }
}

const std::vector<StrokePoint> &displayedPoints(const StrokeGroup &group, std::size_t stroke)
{
    if (group.isDeformed() && stroke < group.deformed->strokes.size() &&
        group.deformed->strokes[stroke].size() == group.strokes[stroke].data->points.size())
        return group.deformed->strokes[stroke];
    return group.strokes[stroke].data->points;
}

std::vector<Stroke> posedStrokes(const StrokeGroup &group)
{
    std::vector<Stroke> strokes = group.strokes;
    if (!group.isDeformed())
        return strokes;
    for (std::size_t i = 0; i < strokes.size(); ++i) {
        if (!strokes[i].data)
            continue;
        auto data = std::make_shared<StrokeData>(*strokes[i].data);
        data->points = displayedPoints(group, i);
        // A cut-out pose's line goes round each joint it crosses, as the pose is drawn.
        if (!group.deformed->pieces.empty() && i < group.deformed->pieceOf.size() &&
            group.deformed->pieceOf[i].size() == data->points.size()) {
            const std::vector<std::int16_t> &piece = group.deformed->pieceOf[i];
            std::vector<StrokePoint> joined;
            for (std::size_t k = 0; k < data->points.size(); ++k) {
                joined.push_back(data->points[k]);
                if (k + 1 < data->points.size() && piece[k] != piece[k + 1])
                    if (const auto seam = cutOutSeam(group, i, k))
                        joined.insert(joined.end(), seam->arc.begin(), seam->arc.end());
            }
            data->points = std::move(joined);
        }
        strokes[i].data = std::move(data);
    }
    return strokes;
}

namespace {
std::vector<PaintItem> paintListOf(const StrokeGroup *groups, std::size_t count,
                                   const RenderOptions &options)
{
    std::vector<PaintItem> items;
    for (const StrokeGroup &g : std::span(groups, count)) {
        if (!g.visible && !options.showHidden)
            continue;
        for (std::size_t i = 0; i < g.strokes.size(); ++i) {
            const Stroke &s = g.strokes[i];
            if (!s.data || qAlpha(s.data->color) == 0) // a gap closer, or ink of no colour
                continue;
            const QRgb color = options.tint ? options.tint->rgba() : s.data->color;
            items.push_back(PaintItem{&displayedPoints(g, i), color, s.data->width, 1});
        }
    }
    // Repeats of the same points, colour and width: one item at the last place, with the
    // opacity its coats add up to.
    struct Key {
        const std::vector<StrokePoint> *points;
        QRgb color;
        float width;
        bool operator==(const Key &) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key &k) const
        {
            return std::hash<const void *>()(k.points) ^
                   (std::size_t(k.color) * 0x9e3779b97f4a7c15u) ^ std::hash<float>()(k.width);
        }
    };
    std::unordered_map<Key, std::pair<int, int>, KeyHash> counts; // total, still to come
    for (const PaintItem &item : items) {
        auto &[total, left] = counts[Key{item.points, item.color, item.width}];
        ++total;
        ++left;
    }
    if (counts.size() == items.size())
        return items;
    std::vector<PaintItem> merged;
    merged.reserve(counts.size());
    const qreal opacity = std::clamp(options.opacity, 0.0, 1.0);
    for (const PaintItem &item : items) {
        auto &[total, left] = counts[Key{item.points, item.color, item.width}];
        if (--left > 0)
            continue;
        PaintItem kept = item;
        kept.coats = total;
        if (total > 1 && opacity > 0.0) {
            const qreal alpha = coatedAlpha(qAlpha(item.color) / 255.0 * opacity, total);
            const int stored = int(std::lround(std::min(1.0, alpha / opacity) * 255.0));
            kept.color = qRgba(qRed(item.color), qGreen(item.color), qBlue(item.color), stored);
        }
        merged.push_back(kept);
    }
    return merged;
}
} // namespace

std::vector<PaintItem> paintList(const Frame &frame, const RenderOptions &options)
{
    return paintListOf(frame.groups.data(), frame.groups.size(), options);
}

std::vector<PaintItem> paintList(const StrokeGroup &group, const RenderOptions &options)
{
    return paintListOf(&group, 1, options);
}

namespace {
// The frame's fills and strokes, back to front, with the painter as it is; `replaceFills`:
// each fill replaces what lies under it (CompositionMode_Source, edges blended by coverage).
void paintFrameItems(QPainter &painter, const Frame &frame, const DocumentSettings &settings,
                     const RenderOptions &options, bool replaceFills = false)
{
    if (!frameHasFills(frame, options) && !frameHasPictures(frame, options)) {
        for (const PaintItem &item : paintList(frame, options))
            paintStroke(painter, *item.points, item.color, item.width);
        return;
    }
    for (const StrokeGroup &group : frame.groups) {
        if (group.picture && (group.visible || options.showHidden))
            paintPicture(painter, group, options.tint);
        for (const PaintLayer &layer : paintLayers(group, settings, options)) {
            if (replaceFills)
                painter.setCompositionMode(QPainter::CompositionMode_Source);
            for (const FillItem &fill : paintedFills(group, layer.fills))
                paintFill(painter, fill);
            painter.setCompositionMode(QPainter::CompositionMode_SourceOver);
            for (const PaintItem &item : layer.strokes)
                paintStroke(painter, *item.points, item.color, item.width);
        }
    }
}
} // namespace

namespace {
// The page's background and the underlay (options say which), under the drawing; the page's
// rectangle in canvas coordinates.
QRectF paintPage(QPainter &painter, const DocumentSettings &settings, const RenderOptions &options)
{
    const QRectF page(QPointF(0, 0), QSizeF(settings.canvasSize));
    if (options.paintBackground)
        painter.fillRect(page, QColor::fromRgba(settings.background));
    if (options.underlay) {
        painter.save();
        painter.setClipRect(page, Qt::IntersectClip);
        options.underlay(painter);
        painter.restore();
    }
    return page;
}

// A composed shot (scene/shot.h): the page once, then each layer's plane at its opacity, seen
// through its own camera when the picture is seen through one.
void paintPlanes(QPainter &painter, const Frame &frame, const DocumentSettings &settings,
                 const RenderOptions &options)
{
    painter.save();
    const QRectF page = paintPage(painter, settings, options);
    RenderOptions planeOptions = options;
    planeOptions.paintBackground = false;
    planeOptions.underlay = {};
    const QTransform shotCamera =
        options.camera ? cameraTransform(*options.camera, page.size()) : QTransform();
    int begin = 0;
    for (const FramePlane &plane : frame.planes) {
        const int end = std::clamp(plane.groupEnd, begin, int(frame.groups.size()));
        Frame layer;
        layer.id = frame.id;
        layer.groups.assign(frame.groups.begin() + begin, frame.groups.begin() + end);
        begin = end;
        planeOptions.opacity = options.opacity * std::clamp(plane.opacity, 0.0, 1.0);
        if (layer.groups.empty() || planeOptions.opacity <= 0.0)
            continue;
        painter.save();
        if (options.camera && plane.depth != 0.0) {
            const CameraState seen = planeCamera(*options.camera, plane.depth, page.size());
            painter.setTransform(cameraTransform(seen, page.size()) * shotCamera.inverted(), true);
        }
        paintFrame(painter, layer, settings, planeOptions);
        painter.restore();
    }
    painter.restore();
}
} // namespace

void paintFrame(QPainter &painter, const Frame &frame, const DocumentSettings &settings,
                const RenderOptions &options)
{
    if (!frame.planes.empty()) {
        paintPlanes(painter, frame, settings, options);
        return;
    }
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    paintPage(painter, settings, options);
    const qreal opacity = std::clamp(options.opacity, 0.0, 1.0);
    // A ghost (onion skin: a tint, or an opacity below 1) is painted whole into a layer of the
    // device first and laid on it once at its opacity: painted item by item at that opacity,
    // wherever items overlap (a cut-out limb's pieces and sockets at a joint, a line split at a
    // cut) it came out darker than the rest of the ghost. With a tint each item replaces what
    // lies under it in the layer, as the opaque frame's look: a ghost fill on a ghost fill is
    // one ghost fill (the tinted strokes are one colour: over each other they stay it, as long
    // as the tint is opaque). Devices that are not pictures (SVG) keep item-by-item painting.
    QPaintDevice *device = painter.device();
    const bool layered = (options.tint || opacity < 1.0) && device &&
                         device->devType() == QInternal::Image && opacity > 0.0;
    if (!layered) {
        painter.setOpacity(opacity);
        paintFrameItems(painter, frame, settings, options);
        painter.restore();
        return;
    }
    QImage layer(device->width(), device->height(), QImage::Format_ARGB32_Premultiplied);
    if (layer.isNull()) { // no memory for a layer: item by item, as before
        painter.setOpacity(opacity);
        paintFrameItems(painter, frame, settings, options);
        painter.restore();
        return;
    }
    layer.fill(Qt::transparent);
    {
        QPainter into(&layer);
        into.setRenderHint(QPainter::Antialiasing, true);
        if (painter.hasClipping()) // the clip in device pixels, then the drawing's transform
            into.setClipPath(painter.deviceTransform().map(painter.clipPath()));
        into.setTransform(painter.deviceTransform());
        paintFrameItems(into, frame, settings, options, options.tint.has_value());
    }
    layer.setDevicePixelRatio(device->devicePixelRatioF());
    painter.resetTransform();
    painter.setClipping(false);
    painter.setOpacity(opacity);
    painter.drawImage(QPointF(0, 0), layer);
    painter.restore();
}

QImage renderFrame(const Frame &frame, const DocumentSettings &settings, QSize size,
                   const RenderOptions &options)
{
    return renderFrameBand(frame, settings, size, 0, size.height(), options);
}

QImage renderFrameBand(const Frame &frame, const DocumentSettings &settings, QSize size, int top,
                       int rows, const RenderOptions &options)
{
    QImage image(QSize(size.width(), std::max(0, rows)), QImage::Format_ARGB32_Premultiplied);
    if (image.isNull())
        return image;
    image.fill(Qt::transparent);
    const QSizeF canvas(settings.canvasSize);
    if (size.isEmpty() || canvas.isEmpty())
        return image;
    QPainter painter(&image);
    const qreal scale = std::min(size.width() / canvas.width(), size.height() / canvas.height());
    painter.translate((size.width() - canvas.width() * scale) / 2,
                      (size.height() - canvas.height() * scale) / 2 - top);
    painter.scale(scale, scale);
    if (options.camera) {
        if (options.paintBackground)
            painter.fillRect(QRectF(QPointF(0, 0), canvas), QColor::fromRgba(settings.background));
        painter.setTransform(cameraTransform(*options.camera, canvas), true);
    }
    paintFrame(painter, frame, settings, options);
    return image;
}

} // namespace finbook::model
