#include "timeline_delegate.h"

#include <finbook/ui/timeline/thumbnail_cache.h>
#include <finbook/ui/timeline/timeline_view.h>
#include <finbook/ui/window/editor_state.h>

#include <QApplication>
#include <QHelpEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QScrollBar>
#include <QToolTip>

#include <algorithm>
#include <cmath>

namespace finbook::ui {

TimelineView::TimelineView(EditorState *state, model::FrameListModel *model,
                           ThumbnailCache *thumbnails, QWidget *parent)
    : QListView(parent)
    , m_state(state)
    , m_model(model)
    , m_thumbnails(thumbnails)
{
    setFlow(QListView::LeftToRight);
    setWrapping(false);
    setUniformItemSizes(true);
    setSpacing(1);
    setHorizontalScrollMode(QAbstractItemView::ScrollPerPixel);
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    // Always on, so the cells never resize when the strip starts or stops overflowing.
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOn);
    setSelectionMode(QAbstractItemView::NoSelection);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setDragEnabled(false);
    setFocusPolicy(Qt::StrongFocus);
    setItemDelegate(new TimelineDelegate(this));
    setModel(model);
    // The pointer says what a drag does where it is: scrub on the numbers, reorder on a picture.
    setMouseTracking(true);
    // Rows added under the frames (the sound row) and a short dock never squeeze the
    // thumbnails below a readable size: the dock grows instead.
    setMinimumHeight(kMinimumCellHeight + 2 * spacing() + 2 * frameWidth() +
                     horizontalScrollBar()->sizeHint().height());

    m_thumbnails->setVisibilityFilter([this](model::Id id) { return isFrameVisible(id); });
    connect(m_thumbnails, &ThumbnailCache::thumbnailRendered, this, [this](model::Id id) {
        const int row = m_model->rowOfFrame(id);
        if (row >= 0)
            update(m_model->index(row));
    });
    connect(m_thumbnails, &ThumbnailCache::thumbnailsInvalidated, viewport(),
            qOverload<>(&QWidget::update));
    connect(m_state, &EditorState::currentFrameChanged, this, &TimelineView::followCurrentFrame);
    connect(m_state, &EditorState::frameSelectionChanged, viewport(),
            qOverload<>(&QWidget::update));
    connect(m_model->document(), &model::Document::settingsChanged, this,
            &TimelineView::updateCellSize);
    m_shownCurrent = m_state->currentFrameIndex();
}

bool TimelineView::isFrameVisible(model::Id frameId) const
{
    if (!isVisible())
        return false;
    const int row = m_model->rowOfFrame(frameId);
    return row >= 0 && visualRect(m_model->index(row)).intersects(viewport()->rect());
}

QRect TimelineView::bandRect(int row) const
{
    const QRect cell = visualRect(m_model->index(row));
    return cell.isValid() ? QRect(cell.left(), cell.top(), cell.width(), kBandHeight) : QRect();
}

QRect TimelineView::thumbnailRect(int row) const
{
    const QRect cell = visualRect(m_model->index(row));
    if (!cell.isValid())
        return {};
    return cell.adjusted(kPadding, kBandHeight + kPadding, -kPadding, -kPadding);
}

std::vector<int> TimelineView::visibleRows() const
{
    std::vector<int> rows;
    const QRect area = viewport()->rect();
    const int first = rowAtX(area.left());
    for (int row = std::max(0, first); row < m_model->rowCount(); ++row) {
        const QRect cell = visualRect(m_model->index(row));
        if (cell.left() > area.right())
            break;
        if (cell.intersects(area))
            rows.push_back(row);
    }
    return rows;
}

void TimelineView::updateCellSize()
{
    const int height = std::max(kMinimumCellHeight, viewport()->height() - 2 * spacing());
    const QSize canvas = m_model->document()->settings().canvasSize;
    const double aspect =
        std::clamp(double(canvas.width()) / std::max(1, canvas.height()), 0.25, 4.0);
    const int thumbHeight = height - kBandHeight - 2 * kPadding;
    const int thumbWidth = std::clamp(int(std::lround(thumbHeight * aspect)), 24, 240);
    const QSize cell(thumbWidth + 2 * kPadding, height);
    m_thumbnails->setThumbnailSize(QSize(thumbWidth, thumbHeight), devicePixelRatioF());
    if (cell == m_cell)
        return;
    m_cell = cell;
    scheduleDelayedItemsLayout();
}

void TimelineView::resizeEvent(QResizeEvent *event)
{
    QListView::resizeEvent(event);
    updateCellSize();
}

int TimelineView::rowAtX(int x) const
{
    const int count = m_model->rowCount();
    if (count == 0)
        return -1;
    const int y = spacing() + m_cell.height() / 2;
    if (const QModelIndex at = indexAt(QPoint(x, y)); at.isValid())
        return at.row();
    if (x < visualRect(m_model->index(0)).left())
        return 0;
    if (x > visualRect(m_model->index(count - 1)).right())
        return count - 1;
    // In the spacing between two cells: the one on the left.
    const QModelIndex left = indexAt(QPoint(x - 2 * spacing() - 1, y));
    return left.isValid() ? left.row() : 0;
}

int TimelineView::slotAtX(int x) const
{
    const int row = rowAtX(x);
    if (row < 0)
        return 0;
    const QRect cell = visualRect(m_model->index(row));
    return x < cell.center().x() ? row : row + 1;
}

void TimelineView::followCurrentFrame(int row)
{
    if (m_shownCurrent >= 0 && m_shownCurrent < m_model->rowCount())
        update(m_model->index(m_shownCurrent));
    m_shownCurrent = row;
    // After the model has caught up with the edit that moved the current frame.
    QMetaObject::invokeMethod(
        this,
        [this] {
            const QModelIndex current = m_model->index(m_state->currentFrameIndex());
            if (!current.isValid())
                return;
            update(current);
            if (m_mode != Mode::Reorder)
                scrollTo(current, QAbstractItemView::EnsureVisible);
        },
        Qt::QueuedConnection);
}

void TimelineView::autoScroll(int x)
{
    const int margin = std::max(8, m_cell.width() / 3);
    const int step = std::max(4, m_cell.width() / 4);
    QScrollBar *bar = horizontalScrollBar();
    if (x < margin)
        bar->setValue(bar->value() - step);
    else if (x > viewport()->width() - margin)
        bar->setValue(bar->value() + step);
}

void TimelineView::mousePressEvent(QMouseEvent *event)
{
    const QPoint pos = event->position().toPoint();
    const QModelIndex at = indexAt(pos);
    setFocus(Qt::MouseFocusReason);
    if (event->button() == Qt::RightButton) {
        if (at.isValid())
            m_state->setCurrentFrameIndex(at.row());
        event->accept();
        return;
    }
    if (event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    if (at.isValid() && pickFrame(at.row(), event->modifiers())) {
        m_mode = Mode::None;
        event->accept();
        return;
    }
    m_state->setSelectedFrames({});
    if (onNumberBand(pos)) {
        m_mode = Mode::Scrub;
        m_state->setCurrentFrameIndex(rowAtX(pos.x()));
    } else {
        m_mode = Mode::Press;
        m_pressRow = at.row();
        m_pressPos = pos;
        m_state->setCurrentFrameIndex(at.row());
    }
    event->accept();
}

bool TimelineView::pickFrame(int row, Qt::KeyboardModifiers modifiers)
{
    const model::Document *doc = m_model->document();
    const auto idsOf = [doc](const std::vector<int> &rows) {
        std::vector<model::Id> ids;
        for (int r : rows)
            ids.push_back(doc->frameAt(r).id);
        return ids;
    };
    if (modifiers & Qt::ShiftModifier) {
        // A range from the current frame (the anchor) to the clicked one.
        const int anchor = std::max(0, m_state->currentFrameIndex());
        std::vector<int> rows;
        for (int r = std::min(anchor, row); r <= std::max(anchor, row); ++r)
            rows.push_back(r);
        m_state->setSelectedFrames(idsOf(rows));
        m_state->setCurrentFrameIndex(row);
        return true;
    }
    if (!(modifiers & Qt::ControlModifier))
        return false;
    std::vector<int> rows = m_state->selectedFrames();
    const auto it = std::find(rows.begin(), rows.end(), row);
    if (it == rows.end()) {
        rows.push_back(row);
        m_state->setSelectedFrames(idsOf(rows));
        m_state->setCurrentFrameIndex(row);
    } else if (rows.size() > 1) {
        rows.erase(it); // Ctrl-click on a picked frame drops it; the current frame stays picked
        m_state->setSelectedFrames(idsOf(rows));
        if (row == m_state->currentFrameIndex())
            m_state->setCurrentFrameIndex(rows.back());
    }
    return true;
}

void TimelineView::mouseDoubleClickEvent(QMouseEvent *event)
{
    mousePressEvent(event);
}

bool TimelineView::onNumberBand(const QPoint &pos) const
{
    const QModelIndex at = indexAt(pos);
    return !at.isValid() || pos.y() < visualRect(at).top() + kBandHeight;
}

bool TimelineView::viewportEvent(QEvent *event)
{
    if (event->type() == QEvent::ToolTip) {
        const QPoint pos = static_cast<QHelpEvent *>(event)->pos();
        if (indexAt(pos).isValid()) {
            QToolTip::showText(static_cast<QHelpEvent *>(event)->globalPos(),
                               onNumberBand(pos)
                                   ? tr("Drag along the frame numbers to scrub through the "
                                        "animation")
                                   : tr("Click to show this frame; drag the picture to move the "
                                        "frame elsewhere; Ctrl- or Shift-click to pick several"),
                               viewport());
            return true;
        }
    }
    return QListView::viewportEvent(event);
}

void TimelineView::mouseMoveEvent(QMouseEvent *event)
{
    const QPoint pos = event->position().toPoint();
    if (!(event->buttons() & Qt::LeftButton) || m_mode == Mode::None) {
        if (!(event->buttons() & Qt::LeftButton))
            viewport()->setCursor(!indexAt(pos).isValid() ? Qt::ArrowCursor
                                  : onNumberBand(pos)     ? Qt::SizeHorCursor
                                                          : Qt::OpenHandCursor);
        event->ignore();
        return;
    }
    if (m_mode == Mode::Press &&
        (pos - m_pressPos).manhattanLength() >= QApplication::startDragDistance())
        m_mode = Mode::Reorder;
    if (m_mode == Mode::Scrub) {
        autoScroll(pos.x());
        m_state->setCurrentFrameIndex(rowAtX(pos.x()));
    } else if (m_mode == Mode::Reorder) {
        autoScroll(pos.x());
        m_dropSlot = slotAtX(pos.x());
        viewport()->update();
    }
    event->accept();
}

void TimelineView::mouseReleaseEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    const bool reorder = m_mode == Mode::Reorder;
    const int from = m_pressRow;
    const int slot = slotAtX(event->position().toPoint().x());
    m_mode = Mode::None;
    m_pressRow = -1;
    m_dropSlot = -1;
    viewport()->update();
    // One MoveFrameCommand through the model; a release where it was picked up is a no-op.
    if (reorder && from >= 0)
        m_model->moveRows({}, from, 1, {}, slot);
    event->accept();
}

void TimelineView::keyPressEvent(QKeyEvent *event)
{
    const int last = m_model->rowCount() - 1;
    switch (event->key()) {
    case Qt::Key_Escape:
        if (m_mode == Mode::Reorder) {
            m_mode = Mode::None;
            m_dropSlot = -1;
            viewport()->update();
        }
        break;
    case Qt::Key_Left:
        m_state->previousFrame();
        break;
    case Qt::Key_Right:
        m_state->nextFrame();
        break;
    case Qt::Key_Home:
        m_state->setCurrentFrameIndex(0);
        break;
    case Qt::Key_End:
        m_state->setCurrentFrameIndex(std::max(0, last));
        break;
    default:
        event->ignore(); // leave the rest to the window's shortcuts
        return;
    }
    event->accept();
}

void TimelineView::wheelEvent(QWheelEvent *event)
{
    // A plain mouse wheel scrolls the strip sideways.
    const QPoint delta = event->angleDelta();
    const int steps = std::abs(delta.x()) > std::abs(delta.y()) ? delta.x() : delta.y();
    QScrollBar *bar = horizontalScrollBar();
    bar->setValue(bar->value() - steps * m_cell.width() / 120);
    event->accept();
}

void TimelineView::contextMenuEvent(QContextMenuEvent *event)
{
    if (m_menuActions.isEmpty()) {
        event->ignore();
        return;
    }
    QMenu menu(this);
    menu.addActions(m_menuActions);
    menu.exec(event->globalPos());
}

void TimelineView::paintEvent(QPaintEvent *event)
{
    QListView::paintEvent(event);
    if (m_mode != Mode::Reorder || m_dropSlot < 0 || m_model->rowCount() == 0)
        return;
    QPainter painter(viewport());
    const QColor accent = palette().color(QPalette::Highlight);
    // Dim the frame being carried, and mark where it will land.
    painter.fillRect(visualRect(m_model->index(m_pressRow)), QColor(0, 0, 0, 70));
    const int count = m_model->rowCount();
    const int x = m_dropSlot < count ? visualRect(m_model->index(m_dropSlot)).left() - spacing()
                                     : visualRect(m_model->index(count - 1)).right() + spacing();
    painter.fillRect(QRect(x - 1, 0, 3, viewport()->height()), accent);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(Qt::NoPen);
    painter.setBrush(accent);
    const QPointF tip(x + 0.5, 7);
    painter.drawPolygon(QPolygonF({tip, tip + QPointF(-5, -7), tip + QPointF(6, -7)}));
}

} // namespace finbook::ui
