// ShortcutRegistry: every action with shortcuts, by objectName, with its defaults and the
// user's choice. An action may have several shortcuts (Redo: Ctrl+Shift+Z and Ctrl+Y); the
// first is its primary one, shown in menus and tooltips. Defaults come from the editor's
// shortcut map (defaultMap()), which overrides what an action was created with, so the whole
// editor stays conflict-free in one place. User choices persist in QSettings under
// "shortcuts/<objectName>" as a list of portable key sequences (only those that differ from
// the default; an empty list means "no shortcut").
#pragma once

#include <QAction>
#include <QHash>
#include <QKeySequence>
#include <QList>
#include <QMap>
#include <QObject>
#include <QPointer>

#include <vector>

class QSettings;

namespace finbook::ui {

using KeyList = QList<QKeySequence>;

class ShortcutRegistry : public QObject {
    Q_OBJECT
public:
    struct Conflict {
        QKeySequence keys;
        QStringList names; // objectNames sharing `keys`, sorted
    };

    explicit ShortcutRegistry(QObject *parent = nullptr);

    // The editor's default shortcuts by objectName (tools, files, edit, view, frames, playback).
    static const QHash<QString, KeyList> &defaultMap();

    // Adds an action (objectName required). Its defaults are defaultMap()'s entry if there is
    // one, else the shortcuts it carries now. A stored user choice is applied at once.
    void registerAction(QAction *action);
    QList<QAction *> actions() const; // in registration order
    QAction *action(const QString &name) const;

    KeyList defaultShortcuts(const QString &name) const;
    KeyList shortcuts(const QString &name) const;
    // The primary (first) shortcut, or an empty sequence.
    QKeySequence defaultShortcut(const QString &name) const;
    QKeySequence shortcut(const QString &name) const;
    // The current shortcuts of every registered action.
    QMap<QString, KeyList> currentMap() const;
    // Sets the shortcuts of the named actions (unknown names are kept for actions registered
    // later). Empty sequences and repeats in a list are dropped. Saved by save().
    void apply(const QMap<QString, KeyList> &shortcuts);
    // The same with one shortcut per action (replacing all of its shortcuts).
    void apply(const QMap<QString, QKeySequence> &shortcuts);
    void resetToDefaults();

    // Sequences used by more than one action in `map` (empty sequences never conflict).
    static std::vector<Conflict> conflicts(const QMap<QString, KeyList> &map);
    std::vector<Conflict> conflicts() const { return conflicts(currentMap()); }
    // `list` without empty sequences and repeats, in order.
    static KeyList cleaned(const KeyList &list);

    void load(QSettings &settings);
    void save(QSettings &settings) const;

signals:
    void shortcutsChanged();

private:
    struct Entry {
        QPointer<QAction> action;
        KeyList defaultKeys;
    };
    QStringList m_order;
    QHash<QString, Entry> m_entries;
    QHash<QString, KeyList> m_stored; // user choices, also for actions not registered yet
};

} // namespace finbook::ui
