// SwapActions: drawing substitution (issue 49) as QActions for the Object menu, the objects
// panel's drawing picker and the timeline's cel menu. Each action is one undo step.
//
// objectName             default shortcut   what it does
// swap.makeSwappable     —                  the current object's drawing becomes the first of a
//                                           new set (NewSwapSetCommand)
// swap.mouthChart        —                  a new layer "Mouth" (one cel for the whole shot) whose
//                                           object shows a set of the nine mouth shapes, on the
//                                           current object's face (two thirds down its box) or
//                                           at the centre of the view
// swap.newDrawing        —                  an empty drawing in the current object's set, shown
// swap.duplicateDrawing  —                  a copy of the drawing shown, added and shown
// swap.renameDrawing     —                  renames the drawing shown
// swap.deleteDrawing     —                  removes the drawing shown from the set (frames that
//                                           showed it show its neighbour)
// swap.makeOwn           —                  the frame keeps what it shows as its own drawing
// swap.previous          [                  shows the set's previous drawing in this frame (the
//                                           current object's set, else the frame's topmost
//                                           swappable object's)
// swap.next              ]                  shows its next drawing
#pragma once

#include <finbook/model/types.h>

#include <QObject>

#include <functional>

class QAction;
class QMenu;
class QWidget;

namespace finbook::ui {

class EditorState;

class SwapActions : public QObject {
    Q_OBJECT
public:
    // `dialogParent` parents the rename dialog.
    SwapActions(EditorState *state, QWidget *dialogParent, QObject *parent = nullptr);
    ~SwapActions() override;

    QList<QAction *> menuActions() const { return m_menu; }
    QAction *action(const QString &objectName) const;
    // "Show Drawing": one checkable action per drawing of the set the current object (or else
    // the frame's topmost swappable object) shows, that one checked; rebuilt when it is about
    // to show. [ and ] step through the same set.
    QMenu *drawingMenu() const { return m_drawings; }
    // The same menu for object `groupId` (any frame): the timeline's cel menu.
    void fillDrawingMenu(QMenu *menu, model::Id groupId) const;
    // Where a new mouth chart goes (canvas pixels): the centre of the view.
    void setChartCentre(std::function<QPointF()> centre) { m_chartCentre = std::move(centre); }

    void makeSwappable();
    void addMouthChart();
    void addDrawing(bool copy);
    void renameDrawing();
    void deleteDrawing();
    void makeOwn();
    void step(int delta);
    void show(model::Id groupId, model::SwapLink drawing) const;
    void updateEnabled();
    // What [ and ] swap and lip sync keys: the current object, or else the frame's topmost
    // swappable one (kNoId when there is none).
    model::Id stepTarget() const;

signals:
    void message(const QString &text);

private:
    QAction *makeAction(const QString &name, const QString &text, const QKeySequence &shortcut);
    const model::SwapSet *currentSet() const;
    QString freshDrawingName(const model::SwapSet &set) const;

    EditorState *m_state;
    QWidget *m_dialogParent;
    QList<QAction *> m_menu;
    QMenu *m_drawings;
    std::function<QPointF()> m_chartCentre;
};

} // namespace finbook::ui
