#include "objects_panel_delegate.h"

#include <finbook/model/object_list_model.h>

#include <QApplication>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

namespace finbook::ui {

using model::ObjectListModel;

QRect ObjectsPanelDelegate::lockRect(const QRect &row)
{
    return QRect(row.right() - kToggleSize - 2, row.center().y() - kToggleSize / 2, kToggleSize,
                 kToggleSize);
}

QRect ObjectsPanelDelegate::visibilityRect(const QRect &row)
{
    return lockRect(row).translated(-kToggleSize - 2, 0);
}

QSize ObjectsPanelDelegate::sizeHint(const QStyleOptionViewItem &option,
                                     const QModelIndex &index) const
{
    const QSize base = QStyledItemDelegate::sizeHint(option, index);
    return {base.width() + 2 * kToggleSize + 8, std::max(base.height(), kToggleSize + 6)};
}

void ObjectsPanelDelegate::paint(QPainter *painter, const QStyleOptionViewItem &option,
                                 const QModelIndex &index) const
{
    QStyleOptionViewItem opt = option;
    initStyleOption(&opt, index);
    opt.features &= ~QStyleOptionViewItem::HasCheckIndicator; // the eye replaces the box
    const QString name = opt.text;
    opt.text.clear();
    const QWidget *widget = option.widget;
    QStyle *style = widget ? widget->style() : QApplication::style();
    style->drawControl(QStyle::CE_ItemViewItem, &opt, painter, widget);

    painter->save();
    const bool selected = opt.state & QStyle::State_Selected;
    const QColor ink = opt.palette.color(selected ? QPalette::HighlightedText : QPalette::Text);
    const bool visible = index.data(ObjectListModel::VisibleRole).toBool();
    const bool locked = index.data(ObjectListModel::LockedRole).toBool();
    QRect text = opt.rect.adjusted(6, 0, -(2 * kToggleSize + 10), 0);
    const QString count =
        QStringLiteral("%1").arg(index.data(ObjectListModel::StrokeCountRole).toInt());
    QColor faint = ink;
    faint.setAlphaF(0.55f);
    painter->setPen(faint);
    painter->drawText(text, Qt::AlignRight | Qt::AlignVCenter, count);
    text.adjust(0, 0, -(opt.fontMetrics.horizontalAdvance(count) + 6), 0);
    QFont font = opt.font;
    font.setItalic(!visible);
    painter->setFont(font);
    painter->setPen(visible ? ink : faint);
    painter->drawText(text, Qt::AlignLeft | Qt::AlignVCenter,
                      opt.fontMetrics.elidedText(name, Qt::ElideRight, text.width()));
    paintEye(painter, visibilityRect(opt.rect), visible, ink);
    paintLock(painter, lockRect(opt.rect), locked, ink);
    painter->restore();
}

void ObjectsPanelDelegate::paintEye(QPainter *painter, const QRect &box, bool visible,
                                    const QColor &ink)
{
    painter->setRenderHint(QPainter::Antialiasing, true);
    QColor color = ink;
    if (!visible)
        color.setAlphaF(0.35f);
    painter->setPen(QPen(color, 1.4));
    painter->setBrush(Qt::NoBrush);
    const QRectF r = QRectF(box).adjusted(3, 6, -3, -6);
    QPainterPath eye;
    eye.moveTo(r.left(), r.center().y());
    eye.quadTo(r.center().x(), r.top() - 4, r.right(), r.center().y());
    eye.quadTo(r.center().x(), r.bottom() + 4, r.left(), r.center().y());
    painter->drawPath(eye);
    painter->setBrush(color);
    painter->drawEllipse(r.center(), 2.2, 2.2);
    if (!visible)
        painter->drawLine(QPointF(box.left() + 4, box.bottom() - 4),
                          QPointF(box.right() - 4, box.top() + 4));
}

void ObjectsPanelDelegate::paintLock(QPainter *painter, const QRect &box, bool locked,
                                     const QColor &ink)
{
    painter->setRenderHint(QPainter::Antialiasing, true);
    QColor color = ink;
    if (!locked)
        color.setAlphaF(0.3f);
    painter->setPen(QPen(color, 1.4));
    const QRectF body(box.left() + 5, box.center().y() - 1, box.width() - 10, 7);
    const QRectF shackle(body.left() + 2, body.top() - 6, body.width() - 4, 10);
    painter->setBrush(Qt::NoBrush);
    // An open lock lifts its shackle.
    painter->drawArc(shackle.translated(0, locked ? 0 : -2), 0, 180 * 16);
    painter->setBrush(locked ? QBrush(color) : QBrush(Qt::NoBrush));
    painter->drawRoundedRect(body, 1.5, 1.5);
}

bool ObjectsPanelDelegate::editorEvent(QEvent *event, QAbstractItemModel *model,
                                       const QStyleOptionViewItem &option, const QModelIndex &index)
{
    const bool press =
        event->type() == QEvent::MouseButtonPress || event->type() == QEvent::MouseButtonDblClick;
    // The eye stands in for the check box, so no mouse event reaches the base class's one.
    if (!press && event->type() != QEvent::MouseButtonRelease)
        return false;
    const auto *mouse = static_cast<QMouseEvent *>(event);
    const QPoint pos = mouse->position().toPoint();
    int role = -1;
    if (visibilityRect(option.rect).contains(pos))
        role = ObjectListModel::VisibleRole;
    else if (lockRect(option.rect).contains(pos))
        role = ObjectListModel::LockedRole;
    if (role < 0 || mouse->button() != Qt::LeftButton)
        return false;
    // Toggle on release; swallow the press so the click does not also start a drag or rename.
    if (event->type() == QEvent::MouseButtonRelease)
        model->setData(index, !index.data(role).toBool(), role);
    return true;
}

void ObjectsPanelDelegate::updateEditorGeometry(QWidget *editor, const QStyleOptionViewItem &option,
                                                const QModelIndex &) const
{
    editor->setGeometry(option.rect.adjusted(2, 1, -(2 * kToggleSize + 8), -1));
}

} // namespace finbook::ui
