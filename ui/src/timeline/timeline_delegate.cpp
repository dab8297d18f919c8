#include "timeline_delegate.h"

#include <finbook/ui/timeline/thumbnail_cache.h>
#include <finbook/ui/timeline/timeline_view.h>
#include <finbook/ui/window/editor_state.h>

#include <QPainter>

#include <algorithm>

namespace finbook::ui {

using model::FrameListModel;

TimelineDelegate::TimelineDelegate(TimelineView *view)
    : QStyledItemDelegate(view)
    , m_view(view)
{}

QSize TimelineDelegate::sizeHint(const QStyleOptionViewItem &, const QModelIndex &) const
{
    return m_view->cellSize();
}

void TimelineDelegate::paint(QPainter *painter, const QStyleOptionViewItem &option,
                             const QModelIndex &index) const
{
    painter->save();
    const bool current = index.row() == m_view->editorState()->currentFrameIndex();
    // Frames picked together (Ctrl/Shift-click) show their number band highlighted too.
    const std::vector<int> picked = m_view->editorState()->selectedFrames();
    const bool selected =
        current ||
        (picked.size() > 1 && std::binary_search(picked.begin(), picked.end(), index.row()));
    const QRect cell = option.rect;
    const QPalette &palette = option.palette;
    painter->fillRect(cell, palette.color(QPalette::Button));
    const QRect band(cell.left(), cell.top(), cell.width(), TimelineView::kBandHeight);
    paintBand(painter, band, index, selected);
    const QRect area =
        cell.adjusted(TimelineView::kPadding, TimelineView::kBandHeight + TimelineView::kPadding,
                      -TimelineView::kPadding, -TimelineView::kPadding);
    paintThumbnail(painter, area, index);
    if (!index.data(FrameListModel::InPlayRangeRole).toBool())
        painter->fillRect(area, QColor(0, 0, 0, 90)); // outside the play range
    paintHold(painter, area, index.data(FrameListModel::HoldRole).toInt());
    // A grip at the picture's top left: the picture is what a drag moves (the numbers scrub).
    painter->setPen(Qt::NoPen);
    painter->setBrush(QColor(0, 0, 0, 110));
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 2; ++column)
            painter->drawRect(QRect(area.left() + 3 + 4 * column, area.top() + 3 + 4 * row, 2, 2));
    if (selected) {
        QPen pen(palette.color(QPalette::Highlight), current ? 2 : 1);
        pen.setJoinStyle(Qt::MiterJoin);
        painter->setPen(pen);
        painter->setBrush(Qt::NoBrush);
        painter->drawRect(QRectF(cell).adjusted(1, 1, -1, -1));
    }
    painter->restore();
}

void TimelineDelegate::paintBand(QPainter *painter, const QRect &band, const QModelIndex &index,
                                 bool current) const
{
    const QPalette &palette = m_view->palette();
    painter->fillRect(band,
                      current ? palette.color(QPalette::Highlight) : palette.color(QPalette::Mid));
    QFont font = m_view->font();
    font.setPixelSize(TimelineView::kBandHeight - 5);
    painter->setFont(font);
    painter->setPen(current ? palette.color(QPalette::HighlightedText)
                            : palette.color(QPalette::ButtonText));
    painter->drawText(band, Qt::AlignCenter,
                      QString::number(index.data(FrameListModel::FrameNumberRole).toInt()));
    if (index.data(FrameListModel::CameraKeyRole).toBool()) {
        // A camera key in this frame's ticks: a small diamond at the band's left, in the
        // camera's colour (the canvas draws its frame and path in it).
        const qreal r = (TimelineView::kBandHeight - 6) / 2.0;
        const QPointF c(band.left() + 4 + r, band.center().y() + 0.5);
        painter->save();
        painter->setRenderHint(QPainter::Antialiasing, true);
        painter->setPen(QPen(QColor(255, 255, 255, 180), 1));
        painter->setBrush(QColor(230, 120, 20));
        painter->drawPolygon(QPolygonF{c + QPointF(0, -r), c + QPointF(r, 0), c + QPointF(0, r),
                                       c + QPointF(-r, 0)});
        painter->restore();
    }
}

void TimelineDelegate::paintThumbnail(QPainter *painter, const QRect &area,
                                      const QModelIndex &index) const
{
    const auto frameId = model::Id(index.data(FrameListModel::FrameIdRole).toULongLong());
    const QPixmap pixmap = m_view->thumbnails()->thumbnail(frameId);
    if (pixmap.isNull()) {
        // Placeholder until the zero-timer has rendered it: the paper, faintly hatched.
        const QColor paper =
            QColor::fromRgba(m_view->frameModel()->document()->settings().background);
        painter->fillRect(area, paper);
        painter->fillRect(area, QBrush(QColor(0, 0, 0, 24), Qt::BDiagPattern));
        return;
    }
    const QSizeF size = pixmap.deviceIndependentSize();
    const QPointF at(area.left() + (area.width() - size.width()) / 2,
                     area.top() + (area.height() - size.height()) / 2);
    painter->drawPixmap(at, pixmap);
}

void TimelineDelegate::paintHold(QPainter *painter, const QRect &area, int hold) const
{
    if (hold <= 1)
        return;
    QFont font = m_view->font();
    font.setPixelSize(11);
    font.setBold(true);
    painter->setFont(font);
    const QString text = QStringLiteral("\u00d7%1").arg(hold);
    const int width = painter->fontMetrics().horizontalAdvance(text) + 6;
    const QRect badge(area.right() - width - 1, area.bottom() - 15, width, 15);
    painter->setRenderHint(QPainter::Antialiasing, true);
    painter->setPen(Qt::NoPen);
    painter->setBrush(QColor(30, 30, 30, 200));
    painter->drawRoundedRect(badge, 3, 3);
    painter->setPen(Qt::white);
    painter->drawText(badge, Qt::AlignCenter, text);
}

} // namespace finbook::ui
