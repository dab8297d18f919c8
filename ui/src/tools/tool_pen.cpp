#include <finbook/model/render.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/tools/stroke_editing.h>
#include <finbook/ui/tools/tool_pen.h>
#include <finbook/ui/window/editor_state.h>

#include <QKeyEvent>
#include <QPainter>
#include <QPen>

#include <algorithm>
#include <cmath>

namespace finbook::ui {

namespace {
void dropRepeats(std::vector<model::StrokePoint> &points)
{
    points.erase(std::unique(points.begin(), points.end(),
                             [](const model::StrokePoint &a, const model::StrokePoint &b) {
                                 return a.x == b.x && a.y == b.y;
                             }),
                 points.end());
}
} // namespace

PenTool::PenTool(QObject *parent)
    : CanvasTool(parent)
{}

QIcon PenTool::icon() const
{
    return QIcon::fromTheme(QStringLiteral("draw-freehand"),
                            QIcon(QStringLiteral(":/icons/tool_pen.svg")));
}

void PenTool::setSettings(const PenSettings &settings)
{
    PenSettings s = settings;
    s.width = std::isfinite(s.width) ? std::clamp(s.width, kMinWidth, kMaxWidth) : 3.0;
    s.smoothing = std::clamp(s.smoothing, 0, kMaxSmoothing);
    s.stabiliser = std::clamp(s.stabiliser, 0, kMaxStabiliser);
    if (!s.color.isValid())
        s.color = Qt::black;
    if (s == m_settings)
        return;
    m_settings = s;
    emit settingsChanged(m_settings);
}

void PenTool::press(const ToolEvent &event)
{
    if (const QString problem = StrokeEditing::targetProblem(*state()); !problem.isEmpty()) {
        canvas()->postMessage(problem);
        return;
    }
    const auto first = sampleOf(event);
    if (!first)
        return;
    m_drawing = true;
    m_points.clear();
    m_string = LazyString(stabiliserLength(m_settings.stabiliser, canvas()->zoom()));
    m_string.start(*first);
    m_cursor = *first;
    m_points.push_back(*first);
    canvas()->updateCanvasRect(lastSegmentRect());
}

void PenTool::move(const ToolEvent &event)
{
    if (!m_drawing)
        return;
    const auto cursor = sampleOf(event);
    if (!cursor)
        return;
    const QRectF before = stringRect();
    m_cursor = *cursor;
    const std::size_t count = m_points.size();
    if (const auto ink = m_string.follow(*cursor))
        append(*ink);
    QRectF dirty = m_points.size() != count ? lastSegmentRect() : QRectF();
    if (m_string.length() > 0) // the string from the ink to the pen moves too
        dirty = dirty.united(before).united(stringRect());
    if (!dirty.isEmpty())
        canvas()->updateCanvasRect(dirty);
}

void PenTool::release(const ToolEvent &event)
{
    if (!m_drawing)
        return;
    if (const auto last = sampleOf(event)) {
        if (m_string.length() > 0) {
            // The ink catches up: the stroke ends exactly where the pen lifted.
            const model::StrokePoint end = m_string.finish(*last);
            const model::StrokePoint &tail = m_points.back();
            if (m_points.size() > 1 && std::hypot(tail.x - end.x, tail.y - end.y) < minStep())
                m_points.back() = end;
            else
                m_points.push_back(end);
        } else {
            append(*last);
        }
    }
    m_drawing = false;
    std::vector<model::StrokePoint> points =
        finishedPoints(std::move(m_points), m_settings.smoothing);
    m_points.clear();
    canvas()->updateCanvasRect();
    if (points.empty())
        return;
    auto data = std::make_shared<model::StrokeData>();
    data->points = std::move(points);
    data->color = m_settings.color.rgba();
    data->width = float(m_settings.width);
    QString problem;
    if (!StrokeEditing::addStrokes(*state(), {data}, tr("Draw Stroke"), &problem))
        canvas()->postMessage(problem);
}

void PenTool::deactivate()
{
    cancel();
}

bool PenTool::keyPress(QKeyEvent *event)
{
    if (event->key() == Qt::Key_Escape && m_drawing) {
        cancel();
        return true;
    }
    return false;
}

void PenTool::cancel()
{
    if (!m_drawing)
        return;
    m_drawing = false;
    m_points.clear();
    if (canvas())
        canvas()->updateCanvasRect();
}

std::optional<model::StrokePoint> PenTool::sampleOf(const ToolEvent &event) const
{
    const float x = float(event.pos.x()), y = float(event.pos.y());
    // A mouse has no pressure: draw it at full width. Non-finite input is dropped here so it
    // never reaches the document.
    const float p = event.tablet && m_settings.pressure ? float(event.pressure) : 1.0f;
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(p))
        return std::nullopt;
    return model::StrokePoint{x, y, std::clamp(p, 0.0f, 1.0f)};
}

float PenTool::minStep() const
{
    // Samples closer than half a screen pixel add nothing visible but cost memory and time.
    return float(0.5 / std::max(canvas()->zoom(), 1e-6));
}

void PenTool::append(const model::StrokePoint &point)
{
    if (!m_points.empty()) {
        const model::StrokePoint &last = m_points.back();
        if (std::hypot(last.x - point.x, last.y - point.y) < minStep())
            return;
    }
    m_points.push_back(point);
}

QRectF PenTool::stringRect() const
{
    if (m_string.length() <= 0 || !m_drawing)
        return {};
    const model::StrokePoint &ink = m_string.ink();
    const qreal pad = 8.0 / std::max(canvas()->zoom(), 1e-6);
    return QRectF(QPointF(ink.x, ink.y), QPointF(m_cursor.x, m_cursor.y))
        .normalized()
        .adjusted(-pad, -pad, pad, pad);
}

QRectF PenTool::lastSegmentRect() const
{
    if (m_points.empty())
        return {};
    const model::StrokePoint &a = m_points.back();
    const model::StrokePoint &b = m_points.size() > 1 ? m_points[m_points.size() - 2] : a;
    const qreal pad = m_settings.width / 2 + 2;
    return QRectF(QPointF(a.x, a.y), QPointF(b.x, b.y)).normalized().adjusted(-pad, -pad, pad, pad);
}

std::vector<model::StrokePoint> PenTool::finishedPoints(std::vector<model::StrokePoint> points,
                                                        int smoothing)
{
    std::erase_if(points, [](const model::StrokePoint &p) {
        return !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.pressure);
    });
    // Repeats go before smoothing (they would weigh a spot twice) and after (smoothing can
    // pull neighbours onto one spot).
    dropRepeats(points);
    // A 1-2-1 filter per pass; the ends stay where the pen touched down and lifted.
    for (int pass = 0; pass < smoothing && points.size() > 2; ++pass) {
        std::vector<model::StrokePoint> next = points;
        for (std::size_t i = 1; i + 1 < points.size(); ++i) {
            next[i].x = (points[i - 1].x + 2 * points[i].x + points[i + 1].x) / 4;
            next[i].y = (points[i - 1].y + 2 * points[i].y + points[i + 1].y) / 4;
            next[i].pressure =
                (points[i - 1].pressure + 2 * points[i].pressure + points[i + 1].pressure) / 4;
        }
        points = std::move(next);
    }
    dropRepeats(points);
    return points;
}

void PenTool::paintOverlay(QPainter &painter, const QTransform &canvasToWidget)
{
    if (!m_drawing || m_points.empty())
        return;
    painter.save();
    painter.setTransform(canvasToWidget, true);
    model::paintStroke(painter, m_points, m_settings.color.rgba(), float(m_settings.width));
    painter.restore();
    if (m_string.length() <= 0)
        return;
    // The stabiliser's string: a thin line from the ink to the pen, and a ring at the pen.
    const QPointF ink = canvasToWidget.map(QPointF(m_string.ink().x, m_string.ink().y));
    const QPointF pen = canvasToWidget.map(QPointF(m_cursor.x, m_cursor.y));
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(QPen(QColor(120, 120, 120, 200), 1.0, Qt::DashLine));
    painter.drawLine(ink, pen);
    painter.setPen(QPen(QColor(120, 120, 120, 220), 1.0));
    painter.setBrush(Qt::NoBrush);
    painter.drawEllipse(pen, 3.0, 3.0);
    painter.restore();
}

} // namespace finbook::ui
