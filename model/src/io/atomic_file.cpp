// writeFileAtomically: temporary file, unbuffered checked writes, fsync, rename, backup.
//
// The order is what makes it safe: nothing the user already has (the target, its backup) is
// touched until the new bytes are known to be on the disk, and the old backup is replaced only
// once the new file is in place. The current file is first kept under a temporary name (a
// hard link, or a copy), so each step can be undone: a full disk, a read-only folder, a failed
// rename or a kill at any moment leaves the target old or new and the backup the old backup,
// or (once the target is new) the file it replaced.
#include "../finbook_file_tr.h"

#include <finbook/model/io/atomic_file.h>
#include <finbook/model/io/atomic_file_faults.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRandomGenerator>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace finbook::model {

namespace {
using file_format::FinbookFile;

AtomicFaultHook &faultHook()
{
    static AtomicFaultHook hook;
    return hook;
}

// Runs `call` (a system call returning -1 and errno on failure) unless the test hook makes
// this step fail first.
template <class Call> int step(AtomicStep which, Call call)
{
    if (const AtomicFaultHook &hook = faultHook(); hook) {
        if (const int error = hook(which); error != 0) {
            errno = error;
            return -1;
        }
    }
    return call();
}

QByteArray encoded(const QString &path)
{
    return QFile::encodeName(path);
}

// Closes on scope exit unless released; used on error paths, where close's own error no
// longer matters.
class FdGuard {
public:
    explicit FdGuard(int fd)
        : m_fd(fd)
    {}
    ~FdGuard()
    {
        if (m_fd >= 0)
            ::close(m_fd);
    }
    FdGuard(const FdGuard &) = delete;
    FdGuard &operator=(const FdGuard &) = delete;
    int get() const { return m_fd; }
    int release() { return std::exchange(m_fd, -1); }

private:
    int m_fd;
};

QString temporaryStem(const QString &target)
{
    QString stem = QFileInfo(target).fileName();
    if (encoded(stem).size() > 200) // keep the temporary name under NAME_MAX
        stem = QStringLiteral("finbook");
    return QStringLiteral(".%1.").arg(stem);
}

// When the process `pid` started, in clock ticks since boot (field 22 of /proc/PID/stat); 0
// when that cannot be read (no /proc). Together with the pid it names one process: a pid alone
// is reused, quickly where pid_max is small or the lowest free pid is handed out.
quint64 processStartTicks(qint64 pid)
{
    QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!stat.open(QIODevice::ReadOnly))
        return 0;
    const QByteArray line = stat.read(4096);
    const qsizetype close = line.lastIndexOf(')'); // the command name may hold spaces
    if (close < 0)
        return 0;
    // After the name: state (field 3) ... starttime (field 22).
    const QList<QByteArray> fields = line.mid(close + 2).split(' ');
    if (fields.size() < 20)
        return 0;
    bool ok = false;
    const quint64 ticks = fields.at(19).toULongLong(&ok);
    return ok ? ticks : 0;
}

// A name beside `target` for a temporary file: hidden, with this process's id and start time
// (so a later save can tell a killed save's leftover from a live one, even when the pid has
// been reused) and a random part (so two processes saving the same file never write into each
// other's temporary file).
QString siblingName(const QString &target)
{
    static const quint64 startTicks = processStartTicks(::getpid());
    return QFileInfo(target).dir().filePath(
        temporaryStem(target) +
        QStringLiteral("%1-%2-%3.tmp")
            .arg(::getpid())
            .arg(startTicks)
            .arg(QString::number(QRandomGenerator::global()->generate64(), 36)));
}

// Whether the process that named a temporary file `pid-start-random.tmp` (or, from older
// versions, `pid-random.tmp`) is still running: its pid is alive and, when both start times
// are known, it is the same process rather than a later one given the same pid.
bool saverAlive(const QString &suffix)
{
    const QStringList parts = suffix.split(QLatin1Char('-'));
    bool ok = false;
    const qint64 pid = parts.value(0).toLongLong(&ok);
    if (!ok || pid <= 0)
        return true; // not one of ours: leave it
    if (pid == ::getpid())
        return true;
    if (::kill(pid_t(pid), 0) != 0 && errno == ESRCH)
        return false;
    if (parts.size() < 3)
        return true;
    const quint64 recorded = parts.at(1).toULongLong(&ok);
    const quint64 now = processStartTicks(pid);
    return !ok || recorded == 0 || now == 0 || now == recorded;
}

// Removes the temporary files of `target` left by saves that were killed: those whose process
// is gone. A live process's temporary (another Finbook saving the same file) is left alone.
void removeLeftovers(const QString &target)
{
    const QDir dir = QFileInfo(target).dir();
    const QString stem = temporaryStem(target);
    // The name is never part of a pattern: "[", "*" or "?" in it would be wildcards.
    for (const QString &name :
         dir.entryList({QStringLiteral("*.tmp")}, QDir::Files | QDir::Hidden)) {
        if (!name.startsWith(stem))
            continue;
        const QString suffix = name.mid(stem.size()).chopped(4); // without ".tmp"
        if (!saverAlive(suffix))
            ::unlink(encoded(dir.filePath(name)).constData());
    }
}

// A new, exclusive file beside `target`, its name in `temporary`; -1 and errno on failure.
int createTemporary(const QString &target, QString &temporary)
{
    for (int attempt = 0; attempt < 64; ++attempt) {
        temporary = siblingName(target);
        const int fd = step(AtomicStep::CreateTemporary, [&] {
            return ::open(encoded(temporary).constData(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC,
                          0666);
        });
        if (fd >= 0 || errno != EEXIST)
            return fd;
    }
    errno = EEXIST;
    return -1;
}

// Writes everything or returns the errno that stopped it. A write that reports no progress
// is a device that will not take more: counted as a full disk rather than looping.
int writeAll(int fd, QByteArrayView bytes, const WriteFunction &write)
{
    const char *p = bytes.data();
    qint64 left = bytes.size();
    while (left > 0) {
        const qint64 chunk = std::min<qint64>(left, qint64(1) << 30);
        const qint64 n = write ? write(fd, p, chunk) : qint64(::write(fd, p, std::size_t(chunk)));
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            return errno != 0 ? errno : EIO;
        if (n == 0)
            return ENOSPC;
        p += n;
        left -= n;
    }
    return 0;
}

// fsync and close, both checked: NFS and some FUSE file systems report a failed write only
// here.
int syncAndClose(FdGuard &fd)
{
    if (step(AtomicStep::SyncTemporary, [&] { return ::fsync(fd.get()); }) != 0)
        return errno;
    if (step(AtomicStep::CloseTemporary, [&] { return ::close(fd.release()); }) != 0)
        return errno;
    return 0;
}

// The folder entry of a rename reaches the disk with the folder's own fsync. Its failure is
// not reported: some file systems refuse fsync on folders, and the file's data is safe already.
void syncFolder(const QString &path)
{
    const int fd = ::open(encoded(QFileInfo(path).absolutePath()).constData(),
                          O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
}

// Copies `from` into a new temporary file beside `to` and returns its path; for file systems
// without hard links.
std::optional<int> copyToTemporary(const QString &from, const QString &to, QString &temporary)
{
    FdGuard in(::open(encoded(from).constData(), O_RDONLY | O_CLOEXEC));
    if (in.get() < 0)
        return errno;
    FdGuard out(createTemporary(to, temporary));
    if (out.get() < 0)
        return errno;
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(in.get(), buffer, sizeof(buffer));
        if (n < 0 && errno == EINTR)
            continue;
        int error = n < 0 ? errno : 0;
        if (n > 0)
            error = writeAll(out.get(), QByteArrayView(buffer, n), {});
        if (error == 0 && n == 0)
            error = syncAndClose(out);
        if (error != 0 || n == 0) {
            if (error != 0)
                ::unlink(encoded(temporary).constData());
            return error == 0 ? std::nullopt : std::optional<int>(error);
        }
    }
}

WriteFailure backupFailure(const QString &backup, int error)
{
    WriteFailure failure = writeFailureFromErrno(error);
    failure.detail = FinbookFile::tr("the backup \"%1\" cannot be written (%2)")
                         .arg(QFileInfo(backup).fileName(), failure.detail);
    if (failure.problem == WriteProblem::Other || failure.problem == WriteProblem::FolderMissing)
        failure.problem = WriteProblem::Other; // the sentence is about the backup, not the folder
    return failure;
}

// Keeps the current `target` under a new temporary name beside `backup` (in `kept`): a hard
// link (free even for a huge file) or a copy. Nothing the user has changes. Empty `kept` and
// no failure when there is no target yet.
std::optional<WriteFailure> keepCurrent(const QString &target, const QString &backup, QString &kept)
{
    kept.clear();
    struct stat st;
    if (::lstat(encoded(target).constData(), &st) != 0)
        return std::nullopt; // nothing to keep
    QString temporary;
    int error = EEXIST;
    for (int attempt = 0; attempt < 64 && error == EEXIST; ++attempt) {
        temporary = siblingName(backup);
        error = step(AtomicStep::LinkBackup,
                     [&] {
                         return ::link(encoded(target).constData(), encoded(temporary).constData());
                     }) == 0
                    ? 0
                    : errno;
    }
    if (error == EXDEV || error == EPERM || error == ENOTSUP || error == EMLINK) { // no links
        error = step(AtomicStep::CopyBackup, [] { return 0; }) == 0
                    ? copyToTemporary(target, backup, temporary).value_or(0)
                    : errno;
    }
    if (error != 0)
        return backupFailure(backup, error);
    kept = temporary;
    return std::nullopt;
}

// The new file is in place at `target`; `kept` (the file it replaced) becomes the backup. If
// that fails, the replaced file goes back to `target`, so target and backup are as before the
// save; only if that fails too does the save stand (the new file is complete) with the old
// backup kept and the replaced file left at `kept`.
std::optional<WriteFailure> replaceBackup(const QString &target, const QString &backup,
                                          const QString &kept)
{
    if (step(AtomicStep::ReplaceBackup, [&] {
            return ::rename(encoded(kept).constData(), encoded(backup).constData());
        }) == 0) {
        // rename() of two links to one file does nothing and succeeds (a backup linked to the
        // target by an older Finbook killed mid-save): the temporary link would stay behind.
        // Removing it is harmless once it was moved.
        ::unlink(encoded(kept).constData());
        return std::nullopt;
    }
    const int error = errno;
    if (step(AtomicStep::RestoreTarget,
             [&] { return ::rename(encoded(kept).constData(), encoded(target).constData()); }) != 0)
        return std::nullopt;
    return backupFailure(backup, error);
}

QString resolvedTarget(const QString &path)
{
    const QFileInfo info(path);
    if (!info.isSymLink())
        return path;
    const QString canonical = info.canonicalFilePath();
    return canonical.isEmpty() ? info.symLinkTarget() : canonical;
}
} // namespace

WriteProblem classifyWriteError(int systemError)
{
    switch (systemError) {
    case ENOSPC:
    case EDQUOT:
        return WriteProblem::DiskFull;
    case EROFS:
        return WriteProblem::ReadOnly;
    case EACCES:
    case EPERM:
        return WriteProblem::NoPermission;
    case ENOENT:
    case ENOTDIR:
        return WriteProblem::FolderMissing;
    default:
        return WriteProblem::Other;
    }
}

WriteFailure writeFailureFromErrno(int systemError)
{
    return WriteFailure{classifyWriteError(systemError), systemError,
                        QString::fromLocal8Bit(std::strerror(systemError))};
}

QString describeWriteFailure(const WriteFailure &failure, const QString &folder)
{
    const QString shown = QDir::toNativeSeparators(folder);
    switch (failure.problem) {
    case WriteProblem::DiskFull:
        return FinbookFile::tr("the disk is full");
    case WriteProblem::ReadOnly:
        return FinbookFile::tr("the disk is read-only");
    case WriteProblem::NoPermission:
        return FinbookFile::tr("you do not have permission to write in the folder \"%1\"")
            .arg(shown);
    case WriteProblem::FolderMissing:
        return FinbookFile::tr("the folder \"%1\" does not exist").arg(shown);
    case WriteProblem::Other:
        break;
    }
    return failure.detail;
}

std::optional<WriteFailure> writeFileAtomically(const QString &path, QByteArrayView bytes,
                                                const AtomicWriteOptions &options)
{
    const QString target = resolvedTarget(path);
    QString temporary;
    FdGuard fd(createTemporary(target, temporary));
    if (fd.get() < 0)
        return writeFailureFromErrno(errno);
    const auto abandon = [&](int error) {
        ::unlink(encoded(temporary).constData());
        return writeFailureFromErrno(error);
    };
    struct stat st;
    if (::stat(encoded(target).constData(), &st) == 0 && S_ISREG(st.st_mode))
        ::fchmod(fd.get(), st.st_mode & 07777); // a replaced file keeps its permissions
    if (const int error = writeAll(fd.get(), bytes, options.write))
        return abandon(error);
    if (const int error = syncAndClose(fd))
        return abandon(error);
    QString kept; // the current file under a temporary name, until it is the backup
    if (!options.backupPath.isEmpty()) {
        if (auto failure = keepCurrent(target, options.backupPath, kept)) {
            ::unlink(encoded(temporary).constData());
            return failure;
        }
    }
    if (step(AtomicStep::ReplaceTarget, [&] {
            return ::rename(encoded(temporary).constData(), encoded(target).constData());
        }) != 0) {
        const int error = errno;
        if (!kept.isEmpty())
            ::unlink(encoded(kept).constData());
        return abandon(error);
    }
    if (!kept.isEmpty()) {
        syncFolder(target); // the new file's name first: a crash now keeps it
        if (auto failure = replaceBackup(target, options.backupPath, kept)) {
            syncFolder(target);
            return failure; // the old file is back; the new one is gone with its name
        }
    }
    syncFolder(target);
    removeLeftovers(target);
    if (!options.backupPath.isEmpty())
        removeLeftovers(options.backupPath);
    return std::nullopt;
}

AtomicFaultHook setAtomicFaultHook(AtomicFaultHook hook)
{
    return std::exchange(faultHook(), std::move(hook));
}

} // namespace finbook::model
