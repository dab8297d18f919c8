// One run of the ffmpeg program fed raw frames on its standard input (blocking; for the
// exporting thread). Its error output is kept, the last few kilobytes, for the message.
#pragma once

#include <finbook/model/export/export_options.h>

#include <QImage>
#include <QProcess>

#include <functional>
#include <optional>

namespace finbook::model {

class FfmpegEncoder {
public:
    using Cancelled = std::function<bool()>;

    // `what` names the output for messages ("GIF", "MP4 video").
    explicit FfmpegEncoder(const QString &what);
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
    ExportError failure();
    ExportError cancelled();

    QString m_what;
    QProcess m_process;
    QByteArray m_errors;
};

} // namespace finbook::model
