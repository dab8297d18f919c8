// The soundtrack of a video export (private to the model): the mix of the exported range,
// as a WAV file ffmpeg reads as its second input, and the arguments that encode it.
#pragma once

#include <finbook/model/export/export_options.h>
#include <finbook/model/export/export_plan.h>

#include <QStringList>

namespace finbook::model {

// Whether this export carries sound: an MP4 or WebM of a document whose unmuted clips sound
// somewhere in the exported range. Only MP4 (AAC) and WebM (Opus) do; the other formats have
// no sound (the export dialog says so).
bool exportHasSound(const ExportSource &source, const ExportOptions &options);

// The mixed soundtrack of the plan's range as WAV bytes, exactly as long as the video
// (plan.ticks at plan.fps), starting at the sound under the range's first frame. Clips that do
// not decode are left silent.
QByteArray exportSoundtrackWav(const ExportSource &source, const ExportPlan &plan);

// Whether an HTML flipbook of `source` carries sound (an unmuted clip).
bool flipbookHasSound(const ExportSource &source);
// The same mix, smaller for embedding in a page: mono at half the rate (24 kHz, 48 KB a second).
QByteArray flipbookSoundtrackWav(const ExportSource &source, const ExportPlan &plan);

// ffmpeg arguments for the sound input at `wavPath` (after the frames' input) and for its
// encoding into `format`'s audio codec (before the output).
QStringList soundInputArguments(const QString &wavPath);
QStringList soundOutputArguments(ExportFormat format);

} // namespace finbook::model
