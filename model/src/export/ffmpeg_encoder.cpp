#include "ffmpeg_encoder.h"

#include "export_formats.h"
#include "export_text.h"

#include <finbook/model/export/exporter.h>

#include <QFileInfo>
#include <QStandardPaths>

namespace finbook::model {

namespace {
constexpr qsizetype kErrorBytes = 4096; // ffmpeg's last words; the start is rarely the cause
constexpr int kTailLines = 6;
constexpr int kPollMs = 100; // how quickly a cancel or a dead ffmpeg is noticed
} // namespace

QString ffmpegProgram()
{
    QString name = qEnvironmentVariable("FINBOOK_FFMPEG");
    if (name.isEmpty())
        name = QStringLiteral("ffmpeg");
    if (name.contains(QLatin1Char('/')))
        return QFileInfo(name).isExecutable() && QFileInfo(name).isFile() ? name : QString();
    return QStandardPaths::findExecutable(name);
}

FfmpegEncoder::FfmpegEncoder(const QString &what)
    : m_what(what)
{
    m_process.setProcessChannelMode(QProcess::SeparateChannels);
    m_process.setStandardOutputFile(QProcess::nullDevice());
}

FfmpegEncoder::~FfmpegEncoder()
{
    abort();
}

std::optional<ExportError> FfmpegEncoder::start(const QStringList &arguments)
{
    const QString program = ffmpegProgram();
    if (!program.isEmpty()) {
        m_process.start(program, arguments, QIODevice::ReadWrite);
        if (m_process.waitForStarted())
            return std::nullopt;
    }
    return exportError(ExportErrorCode::EncoderMissing,
                       Export::tr("Exporting %1 needs the ffmpeg program, which was not found; "
                                  "install it (on Debian: apt install ffmpeg) and export again.")
                           .arg(m_what),
                       m_process.errorString());
}

std::optional<ExportError> FfmpegEncoder::write(const QImage &frame, const Cancelled &isCancelled)
{
    if (m_process.state() != QProcess::Running)
        return failure();
    m_process.write(reinterpret_cast<const char *>(frame.constBits()), frame.sizeInBytes());
    while (m_process.bytesToWrite() > 0) {
        if (isCancelled && isCancelled())
            return cancelled();
        if (!m_process.waitForBytesWritten(kPollMs)) {
            readErrors();
            if (m_process.state() != QProcess::Running || m_process.error() == QProcess::WriteError)
                return failure();
        }
    }
    readErrors();
    return std::nullopt;
}

std::optional<ExportError> FfmpegEncoder::finish(const Cancelled &isCancelled)
{
    m_process.closeWriteChannel();
    while (m_process.state() != QProcess::NotRunning) {
        if (isCancelled && isCancelled())
            return cancelled();
        m_process.waitForFinished(kPollMs);
        readErrors();
    }
    readErrors();
    // At -loglevel error anything printed is an error; ffmpeg has been seen to report a failed
    // write and exit with 0, so its words count as much as its exit code.
    if (m_process.exitStatus() != QProcess::NormalExit || m_process.exitCode() != 0 ||
        !errorTail().isEmpty())
        return failure();
    return std::nullopt;
}

void FfmpegEncoder::abort()
{
    if (m_process.state() == QProcess::NotRunning)
        return;
    m_process.kill();
    m_process.waitForFinished(5000);
}

void FfmpegEncoder::readErrors()
{
    m_errors += m_process.readAllStandardError();
    if (m_errors.size() > kErrorBytes)
        m_errors = m_errors.right(kErrorBytes);
}

QString FfmpegEncoder::errorTail() const
{
    QStringList lines = QString::fromLocal8Bit(m_errors).split(QLatin1Char('\n'));
    for (QString &line : lines)
        line = line.trimmed();
    lines.removeAll(QString());
    return lines.mid(std::max<qsizetype>(0, lines.size() - kTailLines)).join(QLatin1Char('\n'));
}

ExportError FfmpegEncoder::failure()
{
    // Let ffmpeg finish saying why before reading its last words.
    m_process.closeWriteChannel();
    if (m_process.state() != QProcess::NotRunning && !m_process.waitForFinished(5000))
        abort();
    readErrors();
    const QString tail = errorTail();
    const QString why = tail.isEmpty()
                            ? (m_process.exitStatus() == QProcess::CrashExit
                                   ? Export::tr("it stopped unexpectedly")
                                   : Export::tr("exit code %1").arg(m_process.exitCode()))
                            : tail.split(QLatin1Char('\n')).last();
    return exportError(ExportErrorCode::EncoderFailed,
                       Export::tr("ffmpeg could not make the %1 (%2); nothing was written. If the "
                                  "disk is full, free some space and export again.")
                           .arg(m_what, why),
                       tail);
}

ExportError FfmpegEncoder::cancelled()
{
    abort();
    return cancelledError();
}

} // namespace finbook::model
