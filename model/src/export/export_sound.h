// The soundtrack of an export (private to the model): the clips the exported range needs,
// decoded once within one SoundBudget, their mix written as a WAV file ffmpeg reads as its
// second input (or embedded in an HTML page), and the arguments that encode it.
#pragma once

#include <finbook/model/export/export_options.h>
#include <finbook/model/export/export_plan.h>
#include <finbook/model/sound/sound_decode.h>

#include <QStringList>

#include <unordered_map>

class QIODevice;

namespace finbook::model {

// Whether this export carries sound: an MP4 or WebM of a document whose unmuted clips sound
// somewhere in the exported range. Only MP4 (AAC) and WebM (Opus) do; the other formats have
// no sound (the export dialog says so).
bool exportHasSound(const ExportSource &source, const ExportOptions &options);

// Whether an HTML flipbook of `source` carries sound (an unmuted clip).
bool flipbookHasSound(const ExportSource &source);

class ExportSoundtrack {
public:
    // Decodes the unmuted clips that reach into the plan's range, each only as far as the
    // range goes, when the export carries sound (exportHasSound, or an HTML flipbook with
    // sound); empty otherwise. A clip that cannot be used is left silent and named in
    // problems().
    ExportSoundtrack(const ExportSource &source, const ExportOptions &options,
                     const ExportPlan &plan);
    bool carriesSound() const { return m_carries; }
    // One sentence per clip left out ("The sound "x.wav" is left out: …").
    const QStringList &problems() const { return m_problems; }

    // The mix of the range as a 16-bit stereo 48 kHz WAV, exactly as long as the video
    // (plan.ticks at plan.fps), starting at the sound under the range's first frame; written
    // a second at a time, so memory does not grow with the length. False when a write fails.
    bool writeWav(QIODevice &device) const;
    // The same mix, smaller for embedding in a page: mono at half the rate (24 kHz, 48 KB a
    // second).
    QByteArray flipbookWav() const;

private:
    // Calls `block` with consecutive pieces of the mix (interleaved stereo floats).
    template <typename Block> bool forEachBlock(Block &&block) const;

    const ExportSource &m_source;
    bool m_carries = false;
    qint64 m_from = 0;  // first sample of the range in the soundtrack
    qint64 m_count = 0; // samples of the video
    std::unordered_map<Id, DecodedSoundPtr> m_sounds;
    QStringList m_problems;
};

// ffmpeg arguments for the sound input at `wavPath` (after the frames' input) and for its
// encoding into `format`'s audio codec (before the output).
QStringList soundInputArguments(const QString &wavPath);
QStringList soundOutputArguments(ExportFormat format);

} // namespace finbook::model
