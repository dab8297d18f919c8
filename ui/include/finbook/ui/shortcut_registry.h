// ShortcutRegistry: every action with a shortcut, by objectName, with its default and the
// user's choice. Defaults come from the editor's shortcut map (defaultMap()), which overrides
// what an action was created with, so the whole editor stays conflict-free in one place.
// User choices persist in QSettings under "shortcuts/<objectName>" (only those that differ
// from the default).
#pragma once

#include <QAction>
#include <QHash>
#include <QKeySequence>
#include <QMap>
#include <QObject>
#include <QPointer>

#include <vector>

class QSettings;

namespace finbook::ui {

class ShortcutRegistry : public QObject {
    Q_OBJECT
public:
    struct Conflict {
        QKeySequence keys;
        QStringList names; // objectNames sharing `keys`, sorted
    };

    explicit ShortcutRegistry(QObject *parent = nullptr);

    // The editor's default shortcuts by objectName (tools, files, edit, view, frames, playback).
    static const QHash<QString, QKeySequence> &defaultMap();

    // Adds an action (objectName required). Its default is defaultMap()'s entry if there is
    // one, else the shortcut it carries now. A stored user choice is applied at once.
    void registerAction(QAction *action);
    QList<QAction *> actions() const; // in registration order
    QAction *action(const QString &name) const;

    QKeySequence defaultShortcut(const QString &name) const;
    QKeySequence shortcut(const QString &name) const;
    // The current shortcut of every registered action.
    QMap<QString, QKeySequence> currentMap() const;
    // Applies shortcuts by name (unknown names ignored) and saves them.
    void apply(const QMap<QString, QKeySequence> &shortcuts);
    void resetToDefaults();

    // Sequences used by more than one action in `map` (empty sequences never conflict).
    static std::vector<Conflict> conflicts(const QMap<QString, QKeySequence> &map);
    std::vector<Conflict> conflicts() const { return conflicts(currentMap()); }

    void load(QSettings &settings);
    void save(QSettings &settings) const;

signals:
    void shortcutsChanged();

private:
    struct Entry {
        QPointer<QAction> action;
        QKeySequence defaultKeys;
    };
    QStringList m_order;
    QHash<QString, Entry> m_entries;
    QHash<QString, QKeySequence> m_stored; // user choices loaded before their action existed
};

} // namespace finbook::ui
