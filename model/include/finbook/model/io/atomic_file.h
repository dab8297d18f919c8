// Writing a whole file so that a crash, a kill or a full disk never leaves it half written.
//
// writeFileAtomically puts the bytes in a temporary file beside the target, written without
// any buffer in between (every write's error is seen), fsync'ed and closed with their errors
// checked; only then is the previous file kept as a backup and the temporary renamed over
// the target. QSaveFile is not used because Qt 6.4 renames even when the flush in commit()
// failed (a full disk left a 0-byte file) and ignores a failing sync.
#pragma once

#include <QByteArrayView>
#include <QString>

#include <functional>
#include <optional>

namespace finbook::model {

// What stopped a write, sorted by what the user can do about it.
enum class WriteProblem {
    DiskFull,      // ENOSPC, EDQUOT: free space or choose another disk
    ReadOnly,      // EROFS: the disk or folder is mounted read-only
    NoPermission,  // EACCES, EPERM: the user may not write there
    FolderMissing, // ENOENT, ENOTDIR: the folder is gone or is a file
    Other,         // anything else (EIO, ...): the system's own words
};

struct WriteFailure {
    WriteProblem problem = WriteProblem::Other;
    int systemError = 0; // the errno behind it
    QString detail;      // the system's description of systemError
};

WriteProblem classifyWriteError(int systemError);
WriteFailure writeFailureFromErrno(int systemError);

// The failure as a phrase that fits after "Could not save "x":", e.g. "the disk is full".
// `folder` is the folder being written to, named in the permission and missing-folder cases.
QString describeWriteFailure(const WriteFailure &failure, const QString &folder);

// Test seam: writes up to `size` bytes to descriptor `fd` like ::write (returns the count or
// -1 with errno set). Tests pass one that fails to prove what a failing disk does.
using WriteFunction = std::function<qint64(int fd, const char *data, qint64 size)>;

struct AtomicWriteOptions {
    // When set and the target exists, the target is kept under this name (a hard link, or a
    // copy where links are not supported) right before it is replaced.
    QString backupPath;
    WriteFunction write; // empty: ::write
};

// Replaces the file at `path` (a symbolic link is followed) by `bytes`. Promises: on success
// `path` holds exactly `bytes`, synced to the disk; on failure `path` and `backupPath` are
// exactly as before and no temporary file is left behind. New files get the usual
// permissions (0666 less the umask); a replaced file keeps its own.
std::optional<WriteFailure> writeFileAtomically(const QString &path, QByteArrayView bytes,
                                                const AtomicWriteOptions &options = {});

} // namespace finbook::model
