// A table of every registered action with a QKeySequenceEdit for its shortcut; conflicts are
// shown in red as the user types. Nothing is applied until the owner calls shortcuts().
#pragma once

#include <QKeySequence>
#include <QMap>
#include <QWidget>

class QKeySequenceEdit;
class QLabel;
class QTableWidget;

namespace finbook::ui {

class ShortcutRegistry;

class ShortcutEditor : public QWidget {
    Q_OBJECT
public:
    explicit ShortcutEditor(const ShortcutRegistry *registry, QWidget *parent = nullptr);

    QMap<QString, QKeySequence> shortcuts() const;
    void setShortcut(const QString &name, const QKeySequence &keys);
    bool hasConflicts() const;

private:
    void restoreDefaults();
    void markConflicts();

    const ShortcutRegistry *m_registry;
    QTableWidget *m_table;
    QLabel *m_conflicts;
    QMap<QString, QKeySequenceEdit *> m_edits;
};

} // namespace finbook::ui
