#include "test_hooks.h"

#include <finbook/model/finbook_file.h>

#include <QAction>
#include <QApplication>
#include <QFile>
#include <QTextStream>

#include <cstdio>

namespace finbook::app {

bool testHooksRequested()
{
    return qEnvironmentVariableIsSet("FINBOOK_TEST_ACTIONS") ||
           qEnvironmentVariableIsSet("FINBOOK_TEST_RECOVERY") ||
           qEnvironmentVariableIsSet("FINBOOK_TEST_DUMP");
}

ui::MainWindow::RecoveryChoice
ScriptedMainWindow::askRecovery(const std::vector<model::RecoveryCopy> &copies)
{
    QTextStream(stdout) << "recovery copies: " << copies.size() << Qt::endl;
    const QString answer = qEnvironmentVariable("FINBOOK_TEST_RECOVERY");
    if (answer == QLatin1String("restore"))
        return {ui::RecoveryDialog::Action::Restore, 0};
    if (answer == QLatin1String("discard"))
        return {ui::RecoveryDialog::Action::Discard, 0};
    return {ui::RecoveryDialog::Action::Later, 0};
}

void ScriptedMainWindow::reportError(const QString &, const QString &message)
{
    QTextStream(stderr) << message << Qt::endl;
}

void ScriptedMainWindow::runHooks()
{
    offerRecovery();
    const QStringList actions =
        qEnvironmentVariable("FINBOOK_TEST_ACTIONS").split(QLatin1Char(','), Qt::SkipEmptyParts);
    for (const QString &name : actions) {
        if (QAction *a = action(name))
            a->trigger();
        else
            QTextStream(stderr) << "no action " << name << Qt::endl;
    }
    const QString dump = qEnvironmentVariable("FINBOOK_TEST_DUMP");
    if (dump.isEmpty())
        return;
    QFile out(dump);
    if (out.open(QIODevice::WriteOnly))
        out.write(model::serializeFinbook(*document()));
    QFile state(dump + QStringLiteral(".state"));
    if (state.open(QIODevice::WriteOnly))
        state.write((document()->undoStack()->isClean() ? "clean\n" : "modified\n") +
                    filePath().toUtf8() + '\n');
    std::fflush(stdout);
    QCoreApplication::exit(0);
}

} // namespace finbook::app
