#include <finbook/model/commands.h>
#include <finbook/model/scene/layer_commands.h>
#include <finbook/model/scene/shot.h>
#include <finbook/ui/layers/layer_actions.h>
#include <finbook/ui/layers/layer_sheet.h>
#include <finbook/ui/window/editor_state.h>

#include <QContextMenuEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <utility>

namespace finbook::ui {

namespace {
constexpr int kEyeX = 6, kLockX = 24, kNameX = 44, kGlyph = 14;
constexpr int kGrip = 3; // pixels either side of a cel's end that grab its exposure
const QColor kCel(0xb8, 0xd0, 0xf0), kCurrentCel(0x70, 0xa0, 0xe8), kEmptyCel(0xe8, 0xe8, 0xe8);
} // namespace

LayerSheet::LayerSheet(EditorState *state, LayerActions *actions, QWidget *parent)
    : QWidget(parent)
    , m_state(state)
    , m_actions(actions)
{
    setObjectName(QStringLiteral("layerSheet"));
    setMouseTracking(true);
    model::Document *doc = state->document();
    const auto changed = [this] {
        relayout();
        update();
    };
    for (auto signal : {&model::Document::layersChanged, &model::Document::currentLayerChanged,
                        &model::Document::documentReset})
        connect(doc, signal, this, changed);
    connect(doc, &model::Document::celsChanged, this, changed);
    connect(doc, &model::Document::frameChanged, this, qOverload<>(&QWidget::update));
    connect(state, &EditorState::tickChanged, this, qOverload<>(&QWidget::update));
    connect(state, &EditorState::currentFrameChanged, this, qOverload<>(&QWidget::update));
    relayout();
}

QSize LayerSheet::sizeHint() const
{
    const qint64 ticks = model::shotTicks(m_state->document()->layers()) + 8;
    return {kHeaderWidth + int(std::min<qint64>(ticks * m_tickWidth, 1 << 22)),
            m_state->document()->layerCount() * kRowHeight + 1};
}

QSize LayerSheet::minimumSizeHint() const
{
    return {kHeaderWidth + 40, sizeHint().height()};
}

void LayerSheet::relayout()
{
    setMinimumSize(sizeHint());
    updateGeometry();
}

int LayerSheet::rowOfLayer(int layerIndex) const
{
    return m_state->document()->layerCount() - 1 - layerIndex;
}

QRect LayerSheet::rowRect(int layerIndex) const
{
    return {0, rowOfLayer(layerIndex) * kRowHeight, width(), kRowHeight};
}

int LayerSheet::layerAtY(int y) const
{
    const int row = y / kRowHeight;
    const int count = m_state->document()->layerCount();
    return y < 0 || row >= count ? -1 : count - 1 - row;
}

int LayerSheet::xOfTick(qint64 tick) const
{
    return kHeaderWidth + int(std::min<qint64>(tick * m_tickWidth, 1 << 24));
}

qint64 LayerSheet::tickAtX(int x) const
{
    return std::max<qint64>(0, (x - kHeaderWidth) / m_tickWidth);
}

int LayerSheet::celEndNear(int layerIndex, int x) const
{
    const model::Layer &layer = m_state->document()->layerAt(layerIndex);
    qint64 end = 0;
    for (std::size_t i = 0; i < layer.cels.size(); ++i) {
        end += std::clamp(layer.cels[i].hold, 1, model::kMaxHold);
        if (std::abs(xOfTick(end) - x) <= kGrip)
            return int(i);
    }
    return -1;
}

void LayerSheet::paintRow(QPainter &painter, int layerIndex) const
{
    const model::Document *doc = m_state->document();
    const model::Layer &layer = doc->layerAt(layerIndex);
    const QRect row = rowRect(layerIndex);
    const bool current = layerIndex == doc->currentLayerIndex();
    painter.fillRect(QRect(0, row.top(), kHeaderWidth, row.height()),
                     current ? palette().highlight() : palette().button());
    painter.setPen(current ? palette().highlightedText().color() : palette().buttonText().color());
    const int mid = row.center().y();
    // Eye: an open eye when shown, a dash when hidden; lock: a closed padlock when locked.
    const QRect eye(kEyeX, mid - kGlyph / 2, kGlyph, kGlyph);
    if (layer.properties.visible) {
        painter.drawEllipse(eye.adjusted(0, 3, 0, -3));
        painter.drawEllipse(eye.center(), 2, 2);
    } else {
        painter.drawLine(eye.left(), mid, eye.right(), mid);
    }
    const QRect lock(kLockX, mid - kGlyph / 2, kGlyph - 2, kGlyph);
    if (layer.properties.locked) {
        painter.drawRect(lock.adjusted(0, 6, 0, 0));
        painter.drawArc(lock.adjusted(2, 0, -2, -6), 0, 180 * 16);
    } else {
        painter.drawPoint(lock.center() + QPoint(0, 3));
    }
    const QRect name(kNameX, row.top(), kHeaderWidth - kNameX - 4, row.height());
    painter.drawText(
        name, Qt::AlignVCenter | Qt::AlignLeft,
        painter.fontMetrics().elidedText(layer.properties.name, Qt::ElideRight, name.width()));
    // Cels.
    const qint64 tick = m_state->currentTick();
    qint64 start = 0;
    for (std::size_t i = 0; i < layer.cels.size(); ++i) {
        const model::Frame &cel = layer.cels[i];
        const qint64 end = start + std::clamp(cel.hold, 1, model::kMaxHold);
        const int hold = m_drag == Drag::Exposure && cel.id == m_dragFrame ? m_dragHold : cel.hold;
        const QRect block(xOfTick(start), row.top() + 2, xOfTick(start + hold) - xOfTick(start) - 1,
                          row.height() - 4);
        const bool shown = tick >= start && tick < end;
        painter.fillRect(block, cel.groups.empty()   ? kEmptyCel
                                : (current && shown) ? kCurrentCel
                                                     : kCel);
        painter.setPen(QColor(0x50, 0x60, 0x70));
        painter.drawRect(block);
        if (!cel.groups.empty() && block.width() > 14)
            painter.drawText(block.adjusted(3, 0, 0, 0), Qt::AlignVCenter | Qt::AlignLeft,
                             QString::number(i + 1));
        start = end;
    }
    if (!layer.properties.visible || layer.properties.locked) // greyed
        painter.fillRect(QRect(kHeaderWidth, row.top(), width() - kHeaderWidth, row.height()),
                         QColor(128, 128, 128, layer.properties.visible ? 40 : 90));
}

void LayerSheet::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    painter.fillRect(rect(), palette().base());
    const model::Document *doc = m_state->document();
    for (int i = 0; i < doc->layerCount(); ++i)
        paintRow(painter, i);
    painter.setPen(palette().mid().color());
    for (int i = 0; i <= doc->layerCount(); ++i)
        painter.drawLine(0, i * kRowHeight, width(), i * kRowHeight);
    painter.drawLine(kHeaderWidth, 0, kHeaderWidth, height());
    // The playhead, over every row.
    const int x = xOfTick(m_state->currentTick()) + m_tickWidth / 2;
    painter.setPen(QPen(QColor(0xd0, 0x30, 0x30), 2));
    painter.drawLine(x, 0, x, doc->layerCount() * kRowHeight);
}

void LayerSheet::mousePressEvent(QMouseEvent *event)
{
    model::Document *doc = m_state->document();
    const int layerIndex = layerAtY(event->position().toPoint().y());
    if (event->button() != Qt::LeftButton || layerIndex < 0)
        return;
    const int x = event->position().toPoint().x();
    const model::Layer &layer = doc->layerAt(layerIndex);
    if (x < kHeaderWidth) {
        model::LayerProperties p = layer.properties;
        if (x >= kEyeX && x < kEyeX + kGlyph) {
            p.visible = !p.visible;
            doc->undoStack()->push(new model::SetLayerPropertiesCommand(
                doc, layer.id, p,
                p.visible ? LayerActions::tr("Show Layer") : LayerActions::tr("Hide Layer")));
        } else if (x >= kLockX && x < kLockX + kGlyph) {
            p.locked = !p.locked;
            doc->undoStack()->push(new model::SetLayerPropertiesCommand(
                doc, layer.id, p,
                p.locked ? LayerActions::tr("Lock Layer") : LayerActions::tr("Unlock Layer")));
        } else {
            doc->setCurrentLayer(layer.id);
        }
        return;
    }
    doc->setCurrentLayer(layer.id);
    if (const int cel = celEndNear(layerIndex, x); cel >= 0 && !layer.properties.locked) {
        m_drag = Drag::Exposure;
        m_dragFrame = layer.cels[std::size_t(cel)].id;
        m_dragStart = model::celStart(layer.cels, cel);
        m_dragHold = layer.cels[std::size_t(cel)].hold;
        return;
    }
    m_drag = Drag::Scrub;
    m_state->setCurrentTick(tickAtX(x));
}

void LayerSheet::mouseMoveEvent(QMouseEvent *event)
{
    const QPoint p = event->position().toPoint();
    if (m_drag == Drag::Scrub) {
        m_state->setCurrentTick(tickAtX(p.x()));
        return;
    }
    if (m_drag == Drag::Exposure) {
        const qint64 end = (p.x() - kHeaderWidth + m_tickWidth / 2) / m_tickWidth;
        m_dragHold = int(std::clamp<qint64>(end - m_dragStart, 1, model::kMaxHold));
        update();
        return;
    }
    const int layerIndex = layerAtY(p.y());
    setCursor(layerIndex >= 0 && p.x() >= kHeaderWidth && celEndNear(layerIndex, p.x()) >= 0
                  ? Qt::SizeHorCursor
                  : Qt::ArrowCursor);
}

void LayerSheet::mouseReleaseEvent(QMouseEvent *)
{
    const Drag was = std::exchange(m_drag, Drag::None);
    if (was != Drag::Exposure)
        return;
    model::Document *doc = m_state->document();
    if (const model::Frame *f = doc->frame(m_dragFrame); f && f->hold != m_dragHold)
        doc->undoStack()->push(new model::SetFrameHoldCommand(doc, m_dragFrame, m_dragHold));
    update();
}

void LayerSheet::mouseDoubleClickEvent(QMouseEvent *event)
{
    const int layerIndex = layerAtY(event->position().toPoint().y());
    if (layerIndex >= 0 && event->position().x() >= kNameX &&
        event->position().x() < kHeaderWidth) {
        m_state->document()->setCurrentLayer(m_state->document()->layerAt(layerIndex).id);
        m_actions->editProperties();
    }
}

void LayerSheet::contextMenuEvent(QContextMenuEvent *event)
{
    const int layerIndex = layerAtY(event->pos().y());
    if (layerIndex >= 0)
        m_state->document()->setCurrentLayer(m_state->document()->layerAt(layerIndex).id);
    QMenu menu(this);
    menu.addActions(m_actions->menuActions());
    menu.exec(event->globalPos());
}

void LayerSheet::wheelEvent(QWheelEvent *event)
{
    if (!(event->modifiers() & Qt::ControlModifier)) {
        event->ignore(); // the scroll area scrolls
        return;
    }
    const int step = event->angleDelta().y() > 0 ? 2 : -2;
    m_tickWidth = std::clamp(m_tickWidth + step, 4, 40);
    relayout();
    update();
    event->accept();
}

} // namespace finbook::ui
