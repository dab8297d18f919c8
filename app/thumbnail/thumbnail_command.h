// `finbook thumbnail FILE OUT.png SIZE`: the first frame of FILE as a PNG whose longer side is
// SIZE pixels (the canvas's aspect kept), for file managers (resources/desktop/
// finbook.thumbnailer). It reads only the first frame (first_frame.h). A file that is not a
// readable .finbook gives exit code 2, one line on `err`, and no OUT.png; a PNG that cannot be
// written gives exit code 1. OUT.png appears complete or not at all.
#pragma once

#include <QStringList>

class QTextStream;

namespace finbook::app {

// Thumbnails larger than this are refused: file managers ask for 128 to 1024.
constexpr int kMaxThumbnailSize = 2048;

// `arguments`: FILE OUT SIZE (the words after "thumbnail").
int runThumbnailCommand(const QStringList &arguments, QTextStream &err);

} // namespace finbook::app
