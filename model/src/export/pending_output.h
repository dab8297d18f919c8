// Output that reaches its target only when complete: a file written beside the target and
// renamed over it, or a hidden folder of files moved into the target folder. Every write is
// checked and synced to disk before the rename, so a full disk shows up as an error here and
// never as a short file at the target.
#pragma once

#include <QString>
#include <QStringList>
#include <QTemporaryDir>
#include <QTemporaryFile>

#include <functional>
#include <memory>
#include <optional>

namespace finbook::model {

// Writes `bytes` to `file` (open for writing), flushes and syncs it. The reason on failure.
std::optional<QString> writeSynced(QFile &file, const QByteArray &bytes);
// Creates or truncates `path` and writes `bytes` to it with writeSynced.
std::optional<QString> writeFileSynced(const QString &path, const QByteArray &bytes);

// Makes `folder` (and its parents) if missing; removes it again on destruction unless kept,
// when it was made here and is empty, so a failed export leaves no new empty folder behind.
class FolderGuard {
public:
    explicit FolderGuard(const QString &folder);
    ~FolderGuard();
    FolderGuard(const FolderGuard &) = delete;
    FolderGuard &operator=(const FolderGuard &) = delete;
    bool ok() const { return m_ok; }
    void keep() { m_created.clear(); }

private:
    QStringList m_created; // deepest first
    bool m_ok = false;
};

// A hidden temporary file beside `target`; commit() syncs it and renames it over the target.
// Until then, and after a failure, the temporary is removed on destruction.
class PendingFile {
public:
    explicit PendingFile(const QString &target);
    bool open(QString *reason); // creates the temporary (open for writing)
    QString path() const { return m_file ? m_file->fileName() : QString(); }
    QFile &file() { return *m_file; }
    // Syncs what is in the temporary (written here or by another program) and renames it to
    // `destination` (the target's path as the system names it: the encoded target, or other
    // bytes when its name is not valid in the file name encoding). Unless `replace`, a file
    // that appeared there meanwhile stays and `*appeared` is set.
    std::optional<QString> commit(const QByteArray &destination, bool replace = true,
                                  bool *appeared = nullptr);

private:
    QString m_target;
    std::unique_ptr<QTemporaryFile> m_file;
};

// A hidden folder inside `folder` collecting the files of a sequence; commit() moves them all
// into `folder`. Removed with whatever is left in it on destruction.
//
// The swap survives a kill at any point. Before its first rename it writes a journal (the
// names it moves, synced) into the hidden folder; the files it replaces are set aside in there
// too, and once every new file is in place the journal is marked done. A killed export leaves
// the hidden folder behind, and the next export to the folder finds it (TargetLock::
// removeLeftovers) and calls finishInterruptedSwap: a swap marked done is complete (the
// set-aside files go), one not done is undone (the folder gets back exactly its old files).
class PendingFolder {
public:
    explicit PendingFolder(const QString &folder);
    bool isValid() const { return m_staging.isValid(); }
    QString errorString() const { return m_staging.errorString(); }
    QString filePath(const QString &name) const { return m_staging.filePath(name); }
    // Moves files 0 .. count-1 (named by name(i)) into `folder` as a whole: the files they
    // replace, and the files named in `stale` (an earlier sequence's frames past this one's
    // end), are set aside until every new one is in place and then deleted; on a failure every
    // new file is taken out again and every set-aside one put back, so the folder is exactly as
    // before. Unless `replace`, a file that appeared at the target meanwhile is such a failure
    // (its path in `*appeared`), and `stale` must be empty.
    std::optional<QString> commit(qint64 count, const std::function<QString(qint64)> &name,
                                  bool replace, QString *appeared = nullptr,
                                  const QStringList &stale = {});

private:
    QString m_folder;
    QTemporaryDir m_staging;
};

// Finishes the swap of a hidden folder `staging` that a killed export left in `folder`: undone
// when it had not ended (new files taken out, set-aside ones put back), nothing to do when it
// had (or had not begun). The hidden folder may be deleted afterwards. Safe to run again after
// a kill during it.
void finishInterruptedSwap(const QString &folder, const QString &staging);

} // namespace finbook::model
