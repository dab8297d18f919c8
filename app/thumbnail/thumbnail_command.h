// `finbook thumbnail FILE OUT.png SIZE`: the first frame of FILE as a PNG whose longer side is
// SIZE pixels (the canvas's aspect kept), for file managers (resources/desktop/
// finbook.thumbnailer). It reads only the first frame (first_frame.h). A file that is not a
// readable .finbook gives exit code 2, one line on `err`, and no OUT.png; a PNG that cannot be
// written gives exit code 1. OUT.png appears complete or not at all.
//
// Its cost is bounded whatever the file asks for (file managers run it on every file they
// show, downloads included): about 2 s of wall time and 300 MB on a two-core machine. The
// picture is the first frame as the editor shows it when that is painted within
// kFullPictureMs and its shading meshes add up to at most kShadingVertexBudget vertices; else
// the same with its fills flat (no shading) when that is painted within kFlatPictureMs; else
// its strokes alone. A cheaper picture rather than none.
#pragma once

#include <QStringList>

class QTextStream;

namespace finbook::app {

// Thumbnails larger than this are refused: file managers ask for 128 to 1024.
constexpr int kMaxThumbnailSize = 2048;

// The time the full picture, then the flat one, may take (wall milliseconds).
constexpr int kFullPictureMs = 1000;
constexpr int kFlatPictureMs = 400;
// Shading meshes beyond this many vertices in all (model::shadingVertexEstimate) are not
// tried: a few seconds and a few hundred megabytes on this kind of machine.
constexpr long long kShadingVertexBudget = 120000;

// `arguments`: FILE OUT SIZE (the words after "thumbnail").
int runThumbnailCommand(const QStringList &arguments, QTextStream &err);

// True while a picture the command stopped waiting for is still being painted: the process
// must then end with _exit (its threads read caches that exit() would destroy under them).
bool thumbnailWorkLeftRunning();

} // namespace finbook::app
