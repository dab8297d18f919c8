#include <finbook/geometry/embedding.h>
#include <finbook/ui/inbetween/between_fit_view.h>

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <limits>

namespace finbook::ui {

namespace {
constexpr double kPickRadius = 8.0; // widget px
constexpr double kMargin = 10.0;    // widget px round the drawings
constexpr QRgb kParts[] = {0xffd62728, 0xff1f77b4, 0xff2ca02c, 0xffff7f0e,
                           0xff9467bd, 0xff8c564b, 0xffe377c2, 0xff17becf};

double segmentDistance2(QPointF p, QPointF a, QPointF b)
{
    const QPointF d = b - a;
    const double length2 = QPointF::dotProduct(d, d);
    const double s =
        length2 > 0.0 ? std::clamp(QPointF::dotProduct(p - a, d) / length2, 0.0, 1.0) : 0.0;
    const QPointF q = p - (a + s * d);
    return QPointF::dotProduct(q, q);
}
} // namespace

BetweenFitView::BetweenFitView(QWidget *parent)
    : QWidget(parent)
{
    setMinimumSize(240, 180);
    // Clicked, it takes the keyboard from the dialog's fields: Ctrl+Z then undoes the pins,
    // not the text of the spin box typed in last.
    setFocusPolicy(Qt::StrongFocus);
    setToolTip(tr("Drag from a line of the first drawing to where it belongs on the second to "
                  "pin it there; drag a pin to move it, right-click it to take it away."));
}

void BetweenFitView::setFit(std::shared_ptr<const model::DrawingFit> fit)
{
    m_fit = std::move(fit);
    m_fitted.resize(0, 2);
    m_bounds = QRectF();
    if (!m_fit) {
        m_part.clear();
        m_partsOf.reset();
        update();
        return;
    }
    if (m_dragged < 0)
        m_pins = m_fit->pins;
    m_fitted =
        geometry::applyEmbedding(m_fit->meshed->embedding, m_fit->fit.U, m_fit->meshed->mesh.F);
    const auto add = [&](QPointF p) { m_bounds = m_bounds.united(QRectF(p, QSizeF(0.01, 0.01))); };
    for (Eigen::Index r = 0; r < m_fitted.rows(); ++r)
        add(QPointF(m_fitted(r, 0), m_fitted(r, 1)));
    for (const model::Stroke &s : m_fit->b.strokes)
        if (s.data)
            for (const model::StrokePoint &p : s.data->points)
                add(QPointF(p.x, p.y));
    if (m_partsOf != m_fit->meshed) {
        m_partsOf = m_fit->meshed;
        m_part.clear();
        const auto &joints = m_fit->skeleton.joints;
        const auto &parent = m_fit->skeleton.parent;
        for (const model::Stroke &s : m_fit->a.strokes) {
            if (!s.data)
                continue;
            for (const model::StrokePoint &p : s.data->points) {
                int best = -1;
                double bestD = std::numeric_limits<double>::infinity();
                for (std::size_t j = 0; j < joints.size() && j < parent.size(); ++j) {
                    if (parent[j] < 0)
                        continue;
                    const auto &a = joints[std::size_t(parent[j])];
                    const auto &b = joints[j];
                    const double d = segmentDistance2(QPointF(p.x, p.y), QPointF(a.x(), a.y()),
                                                      QPointF(b.x(), b.y()));
                    if (d < bestD) {
                        bestD = d;
                        best = int(j);
                    }
                }
                m_part.push_back(best);
            }
        }
    }
    update();
}

void BetweenFitView::setPins(std::vector<model::BetweenPin> pins)
{
    m_pins = std::move(pins);
    update();
}

QPointF BetweenFitView::fittedPoint(std::size_t s, std::size_t k) const
{
    if (!m_fit || s + 1 >= m_fit->meshed->strokeOffsets.size())
        return {};
    const Eigen::Index r = Eigen::Index(m_fit->meshed->strokeOffsets[s] + k);
    return r < m_fitted.rows() ? QPointF(m_fitted(r, 0), m_fitted(r, 1)) : QPointF();
}

QTransform BetweenFitView::view() const
{
    const QRectF box = m_bounds.isEmpty() ? QRectF(0, 0, 1, 1) : m_bounds;
    const double scale = std::min((width() - 2 * kMargin) / std::max(box.width(), 1e-6),
                                  (height() - 2 * kMargin) / std::max(box.height(), 1e-6));
    QTransform t;
    t.translate(width() / 2.0, height() / 2.0);
    t.scale(scale, scale);
    t.translate(-box.center().x(), -box.center().y());
    return t;
}

QPointF BetweenFitView::toWidget(QPointF canvas) const
{
    return view().map(canvas);
}

QPointF BetweenFitView::toCanvas(QPointF widget) const
{
    return view().inverted().map(widget);
}

void BetweenFitView::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    painter.fillRect(rect(), Qt::white);
    painter.setRenderHint(QPainter::Antialiasing);
    if (!m_fit) {
        painter.setPen(palette().color(QPalette::PlaceholderText));
        painter.drawText(rect(), Qt::AlignCenter, tr("No drawing to fit"));
        return;
    }
    const QTransform t = view();
    const auto polyline = [&](const std::vector<QPointF> &points) {
        QPainterPath path;
        for (std::size_t i = 0; i < points.size(); ++i)
            i == 0 ? path.moveTo(t.map(points[i])) : path.lineTo(t.map(points[i]));
        return path;
    };
    painter.setPen(QPen(QColor(190, 190, 190), 5.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    for (const model::Stroke &s : m_fit->b.strokes) {
        if (!s.data || qAlpha(s.data->color) == 0)
            continue;
        std::vector<QPointF> points;
        for (const model::StrokePoint &p : s.data->points)
            points.emplace_back(p.x, p.y);
        painter.drawPath(polyline(points));
    }
    // The first drawing as fitted, a colour per part: runs of points of one part.
    std::size_t point = 0;
    for (std::size_t s = 0; s < m_fit->a.strokes.size(); ++s) {
        const model::Stroke &stroke = m_fit->a.strokes[s];
        if (!stroke.data)
            continue;
        const std::size_t n = stroke.data->points.size();
        const bool inked = qAlpha(stroke.data->color) != 0;
        std::size_t k = 0;
        while (k < n) {
            const int part = point + k < m_part.size() ? m_part[point + k] : -1;
            std::vector<QPointF> run{fittedPoint(s, k)};
            std::size_t e = k + 1;
            for (; e < n; ++e) {
                run.push_back(fittedPoint(s, e));
                if ((point + e < m_part.size() ? m_part[point + e] : -1) != part)
                    break;
            }
            if (inked) {
                const QColor colour =
                    part < 0 ? QColor(Qt::black)
                             : QColor::fromRgba(kParts[std::size_t(part) % std::size(kParts)]);
                painter.setPen(QPen(colour, 1.6, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
                painter.drawPath(polyline(run));
            }
            k = e == n ? n : e;
        }
        point += n;
    }
    // Pins: where the fit puts the pinned point (ring) and where it belongs (dot).
    for (const model::BetweenPin &pin : m_pins) {
        const QPointF to = t.map(pin.onB);
        painter.setPen(QPen(QColor(200, 0, 0), 1.5));
        painter.setBrush(QColor(230, 40, 40));
        painter.drawEllipse(to, 4.5, 4.5);
    }
}

std::optional<QPointF> BetweenFitView::pickLine(QPointF widget) const
{
    if (!m_fit)
        return std::nullopt;
    const QTransform t = view();
    double best = kPickRadius * kPickRadius;
    std::optional<QPointF> found;
    for (std::size_t s = 0; s < m_fit->a.strokes.size(); ++s) {
        const model::Stroke &stroke = m_fit->a.strokes[s];
        if (!stroke.data || qAlpha(stroke.data->color) == 0)
            continue;
        for (std::size_t k = 0; k < stroke.data->points.size(); ++k) {
            const QPointF d = t.map(fittedPoint(s, k)) - widget;
            const double d2 = QPointF::dotProduct(d, d);
            if (d2 <= best) {
                best = d2;
                found = QPointF(stroke.data->points[k].x, stroke.data->points[k].y);
            }
        }
    }
    return found;
}

int BetweenFitView::pickPin(QPointF widget) const
{
    const QTransform t = view();
    int found = -1;
    double best = kPickRadius * kPickRadius;
    for (std::size_t i = 0; i < m_pins.size(); ++i) {
        const QPointF d = t.map(m_pins[i].onB) - widget;
        const double d2 = QPointF::dotProduct(d, d);
        if (d2 <= best) {
            best = d2;
            found = int(i);
        }
    }
    return found;
}

void BetweenFitView::mousePressEvent(QMouseEvent *event)
{
    const QPointF at = event->position();
    const int pin = pickPin(at);
    if (event->button() == Qt::RightButton) {
        if (pin >= 0) {
            const std::vector<model::BetweenPin> before = m_pins;
            m_pins.erase(m_pins.begin() + pin);
            update();
            emit pinsChanged(before, m_pins);
        }
        return;
    }
    if (event->button() != Qt::LeftButton)
        return;
    m_before = m_pins;
    if (pin >= 0) {
        m_dragged = pin;
    } else if (const std::optional<QPointF> onA = pickLine(at)) {
        m_pins.push_back(model::BetweenPin{*onA, toCanvas(at)});
        m_dragged = int(m_pins.size()) - 1;
        update();
    }
}

void BetweenFitView::mouseMoveEvent(QMouseEvent *event)
{
    if (m_dragged < 0 || m_dragged >= int(m_pins.size()))
        return;
    m_pins[std::size_t(m_dragged)].onB = toCanvas(event->position());
    update();
    emit pinsDragged(m_pins);
}

void BetweenFitView::mouseReleaseEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton || m_dragged < 0)
        return;
    m_dragged = -1;
    if (m_pins != m_before)
        emit pinsChanged(m_before, m_pins);
}

} // namespace finbook::ui
