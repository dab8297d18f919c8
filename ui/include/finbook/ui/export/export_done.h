// What a finished export says: where the files went, with Show in Folder and, for an HTML
// page, Open in Browser. The box does not block the editor.
#pragma once

#include <QStringList>
#include <QUrl>

#include <functional>

class QMessageBox;
class QWidget;

namespace finbook::ui {

// Opens a URL with the desktop (QDesktopServices::openUrl); tests give their own.
using UrlOpener = std::function<bool(const QUrl &)>;

// Shows (non-modal, deleted on close) "summary" with the buttons "export.showFolder" (opens
// the folder that holds `files`) and, when `page` is not empty, "export.openBrowser" (opens
// that page). Returns the box.
QMessageBox *showExportDone(QWidget *parent, const QString &summary, const QStringList &files,
                            const QString &page, UrlOpener open = {});

} // namespace finbook::ui
