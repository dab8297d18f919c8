// ObjectActions: object (stroke group) commands of the current frame as QActions, for the
// editor's Object menu and the objects panel's tool bar. Each action is one undo step.
//
// objectName             default shortcut   what it does
// object.new             Ctrl+Shift+N       new empty object above the current one, made current
// object.delete          —                  deletes the current object (not the frame's last)
// object.merge           Ctrl+E             merges the objects selected in the panel into the
//                                           lowest of them, or the current object into the one
//                                           below it (MergeObjectsCommand; drawing order kept;
//                                           refused with a message when a picture would end
//                                           up under lines it was above)
// object.moveSelection   —                  submenu: moves the selected strokes to another
//                                           object of the frame (MoveStrokesCommand)
// object.raise           Ctrl+]             brings the current object one step forward
// object.lower           Ctrl+[             sends it one step back
// object.toggleVisible   —                  shows / hides the current object
// object.toggleLocked    —                  locks / unlocks the current object
#pragma once

#include <finbook/model/types.h>

#include <QAction>
#include <QObject>

#include <vector>

class QMenu;

namespace finbook::ui {

class EditorState;

class ObjectActions : public QObject {
    Q_OBJECT
public:
    explicit ObjectActions(EditorState *state, QObject *parent = nullptr);
    ~ObjectActions() override;

    QAction *newObject() const { return m_new; }
    QAction *remove() const { return m_remove; }
    QAction *merge() const { return m_merge; }
    QAction *moveSelection() const { return m_moveSelection; }
    QAction *raise() const { return m_raise; }
    QAction *lower() const { return m_lower; }
    QAction *toggleVisible() const { return m_toggleVisible; }
    QAction *toggleLocked() const { return m_toggleLocked; }
    QList<QAction *> menuActions() const { return m_menu; }
    // The submenu of moveSelection(): one action per other object of the frame, top first,
    // each carrying the object id as data. Rebuilt when it is about to show.
    QMenu *targetMenu() const { return m_targets; }
    void refreshTargets();

    // Objects selected in the panel (ids); two or more make object.merge merge them.
    void setObjectSelection(std::vector<model::Id> groupIds);
    const std::vector<model::Id> &objectSelection() const { return m_selection; }

    void addObject();
    void removeObject();
    void mergeObjects();
    void moveSelectionTo(model::Id targetGroupId);
    void reorder(int delta);
    void updateEnabled();

signals:
    // A sentence for the status bar: why an action did nothing (a merge refused).
    void message(const QString &text);

private:
    QAction *makeAction(const QString &name, const QString &text, const QKeySequence &shortcut);
    QString freshName() const;
    std::vector<model::Id> selectionInFrame() const;

    EditorState *m_state;
    std::vector<model::Id> m_selection;
    QList<QAction *> m_menu;
    QMenu *m_targets;
    QAction *m_new;
    QAction *m_remove;
    QAction *m_merge;
    QAction *m_moveSelection;
    QAction *m_raise;
    QAction *m_lower;
    QAction *m_toggleVisible;
    QAction *m_toggleLocked;
};

} // namespace finbook::ui
