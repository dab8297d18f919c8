// MainWindow: autosave of unsaved changes, and the recovery copies offered at start-up.
#include <finbook/model/document.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/recovery/autosaver.h>
#include <finbook/model/reference/reference_layer.h>
#include <finbook/ui/recovery/recovery_dialog.h>
#include <finbook/ui/window/main_window.h>

#include <QFileInfo>
#include <QStatusBar>

namespace finbook::ui {

void MainWindow::createRecovery()
{
    m_recovery = std::make_unique<model::RecoverySession>();
    m_autosaver = new model::Autosaver(m_doc, m_recovery.get(), this);
    applyAutosaveInterval();
    connect(m_autosaver, &model::Autosaver::copyFailed, this,
            [this](const QString &message) { statusBar()->showMessage(message, 15000); });
}

void MainWindow::applyAutosaveInterval()
{
    // FINBOOK_AUTOSAVE_MS (milliseconds) overrides the preference, for tests and for people
    // who want copies more often than every minute.
    bool set = false;
    const int overridden = qEnvironmentVariableIntValue("FINBOOK_AUTOSAVE_MS", &set);
    m_autosaver->setInterval(set ? overridden : m_prefs.autosaveMinutes * 60 * 1000);
}

void MainWindow::offerRecovery()
{
    for (;;) {
        const std::vector<model::RecoveryCopy> copies = m_recovery->orphans();
        if (copies.empty())
            return;
        const RecoveryChoice choice = askRecovery(copies);
        if (choice.action == RecoveryDialog::Action::Later || choice.index < 0 ||
            choice.index >= int(copies.size()))
            return;
        const model::RecoveryCopy &copy = copies[std::size_t(choice.index)];
        if (choice.action == RecoveryDialog::Action::Discard) {
            m_recovery->discard(copy);
            continue;
        }
        restoreRecovery(copy);
        return; // one document at a time; the others are offered at the next start
    }
}

// The copy becomes the document, unsaved, with the file it came from (if it is still there)
// as where Save goes; the copy itself now belongs to this window's autosave.
bool MainWindow::restoreRecovery(const model::RecoveryCopy &copy)
{
    if (!maybeSave())
        return false;
    QStringList problems;
    auto loaded = model::loadFinbook(copy.path);
    if (!loaded)
        loaded = model::loadFinbookRecovering(copy.path, &problems);
    if (!loaded) {
        reportError(tr("Cannot Recover"), loaded.error().message);
        return false;
    }
    model::adoptLoadedDocument(*m_doc, std::move(*loaded));
    const QString original = copy.info.originalPath;
    setFilePath(QFileInfo::exists(original) ? QFileInfo(original).absoluteFilePath() : QString());
    m_doc->undoStack()->resetClean();
    m_autosaver->adopt(copy.path);
    statusBar()->showMessage(
        tr("Recovered %1 as it was at %2; save it to keep it.")
            .arg(RecoveryDialog::describe(copy).section(QStringLiteral(" \u2014 "), 0, 0),
                 QLocale().toString(copy.info.savedAt.toLocalTime(), QLocale::ShortFormat)),
        10000);
    return true;
}

MainWindow::RecoveryChoice MainWindow::askRecovery(const std::vector<model::RecoveryCopy> &copies)
{
    RecoveryDialog dialog(copies, this);
    dialog.exec();
    return {dialog.action(), dialog.chosen()};
}

} // namespace finbook::ui
