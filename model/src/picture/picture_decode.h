// Decoding one picture held in memory for readPictureLayers (picture_import.h), with its size
// checked against the import's limits before any pixel is decoded. Private to the model.
#pragma once

#include <finbook/geometry/expected.h>

#include <QByteArray>
#include <QImage>
#include <QSize>
#include <QString>

namespace finbook::model::picture_detail {

// QCoreApplication::translate("PictureImport", text).
QString pictureTr(const char *text);

// "“NAME” cannot be imported: WHY", NAME being the file name of `path`.
QString importRefusal(const QString &path, const QString &why);

// Why a picture of `size` cannot be decoded when `budget` decoded bytes are left (side, pixel
// count, budget); empty when it can.
QString sizeRefusal(QSize size, qint64 budget);

// The picture in `bytes` as Format_ARGB32_Premultiplied. Qt's readers first; when none reads it
// and `ffmpeg` is set, FFmpeg's (through the reference layer's decoder). The claimed size is
// checked before decoding and the decoded one after; `budget` (decoded bytes left for this
// import) is lowered by the picture's bytes. A sentence (without the file's name) on failure.
Expected<QImage, QString> decodePicture(const QByteArray &bytes, qint64 *budget, bool ffmpeg);

} // namespace finbook::model::picture_detail
