#include <finbook/ui/export/export_job.h>

#include <QThread>

namespace finbook::ui {

ExportJob::ExportJob(model::ExportSource source, model::ExportOptions options, QObject *parent)
    : QObject(parent)
    , m_source(std::move(source))
    , m_options(std::move(options))
{
    qRegisterMetaType<model::ExportError>();
    // Connected first, so it runs before any slot a user of the job connects.
    connect(this, &ExportJob::finished, this, [this] { m_running = false; });
}

ExportJob::~ExportJob()
{
    if (!m_thread)
        return;
    m_cancel = true;
    m_thread->wait();
    delete m_thread;
}

void ExportJob::start()
{
    if (m_running || m_thread)
        return;
    m_running = true;
    m_thread = QThread::create([this] { run(); });
    m_thread->setObjectName(QStringLiteral("finbook-export"));
    m_thread->start(QThread::LowPriority);
}

void ExportJob::run()
{
    const auto result =
        model::exportAnimation(m_source, m_options, [this](qint64 done, qint64 total) {
            emit progressed(done, total);
            return !m_cancel.load();
        });
    if (result) {
        m_fileCount = result->fileCount;
        m_note = result->note;
    }
    if (result)
        emit finished(true, model::ExportError{}, result->files);
    else
        emit finished(false, result.error(), {});
}

} // namespace finbook::ui
