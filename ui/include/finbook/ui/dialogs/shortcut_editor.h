// A table of every registered action with two QKeySequenceEdits, its shortcut and an
// alternative (Redo: Ctrl+Shift+Z or Ctrl+Y); conflicts are shown in red as the user types.
// Nothing is applied until the owner calls shortcuts(). The edits are named after the action
// ("edit.redo") and the alternative with ".alternative" appended.
#pragma once

#include <QKeySequence>
#include <QList>
#include <QMap>
#include <QWidget>

#include <array>

class QKeySequenceEdit;
class QLabel;
class QTableWidget;

namespace finbook::ui {

class ShortcutRegistry;

class ShortcutEditor : public QWidget {
    Q_OBJECT
public:
    explicit ShortcutEditor(const ShortcutRegistry *registry, QWidget *parent = nullptr);

    static constexpr int kShortcutsPerAction = 2;

    // Each action's shortcuts as edited, without empty ones.
    QMap<QString, QList<QKeySequence>> shortcuts() const;
    // Sets the first `keys.size()` edits of an action and clears the others.
    void setShortcuts(const QString &name, const QList<QKeySequence> &keys);
    void setShortcut(const QString &name, const QKeySequence &keys) { setShortcuts(name, {keys}); }
    QKeySequenceEdit *edit(const QString &name, int slot) const;
    bool hasConflicts() const;

private:
    using Edits = std::array<QKeySequenceEdit *, kShortcutsPerAction>;
    void restoreDefaults();
    void markConflicts();

    const ShortcutRegistry *m_registry;
    QTableWidget *m_table;
    QLabel *m_conflicts;
    QMap<QString, Edits> m_edits;
};

} // namespace finbook::ui
