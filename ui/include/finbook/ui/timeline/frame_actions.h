// FrameActions: the frame commands as QActions, for the Frame menu, the timeline's context
// menu and shortcuts. Every action pushes one command onto the document's undo stack and keeps
// the current frame on the frame the user is working with.
//
// objectName          default shortcut   what it does
// frame.insertBefore  Ctrl+F5            new empty frame before the current one, made current
// frame.insertAfter   F5                 new empty frame after the current one, made current
// frame.duplicate     F6                 copy of the current frame right after it, made current
// frame.inbetweens    Ctrl+Shift+F6      in-betweens between the first and last picked frames
//                                        (Ctrl/Shift-click in the timeline); asks for them
// frame.delete        Shift+F5           deletes the current frame (disabled on the last one)
// frame.moveLeft      Alt+Left           swaps the current frame with the one before
// frame.moveRight     Alt+Right          swaps the current frame with the one after
// frame.holdMore      Alt+=              holds the current frame one tick longer
// frame.holdLess      Alt+-              holds it one tick shorter (not below 1)
// frame.previous      ,                  previous frame
// frame.next          .                  next frame
// F5 / F6 / Shift+F5 follow Flash and Pencil2D; ',' and '.' follow Pencil2D and Krita.
#pragma once

#include <finbook/model/types.h>

#include <QAction>
#include <QObject>

namespace finbook::ui {

class EditorState;

class FrameActions : public QObject {
    Q_OBJECT
public:
    explicit FrameActions(EditorState *state, QObject *parent = nullptr);

    QAction *insertBefore() const { return m_insertBefore; }
    QAction *insertAfter() const { return m_insertAfter; }
    QAction *duplicate() const { return m_duplicate; }
    QAction *inbetweens() const { return m_inbetweens; }
    QAction *remove() const { return m_remove; }
    QAction *moveLeft() const { return m_moveLeft; }
    QAction *moveRight() const { return m_moveRight; }
    QAction *holdMore() const { return m_holdMore; }
    QAction *holdLess() const { return m_holdLess; }
    QAction *previous() const { return m_previous; }
    QAction *next() const { return m_next; }
    // Everything above in menu order, with separator actions between the groups.
    QList<QAction *> menuActions() const { return m_menu; }

signals:
    // frame.inbetweens was triggered for these keys (first before second in the document);
    // whoever owns a window opens the dialog.
    void inbetweensRequested(finbook::model::Id firstKey, finbook::model::Id secondKey);

private:
    QAction *makeAction(const QString &name, const QString &text, const QKeySequence &shortcut);
    void addSeparator();
    void insertFrame(int index);
    void duplicateFrame();
    void requestInbetweens();
    void removeFrame();
    void moveFrame(int delta);
    void changeHold(int delta);
    void updateEnabled();

    EditorState *m_state;
    QList<QAction *> m_menu;
    QAction *m_insertBefore;
    QAction *m_insertAfter;
    QAction *m_duplicate;
    QAction *m_inbetweens;
    QAction *m_remove;
    QAction *m_moveLeft;
    QAction *m_moveRight;
    QAction *m_holdMore;
    QAction *m_holdLess;
    QAction *m_previous;
    QAction *m_next;
};

} // namespace finbook::ui
