// SVG frames. A stroke's width follows its pressure, which SVG strokes cannot do, so each
// stroke is written as a filled outline: the union (non-zero fill of one path) of a tapered
// capsule per segment, the convex hull of the circles at its two samples. It scales without
// pixels and renders like the canvas, which paints the same widths.
#include "decimal_text.h"
#include "export_formats.h"

#include <finbook/model/fill/fill_render.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/render.h>

#include <QBuffer>
#include <QLineF>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace finbook::model {

namespace {
// Far beyond any canvas (kMaxCanvasSide), yet far from where llround overflows. Outlines are
// clipped near the canvas first (outline()), so this only guards the conversion.
constexpr double kLargestNumber = 1e9;

// Canvas units to 1/100 px, trailing zeros dropped: "12.5", "3", "-0.25".
void appendNumber(QByteArray &out, double value)
{
    appendDecimal(out, value, 2, kLargestNumber);
}

void appendPoint(QByteArray &out, char command, QPointF p)
{
    out += command;
    appendNumber(out, p.x());
    out += ' ';
    appendNumber(out, p.y());
}

// An arc of radius r to `to`, turning the way every outline here turns (negative angles).
void appendArc(QByteArray &out, double r, bool large, QPointF to)
{
    out += 'A';
    appendNumber(out, r);
    out += ' ';
    appendNumber(out, r);
    out += large ? " 0 1 0 " : " 0 0 0 ";
    appendNumber(out, to.x());
    out += ' ';
    appendNumber(out, to.y());
}

void appendCircle(QByteArray &out, QPointF c, double r)
{
    appendPoint(out, 'M', c + QPointF(r, 0));
    appendArc(out, r, false, c - QPointF(r, 0));
    appendArc(out, r, false, c + QPointF(r, 0));
    out += 'Z';
}

// The hull of circle (p0, r0) and circle (p1, r1): two tangent lines and two arcs.
void appendCapsule(QByteArray &out, QPointF p0, double r0, QPointF p1, double r1)
{
    const QPointF d = p1 - p0;
    const double length = std::hypot(d.x(), d.y());
    if (length <= std::abs(r1 - r0) + 1e-6) { // one circle holds the other
        appendCircle(out, r0 >= r1 ? p0 : p1, std::max(r0, r1));
        return;
    }
    const QPointF u = d / length;
    const QPointF n(-u.y(), u.x());
    const double a = (r0 - r1) / length; // cosine of the tangent points' angle from u
    const double b = std::sqrt(std::max(0.0, 1.0 - a * a));
    const QPointF plus = a * u + b * n, minus = a * u - b * n;
    appendPoint(out, 'M', p0 + r0 * plus);
    appendPoint(out, 'L', p1 + r1 * plus);
    appendArc(out, r1, a < 0, p1 + r1 * minus);
    appendPoint(out, 'L', p0 + r0 * minus);
    appendArc(out, r0, a > 0, p0 + r0 * plus);
    out += 'Z';
}

bool finite(const StrokePoint &p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.pressure);
}

// The same widths paintStroke draws: width × pressure, at least a quarter pixel (a lone
// sample: a dot of at least half a pixel). Only what can reach `visible` is written: each
// segment is clipped, in floating point, to `visible` grown by its widest radius, so a point
// near 1e30 gives a short capsule at the edge instead of numbers no integer holds.
QByteArray outline(const std::vector<StrokePoint> &points, float width, const QRectF &visible)
{
    QByteArray d;
    const auto radius = [&](const StrokePoint &p, double least) {
        return std::max(least, double(width) * double(p.pressure)) / 2;
    };
    if (points.size() == 1 && finite(points.front())) {
        const StrokePoint &p = points.front();
        const double r = radius(p, 0.5);
        if (visible.adjusted(-r, -r, r, r).contains(QPointF(p.x, p.y)))
            appendCircle(d, QPointF(p.x, p.y), r);
        return d;
    }
    for (std::size_t i = 1; i < points.size(); ++i) {
        const StrokePoint &a = points[i - 1], &b = points[i];
        if (!finite(a) || !finite(b))
            continue;
        const double ra = radius(a, 0.25), rb = radius(b, 0.25);
        const double reach = std::max(ra, rb) + 1.0;
        QPointF from(a.x, a.y), to(b.x, b.y);
        double t0 = 0.0, t1 = 1.0;
        if (!clipSegment(from, to, visible.adjusted(-reach, -reach, reach, reach), &t0, &t1))
            continue;
        appendCapsule(d, from, ra + t0 * (rb - ra), to, ra + t1 * (rb - ra));
    }
    return d;
}

QByteArray colour(QRgb rgb)
{
    return QColor::fromRgb(rgb).name(QColor::HexRgb).toLatin1();
}

// A fill's faces as one path: a closed subpath per ring, holes running the other way, so the
// non-zero rule leaves them empty as the canvas does.
QByteArray fillPath(const QPainterPath &path)
{
    QByteArray d;
    for (const QPolygonF &ring : path.toSubpathPolygons()) {
        if (ring.size() < 3)
            continue;
        for (qsizetype i = 0; i < ring.size(); ++i) {
            if (i == ring.size() - 1 && ring[i] == ring.front())
                break;
            appendPoint(d, i == 0 ? 'M' : 'L', ring[i]);
        }
        d += 'Z';
    }
    return d;
}

// A shaded fill's tones as a few filled regions: the mesh pieces of each tone merged into
// their outlines (QPainterPath::simplified), so a tone is one path of a few polygons.
void appendTones(QByteArray &svg, const FillItem &fill, Id groupId, int k)
{
    int t = 0;
    for (const ToneItem &tone : fill.tones) {
        const QByteArray d = fillPath(tone.path.simplified());
        ++t;
        if (d.isEmpty())
            continue;
        svg += "<path id=\"tone-" + QByteArray::number(groupId) + '-' + QByteArray::number(k) +
               '-' + QByteArray::number(t) + "\" class=\"tone\" fill=\"" + colour(tone.color) + '"';
        const int alpha = qAlpha(tone.color);
        if (alpha < 255)
            svg += " fill-opacity=\"" + QByteArray::number(alpha / 255.0, 'g', 3) + '"';
        svg += " fill-rule=\"nonzero\" d=\"" + d + "\"/>\n";
    }
}

void appendFills(QByteArray &svg, const StrokeGroup &group, const std::vector<FillItem> &fills,
                 int &k)
{
    for (const FillItem &fill : fills) {
        const QByteArray d = fillPath(fill.path);
        ++k;
        if (d.isEmpty())
            continue;
        svg += "<path id=\"fill-" + QByteArray::number(group.id) + '-' + QByteArray::number(k) +
               "\" class=\"fill\" fill=\"" + colour(fill.color) + '"';
        const int alpha = qAlpha(fill.color);
        if (alpha < 255)
            svg += " fill-opacity=\"" + QByteArray::number(alpha / 255.0, 'g', 3) + '"';
        svg += " fill-rule=\"nonzero\" d=\"" + d + "\"/>\n";
        appendTones(svg, fill, group.id, k);
    }
}

void appendStroke(QByteArray &svg, const QByteArray &id, const StrokeData &data,
                  const QByteArray &d)
{
    svg += "<path id=\"stroke-" + id + "\" fill=\"" + colour(data.color) + '"';
    const int alpha = qAlpha(data.color);
    if (alpha < 255)
        svg += " fill-opacity=\"" + QByteArray::number(alpha / 255.0, 'g', 3) + '"';
    svg += " d=\"" + d + "\"/>\n";
}

// A cut-out pose as the canvas paints it: each piece's fills over the pieces below it, then the
// lines with what the pieces above hide cut away (bakedStrokes), so a limb turned over the body
// hides the body's lines in the SVG too. A line cut into parts keeps its id on the first part;
// the others are "stroke-<id>-<part>".
void appendCutOutPose(QByteArray &svg, const StrokeGroup &group, const DocumentSettings &settings,
                      const QRectF &visible)
{
    int k = 0;
    const std::vector<PaintLayer> layers = paintLayers(group, settings);
    for (const PaintLayer &layer : layers)
        appendFills(svg, group, layer.fills, k);
    // Ids past any a document allocates mark the later parts of a cut line.
    constexpr Id kPart = Id(1) << 62;
    Id next = kPart;
    Id whole = kNoId;
    int part = 0;
    for (const Stroke &stroke : bakedStrokes(group, layers, settings, [&] { return next++; })) {
        if (!stroke.data)
            continue;
        if (stroke.id < kPart) {
            whole = stroke.id;
            part = 0;
        }
        const QByteArray d = outline(stroke.data->points, stroke.data->width, visible);
        if (d.isEmpty())
            continue;
        QByteArray id = QByteArray::number(whole);
        if (stroke.id >= kPart)
            id += '-' + QByteArray::number(++part);
        appendStroke(svg, id, *stroke.data, d);
    }
}
// A picture object's picture as the object shows it, drawn at the export's scale into a PNG
// embedded as an <image> over the part of it that can show (under the object's fills and
// lines, as the canvas paints it).
void appendPicture(QByteArray &svg, const StrokeGroup &group, const QRectF &visible, double scale)
{
    const QRectF shown = shownPictureBounds(group).adjusted(-1, -1, 1, 1) & visible;
    if (shown.isEmpty() || !(scale > 0.0))
        return;
    const QRect box(QPoint(int(std::floor(shown.left())), int(std::floor(shown.top()))),
                    QPoint(int(std::ceil(shown.right())) - 1, int(std::ceil(shown.bottom())) - 1));
    const QSize pixels(std::max(1, int(std::ceil(box.width() * scale))),
                       std::max(1, int(std::ceil(box.height() * scale))));
    QImage image(pixels, QImage::Format_ARGB32_Premultiplied);
    if (image.isNull())
        return;
    image.fill(Qt::transparent);
    drawPicture(image,
                QTransform::fromTranslate(-box.left(), -box.top()) *
                    QTransform::fromScale(double(pixels.width()) / box.width(),
                                          double(pixels.height()) / box.height()),
                group);
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, "PNG"))
        return;
    svg += "<image id=\"picture-" + QByteArray::number(group.id) + "\" x=\"" +
           QByteArray::number(box.left()) + "\" y=\"" + QByteArray::number(box.top()) +
           "\" width=\"" + QByteArray::number(box.width()) + "\" height=\"" +
           QByteArray::number(box.height()) +
           "\" preserveAspectRatio=\"none\" xlink:href=\"data:image/png;base64," + png.toBase64() +
           "\"/>\n";
}
} // namespace

QByteArray frameSvg(const Frame &frame, const DocumentSettings &settings, const ExportPlan &plan,
                    const CameraState *camera)
{
    const QSize canvas = settings.canvasSize;
    QByteArray svg;
    svg += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" "
           "xmlns:xlink=\"http://www.w3.org/1999/xlink\" version=\"1.1\" width=\"" +
           QByteArray::number(plan.size.width()) + "\" height=\"" +
           QByteArray::number(plan.size.height()) + "\" viewBox=\"0 0 " +
           QByteArray::number(canvas.width()) + ' ' + QByteArray::number(canvas.height()) + "\">\n";
    if (!plan.transparent)
        svg += "<rect width=\"" + QByteArray::number(canvas.width()) + "\" height=\"" +
               QByteArray::number(canvas.height()) + "\" fill=\"" + colour(plan.background) +
               "\"/>\n";
    // Through a camera, the page is drawn in a group that the camera moves, and what is kept
    // of each stroke is what the shot shows.
    const QRectF visible = camera ? cameraFrame(*camera, QSizeF(canvas)).boundingRect()
                                  : QRectF(QPointF(0, 0), QSizeF(canvas));
    QByteArray closing;
    if (camera) {
        const QTransform t = cameraTransform(*camera, QSizeF(canvas));
        svg += "<g transform=\"matrix(" + QByteArray::number(t.m11(), 'g', 10) + ' ' +
               QByteArray::number(t.m12(), 'g', 10) + ' ' + QByteArray::number(t.m21(), 'g', 10) +
               ' ' + QByteArray::number(t.m22(), 'g', 10) + ' ' +
               QByteArray::number(t.dx(), 'g', 10) + ' ' + QByteArray::number(t.dy(), 'g', 10) +
               ")\">\n";
        closing = "</g>\n";
    }
    // A drawing referenced more than once in the frame (a crafted file may reference one
    // stroke thousands of times) is written once in <defs> and placed with <use>.
    std::unordered_map<const std::vector<StrokePoint> *, int> uses;
    for (const StrokeGroup &group : frame.groups)
        for (std::size_t i = 0; group.visible && i < group.strokes.size(); ++i)
            if (group.strokes[i].data)
                ++uses[&displayedPoints(group, i)];
    std::unordered_map<const std::vector<StrokePoint> *, int> shapes; // -1: nothing to draw
    QByteArray defs;
    for (const StrokeGroup &group : frame.groups) {
        for (std::size_t i = 0; group.visible && i < group.strokes.size(); ++i) {
            const Stroke &stroke = group.strokes[i];
            const std::vector<StrokePoint> *points =
                stroke.data ? &displayedPoints(group, i) : nullptr;
            if (!points || uses[points] < 2 || shapes.count(points))
                continue;
            const QByteArray d = outline(*points, stroke.data->width, visible);
            const int shape = d.isEmpty() ? -1 : int(shapes.size());
            shapes[points] = shape;
            if (shape >= 0)
                defs += "<path id=\"shape-" + QByteArray::number(shape) + "\" d=\"" + d + "\"/>\n";
        }
    }
    if (!defs.isEmpty())
        svg += "<defs>\n" + defs + "</defs>\n";
    for (const StrokeGroup &group : frame.groups) {
        if (!group.visible)
            continue;
        svg += "<g id=\"object-" + QByteArray::number(group.id) + "\">\n";
        if (group.picture)
            appendPicture(svg, group, visible, double(plan.size.width()) / canvas.width());
        if (group.isDeformed() && !group.deformed->pieces.empty()) {
            appendCutOutPose(svg, group, settings, visible);
            svg += "</g>\n";
            continue;
        }
        int k = 0;
        appendFills(svg, group, fillList(group, settings), k);
        for (std::size_t i = 0; i < group.strokes.size(); ++i) {
            const Stroke &stroke = group.strokes[i];
            if (!stroke.data)
                continue;
            const std::vector<StrokePoint> &points = displayedPoints(group, i);
            const auto shape = shapes.find(&points);
            QByteArray d;
            if (shape == shapes.end())
                d = outline(points, stroke.data->width, visible);
            if (shape != shapes.end() ? shape->second < 0 : d.isEmpty())
                continue;
            if (!d.isEmpty()) {
                appendStroke(svg, QByteArray::number(stroke.id), *stroke.data, d);
                continue;
            }
            svg += "<use id=\"stroke-" + QByteArray::number(stroke.id) + "\" fill=\"" +
                   colour(stroke.data->color) + '"';
            const int alpha = qAlpha(stroke.data->color);
            if (alpha < 255)
                svg += " fill-opacity=\"" + QByteArray::number(alpha / 255.0, 'g', 3) + '"';
            svg += " xlink:href=\"#shape-" + QByteArray::number(shape->second) + "\"/>\n";
        }
        svg += "</g>\n";
    }
    svg += closing + "</svg>\n";
    return svg;
}

} // namespace finbook::model
