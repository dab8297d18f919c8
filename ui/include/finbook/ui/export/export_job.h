// ExportJob: one model::exportAnimation run on its own thread, so the window stays responsive.
//
// The job works on a snapshot (model::ExportSource), never on the live document, so editing
// during an export is safe. progressed() is emitted on the worker thread (connections to
// GUI objects are queued); finished() once, when the worker is done. cancel() is safe from
// any thread; the export then stops at the next frame and leaves nothing at the target.
#pragma once

#include <finbook/model/export/exporter.h>

#include <QObject>
#include <QStringList>

#include <atomic>

class QThread;

namespace finbook::ui {

class ExportJob : public QObject {
    Q_OBJECT
public:
    ExportJob(model::ExportSource source, model::ExportOptions options, QObject *parent = nullptr);
    ~ExportJob() override; // cancels a running export and waits for it

    void start();
    void cancel() { m_cancel = true; }
    bool isRunning() const { return m_running; }
    const model::ExportOptions &options() const { return m_options; }
    // Files the finished export wrote (`files` lists only the first of a long sequence).
    qint64 fileCount() const { return m_fileCount; }
    // What the finished export left out, in a sentence (ExportResult::note); read after
    // finished().
    QString note() const { return m_note; }

signals:
    void progressed(qint64 done, qint64 total);
    // ok false: `error` says why (cancelled, disk full, ffmpeg ...); `files` what was written.
    void finished(bool ok, const model::ExportError &error, const QStringList &files);

private:
    void run();

    model::ExportSource m_source;
    model::ExportOptions m_options;
    std::atomic<bool> m_cancel{false};
    std::atomic<qint64> m_fileCount{0};
    QString m_note; // written by the worker before finished() is emitted
    bool m_running = false;
    QThread *m_thread = nullptr;
};

} // namespace finbook::ui

Q_DECLARE_METATYPE(finbook::model::ExportError)
