// The ffmpeg command line of each encoded format, reading raw BGRA frames from stdin.
#pragma once

#include <finbook/model/export/export_plan.h>

#include <QStringList>

namespace finbook::model {

struct FfmpegJob {
    QStringList arguments;
    // GIF: a first run over the same frames that only writes the palette (palettegen), read
    // by the second run (`arguments`, paletteuse). Empty for the other formats.
    QStringList paletteArguments;
    // True: every playback tick is piped (held drawings repeated), for constant-rate video.
    // False: each drawing is piped once and ffmpeg stretches it over its hold (GIF delays).
    bool perTick = true;
    QString what; // names the output in messages
};

// `palette`: where the GIF's first run writes its palette (a PNG) and the second reads it.
// `soundWav`: MP4 and WebM only, a WAV file (export_sound.h) encoded as the audio stream.
FfmpegJob ffmpegJob(ExportFormat format, const ExportPlan &plan, const QString &output,
                    const QString &palette = QString(), const QString &soundWav = QString());

// setpts expression that starts drawing N at its first tick: N plus the extra ticks of the
// drawings held before it. Empty when it would be too long for one command-line argument.
QString holdTimestamps(const std::vector<int> &holds);

} // namespace finbook::model
