#include "instance_server.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocalServer>
#include <QLocalSocket>
#include <QStandardPaths>
#include <QTimer>

namespace finbook::app {

namespace {
// A request is a few paths; anything longer is not from Finbook and is dropped.
constexpr qint64 kMaxRequestBytes = 1 << 20;
constexpr int kRequestTimeoutMs = 5000;
} // namespace

QString instanceSocketPath()
{
    const QString overridden = qEnvironmentVariable("FINBOOK_INSTANCE_SOCKET");
    if (!overridden.isEmpty())
        return overridden;
    // The runtime folder is the user's own (mode 0700): no other user can reach the socket.
    // One Finbook per display: a file opened on one screen session (an X display, a Wayland
    // socket) never lands in a window shown on another.
    QString display = qEnvironmentVariable("WAYLAND_DISPLAY");
    if (display.isEmpty())
        display = qEnvironmentVariable("DISPLAY");
    QString suffix;
    for (const QChar c : display)
        if (c.isLetterOrNumber() || c == QLatin1Char('.') || c == QLatin1Char('-'))
            suffix += c;
        else if (c == QLatin1Char(':'))
            suffix += QLatin1Char('_');
    return QStandardPaths::writableLocation(QStandardPaths::RuntimeLocation) +
           QStringLiteral("/finbook-instance") +
           (suffix.isEmpty() ? QString() : QLatin1Char('-') + suffix);
}

bool forwardToRunningInstance(const QStringList &files, int timeoutMs)
{
    QLocalSocket socket;
    socket.connectToServer(instanceSocketPath());
    if (!socket.waitForConnected(timeoutMs))
        return false;
    QJsonArray paths;
    for (const QString &file : files)
        paths.append(QFileInfo(file).absoluteFilePath());
    QByteArray request =
        QJsonDocument(QJsonObject{{QStringLiteral("files"), paths}}).toJson(QJsonDocument::Compact);
    request += '\n';
    socket.write(request);
    if (!socket.waitForBytesWritten(timeoutMs))
        return false;
    while (!socket.canReadLine()) {
        if (!socket.waitForReadyRead(timeoutMs))
            return false;
    }
    return socket.readLine().trimmed() == "ok";
}

InstanceServer::InstanceServer(QObject *parent)
    : QObject(parent)
    , m_server(new QLocalServer(this))
{
    // No socket options: with them Qt binds elsewhere and renames the socket over the path,
    // which would silently take the place of a running Finbook's socket.
    connect(m_server, &QLocalServer::newConnection, this, &InstanceServer::acceptConnection);
}

InstanceServer::~InstanceServer() = default;

bool InstanceServer::listen(const QString &path)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    if (m_server->listen(path))
        return true;
    if (m_server->serverError() != QAbstractSocket::AddressInUseError)
        return false;
    // Someone answers there: another Finbook. No one: a crashed Finbook's socket file.
    QLocalSocket probe;
    probe.connectToServer(path);
    if (probe.waitForConnected(1000))
        return false;
    QLocalServer::removeServer(path);
    return m_server->listen(path);
}

void InstanceServer::acceptConnection()
{
    while (QLocalSocket *socket = m_server->nextPendingConnection()) {
        connect(socket, &QLocalSocket::disconnected, socket, &QObject::deleteLater);
        socket->setReadBufferSize(kMaxRequestBytes);
        // A client that connects and says nothing is dropped, not waited for.
        QTimer::singleShot(kRequestTimeoutMs, socket, [socket] { socket->abort(); });
        connect(socket, &QLocalSocket::readyRead, this, [this, socket] {
            if (!socket->canReadLine()) {
                if (socket->bytesAvailable() >= kMaxRequestBytes)
                    socket->abort();
                return;
            }
            const QByteArray line = socket->readLine(kMaxRequestBytes);
            const QJsonObject request = QJsonDocument::fromJson(line).object();
            QStringList files;
            for (const QJsonValue &v : request.value(QStringLiteral("files")).toArray())
                if (v.isString() && QFileInfo(v.toString()).isAbsolute())
                    files << v.toString();
            if (request.isEmpty()) {
                socket->abort();
                return;
            }
            socket->write("ok\n");
            socket->flush();
            socket->disconnectFromServer();
            // Opening may show a dialog: not inside this socket's signal.
            QTimer::singleShot(0, this, [this, files] { emit openRequested(files); });
        });
    }
}

} // namespace finbook::app
