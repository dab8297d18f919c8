#include "cli_terminal.h"

#include <QtGlobal>

#include <csignal>

#ifdef Q_OS_UNIX
#include <unistd.h>
#endif

namespace finbook::app {

namespace {
volatile std::sig_atomic_t g_signal = 0;

void noteSignal(int signal)
{
    g_signal = signal;
}
} // namespace

bool stderrIsTerminal()
{
#ifdef Q_OS_UNIX
    return ::isatty(STDERR_FILENO) == 1;
#else
    return false;
#endif
}

bool stdoutIsTerminal()
{
#ifdef Q_OS_UNIX
    return ::isatty(STDOUT_FILENO) == 1;
#else
    return false;
#endif
}

// SIGINT, SIGTERM and SIGHUP stop the export at its next step (the encoder killed, the
// temporaries removed) instead of killing Finbook with its temporaries left behind.
void catchInterrupts()
{
#ifdef Q_OS_UNIX
    struct sigaction action {};
    action.sa_handler = noteSignal;
    sigemptyset(&action.sa_mask);
    for (const int signal : {SIGINT, SIGTERM, SIGHUP})
        ::sigaction(signal, &action, nullptr);
#endif
}

bool interrupted()
{
    return g_signal != 0;
}

int interruptSignal()
{
    return int(g_signal);
}

} // namespace finbook::app
