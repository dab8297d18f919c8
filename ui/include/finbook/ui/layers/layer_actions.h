// LayerActions: the layer commands as QActions, for the Layer menu, the dope sheet's context
// menu and shortcuts. Each pushes one command (scene/layer_commands.h); the layer made or
// picked becomes current.
//
// objectName          default shortcut   what it does
// layer.new           Ctrl+Alt+N         new layer above the current one
// layer.duplicate                        copy of the current layer above it
// layer.delete                           deletes the current layer (not the last one)
// layer.moveUp        Ctrl+PgUp          moves the current layer one up (in front)
// layer.moveDown      Ctrl+PgDown        moves it one down (behind)
// layer.above         PgUp               makes the layer above current (Krita)
// layer.below         PgDown             makes the layer below current
// layer.visible                          shows or hides the current layer
// layer.locked                           locks or unlocks it (tools leave a locked layer alone)
// layer.properties                       name, opacity, depth, onion skin
// layer.insertTime                       one more tick at the playhead on the current layer
// layer.deleteTime                       one tick less at the playhead on the current layer
#pragma once

#include <QAction>
#include <QObject>

class QWidget;

namespace finbook::ui {

class EditorState;

class LayerActions : public QObject {
    Q_OBJECT
public:
    // `dialogParent` parents the properties dialog.
    LayerActions(EditorState *state, QWidget *dialogParent, QObject *parent = nullptr);

    QAction *action(const QString &objectName) const;
    // In menu order, with separator actions between the groups.
    QList<QAction *> menuActions() const { return m_menu; }

public slots:
    void editProperties();

private:
    QAction *makeAction(const QString &name, const QString &text);
    void addSeparator();
    void updateEnabled();
    void setFlag(bool locked, bool value);

    EditorState *m_state;
    QWidget *m_dialogParent;
    QList<QAction *> m_menu;
};

} // namespace finbook::ui
