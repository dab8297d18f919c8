// ObjectsPanel: the objects of the current frame, top object first like a layers panel.
//
// A row of buttons over the list holds the ObjectActions (new, delete, raise, lower, merge, move
// selection to…). In the list: click picks the current object (two-way with
// EditorState::currentGroupId), Ctrl/Shift-click selects several for merging, double-click
// renames, the eye and lock at the right of a row toggle visibility and lock, and dragging a
// row reorders (z-order). Every edit is a command on the document's undo stack.
#pragma once

#include <finbook/model/types.h>

#include <QWidget>

class QAction;
class QListView;
class QToolButton;

namespace finbook::model {
class ObjectListModel;
}

namespace finbook::ui {

class EditorState;
class ObjectActions;

class ObjectsPanel : public QWidget {
    Q_OBJECT
public:
    ObjectsPanel(EditorState *state, ObjectActions *actions, QWidget *parent = nullptr);

    QListView *view() const { return m_view; }
    // The tool-bar button of one of the ObjectActions (null if it has none).
    QToolButton *button(const QAction *action) const;
    model::ObjectListModel *objectModel() const { return m_model; }
    // Viewport rectangles of a row's visibility and lock toggles.
    QRect visibilityToggleRect(int row) const;
    QRect lockToggleRect(int row) const;

    // A widget under the list (the swap picker).
    void addFooter(QWidget *footer);

    QSize sizeHint() const override { return {280, 260}; }

private:
    void followFrame();
    void selectCurrentGroup();
    void viewCurrentChanged();
    void viewSelectionChanged();

    EditorState *m_state;
    ObjectActions *m_actions;
    model::ObjectListModel *m_model;
    QListView *m_view;
    bool m_syncing = false;
};

} // namespace finbook::ui
