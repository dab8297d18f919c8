// Paints an objects-panel row (name, stroke count, eye and lock toggles) and turns clicks on
// the toggles into VisibleRole / LockedRole edits of the model (which push commands).
#pragma once

#include <QStyledItemDelegate>

namespace finbook::ui {

class ObjectsPanelDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    using QStyledItemDelegate::QStyledItemDelegate;

    static constexpr int kToggleSize = 20;
    static QRect visibilityRect(const QRect &row);
    static QRect lockRect(const QRect &row);

    void paint(QPainter *painter, const QStyleOptionViewItem &option,
               const QModelIndex &index) const override;
    QSize sizeHint(const QStyleOptionViewItem &option, const QModelIndex &index) const override;
    bool editorEvent(QEvent *event, QAbstractItemModel *model, const QStyleOptionViewItem &option,
                     const QModelIndex &index) override;
    void updateEditorGeometry(QWidget *editor, const QStyleOptionViewItem &option,
                              const QModelIndex &index) const override;

private:
    static void paintEye(QPainter *painter, const QRect &box, bool visible, const QColor &ink);
    static void paintLock(QPainter *painter, const QRect &box, bool locked, const QColor &ink);
};

} // namespace finbook::ui
