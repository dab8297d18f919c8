// Autosave: a recovery copy of a document with unsaved changes, written every few minutes
// and after a burst of edits, off the GUI thread.
//
// The GUI thread only takes a snapshot (the layers copied: stroke data is immutable and
// shared, so this costs pointers, not points) and posts it; a worker thread serializes it,
// renders the thumbnail and writes the copy atomically (io/atomic_file.h), so a crash during
// autosave leaves the previous copy whole. Every file operation (write, remove, adopt) runs on
// that one worker in the order asked, so a discard can never be overtaken by a write.
//
// The copy is removed when the document becomes clean (saved, or undone back to its saved
// state), when it is replaced (new, open) and on discard() (the window closed).
#pragma once

#include <finbook/model/recovery/recovery_store.h>

#include <QObject>
#include <QThread>
#include <QTimer>

namespace finbook::model {

class Document;
class RecoveryWriter;

class Autosaver : public QObject {
    Q_OBJECT
public:
    static constexpr int kDefaultIntervalMs = 2 * 60 * 1000;
    static constexpr int kDefaultBurstEdits = 40;
    static constexpr int kDefaultBurstQuietMs = 3000;

    // `session` must outlive this; with an invalid session nothing is ever written.
    Autosaver(Document *document, const RecoverySession *session, QObject *parent = nullptr);
    // Finishes what the worker has queued, then stops it. The copy stays unless discarded:
    // quitting with unsaved changes is what it is for.
    ~Autosaver() override;

    // Milliseconds between copies while there are unsaved changes; 0 turns autosave off.
    void setInterval(int ms);
    int interval() const { return m_intervalMs; }
    // After `edits` edits, a copy is taken once editing pauses for `quietMs`.
    void setBurst(int edits, int quietMs);
    // What the copy says about the document (the window's title and file).
    void setDocumentInfo(const QString &title, const QString &originalPath);

    // Takes a copy now if the document has changes that no copy holds yet.
    void autosaveNow();
    // Removes the copy (and cancels nothing already written: it runs after it).
    void discard();
    // Makes an orphan copy (RecoverySession::orphans) this document's copy, e.g. after it was
    // restored: it then lives and dies with this document.
    void adopt(const QString &orphanPath);
    // Blocks until the worker has done everything queued (tests, the benchmark).
    void waitForIdle();

    QString copyPath() const;
    // Nanoseconds the GUI thread spent in the last autosaveNow() (the snapshot).
    qint64 lastSnapshotNanoseconds() const { return m_lastSnapshotNs; }

signals:
    void copyWritten(const QString &path);
    // One translated sentence: why the copy could not be written ("the disk is full").
    void copyFailed(const QString &message);

private:
    void edited();
    void cleanChanged(bool clean);
    void documentReset();
    void finished(const QString &path, const QString &error);
    void drain();

    Document *m_doc;
    const RecoverySession *m_session;
    QThread m_thread;
    RecoveryWriter *m_writer = nullptr;
    QTimer m_interval;
    int m_intervalMs = 0; // 0: autosave is off
    QTimer m_quiet;
    int m_burstEdits = kDefaultBurstEdits;
    int m_editsSinceCopy = 0;
    bool m_changed = false; // edits no copy holds yet
    QString m_title;
    QString m_originalPath;
    qint64 m_lastSnapshotNs = 0;
};

} // namespace finbook::model
