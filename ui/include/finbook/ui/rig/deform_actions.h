// The Deform menu: reset the current object's pose, apply (bake) it as the new drawing, and
// its mesh density. Also owns the DeformController the Pin tool and Show Mesh share.
#pragma once

#include <finbook/model/deform_controller.h>

#include <QAction>
#include <QObject>

class QDoubleSpinBox;
class QMenu;
class QWidget;

namespace finbook::ui {

class EditorState;

class DeformActions : public QObject {
    Q_OBJECT
public:
    explicit DeformActions(EditorState *state, QObject *parent = nullptr);

    model::DeformController *controller() { return &m_controller; }
    QAction *resetAction() const { return m_reset; }
    QAction *bakeAction() const { return m_bake; }
    QAction *removePinsAction() const { return m_removePins; }
    QList<QAction *> actions() const { return {m_reset, m_bake, m_removePins}; }
    // A spin box bound to the current object's mesh density (one undo step per edit).
    QDoubleSpinBox *createDensitySpinBox(QWidget *parent);
    // Extra rigidity passes after the paper's two steps; remembered across sessions.
    QMenu *createRigidityMenu(QWidget *parent);

signals:
    // Sentences for the status bar (deformation errors, busy state).
    void messagePosted(const QString &message);

private:
    void updateEnabled();

    EditorState *m_state;
    model::DeformController m_controller;
    QAction *m_reset;
    QAction *m_bake;
    QAction *m_removePins;
    int m_densitySerial = 0;
};

} // namespace finbook::ui
