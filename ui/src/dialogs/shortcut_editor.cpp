#include <finbook/ui/dialogs/shortcut_editor.h>
#include <finbook/ui/i18n/action_text.h>
#include <finbook/ui/keys/shortcut_registry.h>

#include <QHeaderView>
#include <QKeySequenceEdit>
#include <QLabel>
#include <QPushButton>
#include <QScrollBar>
#include <QTableWidget>
#include <QVBoxLayout>

namespace finbook::ui {

namespace {
QString plainText(const QAction *action)
{
    return shortcutName(action);
}
} // namespace

ShortcutEditor::ShortcutEditor(const ShortcutRegistry *registry, QWidget *parent)
    : QWidget(parent)
    , m_registry(registry)
    , m_table(new QTableWidget(this))
    , m_conflicts(new QLabel(this))
{
    const QList<QAction *> actions = registry->actions();
    m_table->setColumnCount(1 + kShortcutsPerAction);
    m_table->setRowCount(int(actions.size()));
    m_table->setHorizontalHeaderLabels({tr("Action"), tr("Shortcut"), tr("Alternative")});
    // The action names are never cut off ("Dokumenteinstellungen..."); the edits share the rest.
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    for (int column = 1; column <= kShortcutsPerAction; ++column)
        m_table->horizontalHeader()->setSectionResizeMode(column, QHeaderView::Stretch);
    m_table->verticalHeader()->hide();
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    for (int row = 0; row < int(actions.size()); ++row) {
        QAction *a = actions[row];
        auto *item = new QTableWidgetItem(plainText(a));
        item->setFlags(Qt::ItemIsEnabled);
        item->setToolTip(a->objectName());
        m_table->setItem(row, 0, item);
        Edits edits{};
        const QList<QKeySequence> keys = a->shortcuts();
        for (int slot = 0; slot < kShortcutsPerAction; ++slot) {
            auto *edit = new QKeySequenceEdit(keys.value(slot), m_table);
            edit->setObjectName(slot == 0 ? a->objectName()
                                          : a->objectName() + QStringLiteral(".alternative"));
            edit->setClearButtonEnabled(true);
            m_table->setCellWidget(row, 1 + slot, edit);
            connect(edit, &QKeySequenceEdit::keySequenceChanged, this,
                    &ShortcutEditor::markConflicts);
            edits[std::size_t(slot)] = edit;
        }
        m_edits.insert(a->objectName(), edits);
    }
    // The action names as wide as the longest one (translations run longer than English);
    // the key column takes the rest, at least enough for a long shortcut.
    QHeaderView *header = m_table->horizontalHeader();
    header->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    header->setSectionResizeMode(1, QHeaderView::Stretch);
    m_table->setWordWrap(false);
    m_table->resizeColumnToContents(0);
    const int keysWidth = fontMetrics().horizontalAdvance(
                              QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::ALT | Qt::Key_Backspace)
                                  .toString(QKeySequence::NativeText)) +
                          4 * fontMetrics().averageCharWidth();
    m_table->setMinimumWidth(header->sectionSize(0) + keysWidth + 2 * m_table->frameWidth() +
                             m_table->verticalScrollBar()->sizeHint().width());
    m_conflicts->setWordWrap(true);
    auto *defaults = new QPushButton(tr("Restore Defaults"), this);
    connect(defaults, &QPushButton::clicked, this, &ShortcutEditor::restoreDefaults);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_table);
    layout->addWidget(m_conflicts);
    layout->addWidget(defaults, 0, Qt::AlignLeft);
    markConflicts();
}

QMap<QString, QList<QKeySequence>> ShortcutEditor::shortcuts() const
{
    QMap<QString, QList<QKeySequence>> map;
    for (auto it = m_edits.begin(); it != m_edits.end(); ++it) {
        QList<QKeySequence> keys;
        for (const QKeySequenceEdit *edit : it.value())
            keys << edit->keySequence();
        map.insert(it.key(), ShortcutRegistry::cleaned(keys));
    }
    return map;
}

void ShortcutEditor::setShortcuts(const QString &name, const QList<QKeySequence> &keys)
{
    const auto found = m_edits.constFind(name);
    if (found == m_edits.constEnd())
        return;
    for (int slot = 0; slot < kShortcutsPerAction; ++slot)
        (*found)[std::size_t(slot)]->setKeySequence(keys.value(slot));
}

QKeySequenceEdit *ShortcutEditor::edit(const QString &name, int slot) const
{
    const auto found = m_edits.constFind(name);
    if (found == m_edits.constEnd() || slot < 0 || slot >= kShortcutsPerAction)
        return nullptr;
    return (*found)[std::size_t(slot)];
}

bool ShortcutEditor::hasConflicts() const
{
    return !ShortcutRegistry::conflicts(shortcuts()).empty();
}

void ShortcutEditor::restoreDefaults()
{
    for (auto it = m_edits.begin(); it != m_edits.end(); ++it)
        setShortcuts(it.key(), m_registry->defaultShortcuts(it.key()));
}

void ShortcutEditor::markConflicts()
{
    const auto conflicts = ShortcutRegistry::conflicts(shortcuts());
    QList<QKeySequence> clashing;
    QStringList lines;
    for (const ShortcutRegistry::Conflict &c : conflicts) {
        clashing << c.keys;
        QStringList texts;
        for (const QString &name : c.names)
            if (const QAction *a = m_registry->action(name))
                texts << plainText(a);
        lines << tr("%1 is used by: %2")
                     .arg(c.keys.toString(QKeySequence::NativeText),
                          texts.join(QStringLiteral(", ")));
    }
    for (const Edits &edits : m_edits)
        for (QKeySequenceEdit *edit : edits)
            edit->setStyleSheet(!edit->keySequence().isEmpty() &&
                                        clashing.contains(edit->keySequence())
                                    ? QStringLiteral("background: #f4c0c0;")
                                    : QString());
    m_conflicts->setText(lines.isEmpty() ? QString()
                                         : tr("Conflicting shortcuts:") + QLatin1Char('\n') +
                                               lines.join(QLatin1Char('\n')));
}

} // namespace finbook::ui
