#include <finbook/ui/recovery/recovery_dialog.h>

#include <QDialogButtonBox>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

namespace finbook::ui {

RecoveryDialog::RecoveryDialog(const std::vector<model::RecoveryCopy> &copies, QWidget *parent)
    : QDialog(parent)
    , m_list(new QListWidget(this))
{
    setObjectName(QStringLiteral("recoveryDialog"));
    setWindowTitle(tr("Recover Unsaved Work"));
    auto *intro = new QLabel(tr("Finbook did not close normally last time. It kept these "
                                "copies of work that was not saved:"),
                             this);
    intro->setWordWrap(true);
    m_list->setIconSize(QSize(160, 120));
    m_list->setSpacing(4);
    for (const model::RecoveryCopy &copy : copies) {
        auto *item = new QListWidgetItem(describe(copy), m_list);
        if (!copy.thumbnail.isNull())
            item->setIcon(QIcon(QPixmap::fromImage(copy.thumbnail)));
    }
    m_list->setCurrentRow(0);
    auto *buttons = new QDialogButtonBox(this);
    QPushButton *restore = buttons->addButton(tr("&Restore"), QDialogButtonBox::AcceptRole);
    QPushButton *discard = buttons->addButton(tr("&Discard"), QDialogButtonBox::DestructiveRole);
    QPushButton *later = buttons->addButton(tr("&Later"), QDialogButtonBox::RejectRole);
    restore->setDefault(true);
    restore->setToolTip(tr("Open the copy as an unsaved animation"));
    discard->setToolTip(tr("Delete the copy for good"));
    later->setToolTip(tr("Keep the copies and ask again at the next start"));
    connect(restore, &QPushButton::clicked, this, [this] { finish(Action::Restore); });
    connect(discard, &QPushButton::clicked, this, [this] { finish(Action::Discard); });
    connect(later, &QPushButton::clicked, this, [this] { finish(Action::Later); });
    connect(m_list, &QListWidget::itemDoubleClicked, this, [this] { finish(Action::Restore); });
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addWidget(m_list);
    layout->addWidget(buttons);
    resize(560, 420);
}

int RecoveryDialog::chosen() const
{
    return std::max(0, m_list->currentRow());
}

QString RecoveryDialog::describe(const model::RecoveryCopy &copy)
{
    const QString title = copy.info.title.isEmpty() ? tr("Untitled") : copy.info.title;
    const QString when = QLocale().toString(copy.info.savedAt.toLocalTime(), QLocale::ShortFormat);
    return tr("%1 \u2014 %2 \u2014 %n frame(s)", nullptr, copy.info.frames).arg(title, when);
}

void RecoveryDialog::finish(Action action)
{
    m_action = action;
    if (action == Action::Later)
        reject();
    else
        accept();
}

} // namespace finbook::ui
