#include <finbook/ui/dialogs/shortcuts_dialog.h>
#include <finbook/ui/i18n/action_text.h>
#include <finbook/ui/keys/shortcut_registry.h>

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLineEdit>
#include <QScreen>
#include <QScrollBar>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace finbook::ui {

ShortcutsDialog::ShortcutsDialog(const ShortcutRegistry *registry, QWidget *parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Keyboard Shortcuts"));
    setObjectName(QStringLiteral("shortcutsDialog"));
    QList<QPair<QString, QString>> rows;
    for (const QAction *a : registry->actions())
        rows.append({shortcutName(a),
                     QKeySequence::listToString(a->shortcuts(), QKeySequence::NativeText)});
    rows.append({tr("Pan the view"), tr("Space + drag, or middle button drag")});
    rows.append({tr("Zoom about the cursor"), tr("Mouse wheel")});

    auto *table = new QTableWidget(int(rows.size()), 2, this);
    table->setObjectName(QStringLiteral("shortcutsTable"));
    table->setHorizontalHeaderLabels({tr("Action"), tr("Shortcut")});
    table->verticalHeader()->hide();
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setWordWrap(false);
    for (int r = 0; r < int(rows.size()); ++r) {
        table->setItem(r, 0, new QTableWidgetItem(rows[r].first));
        table->setItem(r, 1, new QTableWidgetItem(rows[r].second));
    }
    m_rows = int(rows.size());
    // Both columns as wide as their longest text (translations run longer than English), and
    // the table at least that wide, so nothing is elided unless the screen is too narrow.
    QHeaderView *header = table->horizontalHeader();
    header->setSectionResizeMode(QHeaderView::ResizeToContents);
    header->setStretchLastSection(true);
    table->resizeColumnsToContents();
    const int contentWidth =
        header->length() + 2 * table->frameWidth() + table->verticalScrollBar()->sizeHint().width();
    const QScreen *screen = parent ? parent->screen() : this->screen();
    const int maxWidth = screen ? screen->availableGeometry().width() * 9 / 10 : contentWidth;
    table->setMinimumWidth(std::min(contentWidth, maxWidth));

    auto *filter = new QLineEdit(this);
    filter->setPlaceholderText(tr("Filter"));
    filter->setClearButtonEnabled(true);
    connect(filter, &QLineEdit::textChanged, this, [table](const QString &text) {
        for (int r = 0; r < table->rowCount(); ++r)
            table->setRowHidden(r,
                                !table->item(r, 0)->text().contains(text, Qt::CaseInsensitive) &&
                                    !table->item(r, 1)->text().contains(text, Qt::CaseInsensitive));
    });
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(filter);
    layout->addWidget(table);
    layout->addWidget(buttons);
    resize(std::max(520, sizeHint().width()), 600);
}

} // namespace finbook::ui
