// ExportDialog: starting, following and cancelling the export.
#include <finbook/model/document.h>
#include <finbook/model/export/export_plan.h>
#include <finbook/model/export/exporter.h>
#include <finbook/ui/export/export_dialog.h>
#include <finbook/ui/export/export_job.h>

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>

namespace finbook::ui {

bool ExportDialog::isExporting() const
{
    return m_job && m_job->isRunning();
}

void ExportDialog::startExport()
{
    if (isExporting())
        return;
    model::ExportOptions options = this->options();
    if (options.target.isEmpty()) {
        showFailure(tr("Choose where to export the animation to."), QString());
        return;
    }
    model::ExportSource source = model::exportSource(m_doc);
    if (const auto plan = model::planExport(source, options)) {
        if (const auto tooLarge = model::checkExportSize(*plan, options)) {
            if (!confirmLargeExport(tooLarge->message))
                return;
            options.maxFrames = model::exportFrameCount(*plan, options);
        }
    }
    const QStringList existing = model::existingExportTargets(source, options);
    if (!existing.isEmpty()) {
        if (!confirmOverwrite(existing))
            return;
        options.overwrite = true;
    }
    m_job = std::make_unique<ExportJob>(std::move(source), std::move(options));
    connect(m_job.get(), &ExportJob::progressed, this, [this](qint64 done, qint64 total) {
        // QProgressBar counts in int: show per-mille of huge exports.
        const bool huge = total > 1'000'000;
        m_progress->setRange(0, int(huge ? 1000 : total));
        m_progress->setValue(int(huge ? done * 1000 / total : done));
    });
    connect(m_job.get(), &ExportJob::finished, this, &ExportDialog::jobFinished);
    m_progress->setRange(0, 0); // busy until the first frame is done
    m_status->setText(tr("Exporting..."));
    setRunning(true);
    m_job->start();
    emit exportStarted();
}

void ExportDialog::cancelExport()
{
    if (!isExporting())
        return;
    m_job->cancel();
    m_cancelButton->setEnabled(false);
    m_status->setText(tr("Cancelling..."));
}

void ExportDialog::reject()
{
    // The job's destructor waits for the worker, which stops at its next frame.
    if (isExporting())
        m_job->cancel();
    QDialog::reject();
}

void ExportDialog::jobFinished(bool ok, const model::ExportError &error, const QStringList &files)
{
    setRunning(false);
    if (ok) {
        const QString where = files.size() == 1 ? files.first() : options().target;
        m_written = files;
        const qint64 count = m_job ? m_job->fileCount() : files.size();
        m_summary = tr("Exported %n file(s) to %1", nullptr, int(std::min<qint64>(count, INT_MAX)))
                        .arg(QDir::toNativeSeparators(where));
        if (m_job && !m_job->note().isEmpty())
            m_summary += QLatin1Char(' ') + m_job->note();
        m_status->setText(m_summary);
        emit exportFinished(true);
        accept();
        return;
    }
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    emit exportFinished(false);
    if (error.code == model::ExportErrorCode::Cancelled) {
        m_status->setText(tr("Export cancelled; nothing was written."));
        return;
    }
    m_status->setText(error.message);
    showFailure(error.message, error.detail);
}

void ExportDialog::setRunning(bool running)
{
    for (QWidget *w : findChildren<QWidget *>())
        if (w != m_progress && w != m_status && w != static_cast<QWidget *>(m_buttons) &&
            w->parent() == this)
            w->setEnabled(!running);
    m_exportButton->setVisible(!running);
    m_cancelButton->setVisible(running);
    m_cancelButton->setEnabled(running);
    if (!running)
        updateFields();
}

bool ExportDialog::confirmOverwrite(const QStringList &existing)
{
    const QString first = QDir::toNativeSeparators(existing.first());
    const QString text =
        existing.size() == 1
            ? tr("\"%1\" already exists. Replace it?").arg(first)
            : tr("%n file(s) at the target already exist, such as \"%1\". Replace them?", nullptr,
                 int(existing.size()))
                  .arg(first);
    return QMessageBox::question(this, tr("Replace Files?"), text,
                                 QMessageBox::Yes | QMessageBox::No,
                                 QMessageBox::No) == QMessageBox::Yes;
}

bool ExportDialog::confirmLargeExport(const QString &message)
{
    return QMessageBox::question(this, tr("Export Anyway?"),
                                 message + QLatin1Char(' ') +
                                     tr("It may take a long time and a lot of disk space. Export "
                                        "anyway?"),
                                 QMessageBox::Yes | QMessageBox::No,
                                 QMessageBox::No) == QMessageBox::Yes;
}

void ExportDialog::showFailure(const QString &message, const QString &detail)
{
    QMessageBox box(QMessageBox::Warning, tr("Cannot Export"), message, QMessageBox::Ok, this);
    if (!detail.isEmpty())
        box.setDetailedText(detail);
    box.exec();
}

} // namespace finbook::ui
