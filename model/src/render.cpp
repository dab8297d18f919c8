#include <finbook/model/render.h>

#include <QPainterPath>
#include <QVarLengthArray>

#include <cmath>

namespace finbook::model {

namespace {
// Width buckets of a quarter pixel: invisible steps, but long runs for the polyline fast path.
int widthBucket(float width, float pressure)
{
    return int(std::lround(width * pressure * 4.0f));
}

void paintDot(QPainter &painter, const StrokePoint &p, qreal width)
{
    painter.setPen(Qt::NoPen);
    painter.drawEllipse(QPointF(p.x, p.y), width / 2, width / 2);
}
} // namespace

void paintStroke(QPainter &painter, const std::vector<StrokePoint> &points, QRgb color, float width)
{
    if (points.empty())
        return;
    const QColor c = QColor::fromRgba(color);
    painter.setBrush(c);
    if (points.size() == 1) {
        paintDot(painter, points.front(), std::max(0.5f, width * points.front().pressure));
        return;
    }
    QPen pen(c, 1.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
    QVarLengthArray<QPointF, 256> run;
    std::size_t start = 0;
    while (start + 1 < points.size()) {
        const int bucket = widthBucket(width, points[start + 1].pressure);
        std::size_t end = start + 1;
        while (end + 1 < points.size() && widthBucket(width, points[end + 1].pressure) == bucket)
            ++end;
        run.clear();
        for (std::size_t i = start; i <= end; ++i)
            run.append(QPointF(points[i].x, points[i].y));
        pen.setWidthF(std::max(0.25, bucket / 4.0));
        painter.setPen(pen);
        painter.drawPolyline(run.constData(), int(run.size()));
        start = end;
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
        strokes[i].data = std::move(data);
    }
    return strokes;
}

void paintFrame(QPainter &painter, const Frame &frame, const DocumentSettings &settings,
                const RenderOptions &options)
{
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    if (options.paintBackground)
        painter.fillRect(QRectF(QPointF(0, 0), QSizeF(settings.canvasSize)),
                         QColor::fromRgba(settings.background));
    painter.setOpacity(options.opacity);
    for (const StrokeGroup &g : frame.groups) {
        if (!g.visible && !options.showHidden)
            continue;
        for (std::size_t i = 0; i < g.strokes.size(); ++i) {
            const Stroke &s = g.strokes[i];
            if (!s.data)
                continue;
            const QRgb color = options.tint ? options.tint->rgba() : s.data->color;
            paintStroke(painter, displayedPoints(g, i), color, s.data->width);
        }
    }
    painter.restore();
}

QImage renderFrame(const Frame &frame, const DocumentSettings &settings, QSize size,
                   const RenderOptions &options)
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    const QSizeF canvas(settings.canvasSize);
    if (size.isEmpty() || canvas.isEmpty())
        return image;
    QPainter painter(&image);
    const qreal scale = std::min(size.width() / canvas.width(), size.height() / canvas.height());
    painter.translate((size.width() - canvas.width() * scale) / 2,
                      (size.height() - canvas.height() * scale) / 2);
    painter.scale(scale, scale);
    paintFrame(painter, frame, settings, options);
    return image;
}

} // namespace finbook::model
