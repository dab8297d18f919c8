// Exporting an animation: PNG/SVG sequences, GIF, MP4, WebM, APNG and a one-file HTML flipbook;
// and one frame as a 3D model (OBJ + MTL, its objects inflated: frame_solids.h).
//
// GIF and the videos are encoded by the ffmpeg program (QProcess; frames piped raw to its
// standard input, no temporary images). $FINBOOK_FFMPEG names another ffmpeg executable.
//
// Nothing partial ever appears at the target: a file is written beside it and renamed over it
// only after every byte was written and synced to disk; a sequence is written into a hidden
// folder inside the target folder and moved into place at the end. A failure or a cancel
// removes what was written.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/model/export/export_options.h>

namespace finbook::model {

// Blocking; safe on any thread (it reads only `source`). `progress` may be empty.
Expected<ExportResult, ExportError> exportAnimation(const ExportSource &source,
                                                    const ExportOptions &options,
                                                    const ExportProgress &progress = {});

// The files a sequence export would write into its folder (names only, in order), so callers
// can ask before overwriting; for single-file formats, the target itself (a 3D model: the
// .obj and its .mtl). Empty when the options cannot be exported or the export is larger than
// allowed (checkExportSize).
QStringList exportTargetFiles(const ExportSource &source, const ExportOptions &options);

// Calls `visit` with the path of every file the export writes, in order (the target itself
// for single-file formats, then a 3D model's .mtl); nothing when the options cannot be
// exported. Names are made one at a time however long the sequence.
void forEachExportTarget(const ExportSource &source, const ExportOptions &options,
                         const std::function<void(const QString &path)> &visit);

// The paths of the files at the target that the export would replace (that exist now), the
// names made one at a time however long the sequence.
QStringList existingExportTargets(const ExportSource &source, const ExportOptions &options);

// The ffmpeg executable exports use: $FINBOOK_FFMPEG if set, else "ffmpeg" from PATH; empty
// when there is none.
QString ffmpegProgram();

} // namespace finbook::model
