#include <finbook/ui/camera/bezier_editor.h>

#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace finbook::ui {

namespace {
constexpr double kLowest = -0.5, kHighest = 1.5; // the y range shown
constexpr double kMargin = 14.0;                 // px around the graph
constexpr double kGrab = 10.0;                   // px: how near a press grabs a handle

QPointF clamped(QPointF graph)
{
    return {std::clamp(graph.x(), 0.0, 1.0), std::clamp(graph.y(), kLowest, kHighest)};
}
} // namespace

BezierEditor::BezierEditor(QWidget *parent)
    : QWidget(parent)
    , m_c{QPointF(0.25, 0.1), QPointF(0.25, 1.0)}
{
    setMinimumSize(180, 180);
    setObjectName(QStringLiteral("camera.bezierGraph"));
}

void BezierEditor::setControls(QPointF c1, QPointF c2)
{
    m_c[0] = clamped(c1);
    m_c[1] = clamped(c2);
    update();
    emit controlsChanged();
}

QRectF BezierEditor::graphRect() const
{
    // The unit square, centred, with room above and below it for overshoot.
    const double room = height() - 2 * kMargin;
    const double unit = std::max(1.0, std::min(width() - 2 * kMargin, room / (kHighest - kLowest)));
    const double left = (width() - unit) / 2.0;
    const double top =
        kMargin + (room - (kHighest - kLowest) * unit) / 2.0 + (kHighest - 1.0) * unit;
    return QRectF(left, top, unit, unit);
}

QPointF BezierEditor::toWidget(QPointF graph) const
{
    const QRectF r = graphRect();
    return {r.left() + graph.x() * r.width(), r.bottom() - graph.y() * r.height()};
}

QPointF BezierEditor::toGraph(QPointF widget) const
{
    const QRectF r = graphRect();
    if (r.width() <= 0 || r.height() <= 0)
        return {};
    return {(widget.x() - r.left()) / r.width(), (r.bottom() - widget.y()) / r.height()};
}

void BezierEditor::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing, true);
    p.fillRect(rect(), palette().base());
    const QRectF r = graphRect();
    p.setPen(QPen(palette().mid().color(), 1, Qt::DashLine));
    p.drawRect(r);
    p.drawLine(toWidget({0, 0}), toWidget({1, 1}));
    QPainterPath curve(toWidget({0, 0}));
    curve.cubicTo(toWidget(m_c[0]), toWidget(m_c[1]), toWidget({1, 1}));
    p.setPen(QPen(palette().text().color(), 2));
    p.drawPath(curve);
    p.setPen(QPen(QColor(230, 120, 20), 1.5));
    p.drawLine(toWidget({0, 0}), toWidget(m_c[0]));
    p.drawLine(toWidget({1, 1}), toWidget(m_c[1]));
    p.setBrush(QColor(230, 120, 20));
    for (const QPointF &c : m_c)
        p.drawEllipse(toWidget(c), 5.5, 5.5);
}

void BezierEditor::mousePressEvent(QMouseEvent *event)
{
    m_dragging = -1;
    double best = kGrab;
    for (int i = 0; i < 2; ++i)
        if (const double d = QLineF(toWidget(m_c[i]), event->position()).length(); d <= best) {
            best = d;
            m_dragging = i;
        }
}

void BezierEditor::mouseMoveEvent(QMouseEvent *event)
{
    if (m_dragging < 0)
        return;
    m_c[m_dragging] = clamped(toGraph(event->position()));
    update();
    emit controlsChanged();
}

void BezierEditor::mouseReleaseEvent(QMouseEvent *)
{
    m_dragging = -1;
}

BezierEditorDialog::BezierEditorDialog(QPointF c1, QPointF c2, QWidget *parent)
    : QDialog(parent)
    , m_editor(new BezierEditor(this))
{
    setWindowTitle(tr("Camera Easing Curve"));
    m_editor->setControls(c1, c2);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_editor, 1);
    // The usual easings as curves, to start from.
    auto *presets = new QHBoxLayout;
    const std::tuple<QString, QPointF, QPointF> kinds[] = {
        {tr("Ease"), {0.25, 0.1}, {0.25, 1.0}},
        {tr("Ease In"), {0.42, 0.0}, {1.0, 1.0}},
        {tr("Ease Out"), {0.0, 0.0}, {0.58, 1.0}},
        {tr("Ease In and Out"), {0.42, 0.0}, {0.58, 1.0}},
        {tr("Overshoot"), {0.34, 1.3}, {0.64, 1.0}},
    };
    for (const auto &[name, a, b] : kinds) {
        auto *button = new QPushButton(name, this);
        connect(button, &QPushButton::clicked, this,
                [this, a = a, b = b] { m_editor->setControls(a, b); });
        presets->addWidget(button);
    }
    layout->addLayout(presets);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

} // namespace finbook::ui
