// Test hooks of the real executable: a main window that a test drives through environment
// variables, so a test can edit, let autosave run, kill the process and start it again.
// Finbook uses it only when one of these variables is set; people never do.
//
//   FINBOOK_TEST_ACTIONS=a,b,c  triggers these actions (by object name) once the window shows
//   FINBOOK_TEST_RECOVERY=restore|discard|later  answers the recovery prompt (first copy); it
//                               also prints "recovery copies: N" on stdout when asked
//   FINBOOK_TEST_DUMP=PATH      then writes the document's bytes to PATH (and "clean" or
//                               "modified" and the window's file to PATH.state) and quits
//                               without closing the window (so, like a crash, nothing is
//                               discarded)
#pragma once

#include <finbook/ui/window/main_window.h>

#include <memory>

namespace finbook::app {

// True when any FINBOOK_TEST_* hook is set.
bool testHooksRequested();

class ScriptedMainWindow : public ui::MainWindow {
    Q_OBJECT
public:
    using ui::MainWindow::MainWindow;
    // Runs the hooks: recovery answer, actions, dump (in that order).
    void runHooks();

protected:
    RecoveryChoice askRecovery(const std::vector<model::RecoveryCopy> &copies) override;
    QMessageBox::StandardButton askToSave() override { return QMessageBox::Discard; }
    void reportError(const QString &title, const QString &message) override;
};

} // namespace finbook::app
