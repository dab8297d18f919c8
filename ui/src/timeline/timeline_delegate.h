// Paints one timeline cell: number band, thumbnail (or a placeholder while it renders),
// hold badge "×n", play-range shading and the current-frame highlight.
#pragma once

#include <QStyledItemDelegate>

namespace finbook::ui {

class TimelineView;

class TimelineDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    explicit TimelineDelegate(TimelineView *view);

    void paint(QPainter *painter, const QStyleOptionViewItem &option,
               const QModelIndex &index) const override;
    QSize sizeHint(const QStyleOptionViewItem &option, const QModelIndex &index) const override;

private:
    void paintBand(QPainter *painter, const QRect &band, const QModelIndex &index,
                   bool current) const;
    void paintThumbnail(QPainter *painter, const QRect &area, const QModelIndex &index) const;
    void paintHold(QPainter *painter, const QRect &area, int hold) const;

    TimelineView *m_view;
};

} // namespace finbook::ui
