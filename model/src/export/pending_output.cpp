#include "pending_output.h"

#include "export_text.h"

#include <finbook/model/io/atomic_file.h>

#include <QDir>
#include <QFileInfo>

#include <cerrno>
#include <csignal>
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
void syncPendingFolder(const QString &folder)
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
    syncPendingFolder(QFileInfo(m_target).path());
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

// The swap's journal in the hidden folder: written as kJournalWriting, renamed to kJournal
// once synced (so it is whole or absent), renamed to kJournalDone when the swap has ended.
const QString kJournalWriting = QStringLiteral(".swap-writing");
const QString kJournal = QStringLiteral(".swap");
const QString kJournalDone = QStringLiteral(".swap-done");
const QByteArray kJournalHeader = "finbook-swap 1";

bool existsOrLinks(const QString &path)
{
    const QFileInfo info(path);
    return info.exists() || info.isSymLink();
}

struct Journal {
    QStringList moved; // new files moved into the folder
    QStringList stale; // old files only set aside
};

QByteArray journalBytes(const Journal &journal)
{
    QByteArray bytes = kJournalHeader + '\n';
    for (const QString &name : journal.moved)
        bytes += "n " + name.toUtf8().toPercentEncoding() + '\n';
    for (const QString &name : journal.stale)
        bytes += "s " + name.toUtf8().toPercentEncoding() + '\n';
    return bytes;
}

std::optional<Journal> readJournal(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return std::nullopt;
    const QList<QByteArray> lines = file.readAll().split('\n');
    if (lines.isEmpty() || lines.front() != kJournalHeader)
        return std::nullopt;
    Journal journal;
    for (const QByteArray &line : lines.mid(1)) {
        if (line.size() < 3 || line[1] != ' ')
            continue;
        const QString name = QString::fromUtf8(QByteArray::fromPercentEncoding(line.mid(2)));
        // Only plain names in the folder: a journal is never a way to reach elsewhere.
        if (name.isEmpty() || name.contains(QLatin1Char('/')) || name == QLatin1String(".") ||
            name == QLatin1String(".."))
            continue;
        (line[0] == 'n' ? journal.moved : journal.stale) << name;
    }
    return journal;
}

// Puts `folder` back as it was before the swap recorded in `journal`, whatever part of it was
// done: each new file in place goes back into the hidden folder, each set-aside file returns.
void undoSwap(const QString &folder, const QString &staging, const Journal &journal)
{
    const QDir target(folder), hidden(staging), aside(hidden.filePath(asideName()));
    for (const QString &name : journal.moved) {
        if (!existsOrLinks(hidden.filePath(name)) && existsOrLinks(target.filePath(name)))
            renameOver(target.filePath(name), hidden.filePath(name));
        if (existsOrLinks(aside.filePath(name)))
            renameOver(aside.filePath(name), target.filePath(name));
    }
    for (const QString &name : journal.stale)
        if (existsOrLinks(aside.filePath(name)))
            renameOver(aside.filePath(name), target.filePath(name));
    syncPendingFolder(folder);
}

// Test hook: FINBOOK_TEST_KILL_AT_SWAP_STEP=k kills the process (SIGKILL, as a crash or a
// kill -9 would) just before the k-th rename of a sequence's swap (1 = the journal's), so a
// test can stop it at every step. Unset (people never set it): 0, never.
int killAtSwapStep()
{
    bool ok = false;
    const int step = qEnvironmentVariableIntValue("FINBOOK_TEST_KILL_AT_SWAP_STEP", &ok);
    return ok ? step : 0;
}
} // namespace

std::optional<QString> PendingFolder::commit(qint64 count,
                                             const std::function<QString(qint64)> &name,
                                             bool replace, QString *appeared,
                                             const QStringList &stale)
{
    const int killAt = killAtSwapStep();
    int step = 0;
    const auto nextStep = [&] {
        if (++step == killAt)
            ::raise(SIGKILL);
    };
    syncPendingFolder(m_staging.path());
    const QDir folder(m_folder), hidden(m_staging.path()), aside(m_staging.filePath(asideName()));
    if ((replace || !stale.isEmpty()) && !QDir().mkpath(aside.path()))
        return Export::tr("a folder cannot be created in it");
    Journal journal;
    journal.moved.reserve(qsizetype(count));
    for (qint64 i = 0; i < count; ++i)
        journal.moved << name(i);
    journal.stale = stale;
    if (auto reason = writeFileSynced(hidden.filePath(kJournalWriting), journalBytes(journal)))
        return reason;
    nextStep();
    if (auto reason = renameOver(hidden.filePath(kJournalWriting), hidden.filePath(kJournal)))
        return reason;
    syncPendingFolder(m_staging.path());
    const auto fail = [&](const QString &reason) {
        undoSwap(m_folder, m_staging.path(), journal);
        QFile::remove(hidden.filePath(kJournal));
        return std::optional<QString>(reason);
    };
    for (const QString &file : std::as_const(journal.moved)) {
        const QString target = folder.filePath(file);
        if (replace && existsOrLinks(target)) {
            if (QFileInfo(target).isDir() && !QFileInfo(target).isSymLink())
                return fail(Export::tr("\"%1\" is a folder where a file should go")
                                .arg(QDir::toNativeSeparators(target)));
            nextStep();
            if (auto reason = renameOver(target, aside.filePath(file)))
                return fail(*reason);
        }
        nextStep();
        if (!renameNoReplace(hidden.filePath(file), target)) {
            if (errno == EEXIST && appeared)
                *appeared = target;
            return fail(systemError());
        }
    }
    for (const QString &file : stale) {
        const QString target = folder.filePath(file);
        if (!existsOrLinks(target) || (QFileInfo(target).isDir() && !QFileInfo(target).isSymLink()))
            continue;
        nextStep();
        if (auto reason = renameOver(target, aside.filePath(file)))
            return fail(*reason);
    }
    syncPendingFolder(m_folder);
    // Done: from here a kill leaves the new files, and the hidden folder only the old ones.
    nextStep();
    renameOver(hidden.filePath(kJournal), hidden.filePath(kJournalDone));
    syncPendingFolder(m_staging.path());
    return std::nullopt;
}

void finishInterruptedSwap(const QString &folder, const QString &staging)
{
    const QDir hidden(staging);
    if (existsOrLinks(hidden.filePath(kJournalDone)) || !existsOrLinks(hidden.filePath(kJournal)))
        return; // ended, or not begun (a journal still being written moved nothing)
    if (const auto journal = readJournal(hidden.filePath(kJournal))) {
        undoSwap(folder, staging, *journal);
        QFile::remove(hidden.filePath(kJournal));
        syncPendingFolder(staging);
    }
}

} // namespace finbook::model
