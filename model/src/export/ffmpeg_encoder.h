// One run of the ffmpeg program fed raw frames on its standard input (blocking; for the
// exporting thread). Its error output is kept, the last few kilobytes, for the message. The
// encoder runs in a process group of its own that ends with the export, however the export
// ends (finished, failed, cancelled, Finbook killed): nothing it starts outlives it.
#pragma once

#include <finbook/model/export/export_options.h>

#include <QElapsedTimer>
#include <QImage>
#include <QProcess>

#include <functional>
#include <optional>

namespace finbook::model {

class FfmpegEncoder {
public:
    using Cancelled = std::function<bool()>;

    // `what` names the output for messages ("GIF", "MP4 video"); `output` is the file ffmpeg
    // writes (its growth counts as progress). An ffmpeg that makes no progress for a while
    // (5 minutes; $FINBOOK_ENCODER_TIMEOUT seconds) is killed and reported as failed.
    FfmpegEncoder(const QString &what, const QString &output);
    ~FfmpegEncoder(); // a still running ffmpeg is killed

    // EncoderMissing when there is no ffmpeg or it cannot be started.
    std::optional<ExportError> start(const QStringList &arguments);
    // Pipes the frame's bytes, waiting until ffmpeg took them. EncoderFailed if ffmpeg stopped;
    // Cancelled (ffmpeg killed) as soon as `cancelled` says so.
    std::optional<ExportError> write(const QImage &frame, const Cancelled &cancelled);
    // Ends the input and waits for ffmpeg to finish; EncoderFailed unless it exits with 0.
    std::optional<ExportError> finish(const Cancelled &cancelled);
    void abort();

    // The last lines ffmpeg printed on its error output.
    QString errorTail() const;

private:
    void readErrors();
    void noteProgress();
    bool stalled();
    ExportError failure();
    ExportError cancelled();
    ExportError stuck();
    // Kills the encoder's process group (it, and anything it left in the background) and
    // closes the guard's pipe.
    void endGroup();

    QString m_what;
    QString m_output;
    QProcess m_process;
    QByteArray m_errors;
    qint64 m_stallLimitMs = 0;
    QElapsedTimer m_sinceProgress; // since ffmpeg last read, wrote or said something
    qint64 m_lastSize = -1;
    qint64 m_lastPending = -1;
    qint64 m_group = 0;    // the encoder's process group (its pid), 0 when none
    int m_guardWrite = -1; // Finbook's end of the guard's pipe (ffmpeg_encoder.cpp)
};

} // namespace finbook::model
