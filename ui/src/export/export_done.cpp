#include <finbook/ui/export/export_done.h>

#include <QCoreApplication>
#include <QDesktopServices>
#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>

namespace finbook::ui {

// The translation context of the box's texts.
struct ExportDone {
    Q_DECLARE_TR_FUNCTIONS(ExportDone)
};

QMessageBox *showExportDone(QWidget *parent, const QString &summary, const QStringList &files,
                            const QString &page, UrlOpener open)
{
    if (!open)
        open = [](const QUrl &url) { return QDesktopServices::openUrl(url); };
    // A sequence fills a folder of its own; a single file lives in the folder that holds it.
    QString folder;
    if (!files.isEmpty())
        folder = QFileInfo(files.first()).absolutePath();
    auto *box = new QMessageBox(QMessageBox::Information, ExportDone::tr("Export Finished"),
                                summary, QMessageBox::Close, parent);
    box->setObjectName(QStringLiteral("exportDone"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::NonModal);
    QPushButton *show = box->addButton(ExportDone::tr("Show in Folder"), QMessageBox::ActionRole);
    show->setObjectName(QStringLiteral("export.showFolder"));
    show->setEnabled(!folder.isEmpty());
    QObject::connect(show, &QPushButton::clicked, box,
                     [open, folder] { open(QUrl::fromLocalFile(folder)); });
    if (!page.isEmpty()) {
        QPushButton *browse =
            box->addButton(ExportDone::tr("Open in Browser"), QMessageBox::ActionRole);
        browse->setObjectName(QStringLiteral("export.openBrowser"));
        QObject::connect(browse, &QPushButton::clicked, box,
                         [open, page] { open(QUrl::fromLocalFile(page)); });
    }
    box->show();
    return box;
}

} // namespace finbook::ui
