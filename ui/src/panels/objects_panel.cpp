#include "objects_panel_delegate.h"

#include <finbook/model/object_list_model.h>
#include <finbook/ui/panels/object_actions.h>
#include <finbook/ui/panels/objects_panel.h>
#include <finbook/ui/window/editor_state.h>

#include <QHBoxLayout>
#include <QListView>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

namespace finbook::ui {

void ObjectsPanel::addFooter(QWidget *footer)
{
    footer->setParent(this);
    static_cast<QVBoxLayout *>(layout())->addWidget(footer);
}

ObjectsPanel::ObjectsPanel(EditorState *state, ObjectActions *actions, QWidget *parent)
    : QWidget(parent)
    , m_state(state)
    , m_actions(actions)
    , m_model(new model::ObjectListModel(state->document(), this))

    , m_view(new QListView(this))
{
    setObjectName(QStringLiteral("objects"));
    m_view->setObjectName(QStringLiteral("objects.view"));
    // Plain buttons rather than a QToolBar: they never fold into an overflow menu. Two rows:
    // in one, "Move To" ran past the dock's edge at the default window size (German and
    // French labels are longer still).
    auto *buttons = new QVBoxLayout;
    buttons->setContentsMargins(2, 2, 2, 2);
    buttons->setSpacing(0);
    const std::initializer_list<QAction *> rows[] = {
        {actions->newObject(), actions->remove(), actions->raise(), actions->lower()},
        {actions->merge(), actions->moveSelection()}};
    for (const auto &row : rows) {
        auto *line = new QHBoxLayout;
        line->setSpacing(0);
        for (QAction *action : row) {
            auto *button = new QToolButton(this);
            button->setObjectName(action->objectName() + QStringLiteral(".button"));
            button->setDefaultAction(action);
            button->setAutoRaise(true);
            line->addWidget(button);
        }
        line->addStretch(1);
        buttons->addLayout(line);
    }
    // The style draws a menu button's arrow over its text ("Move To" lost its last letters in
    // every language): give the arrow room of its own.
    QToolButton *move = button(actions->moveSelection());
    move->setPopupMode(QToolButton::InstantPopup);
    move->setMinimumWidth(
        move->sizeHint().width() +
        move->style()->pixelMetric(QStyle::PM_MenuButtonIndicator, nullptr, move));

    m_view->setModel(m_model);
    m_view->setItemDelegate(new ObjectsPanelDelegate(m_view));
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    m_view->setDragDropMode(QAbstractItemView::InternalMove);
    m_view->setDefaultDropAction(Qt::MoveAction);
    m_view->setDropIndicatorShown(true);
    m_view->setUniformItemSizes(true);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addLayout(buttons);
    layout->addWidget(m_view, 1);

    connect(m_state, &EditorState::currentFrameChanged, this, &ObjectsPanel::followFrame);
    connect(m_state, &EditorState::currentGroupChanged, this, &ObjectsPanel::selectCurrentGroup);
    for (auto signal : {&QAbstractItemModel::rowsInserted, &QAbstractItemModel::rowsRemoved})
        connect(m_model, signal, this, &ObjectsPanel::selectCurrentGroup);
    connect(m_model, &QAbstractItemModel::rowsMoved, this, &ObjectsPanel::selectCurrentGroup);
    connect(m_model, &QAbstractItemModel::modelReset, this, &ObjectsPanel::selectCurrentGroup);
    connect(m_view->selectionModel(), &QItemSelectionModel::currentChanged, this,
            &ObjectsPanel::viewCurrentChanged);
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &ObjectsPanel::viewSelectionChanged);
    followFrame();
}

QToolButton *ObjectsPanel::button(const QAction *action) const
{
    return findChild<QToolButton *>(action->objectName() + QStringLiteral(".button"),
                                    Qt::FindDirectChildrenOnly);
}

QRect ObjectsPanel::visibilityToggleRect(int row) const
{
    return ObjectsPanelDelegate::visibilityRect(m_view->visualRect(m_model->index(row)));
}

QRect ObjectsPanel::lockToggleRect(int row) const
{
    return ObjectsPanelDelegate::lockRect(m_view->visualRect(m_model->index(row)));
}

void ObjectsPanel::followFrame()
{
    m_model->setFrameId(m_state->currentFrameId());
    selectCurrentGroup();
}

void ObjectsPanel::selectCurrentGroup()
{
    const int row = m_model->rowOfGroup(m_state->currentGroupId());
    if (row < 0 || m_view->currentIndex().row() == row)
        return;
    m_syncing = true;
    m_view->selectionModel()->setCurrentIndex(m_model->index(row),
                                              QItemSelectionModel::ClearAndSelect);
    m_syncing = false;
}

void ObjectsPanel::viewCurrentChanged()
{
    if (m_syncing)
        return;
    const model::Id id = m_model->groupId(m_view->currentIndex().row());
    if (id != model::kNoId)
        m_state->setCurrentGroupId(id);
}

void ObjectsPanel::viewSelectionChanged()
{
    std::vector<model::Id> ids;
    for (const QModelIndex &index : m_view->selectionModel()->selectedRows())
        ids.push_back(m_model->groupId(index.row()));
    m_actions->setObjectSelection(std::move(ids));
}

} // namespace finbook::ui
