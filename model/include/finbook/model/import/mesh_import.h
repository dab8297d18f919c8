// Importing a 2D triangle mesh (OFF) as an object: its boundary loops become closed strokes,
// so a character given as a mesh (the harmonic-coordinates notebook's "woody") can be caged
// and posed by hand.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/model/types.h>

#include <QString>

namespace finbook::model {

// Reads `path` and returns one closed stroke per boundary loop, placed to fit `canvas`
// (centred, scaled to about two thirds of it; y flipped, since OFF files are y-up).
// Errors are sentences for the user.
Expected<std::vector<StrokeDataPtr>, QString>
importMeshStrokes(const QString &path, QSize canvas, QRgb color = 0xff000000, float width = 2.0f);

} // namespace finbook::model
