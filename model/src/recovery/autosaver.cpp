// Autosaver: timers and the snapshot on the GUI thread, the writing on RecoveryWriter's thread.
#include "../finbook_file_tr.h"
#include "recovery_writer.h"

#include <finbook/model/document.h>
#include <finbook/model/io/atomic_file.h>
#include <finbook/model/recovery/autosaver.h>
#include <finbook/model/reference/reference_layer.h>
#include <finbook/model/sound/soundtrack.h>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QSemaphore>

#include <new>

namespace finbook::model {

Autosaver::Autosaver(Document *document, const RecoverySession *session, QObject *parent)
    : QObject(parent)
    , m_doc(document)
    , m_session(session)
{
    m_thread.setObjectName(QStringLiteral("Finbook autosave"));
    m_writer = new RecoveryWriter;
    m_writer->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_writer, &QObject::deleteLater);
    connect(m_writer, &RecoveryWriter::finished, this, &Autosaver::finished);
    m_thread.start(QThread::LowPriority);

    connect(&m_interval, &QTimer::timeout, this, &Autosaver::autosaveNow);
    setInterval(kDefaultIntervalMs);
    m_quiet.setSingleShot(true);
    m_quiet.setInterval(kDefaultBurstQuietMs);
    connect(&m_quiet, &QTimer::timeout, this, &Autosaver::autosaveNow);

    QUndoStack *stack = document->undoStack();
    connect(stack, &QUndoStack::indexChanged, this, &Autosaver::edited);
    connect(stack, &QUndoStack::cleanChanged, this, &Autosaver::cleanChanged);
    connect(document, &Document::documentReset, this, &Autosaver::documentReset);
}

Autosaver::~Autosaver()
{
    drain(); // quit() alone would drop the jobs still queued
    m_thread.quit();
    m_thread.wait();
}

void Autosaver::setInterval(int ms)
{
    m_intervalMs = std::max(0, ms);
    m_interval.stop();
    if (m_intervalMs > 0) {
        m_interval.setInterval(m_intervalMs);
        m_interval.start();
    }
}

void Autosaver::setBurst(int edits, int quietMs)
{
    m_burstEdits = std::max(1, edits);
    m_quiet.setInterval(std::max(0, quietMs));
}

void Autosaver::setDocumentInfo(const QString &title, const QString &originalPath)
{
    m_title = title;
    m_originalPath = originalPath;
}

QString Autosaver::copyPath() const
{
    return m_session->copyPath(1);
}

void Autosaver::edited()
{
    if (m_doc->undoStack()->isClean())
        return;
    m_changed = true;
    if (++m_editsSinceCopy >= m_burstEdits)
        m_quiet.start(); // restarted by each edit: the copy waits for a pause
}

void Autosaver::autosaveNow()
{
    if (!m_changed || !m_session->isValid() || m_intervalMs <= 0 || m_doc->undoStack()->isClean())
        return;
    QElapsedTimer clock;
    clock.start();
    RecoveryWriter::Snapshot snapshot{
        m_doc->layers(),
        m_doc->settings(),
        RecoveryInfo{m_title, m_originalPath, QDateTime::currentDateTimeUtc(), m_doc->frameCount()},
        copyPath(),
        m_doc->referenceLayer().reference(),
        m_doc->soundtrack().clips(),
        m_doc->camera(),
        m_doc->palette(),
        m_doc->swapSets()};
    QMetaObject::invokeMethod(
        m_writer, [writer = m_writer, s = std::move(snapshot)] { writer->write(s); },
        Qt::QueuedConnection);
    m_lastSnapshotNs = clock.nsecsElapsed();
    m_changed = false;
    m_editsSinceCopy = 0;
    m_quiet.stop();
}

void Autosaver::discard()
{
    m_changed = false;
    m_editsSinceCopy = 0;
    m_quiet.stop();
    QMetaObject::invokeMethod(
        m_writer, [writer = m_writer, path = copyPath()] { writer->remove(path); },
        Qt::QueuedConnection);
}

void Autosaver::adopt(const QString &orphanPath)
{
    QMetaObject::invokeMethod(
        m_writer,
        [writer = m_writer, from = orphanPath, to = copyPath()] { writer->rename(from, to); },
        Qt::QueuedConnection);
}

void Autosaver::drain()
{
    QSemaphore done;
    QMetaObject::invokeMethod(
        m_writer, [&done] { done.release(); }, Qt::QueuedConnection);
    done.acquire();
}

void Autosaver::waitForIdle()
{
    drain();
    QCoreApplication::sendPostedEvents(this); // deliver the finished() signals queued to us
}

void Autosaver::cleanChanged(bool clean)
{
    if (clean)
        discard(); // saved (or undone back to what is saved): the file itself is the copy
}

void Autosaver::documentReset()
{
    discard();
}

void Autosaver::finished(const QString &path, const QString &error)
{
    if (error.isEmpty())
        emit copyWritten(path);
    else
        emit copyFailed(
            file_format::FinbookFile::tr("Autosave could not write a recovery copy: %1.")
                .arg(error));
}

} // namespace finbook::model
