// MainWindow's Deform > Lip Sync… (lipsync/lip_sync_dialog.h).
#include <finbook/ui/lipsync/lip_sync_dialog.h>
#include <finbook/ui/swap/swap_actions.h>
#include <finbook/ui/window/main_window.h>

#include <QMessageBox>
#include <QStatusBar>

namespace finbook::ui {

void MainWindow::showLipSync()
{
    const model::Id mouth = m_swapActions->stepTarget();
    if (mouth == model::kNoId) {
        QMessageBox::information(this, tr("Lip Sync"),
                                 tr("Lip sync keys the drawings of a mouth chart. Make one with "
                                    "Object > New Mouth Chart, redraw its mouths in your style, "
                                    "then come back here."));
        return;
    }
    auto *dialog = new LipSyncDialog(m_state, mouth, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &LipSyncDialog::keyed, this,
            [this](const QString &message) { statusBar()->showMessage(message, 8000); });
    dialog->open();
}

} // namespace finbook::ui
