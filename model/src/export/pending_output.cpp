#include "pending_output.h"

#include "export_text.h"

#include <finbook/model/io/atomic_file.h>

#include <QDir>
#include <QFileInfo>

#include <cerrno>
#include <cstdio>
#include <cstring>

#ifdef Q_OS_UNIX
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace finbook::model {

namespace {
// "the disk is full" and "the disk is read-only" in the user's words (io/atomic_file.h);
// anything else as the system says it.
QString systemError()
{
    const WriteFailure failure = writeFailureFromErrno(errno);
    if (failure.problem == WriteProblem::DiskFull || failure.problem == WriteProblem::ReadOnly)
        return describeWriteFailure(failure, QString());
    return failure.detail;
}

bool syncDescriptor(int fd)
{
#ifdef Q_OS_UNIX
    return fd >= 0 && ::fsync(fd) == 0;
#else
    Q_UNUSED(fd);
    return true;
#endif
}

// A renamed file survives a crash only once its directory entry is on disk too.
void syncFolder(const QString &folder)
{
#ifdef Q_OS_UNIX
    const int fd = ::open(QFile::encodeName(folder).constData(), O_RDONLY | O_DIRECTORY);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
#else
    Q_UNUSED(folder);
#endif
}

// Temporary files are private (0600); the export gets what a new file gets (0666 less the
// umask), or the permissions of the file it replaces. The umask is read from /proc rather
// than with umask(), which would change it for every thread for a moment.
QFileDevice::Permissions outputPermissions(const QByteArray &target)
{
    uint mask = 022;
    QFile status(QStringLiteral("/proc/self/status"));
    if (status.open(QIODevice::ReadOnly)) {
        for (const QByteArray &line : status.readAll().split('\n')) {
            bool ok = false;
            const uint value = line.startsWith("Umask:") ? line.mid(6).trimmed().toUInt(&ok, 8) : 0;
            if (ok)
                mask = value;
        }
    }
    uint mode = 0666u & ~mask;
#ifdef Q_OS_UNIX
    struct stat replaced {};
    if (::stat(target.constData(), &replaced) == 0)
        mode = replaced.st_mode & 0777u;
#else
    Q_UNUSED(target);
#endif
    QFileDevice::Permissions permissions;
    const std::pair<uint, QFileDevice::Permission> bits[] = {
        {0400, QFileDevice::ReadOwner}, {0200, QFileDevice::WriteOwner},
        {0040, QFileDevice::ReadGroup}, {0020, QFileDevice::WriteGroup},
        {0004, QFileDevice::ReadOther}, {0002, QFileDevice::WriteOther}};
    for (const auto &[bit, permission] : bits)
        if (mode & bit)
            permissions |= permission;
    // Qt's "user" bits follow the owner's on Unix; set them too so they do not mask it.
    if (mode & 0400)
        permissions |= QFileDevice::ReadUser;
    if (mode & 0200)
        permissions |= QFileDevice::WriteUser;
    return permissions;
}

// Renames `from` to `to` unless `to` exists (then EEXIST): renameat2's RENAME_NOREPLACE, or a
// hard link and an unlink where the file system has no such rename.
bool renameNoReplace(const QByteArray &a, const QByteArray &b)
{
#if defined(Q_OS_LINUX)
    if (::renameat2(AT_FDCWD, a.constData(), AT_FDCWD, b.constData(), RENAME_NOREPLACE) == 0)
        return true;
    if (errno != EINVAL && errno != ENOSYS)
        return false;
#endif
#ifdef Q_OS_UNIX
    if (::link(a.constData(), b.constData()) != 0)
        return false;
    ::unlink(a.constData());
    return true;
#else
    return QFile::rename(QFile::decodeName(a), QFile::decodeName(b));
#endif
}

bool renameNoReplace(const QString &from, const QString &to)
{
    return renameNoReplace(QFile::encodeName(from), QFile::encodeName(to));
}

std::optional<QString> renameOver(const QByteArray &from, const QByteArray &to)
{
    // std::rename replaces an existing target atomically on POSIX (QFile::rename refuses to).
    if (std::rename(from.constData(), to.constData()) != 0)
        return systemError();
    return std::nullopt;
}

std::optional<QString> renameOver(const QString &from, const QString &to)
{
    return renameOver(QFile::encodeName(from), QFile::encodeName(to));
}
} // namespace

std::optional<QString> writeSynced(QFile &file, const QByteArray &bytes)
{
#ifdef Q_OS_UNIX
    // Straight to the descriptor: QFile's buffer would turn ENOSPC into "Unknown error".
    if (!file.flush())
        return file.errorString();
    const char *data = bytes.constData();
    qint64 left = bytes.size();
    while (left > 0) {
        const ssize_t written = ::write(file.handle(), data, std::size_t(left));
        if (written < 0 && errno == EINTR)
            continue;
        if (written <= 0)
            return systemError();
        data += written;
        left -= written;
    }
#else
    if (file.write(bytes) != bytes.size() || !file.flush())
        return file.errorString();
#endif
    if (!syncDescriptor(file.handle()))
        return systemError();
    return std::nullopt;
}

std::optional<QString> writeFileSynced(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return file.errorString();
    if (auto reason = writeSynced(file, bytes))
        return reason;
    file.close();
    if (file.error() != QFileDevice::NoError)
        return file.errorString();
    return std::nullopt;
}

FolderGuard::FolderGuard(const QString &folder)
{
    QString path = QDir::cleanPath(QFileInfo(folder).absoluteFilePath());
    while (!path.isEmpty() && !QFileInfo(path).exists()) {
        m_created << path;
        const QString parent = QFileInfo(path).path();
        if (parent == path)
            break;
        path = parent;
    }
    m_ok = QDir().mkpath(folder) && QFileInfo(folder).isDir();
}

FolderGuard::~FolderGuard()
{
    for (const QString &path : m_created)
        if (!QDir().rmdir(path)) // only empty folders go
            break;
}

PendingFile::PendingFile(const QString &target)
    : m_target(target)
{}

bool PendingFile::open(QString *reason)
{
    const QFileInfo info(m_target);
    m_file = std::make_unique<QTemporaryFile>(
        info.dir().filePath(QStringLiteral(".%1.XXXXXX.part").arg(info.fileName())));
    if (m_file->open())
        return true;
    if (reason)
        *reason = m_file->errorString();
    return false;
}

std::optional<QString> PendingFile::commit(const QByteArray &destination, bool replace,
                                           bool *appeared)
{
    if (!m_file)
        return QStringLiteral("no file");
    m_file->close();
    QFile written(m_file->fileName());
    if (!written.open(QIODevice::ReadOnly))
        return written.errorString();
    if (!syncDescriptor(written.handle()))
        return systemError();
    written.close();
    QFile::setPermissions(m_file->fileName(), outputPermissions(destination));
    const QByteArray from = QFile::encodeName(m_file->fileName());
    if (!replace && !renameNoReplace(from, destination)) {
        if (appeared)
            *appeared = errno == EEXIST;
        return systemError();
    }
    if (replace)
        if (auto reason = renameOver(from, destination))
            return reason;
    m_file->setAutoRemove(false);
    syncFolder(QFileInfo(m_target).path());
    return std::nullopt;
}

PendingFolder::PendingFolder(const QString &folder)
    : m_folder(folder)
    , m_staging(QDir(folder).filePath(QStringLiteral(".finbook-export-XXXXXX")))
{}

namespace {
QString asideName()
{
    return QStringLiteral(".replaced");
}

bool existsOrLinks(const QString &path)
{
    const QFileInfo info(path);
    return info.exists() || info.isSymLink();
}
} // namespace

std::optional<QString> PendingFolder::commit(qint64 count,
                                             const std::function<QString(qint64)> &name,
                                             bool replace, QString *appeared)
{
    syncFolder(m_staging.path());
    const QDir folder(m_folder), aside(m_staging.filePath(asideName()));
    if (replace && !QDir().mkpath(aside.path()))
        return Export::tr("a folder cannot be created in it");
    for (qint64 i = 0; i < count; ++i) {
        const QString file = name(i), target = folder.filePath(file);
        std::optional<QString> reason;
        if (replace && existsOrLinks(target)) {
            if (QFileInfo(target).isDir() && !QFileInfo(target).isSymLink())
                reason = Export::tr("\"%1\" is a folder where a file should go")
                             .arg(QDir::toNativeSeparators(target));
            else
                reason = renameOver(target, aside.filePath(file));
        }
        if (!reason && !renameNoReplace(m_staging.filePath(file), target)) {
            if (errno == EEXIST && appeared)
                *appeared = target;
            reason = systemError();
        }
        if (reason) {
            rollBack(i, name);
            return reason;
        }
    }
    syncFolder(m_folder);
    return std::nullopt;
}

void PendingFolder::rollBack(qint64 upTo, const std::function<QString(qint64)> &name)
{
    const QDir folder(m_folder), aside(m_staging.filePath(asideName()));
    for (qint64 i = 0; i <= upTo; ++i) {
        const QString file = name(i);
        if (i < upTo) // in place: take it out again
            renameOver(folder.filePath(file), m_staging.filePath(file));
        if (existsOrLinks(aside.filePath(file)))
            renameOver(aside.filePath(file), folder.filePath(file));
    }
    syncFolder(m_folder);
}

} // namespace finbook::model
