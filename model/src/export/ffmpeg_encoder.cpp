#include "ffmpeg_encoder.h"

#include "export_formats.h"
#include "export_text.h"

#include <finbook/model/export/exporter.h>
#include <finbook/model/io/atomic_file.h>

#include <QFileInfo>
#include <QStandardPaths>

#include <cerrno>

#ifdef Q_OS_UNIX
#include <sys/statvfs.h>
#endif
#ifdef Q_OS_LINUX
#include <csignal>
#include <fcntl.h>
#include <sys/prctl.h>
#include <unistd.h>
#endif

namespace finbook::model {

namespace {
constexpr qsizetype kErrorBytes = 4096; // ffmpeg's last words; the start is rarely the cause
constexpr int kTailLines = 6;
constexpr int kPollMs = 100; // how quickly a cancel or a dead ffmpeg is noticed

// An ffmpeg that takes no input, writes no output and says nothing for this long is stuck
// (a broken build, a filter waiting forever): it is killed. $FINBOOK_ENCODER_TIMEOUT (seconds)
// sets another limit, for tests.
qint64 stallLimitMs()
{
    bool ok = false;
    const int seconds = qEnvironmentVariableIntValue("FINBOOK_ENCODER_TIMEOUT", &ok);
    return ok && seconds > 0 ? qint64(seconds) * 1000 : qint64(300) * 1000;
}

// Less free space than ffmpeg needs to write one more block of output.
bool diskFull(const QString &output)
{
#ifdef Q_OS_UNIX
    struct statvfs disk {};
    if (output.isEmpty() ||
        ::statvfs(QFile::encodeName(QFileInfo(output).path()).constData(), &disk) != 0)
        return false;
    return quint64(disk.f_bavail) * quint64(disk.f_frsize) < (quint64(1) << 20);
#else
    Q_UNUSED(output);
    return false;
#endif
}

qint64 sizeOf(const QString &path)
{
    return path.isEmpty() ? 0 : QFileInfo(path).size();
}
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

FfmpegEncoder::FfmpegEncoder(const QString &what, const QString &output)
    : m_what(what)
    , m_output(output)
    , m_stallLimitMs(stallLimitMs())
{
    m_process.setProcessChannelMode(QProcess::SeparateChannels);
    m_process.setStandardOutputFile(QProcess::nullDevice());
}

void FfmpegEncoder::noteProgress()
{
    const qint64 size = sizeOf(m_output);
    const qint64 pending = m_process.bytesToWrite();
    if (size != m_lastSize || pending != m_lastPending) {
        m_lastSize = size;
        m_lastPending = pending;
        m_sinceProgress.start();
    }
}

bool FfmpegEncoder::stalled()
{
    noteProgress();
    return m_sinceProgress.isValid() && m_sinceProgress.elapsed() > m_stallLimitMs;
}

FfmpegEncoder::~FfmpegEncoder()
{
    abort();
    endGroup();
}

#ifdef Q_OS_LINUX
namespace {
// Runs in the forked child before it becomes the encoder (only async-signal-safe calls). The
// encoder leads a process group of its own, so that it and whatever it starts can be ended
// together, and dies with Finbook (kill -9 included). A guard process is forked into the
// group: it waits on a pipe only Finbook writes to and, once that closes (Finbook ended or
// finished with the encoder), kills the whole group, so nothing the encoder left in the
// background outlives the export.
void becomeEncoder(int guardRead)
{
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    const pid_t group = ::getpid();
    if (::fork() == 0) {
        const int devNull = ::open("/dev/null", O_RDWR);
        for (int fd = 0; fd < 3; ++fd)
            ::dup2(devNull, fd);
        ::dup2(guardRead, 3);
        ::close_range(4, ~0u, 0); // every other descriptor of Finbook's (its pipes, its files)
        char byte;
        while (::read(3, &byte, 1) != 0 && errno == EINTR) {
        }
        ::kill(-group, SIGKILL);
        ::_exit(0);
    }
}
} // namespace
#endif

void FfmpegEncoder::endGroup()
{
#ifdef Q_OS_LINUX
    if (m_group > 0)
        ::kill(-pid_t(m_group), SIGKILL);
    m_group = 0;
    if (m_guardWrite >= 0)
        ::close(m_guardWrite);
    m_guardWrite = -1;
#endif
}

std::optional<ExportError> FfmpegEncoder::start(const QStringList &arguments)
{
    const QString program = ffmpegProgram();
    if (!program.isEmpty()) {
#ifdef Q_OS_LINUX
        int guard[2] = {-1, -1};
        if (::pipe2(guard, O_CLOEXEC) == 0) {
            m_guardWrite = guard[1];
            m_process.setChildProcessModifier([read = guard[0]] { becomeEncoder(read); });
        } else { // no guard: the encoder still dies with Finbook
            m_process.setChildProcessModifier([] {
                ::setpgid(0, 0);
                ::prctl(PR_SET_PDEATHSIG, SIGKILL);
            });
        }
#endif
        m_process.start(program, arguments, QIODevice::ReadWrite);
#ifdef Q_OS_LINUX
        if (guard[0] >= 0)
            ::close(guard[0]);
#endif
        if (m_process.waitForStarted()) {
#ifdef Q_OS_LINUX
            m_group = m_process.processId();
#endif
            m_sinceProgress.start();
            return std::nullopt;
        }
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
        if (stalled())
            return stuck();
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
        if (m_process.state() != QProcess::NotRunning && stalled())
            return stuck();
    }
    readErrors();
    endGroup(); // what the encoder left running in the background goes with it
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
    endGroup(); // the encoder and everything it started
    m_process.kill();
    m_process.waitForFinished(5000);
}

void FfmpegEncoder::readErrors()
{
    const QByteArray said = m_process.readAllStandardError();
    if (!said.isEmpty())
        m_sinceProgress.start();
    m_errors += said;
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
    // ffmpeg words a full disk in many ways ("Error initializing output stream" for MP4):
    // the free space of the disk it was writing to says it plainly.
    if (diskFull(m_output)) {
        ExportError full = writeFailed(
            m_output, describeWriteFailure(WriteFailure{WriteProblem::DiskFull, ENOSPC, {}}, {}));
        full.detail = tail;
        return full;
    }
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

ExportError FfmpegEncoder::stuck()
{
    abort();
    readErrors();
    return exportError(ExportErrorCode::EncoderFailed,
                       Export::tr("ffmpeg made no progress for %n second(s) and was stopped; "
                                  "nothing was written. Check that ffmpeg works, then export "
                                  "again.",
                                  nullptr, int(m_stallLimitMs / 1000)),
                       errorTail());
}

ExportError FfmpegEncoder::cancelled()
{
    abort();
    return cancelledError();
}

} // namespace finbook::model
