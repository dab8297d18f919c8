#include <finbook/model/commands.h>
#include <finbook/model/scene/layer_commands.h>
#include <finbook/model/scene/shot.h>
#include <finbook/ui/layers/layer_actions.h>
#include <finbook/ui/layers/layer_sheet.h>
#include <finbook/ui/timeline/thumbnail_cache.h>
#include <finbook/ui/window/editor_state.h>

#include <QApplication>
#include <QContextMenuEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <utility>

namespace finbook::ui {

namespace {
// A cel's label: the drawing its swappable object shows (the name's first word: "A" of
// "A (M B P)"), else its number.
QString celLabel(const model::Document &doc, const model::Frame &cel, int index)
{
    for (auto it = cel.groups.rbegin(); it != cel.groups.rend(); ++it)
        if (const model::SwapDrawing *d = doc.swapDrawing(it->swap); d && !d->name.isEmpty())
            return d->name.section(QLatin1Char(' '), 0, 0, QString::SectionSkipEmpty);
    return QString::number(index + 1);
}
} // namespace

namespace {
constexpr int kEyeX = 6, kLockX = 24, kNameX = 44, kGlyph = 14;
constexpr int kGrip = 3;  // pixels either side of a cel's end that grab its exposure
constexpr int kInset = 2; // a cel's block inside its row
const QColor kCel(0xb8, 0xd0, 0xf0), kCurrentCel(0x70, 0xa0, 0xe8), kEmptyCel(0xe8, 0xe8, 0xe8);
const QColor kPicked(0xf0, 0x90, 0x30), kDrop(0xd0, 0x30, 0x30);

// A cel that shows nothing: no object, or objects without a stroke yet (a new layer's cel, an
// inserted frame not drawn on) — drawn as an empty stretch.
bool showsNothing(const model::Frame &cel)
{
    return std::all_of(cel.groups.begin(), cel.groups.end(),
                       [](const model::StrokeGroup &g) { return !g.hasContent(); });
}
} // namespace

LayerSheet::LayerSheet(EditorState *state, LayerActions *actions, QWidget *parent)
    : QWidget(parent)
    , m_state(state)
    , m_actions(actions)
    , m_thumbnails(new ThumbnailCache(state->document(), this))
{
    setObjectName(QStringLiteral("layerSheet"));
    setMouseTracking(true);
    model::Document *doc = state->document();
    // The blocks show each cel's drawing on the page, whatever the camera does.
    m_thumbnails->setShowsShot(false);
    fitThumbnails();
    m_thumbnails->setCapacity(512);
    connect(m_thumbnails, &ThumbnailCache::thumbnailRendered, this, qOverload<>(&QWidget::update));
    connect(m_thumbnails, &ThumbnailCache::thumbnailsInvalidated, this,
            qOverload<>(&QWidget::update));
    const auto changed = [this] {
        relayout();
        update();
    };
    for (auto signal : {&model::Document::layersChanged, &model::Document::currentLayerChanged,
                        &model::Document::documentReset})
        connect(doc, signal, this, changed);
    connect(doc, &model::Document::celsChanged, this, changed);
    connect(doc, &model::Document::frameChanged, this, qOverload<>(&QWidget::update));
    connect(doc, &model::Document::settingsChanged, this, &LayerSheet::fitThumbnails);
    connect(state, &EditorState::tickChanged, this, qOverload<>(&QWidget::update));
    connect(state, &EditorState::currentFrameChanged, this, qOverload<>(&QWidget::update));
    connect(state, &EditorState::celSelectionChanged, this, qOverload<>(&QWidget::update));
    relayout();
}

void LayerSheet::fitThumbnails()
{
    // As tall as a block allows, as wide as the page's proportions make it (the cache keeps
    // its thumbnails when the size stays).
    const QSizeF page(m_state->document()->settings().canvasSize);
    const int height = kRowHeight - 2 * kInset - 2;
    m_thumbnails->setThumbnailSize(
        QSize(std::clamp(int(height * page.width() / std::max(1.0, page.height())), 8, 64), height),
        devicePixelRatioF());
}

QSize LayerSheet::sizeHint() const
{
    const qint64 ticks = model::shotTicks(m_state->document()->layers()) + 8;
    return {kHeaderWidth + int(std::min<qint64>(ticks * m_tickWidth, 1 << 22)),
            kRulerHeight + m_state->document()->layerCount() * kRowHeight + 1};
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
    return {0, kRulerHeight + rowOfLayer(layerIndex) * kRowHeight, width(), kRowHeight};
}

int LayerSheet::layerAtY(int y) const
{
    const int count = m_state->document()->layerCount();
    if (y < kRulerHeight)
        return -1;
    const int row = (y - kRulerHeight) / kRowHeight;
    return row >= count ? -1 : count - 1 - row;
}

int LayerSheet::nearestLayerAtY(int y) const
{
    const int count = m_state->document()->layerCount();
    return count - 1 - std::clamp((y - kRulerHeight) / kRowHeight, 0, count - 1);
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

int LayerSheet::celUnder(int layerIndex, int x) const
{
    if (x < kHeaderWidth)
        return -1;
    return model::celAt(m_state->document()->layerAt(layerIndex).cels, tickAtX(x));
}

bool LayerSheet::isPicked(model::Id cel) const
{
    const auto &picked = m_state->selectedCels();
    return std::find(picked.begin(), picked.end(), cel) != picked.end();
}

void LayerSheet::paintRuler(QPainter &painter) const
{
    const QRect ruler(kHeaderWidth, 0, width() - kHeaderWidth, kRulerHeight);
    painter.fillRect(QRect(0, 0, width(), kRulerHeight), palette().window());
    painter.setPen(palette().windowText().color());
    // A label every so many ticks that numbers do not touch; a short mark on every tick.
    const int every = m_tickWidth >= 24 ? 1 : m_tickWidth >= 12 ? 2 : m_tickWidth >= 6 ? 5 : 10;
    const qint64 last = tickAtX(width()) + 1;
    QFont small = painter.font();
    small.setPointSizeF(std::max(6.0, small.pointSizeF() * 0.8));
    painter.setFont(small);
    for (qint64 t = 0; t <= last; ++t) {
        const int x = xOfTick(t);
        const bool labelled = t % every == 0;
        painter.drawLine(x, kRulerHeight - (labelled ? 6 : 3), x, kRulerHeight - 1);
        if (labelled)
            painter.drawText(QRect(x + 2, 0, every * m_tickWidth, kRulerHeight - 4),
                             Qt::AlignLeft | Qt::AlignVCenter, QString::number(t + 1));
    }
    painter.setFont(font());
    painter.drawLine(ruler.left(), kRulerHeight - 1, ruler.right(), kRulerHeight - 1);
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
    // Cels: a block each, its drawing at its start and its number after it when there is room.
    const qint64 tick = m_state->currentTick();
    const int visibleLeft = kHeaderWidth, visibleRight = width();
    qint64 start = 0;
    for (std::size_t i = 0; i < layer.cels.size(); ++i) {
        const model::Frame &cel = layer.cels[i];
        const qint64 end = start + std::clamp(cel.hold, 1, model::kMaxHold);
        const int hold = m_drag == Drag::Exposure && cel.id == m_dragFrame ? m_dragHold : cel.hold;
        const QRect block(xOfTick(start), row.top() + kInset,
                          xOfTick(start + hold) - xOfTick(start) - 1, row.height() - 2 * kInset);
        const bool atPlayhead = tick >= start && tick < end;
        start = end;
        if (block.right() < visibleLeft || block.left() > visibleRight)
            continue;
        const bool blank = showsNothing(cel);
        painter.fillRect(block, blank ? kEmptyCel : (current && atPlayhead) ? kCurrentCel : kCel);
        int textLeft = block.left() + 3;
        // Only a block the drawing fits in asks for it (a thumbnail is rendered when asked).
        if (const QSize size = m_thumbnails->thumbnailSize();
            !blank && block.width() >= size.width() + 4) {
            const QRect at(block.left() + 2, block.top() + 1, size.width(), size.height());
            if (const QPixmap thumb = m_thumbnails->thumbnail(cel.id); !thumb.isNull())
                painter.drawPixmap(at, thumb);
            textLeft = at.right() + 3;
        }
        const bool picked = isPicked(cel.id);
        painter.setPen(picked ? QPen(kPicked, 2) : QPen(QColor(0x50, 0x60, 0x70)));
        painter.drawRect(picked ? block.adjusted(1, 1, 0, 0) : block);
        painter.setPen(QColor(0x20, 0x28, 0x30));
        if (!blank && block.right() - textLeft > 10)
            painter.drawText(QRect(textLeft, block.top(), block.right() - textLeft, block.height()),
                             Qt::AlignVCenter | Qt::AlignLeft, celLabel(*doc, cel, int(i)));
    }
    if (!layer.properties.visible || layer.properties.locked) // greyed
        painter.fillRect(QRect(kHeaderWidth, row.top(), width() - kHeaderWidth, row.height()),
                         QColor(128, 128, 128, layer.properties.visible ? 40 : 90));
}

void LayerSheet::paintCelDrop(QPainter &painter) const
{
    // Where the dragged cels go: a marker at the boundary in each row they land on, and their
    // outlines dashed at the mouse.
    const model::Document *doc = m_state->document();
    const auto &picked = m_state->selectedCels();
    painter.setPen(QPen(kDrop, 1, Qt::DashLine));
    for (int l = 0; l < doc->layerCount(); ++l) {
        const model::Layer &layer = doc->layerAt(l);
        if (layer.properties.locked)
            continue;
        const int to = l + m_dropRows;
        const bool lands = to >= 0 && to < doc->layerCount();
        qint64 first = -1, start = 0;
        for (const model::Frame &cel : layer.cels) {
            const qint64 end = start + std::clamp(cel.hold, 1, model::kMaxHold);
            if (isPicked(cel.id)) {
                first = first < 0 ? start : first;
                if (lands) {
                    const QRect row = rowRect(to);
                    painter.drawRect(QRect(xOfTick(start + m_dropTicks), row.top() + kInset,
                                           xOfTick(end) - xOfTick(start) - 1,
                                           row.height() - 2 * kInset));
                }
            }
            start = end;
        }
        if (first < 0 || !lands || doc->layerAt(to).properties.locked)
            continue;
        // The boundary they land at, among the cels that stay there (as the drop computes it).
        const qint64 at = model::celBoundaryStaying(doc->layerAt(to).cels,
                                                    m_dropCopy ? std::vector<model::Id>{} : picked,
                                                    first + m_dropTicks)
                              .tick;
        const QRect row = rowRect(to);
        painter.fillRect(QRect(xOfTick(at) - 1, row.top(), 3, row.height()), kDrop);
    }
}

void LayerSheet::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    painter.fillRect(rect(), palette().base());
    const model::Document *doc = m_state->document();
    paintRuler(painter);
    for (int i = 0; i < doc->layerCount(); ++i)
        paintRow(painter, i);
    painter.setPen(palette().mid().color());
    for (int i = 0; i <= doc->layerCount(); ++i)
        painter.drawLine(0, kRulerHeight + i * kRowHeight, width(), kRulerHeight + i * kRowHeight);
    painter.drawLine(kHeaderWidth, 0, kHeaderWidth, height());
    if (m_drag == Drag::Cels)
        paintCelDrop(painter);
    if (m_drag == Drag::Layer && m_layerDrop >= 0) {
        const QRect row = rowRect(m_layerDrop);
        painter.fillRect(QRect(0, row.top(), kHeaderWidth, row.height()),
                         QColor(kDrop.red(), kDrop.green(), kDrop.blue(), 60));
        painter.setPen(QPen(kDrop, 2));
        painter.drawRect(QRect(0, row.top(), kHeaderWidth, row.height()).adjusted(1, 1, -1, -1));
    }
    // The playhead, over the ruler and every row.
    const int x = xOfTick(m_state->currentTick()) + m_tickWidth / 2;
    painter.setPen(QPen(QColor(0xd0, 0x30, 0x30), 2));
    painter.drawLine(x, 0, x, kRulerHeight + doc->layerCount() * kRowHeight);
}

void LayerSheet::pressCel(int layerIndex, int cel, Qt::KeyboardModifiers modifiers)
{
    model::Document *doc = m_state->document();
    const model::Layer &layer = doc->layerAt(layerIndex);
    const model::Id id = layer.cels[std::size_t(cel)].id;
    std::vector<model::Id> picked = m_state->selectedCels();
    if (modifiers & Qt::ControlModifier) {
        // Ctrl on a picked cel drops it when the button comes up without a drag (a Ctrl-drag
        // copies the picked cels, this one with them).
        const auto at = std::find(picked.begin(), picked.end(), id);
        m_dropOnRelease = at != picked.end();
        if (!m_dropOnRelease)
            picked.push_back(id);
        m_anchor = id;
    } else if ((modifiers & Qt::ShiftModifier) && doc->frame(m_anchor)) {
        // Every cel from the anchor's to this one's layer that overlaps the ticks between them.
        const int anchorLayer = doc->layerIndex(doc->layerOfFrame(m_anchor));
        const std::vector<model::Frame> &anchorCels = doc->layerAt(anchorLayer).cels;
        const int anchorIndex = doc->celIndex(m_anchor);
        const qint64 from =
            std::min(model::celStart(anchorCels, anchorIndex), model::celStart(layer.cels, cel));
        const qint64 to = std::max(model::celStart(anchorCels, anchorIndex + 1),
                                   model::celStart(layer.cels, cel + 1));
        picked.clear();
        for (int l = std::min(anchorLayer, layerIndex); l <= std::max(anchorLayer, layerIndex);
             ++l) {
            qint64 start = 0;
            for (const model::Frame &c : doc->layerAt(l).cels) {
                const qint64 end = start + std::clamp(c.hold, 1, model::kMaxHold);
                if (start < to && end > from)
                    picked.push_back(c.id);
                start = end;
            }
        }
    } else {
        if (!isPicked(id)) // a picked cel stays picked with the others, to be dragged
            picked = {id};
        m_anchor = id;
    }
    m_state->setSelectedCels(std::move(picked));
}

void LayerSheet::mousePressEvent(QMouseEvent *event)
{
    model::Document *doc = m_state->document();
    const QPoint at = event->position().toPoint();
    if (event->button() != Qt::LeftButton)
        return;
    m_pressAt = at;
    const int x = at.x();
    if (at.y() < kRulerHeight) {
        if (x >= kHeaderWidth) {
            m_drag = Drag::Scrub;
            m_state->setCurrentTick(tickAtX(x));
        }
        return;
    }
    const int layerIndex = layerAtY(at.y());
    if (layerIndex < 0)
        return;
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
            m_drag = Drag::LayerPending;
            m_pressLayer = layerIndex;
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
    m_state->setCurrentTick(tickAtX(x));
    if (const int cel = celUnder(layerIndex, x); cel >= 0) {
        pressCel(layerIndex, cel, event->modifiers());
        m_dragFrame = layer.cels[std::size_t(cel)].id;
        m_pressLayer = layerIndex;
        m_pressTick = tickAtX(x);
        m_drag = layer.properties.locked ? Drag::None : Drag::CelsPending;
        return;
    }
    // Past the row's last cel: nothing picked, and a drag scrubs.
    m_state->setSelectedCels({});
    m_drag = Drag::Scrub;
}

void LayerSheet::mouseMoveEvent(QMouseEvent *event)
{
    const QPoint p = event->position().toPoint();
    const bool far = (p - m_pressAt).manhattanLength() >= QApplication::startDragDistance();
    switch (m_drag) {
    case Drag::Scrub:
        m_state->setCurrentTick(tickAtX(p.x()));
        return;
    case Drag::Exposure: {
        const qint64 end = (p.x() - kHeaderWidth + m_tickWidth / 2) / m_tickWidth;
        m_dragHold = int(std::clamp<qint64>(end - m_dragStart, 1, model::kMaxHold));
        update();
        return;
    }
    case Drag::CelsPending:
    case Drag::Cels: {
        if (m_drag == Drag::CelsPending && !far)
            return;
        m_drag = Drag::Cels;
        m_dropRows = nearestLayerAtY(p.y()) - m_pressLayer;
        m_dropTicks = (p.x() < kHeaderWidth ? 0 : tickAtX(p.x())) - m_pressTick;
        m_dropCopy = event->modifiers() & (Qt::AltModifier | Qt::ControlModifier);
        setCursor(m_dropCopy ? Qt::DragCopyCursor : Qt::DragMoveCursor);
        update();
        return;
    }
    case Drag::LayerPending:
    case Drag::Layer: {
        if (m_drag == Drag::LayerPending && !far)
            return;
        m_drag = Drag::Layer;
        m_layerDrop = nearestLayerAtY(p.y());
        setCursor(Qt::SizeVerCursor);
        update();
        return;
    }
    case Drag::None:
        break;
    }
    const int layerIndex = layerAtY(p.y());
    setCursor(layerIndex >= 0 && p.x() >= kHeaderWidth && celEndNear(layerIndex, p.x()) >= 0
                  ? Qt::SizeHorCursor
                  : Qt::ArrowCursor);
}

void LayerSheet::mouseReleaseEvent(QMouseEvent *event)
{
    const Drag was = std::exchange(m_drag, Drag::None);
    model::Document *doc = m_state->document();
    unsetCursor();
    switch (was) {
    case Drag::Exposure:
        if (const model::Frame *f = doc->frame(m_dragFrame); f && f->hold != m_dragHold)
            doc->undoStack()->push(new model::SetFrameHoldCommand(doc, m_dragFrame, m_dragHold));
        break;
    case Drag::CelsPending: // a click, no drag: on a picked cel, that cel alone
        if (m_dropOnRelease) {
            std::vector<model::Id> picked = m_state->selectedCels();
            picked.erase(std::remove(picked.begin(), picked.end(), m_dragFrame), picked.end());
            m_state->setSelectedCels(std::move(picked));
        } else if (!(event->modifiers() & (Qt::ControlModifier | Qt::ShiftModifier)) &&
                   doc->frame(m_dragFrame)) {
            m_state->setSelectedCels({m_dragFrame});
        }
        break;
    case Drag::Cels:
        m_dropCopy = event->modifiers() & (Qt::AltModifier | Qt::ControlModifier);
        if (auto command = model::rearrangeCelsCommand(doc, m_state->selectedCels(), m_dropRows,
                                                       m_dropTicks, m_dropCopy)) {
            doc->undoStack()->push(command.release());
            // The moved cels' layer (the one the drag began on) stays current.
            if (const model::Frame *f = doc->frame(m_dragFrame); f && !m_dropCopy)
                doc->setCurrentLayer(doc->layerOfFrame(m_dragFrame));
        }
        break;
    case Drag::Layer:
        if (m_pressLayer >= 0 && m_pressLayer < doc->layerCount() && m_layerDrop >= 0 &&
            m_layerDrop != m_pressLayer)
            doc->undoStack()->push(
                new model::MoveLayerCommand(doc, doc->layerAt(m_pressLayer).id, m_layerDrop));
        break;
    default:
        break;
    }
    m_layerDrop = -1;
    m_dropOnRelease = false;
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
    if (const int cel = layerIndex >= 0 ? celUnder(layerIndex, event->pos().x()) : -1;
        cel >= 0 && m_celMenu) {
        m_celMenu(&menu, m_state->document()->layerAt(layerIndex).cels[std::size_t(cel)].id);
        if (!menu.isEmpty())
            menu.addSeparator();
    }
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
