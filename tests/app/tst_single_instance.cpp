// A second `finbook FILE` hands FILE to the running Finbook (a real second process here), and
// the running one opens it in a new window or the window already showing it: no window's
// document is replaced, so unsaved work is never at risk.
#include "instance/instance_server.h"
#include "instance/window_list.h"

#include <finbook/model/commands.h>
#include <finbook/model/document.h>
#include <finbook/model/finbook_file.h>
#include <finbook/ui/window/main_window.h>

#include <QApplication>
#include <QFile>
#include <QLocalSocket>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

using namespace finbook;

namespace {

const QString kExample = QStringLiteral(FINBOOK_SOURCE_DIR "/resources/examples/walk.finbook");

// Answers the dialogs a test cannot click: errors are recorded, "save changes?" is never
// expected (a request must not close or replace a document) and answered Cancel.
class TestWindow : public ui::MainWindow {
public:
    static inline int askedToSave = 0; // over all windows (closed ones are deleted)
    static inline QStringList errors;

protected:
    void reportError(const QString &, const QString &message) override { errors << message; }
    QMessageBox::StandardButton askToSave() override
    {
        ++askedToSave;
        return QMessageBox::Cancel;
    }
    bool askOpenAnyway(const QString &message) override
    {
        errors << message;
        return false;
    }
};

void drawSomething(ui::MainWindow *window)
{
    model::Document *doc = window->document();
    auto data = std::make_shared<model::StrokeData>();
    data->points = {{10, 10, 1}, {50, 60, 1}};
    doc->undoStack()->push(
        new model::AddStrokeCommand(doc, doc->frames().front().groups.front().id, data));
}

QProcessEnvironment environment(const QString &socket)
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("FINBOOK_INSTANCE_SOCKET"), socket);
    return env;
}

} // namespace

class TestSingleInstance : public QObject {
    Q_OBJECT
private slots:
    void secondFinbookHandsItsFileOver();
    void noRunningFinbook();
    void oneFinbookPerDisplay();
    void staleSocketIsTakenOver();
    void junkRequestsAreDropped();
    void requestsNeverReplaceADocument();
};

void TestSingleInstance::secondFinbookHandsItsFileOver()
{
    QTemporaryDir dir;
    const QString socket = dir.filePath(QStringLiteral("instance"));
    app::InstanceServer server;
    QVERIFY(server.listen(socket));
    QSignalSpy requests(&server, &app::InstanceServer::openRequested);

    // A relative name, as a shell passes it: the running Finbook gets the absolute path.
    QProcess second;
    second.setProcessEnvironment(environment(socket));
    second.setWorkingDirectory(QFileInfo(kExample).absolutePath());
    QSignalSpy finished(&second, &QProcess::finished);
    second.start(QStringLiteral(FINBOOK_BINARY_DIR "/bin/finbook"),
                 {QStringLiteral("walk.finbook")});
    QVERIFY(finished.wait(30000));
    QCOMPARE(second.exitCode(), 0);
    QVERIFY(requests.wait(5000) || requests.size() == 1);
    QCOMPARE(requests.size(), 1);
    QCOMPARE(requests.front().front().toStringList(),
             QStringList{QFileInfo(kExample).absoluteFilePath()});

    // Without a file: a request for a new window.
    second.setWorkingDirectory(dir.path());
    second.start(QStringLiteral(FINBOOK_BINARY_DIR "/bin/finbook"), QStringList());
    QVERIFY(finished.wait(30000));
    QCOMPARE(second.exitCode(), 0);
    QVERIFY(requests.wait(5000) || requests.size() == 2);
    QCOMPARE(requests.last().front().toStringList(), QStringList());
}

void TestSingleInstance::noRunningFinbook()
{
    QTemporaryDir dir;
    qputenv("FINBOOK_INSTANCE_SOCKET", QFile::encodeName(dir.filePath(QStringLiteral("none"))));
    QVERIFY(!app::forwardToRunningInstance({kExample}, 2000));
    qunsetenv("FINBOOK_INSTANCE_SOCKET");
}

// Two X displays (or Wayland sessions) of one user each have their own Finbook: a file opened
// on one never lands in a window on the other.
void TestSingleInstance::oneFinbookPerDisplay()
{
    const QByteArray display = qgetenv("DISPLAY"), wayland = qgetenv("WAYLAND_DISPLAY"),
                     socket = qgetenv("FINBOOK_INSTANCE_SOCKET");
    qunsetenv("FINBOOK_INSTANCE_SOCKET");
    qunsetenv("WAYLAND_DISPLAY");
    qputenv("DISPLAY", ":42");
    const QString on42 = app::instanceSocketPath();
    qputenv("DISPLAY", ":43.0");
    const QString on43 = app::instanceSocketPath();
    qputenv("WAYLAND_DISPLAY", "wayland-1");
    const QString onWayland = app::instanceSocketPath();
    qunsetenv("DISPLAY");
    qunsetenv("WAYLAND_DISPLAY");
    const QString headless = app::instanceSocketPath();
    for (const auto &[name, value] :
         {std::pair{"DISPLAY", display}, std::pair{"WAYLAND_DISPLAY", wayland},
          std::pair{"FINBOOK_INSTANCE_SOCKET", socket}})
        if (!value.isNull())
            qputenv(name, value);
    QVERIFY2(on42.endsWith(QLatin1String("/finbook-instance-_42")), qPrintable(on42));
    QVERIFY2(on43.endsWith(QLatin1String("/finbook-instance-_43.0")), qPrintable(on43));
    QVERIFY2(onWayland.endsWith(QLatin1String("/finbook-instance-wayland-1")),
             qPrintable(onWayland));
    QVERIFY2(headless.endsWith(QLatin1String("/finbook-instance")), qPrintable(headless));
}

// A Finbook that crashed leaves its socket file: the next one takes it over. A live one keeps
// it: a second server on the same path does not listen.
void TestSingleInstance::staleSocketIsTakenOver()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("instance"));
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    QVERIFY(fd >= 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    const QByteArray name = QFile::encodeName(path);
    std::memcpy(address.sun_path, name.constData(), std::size_t(name.size()));
    QCOMPARE(::bind(fd, reinterpret_cast<sockaddr *>(&address), sizeof(address)), 0);
    ::close(fd); // the file stays, nobody listens
    QVERIFY(QFileInfo::exists(path));

    app::InstanceServer first;
    QVERIFY(first.listen(path));
    app::InstanceServer second;
    QVERIFY(!second.listen(path));
}

void TestSingleInstance::junkRequestsAreDropped()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("instance"));
    app::InstanceServer server;
    QVERIFY(server.listen(path));
    QSignalSpy requests(&server, &app::InstanceServer::openRequested);
    for (const QByteArray &junk :
         {QByteArray("not json\n"), QByteArray("[1,2,3]\n"), QByteArray(3 << 20, 'x')}) {
        QLocalSocket socket;
        socket.connectToServer(path);
        QVERIFY(socket.waitForConnected(2000));
        socket.write(junk);
        socket.flush();
        QTest::qWait(200);
    }
    QCOMPARE(requests.size(), 0);
}

void TestSingleInstance::requestsNeverReplaceADocument()
{
    QTemporaryDir dir;
    const QString other = dir.filePath(QStringLiteral("other.finbook"));
    QVERIFY(QFile::copy(kExample, other));
    const QString damaged = dir.filePath(QStringLiteral("damaged.finbook"));
    QFile out(damaged);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(QByteArray("not a finbook at all"));
    out.close();

    app::WindowList windows([] { return new TestWindow; });
    TestWindow first;
    first.show();
    windows.add(&first);
    drawSomething(&first); // unsaved work
    const QByteArray before = model::serializeFinbook(*first.document());

    ui::MainWindow *shown = windows.open({kExample});
    QCOMPARE(windows.windows().size(), 2);
    QVERIFY(shown != &first);
    QCOMPARE(shown->filePath(), QFileInfo(kExample).absoluteFilePath());

    // The same file again: the window showing it, no third window.
    QCOMPARE(windows.open({kExample}), shown);
    QCOMPARE(windows.windows().size(), 2);

    // No file: a new window; a file next goes into that untouched window.
    ui::MainWindow *empty = windows.open({});
    QCOMPARE(windows.windows().size(), 3);
    QCOMPARE(windows.open({other}), empty);
    QCOMPARE(windows.windows().size(), 3);

    // A file that does not open: said, and no empty window left behind.
    QCOMPARE(windows.open({damaged}), nullptr);
    QTest::qWait(50);
    QCOMPARE(windows.windows().size(), 3);
    QCOMPARE(TestWindow::errors.size(), 1);

    // The first window's unsaved work is exactly as it was, and nobody asked to save it.
    QCOMPARE(model::serializeFinbook(*first.document()), before);
    QVERIFY(!first.document()->undoStack()->isClean());
    QVERIFY(first.filePath().isEmpty());
    QCOMPARE(TestWindow::askedToSave, 0);
    for (ui::MainWindow *w : windows.windows())
        if (w != &first)
            w->close();
}

QTEST_MAIN(TestSingleInstance)
#include "tst_single_instance.moc"
