// Reading OpenRaster files (.ora) for readPictureLayers (picture_import.h says what is read and
// in which order). Private to the model.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/model/picture/picture_import.h>

#include <QString>

#include <vector>

namespace finbook::model::picture_detail {

// The visible layers of the OpenRaster file at `path`, bottom first; a sentence without the
// file's name when it cannot be read.
Expected<std::vector<PictureLayer>, QString> readOpenRaster(const QString &path);

// Multiplies every channel of a Format_ARGB32_Premultiplied image by `opacity` (in [0, 1]).
void multiplyOpacity(QImage &image, double opacity);

} // namespace finbook::model::picture_detail
