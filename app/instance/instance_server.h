// One Finbook per user and display: a second `finbook FILE` (a double-click in a file manager)
// hands FILE to the Finbook already running and exits, and the running one opens it in a new
// window of its own (window_list.h) — or brings forward the window that already shows it, so
// the same file is never edited in two places. No window's document is replaced, so no
// unsaved work is at risk.
//
// The running Finbook listens on a local socket ($FINBOOK_INSTANCE_SOCKET, else
// "finbook-instance-DISPLAY" in the user's runtime folder, $XDG_RUNTIME_DIR, where DISPLAY is
// $WAYLAND_DISPLAY or else $DISPLAY with ':' as '_': "finbook-instance-_0" on X display :0). A
// request is one line of JSON, {"files": [absolute paths]}; the answer "ok\n" comes once the
// request is taken. A Finbook that does not answer within the timeout (hung, or being shut down) is
// not waited for: the new one opens its own window.
#pragma once

#include <QObject>
#include <QStringList>

class QLocalServer;

namespace finbook::app {

// Where the running Finbook listens.
QString instanceSocketPath();

// Hands `files` (made absolute here) to a running Finbook. True when one took them: the caller
// should then exit; false when none runs or it did not answer within `timeoutMs`.
bool forwardToRunningInstance(const QStringList &files, int timeoutMs = 5000);

class InstanceServer : public QObject {
    Q_OBJECT
public:
    explicit InstanceServer(QObject *parent = nullptr);
    ~InstanceServer() override;

    // Starts listening; false when another Finbook already listens (it won a race) or the
    // socket cannot be made. A socket left by a Finbook that crashed is taken over.
    bool listen(const QString &path = instanceSocketPath());

signals:
    // Another `finbook` asked to open these files (absolute paths; empty: a new window).
    void openRequested(const QStringList &files);

private:
    void acceptConnection();

    QLocalServer *m_server;
};

} // namespace finbook::app
