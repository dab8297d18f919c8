// The ffmpeg command line of each encoded format, reading raw BGRA frames from stdin.
#pragma once

#include <finbook/model/export/export_plan.h>

#include <QStringList>

#include <functional>
#include <vector>

namespace finbook::model {

struct FfmpegJob {
    QStringList arguments;
    // GIF: a first run over the same frames that only writes the palette (palettegen), read
    // by the second run (`arguments`, paletteuse). Empty for the other formats.
    QStringList paletteArguments;
    // True: every playback tick is piped (held drawings repeated), for constant-rate video
    // (MP4, WebM, APNG, and GIFs whose drawings all last one tick).
    // False: ffmpeg reads each drawing once from `concatList` (a GIF whose drawings are held
    // for different times: each GIF frame's delay is its drawing's hold).
    bool perTick = true;
    QString concatList;
    QString what; // names the output in messages
};

// `palette`: where the GIF's first run writes its palette (a PNG) and the second reads it.
// `soundWav`: MP4 and WebM only, a WAV file (export_sound.h) encoded as the audio stream.
// `drawings`: GIF only, the concat list (concatList) of the drawings when their holds vary;
// empty: the frames are piped, one per tick.
FfmpegJob ffmpegJob(ExportFormat format, const ExportPlan &plan, const QString &output,
                    const QString &palette = QString(), const QString &soundWav = QString(),
                    const QString &drawings = QString());

// Whether any drawing is held for more than one tick.
bool holdsVary(const std::vector<int> &holds);

// An ffconcat list of the drawings, `file(i)` the i-th one's file (its name in the list's
// folder), each lasting its hold: ffmpeg's concat demuxer turns the durations into
// timestamps, so the command line stays the same size whatever the number of drawings
// (a setpts expression listing the holds failed beyond about 100 drawings: ffmpeg nests each
// of its terms one level deeper).
QByteArray concatList(const std::vector<int> &holds, int fps,
                      const std::function<QString(std::size_t)> &file);

} // namespace finbook::model
