#include <finbook/ui/shortcut_editor.h>
#include <finbook/ui/shortcut_registry.h>

#include <QHeaderView>
#include <QKeySequenceEdit>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace finbook::ui {

namespace {
QString plainText(const QAction *action)
{
    return action->text().remove(QLatin1Char('&'));
}
} // namespace

ShortcutEditor::ShortcutEditor(const ShortcutRegistry *registry, QWidget *parent)
    : QWidget(parent)
    , m_registry(registry)
    , m_table(new QTableWidget(this))
    , m_conflicts(new QLabel(this))
{
    const QList<QAction *> actions = registry->actions();
    m_table->setColumnCount(2);
    m_table->setRowCount(int(actions.size()));
    m_table->setHorizontalHeaderLabels({tr("Action"), tr("Shortcut")});
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_table->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
    m_table->verticalHeader()->hide();
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    for (int row = 0; row < int(actions.size()); ++row) {
        QAction *a = actions[row];
        auto *item = new QTableWidgetItem(plainText(a));
        item->setFlags(Qt::ItemIsEnabled);
        item->setToolTip(a->objectName());
        m_table->setItem(row, 0, item);
        auto *edit = new QKeySequenceEdit(a->shortcut(), m_table);
        edit->setObjectName(a->objectName());
        m_table->setCellWidget(row, 1, edit);
        m_edits.insert(a->objectName(), edit);
        connect(edit, &QKeySequenceEdit::keySequenceChanged, this, &ShortcutEditor::markConflicts);
    }
    m_conflicts->setWordWrap(true);
    auto *defaults = new QPushButton(tr("Restore Defaults"), this);
    connect(defaults, &QPushButton::clicked, this, &ShortcutEditor::restoreDefaults);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_table);
    layout->addWidget(m_conflicts);
    layout->addWidget(defaults, 0, Qt::AlignLeft);
    markConflicts();
}

QMap<QString, QKeySequence> ShortcutEditor::shortcuts() const
{
    QMap<QString, QKeySequence> map;
    for (auto it = m_edits.begin(); it != m_edits.end(); ++it)
        map.insert(it.key(), it.value()->keySequence());
    return map;
}

void ShortcutEditor::setShortcut(const QString &name, const QKeySequence &keys)
{
    if (QKeySequenceEdit *edit = m_edits.value(name))
        edit->setKeySequence(keys);
}

bool ShortcutEditor::hasConflicts() const
{
    return !ShortcutRegistry::conflicts(shortcuts()).empty();
}

void ShortcutEditor::restoreDefaults()
{
    for (auto it = m_edits.begin(); it != m_edits.end(); ++it)
        it.value()->setKeySequence(m_registry->defaultShortcut(it.key()));
}

void ShortcutEditor::markConflicts()
{
    const auto conflicts = ShortcutRegistry::conflicts(shortcuts());
    QStringList clashing, lines;
    for (const ShortcutRegistry::Conflict &c : conflicts) {
        clashing << c.names;
        QStringList texts;
        for (const QString &name : c.names)
            if (const QAction *a = m_registry->action(name))
                texts << plainText(a);
        lines << tr("%1 is used by: %2")
                     .arg(c.keys.toString(QKeySequence::NativeText),
                          texts.join(QStringLiteral(", ")));
    }
    for (auto it = m_edits.begin(); it != m_edits.end(); ++it)
        it.value()->setStyleSheet(
            clashing.contains(it.key()) ? QStringLiteral("background: #f4c0c0;") : QString());
    m_conflicts->setText(lines.isEmpty() ? QString()
                                         : tr("Conflicting shortcuts:") + QLatin1Char('\n') +
                                               lines.join(QLatin1Char('\n')));
}

} // namespace finbook::ui
