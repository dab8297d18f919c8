// Saving when the disk fails: a full disk (a real 64 KiB tmpfs when the test runs as root, an
// injected failing write always), a read-only disk, a folder the user may not write. The old
// file and its backup stay byte for byte as they were and the message says what happened.
#include "tst_file_sample.h"

#include <QDir>
#include <QTemporaryDir>

#include <cerrno>
#include <fcntl.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace finbook::model;
using namespace file_test;

namespace {
// A tmpfs of `size` mounted on a temporary folder while it lives; only root may mount.
class TinyDisk {
public:
    explicit TinyDisk(const char *options)
    {
        if (::geteuid() == 0 && m_dir.isValid())
            m_mounted = ::mount("tmpfs", QFile::encodeName(m_dir.path()).constData(), "tmpfs", 0,
                                options) == 0;
    }
    ~TinyDisk()
    {
        if (m_mounted)
            ::umount2(QFile::encodeName(m_dir.path()).constData(), MNT_DETACH);
    }
    bool mounted() const { return m_mounted; }
    QString filePath(const QString &name) const { return m_dir.filePath(name); }
    bool makeReadOnly()
    {
        return ::mount(nullptr, QFile::encodeName(m_dir.path()).constData(), nullptr,
                       MS_REMOUNT | MS_RDONLY, nullptr) == 0;
    }
    // Writes a filler file until the disk refuses more; returns the errno that stopped it.
    int fill()
    {
        const int fd = ::open(QFile::encodeName(filePath(QStringLiteral("filler"))).constData(),
                              O_WRONLY | O_CREAT | O_APPEND, 0644);
        if (fd < 0)
            return errno;
        const QByteArray block(512, 'x');
        int error = 0;
        while (error == 0)
            if (::write(fd, block.constData(), std::size_t(block.size())) < 0)
                error = errno;
        ::close(fd);
        return error;
    }
    // Every entry, hidden ones too: a leftover temporary file would show here.
    QStringList entries() const
    {
        return QDir(m_dir.path()).entryList(QDir::Files | QDir::Hidden | QDir::System, QDir::Name);
    }

private:
    QTemporaryDir m_dir;
    bool m_mounted = false;
};

QStringList hiddenAndFiles(const QString &dir)
{
    return QDir(dir).entryList(QDir::Files | QDir::Hidden | QDir::System, QDir::Name);
}

// A write that takes `accepted` bytes and then fails with `error`, as a filling disk does.
WriteFunction failingWrite(qint64 accepted, int error)
{
    auto written = std::make_shared<qint64>(0);
    return [=](int fd, const char *data, qint64 size) -> qint64 {
        const qint64 room = accepted - *written;
        if (room <= 0) {
            errno = error;
            return -1;
        }
        const qint64 n = ::write(fd, data, std::size_t(std::min(room, size)));
        if (n > 0)
            *written += n;
        return n;
    };
}

void editHold(Document &doc, int hold)
{
    doc.setFrameHold(doc.frameAt(0).id, hold);
}
} // namespace

class TestSaveSafety : public QObject {
    Q_OBJECT
private slots:
    void fullTmpfsKeepsOldFile();
    void fullTmpfsTwiceKeepsBackup();
    void readOnlyDiskSaysReadOnly();
    void injectedFullDiskKeepsFileAndBackup_data();
    void injectedFullDiskKeepsFileAndBackup();
    void injectedOtherErrorSaysWhat();
    void permissionDeniedSaysPermission();
    void errnoClassification();
    void replacedFileKeepsPermissions();
    void leftoversOfGoneSaversAreRemoved();
    void backupAlreadyLinkedToTheFileLeavesNoTemporary();
};

void TestSaveSafety::fullTmpfsKeepsOldFile()
{
    TinyDisk disk("size=64k");
    if (!disk.mounted())
        QSKIP("needs root to mount a tmpfs; injectedFullDiskKeepsFileAndBackup covers it");
    const QString path = disk.filePath(QStringLiteral("a.finbook"));
    Document doc;
    buildSample(doc);
    QVERIFY(!saveFinbook(doc, path));
    const QByteArray old = fileBytes(path);
    QCOMPARE(disk.fill(), ENOSPC);

    editHold(doc, 5);
    const auto error = saveFinbook(doc, path);
    QVERIFY2(error, "a save onto a full disk reported success");
    QCOMPARE(error->code, FileErrorCode::DiskFull);
    QVERIFY2(error->message.contains(QLatin1String("the disk is full")),
             qPrintable(error->message));
    QVERIFY2(error->message.contains(QLatin1String("a.finbook")), qPrintable(error->message));
    QCOMPARE(fileBytes(path), old);
    QVERIFY(readFinbook(fileBytes(path)));
    QCOMPARE(disk.entries(), (QStringList{QStringLiteral("a.finbook"), QStringLiteral("filler")}));
}

void TestSaveSafety::fullTmpfsTwiceKeepsBackup()
{
    TinyDisk disk("size=64k");
    if (!disk.mounted())
        QSKIP("needs root to mount a tmpfs; injectedFullDiskKeepsFileAndBackup covers it");
    const QString path = disk.filePath(QStringLiteral("a.finbook"));
    Document doc;
    buildSample(doc);
    QVERIFY(!saveFinbook(doc, path));
    const QByteArray first = fileBytes(path);
    editHold(doc, 2);
    QVERIFY(!saveFinbook(doc, path));
    const QByteArray second = fileBytes(path);
    QCOMPARE(fileBytes(finbookBackupPath(path)), first);
    QCOMPARE(disk.fill(), ENOSPC);

    for (int hold : {3, 4}) {
        editHold(doc, hold);
        const auto error = saveFinbook(doc, path);
        QVERIFY(error);
        QCOMPARE(error->code, FileErrorCode::DiskFull);
        QCOMPARE(fileBytes(path), second);
        QCOMPARE(fileBytes(finbookBackupPath(path)), first);
    }
    QCOMPARE(disk.entries(), (QStringList{QStringLiteral("a.finbook"), QStringLiteral("a.finbook~"),
                                          QStringLiteral("filler")}));
}

void TestSaveSafety::readOnlyDiskSaysReadOnly()
{
    TinyDisk disk("size=64k");
    if (!disk.mounted())
        QSKIP("needs root to mount a tmpfs");
    const QString path = disk.filePath(QStringLiteral("a.finbook"));
    Document doc;
    buildSample(doc);
    QVERIFY(!saveFinbook(doc, path));
    const QByteArray old = fileBytes(path);
    QVERIFY(disk.makeReadOnly());
    editHold(doc, 5);
    const auto error = saveFinbook(doc, path);
    QVERIFY(error);
    QCOMPARE(error->code, FileErrorCode::WriteFailed);
    QVERIFY2(error->message.contains(QLatin1String("read-only")), qPrintable(error->message));
    QVERIFY2(!error->message.contains(QLatin1String("disk space")), qPrintable(error->message));
    QCOMPARE(fileBytes(path), old);
}

void TestSaveSafety::injectedFullDiskKeepsFileAndBackup_data()
{
    QTest::addColumn<qint64>("accepted");
    QTest::addColumn<int>("error");
    QTest::newRow("nothing written, ENOSPC") << qint64(0) << ENOSPC;
    QTest::newRow("100 bytes, ENOSPC") << qint64(100) << ENOSPC;
    QTest::newRow("all but one byte, ENOSPC") << qint64(-1) << ENOSPC;
    QTest::newRow("over quota") << qint64(1000) << EDQUOT;
}

void TestSaveSafety::injectedFullDiskKeepsFileAndBackup()
{
    QFETCH(qint64, accepted);
    QFETCH(int, error);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.finbook"));
    Document doc;
    buildSample(doc);
    QVERIFY(!saveFinbook(doc, path));
    const QByteArray first = fileBytes(path);
    editHold(doc, 2);
    QVERIFY(!saveFinbook(doc, path));
    const QByteArray second = fileBytes(path);
    if (accepted < 0)
        accepted = second.size() - 1;

    for (int hold : {3, 4}) { // twice: the second failure must not cost the backup either
        editHold(doc, hold);
        const auto failure = saveFinbook(doc, path, failingWrite(accepted, error));
        QVERIFY(failure);
        QCOMPARE(failure->code, FileErrorCode::DiskFull);
        QVERIFY2(failure->message.contains(QLatin1String("the disk is full")),
                 qPrintable(failure->message));
        QCOMPARE(fileBytes(path), second);
        QCOMPARE(fileBytes(finbookBackupPath(path)), first);
    }
    QCOMPARE(hiddenAndFiles(dir.path()),
             (QStringList{QStringLiteral("a.finbook"), QStringLiteral("a.finbook~")}));
    QVERIFY(!saveFinbook(doc, path)); // and once the disk has room, saving works again
    QCOMPARE(fileBytes(finbookBackupPath(path)), second);
}

void TestSaveSafety::injectedOtherErrorSaysWhat()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.finbook"));
    Document doc;
    buildSample(doc);
    QVERIFY(!saveFinbook(doc, path));
    const QByteArray old = fileBytes(path);
    editHold(doc, 2);
    const auto failure = saveFinbook(doc, path, failingWrite(1000, EIO));
    QVERIFY(failure);
    QCOMPARE(failure->code, FileErrorCode::WriteFailed);
    QVERIFY2(failure->message.contains(QString::fromLocal8Bit(std::strerror(EIO))),
             qPrintable(failure->message));
    QVERIFY2(!failure->message.contains(QLatin1String("Unknown error")),
             qPrintable(failure->message));
    QCOMPARE(fileBytes(path), old);
}

// As root, chmod does not stop writes: a child process that gave up root tries instead.
void TestSaveSafety::permissionDeniedSaysPermission()
{
    QTemporaryDir dir;
    const QString locked = dir.filePath(QStringLiteral("locked"));
    QVERIFY(QDir().mkpath(locked));
    const QString path = locked + QStringLiteral("/a.finbook");
    Document doc;
    buildSample(doc);
    QVERIFY(!saveFinbook(doc, path));
    const QByteArray old = fileBytes(path);
    QVERIFY(::chmod(QFile::encodeName(dir.path()).constData(), 0755) == 0);
    QVERIFY(::chmod(QFile::encodeName(locked).constData(), 0555) == 0);
    editHold(doc, 2);
    int pipeFds[2];
    QVERIFY(::pipe(pipeFds) == 0);
    const pid_t child = ::fork();
    QVERIFY(child >= 0);
    if (child == 0) {
        ::close(pipeFds[0]);
        if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0))
            ::_exit(3);
        const auto error = saveFinbook(doc, path);
        const QByteArray text = error ? error->message.toUtf8() : QByteArray("saved");
        const bool sent =
            ::write(pipeFds[1], text.constData(), std::size_t(text.size())) == ssize_t(text.size());
        ::_exit(sent && error && error->code == FileErrorCode::WriteFailed ? 0 : 1);
    }
    ::close(pipeFds[1]);
    QByteArray message;
    char buffer[4096];
    for (ssize_t n; (n = ::read(pipeFds[0], buffer, sizeof(buffer))) > 0;)
        message.append(buffer, n);
    ::close(pipeFds[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    ::chmod(QFile::encodeName(locked).constData(), 0755);
    QVERIFY2(WIFEXITED(status) && WEXITSTATUS(status) == 0, message.constData());
    QVERIFY2(message.contains("permission"), message.constData());
    QVERIFY2(!message.contains("disk space"), message.constData());
    QCOMPARE(fileBytes(path), old);
}

void TestSaveSafety::errnoClassification()
{
    QCOMPARE(classifyWriteError(ENOSPC), WriteProblem::DiskFull);
    QCOMPARE(classifyWriteError(EDQUOT), WriteProblem::DiskFull);
    QCOMPARE(classifyWriteError(EROFS), WriteProblem::ReadOnly);
    QCOMPARE(classifyWriteError(EACCES), WriteProblem::NoPermission);
    QCOMPARE(classifyWriteError(EPERM), WriteProblem::NoPermission);
    QCOMPARE(classifyWriteError(ENOENT), WriteProblem::FolderMissing);
    QCOMPARE(classifyWriteError(EIO), WriteProblem::Other);
    const QString folder = QStringLiteral("/x/y");
    QCOMPARE(describeWriteFailure(writeFailureFromErrno(EDQUOT), folder),
             QStringLiteral("the disk is full"));
    QVERIFY(describeWriteFailure(writeFailureFromErrno(EACCES), folder).contains(folder));
    QCOMPARE(describeWriteFailure(writeFailureFromErrno(EIO), folder),
             QString::fromLocal8Bit(std::strerror(EIO)));
}

void TestSaveSafety::replacedFileKeepsPermissions()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.finbook"));
    Document doc;
    buildSample(doc);
    QVERIFY(!saveFinbook(doc, path));
    QVERIFY(::chmod(QFile::encodeName(path).constData(), 0640) == 0);
    editHold(doc, 2);
    QVERIFY(!saveFinbook(doc, path));
    struct stat st;
    QVERIFY(::stat(QFile::encodeName(path).constData(), &st) == 0);
    QCOMPARE(int(st.st_mode & 07777), 0640);
}

namespace {
// Field 22 of /proc/PID/stat, read independently of the code under test; 0 when unreadable.
quint64 startTicks(pid_t pid)
{
    QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!stat.open(QIODevice::ReadOnly))
        return 0;
    const QByteArray line = stat.readAll();
    const QList<QByteArray> fields = line.mid(line.lastIndexOf(')') + 2).split(' ');
    return fields.size() > 19 ? fields.at(19).toULongLong() : 0;
}

void touch(const QString &path)
{
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
}
} // namespace

// A save removes the temporary files that killed saves left beside the file: those whose
// process is gone, including one whose pid now belongs to another process (pids are reused).
// A running saver's temporary file and files that are not Finbook's stay.
void TestSaveSafety::leftoversOfGoneSaversAreRemoved()
{
    const pid_t gone = ::fork();
    if (gone == 0)
        ::_exit(0);
    QVERIFY(gone > 0);
    ::waitpid(gone, nullptr, 0);
    const pid_t live = ::fork();
    if (live == 0) {
        ::pause();
        ::_exit(0);
    }
    QVERIFY(live > 0);
    const quint64 liveStart = startTicks(live);

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.finbook"));
    const auto leftover = [&](const QString &suffix) {
        return dir.filePath(QStringLiteral(".a.finbook.%1.tmp").arg(suffix));
    };
    const QString ofGone = leftover(QStringLiteral("%1-%2-k1").arg(gone).arg(liveStart));
    const QString ofGoneOld = leftover(QStringLiteral("%1-k2").arg(gone)); // older naming
    const QString ofLive = leftover(QStringLiteral("%1-%2-k3").arg(live).arg(liveStart));
    const QString ofLiveOld = leftover(QStringLiteral("%1-k4").arg(live));
    const QString reused = leftover(QStringLiteral("%1-%2-k5").arg(live).arg(liveStart + 977));
    const QString notOurs = leftover(QStringLiteral("notes"));
    const QString backupOfGone =
        dir.filePath(QStringLiteral(".a.finbook~.%1-%2-k6.tmp").arg(gone).arg(liveStart));
    for (const QString &file :
         {ofGone, ofGoneOld, ofLive, ofLiveOld, reused, notOurs, backupOfGone})
        touch(file);

    Document doc;
    buildSample(doc);
    QVERIFY(!saveFinbook(doc, path));
    ::kill(live, SIGKILL);
    ::waitpid(live, nullptr, 0);

    QVERIFY(!QFile::exists(ofGone));
    QVERIFY(!QFile::exists(ofGoneOld));
    QVERIFY(!QFile::exists(backupOfGone));
    QVERIFY(QFile::exists(ofLive));
    QVERIFY(QFile::exists(ofLiveOld));
    QVERIFY(QFile::exists(notOurs));
    if (liveStart == 0)
        QSKIP("no /proc here: a reused pid cannot be told from its first owner");
    QVERIFY2(!QFile::exists(reused), "a temporary file of a reused pid was kept");
}

// A save killed after keeping the backup (a hard link to the file) but before replacing the
// file leaves the file and its backup as two names of one file. The next save must still keep
// the backup and leave no temporary file: rename() between two links of one file is a no-op.
void TestSaveSafety::backupAlreadyLinkedToTheFileLeavesNoTemporary()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.finbook"));
    const QString backup = finbookBackupPath(path);
    Document doc;
    buildSample(doc);
    QVERIFY(!saveFinbook(doc, path));
    const QByteArray first = fileBytes(path);
    QVERIFY(::link(QFile::encodeName(path).constData(), QFile::encodeName(backup).constData()) ==
            0);
    editHold(doc, 3);
    QVERIFY(!saveFinbook(doc, path));
    QCOMPARE(fileBytes(backup), first);
    QVERIFY(fileBytes(path) != first);
    QCOMPARE(hiddenAndFiles(dir.path()),
             QStringList({QStringLiteral("a.finbook"), QStringLiteral("a.finbook~")}));
}

QTEST_GUILESS_MAIN(TestSaveSafety)
#include "tst_save_safety.moc"
