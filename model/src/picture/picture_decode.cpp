// decodePicture: Qt's image readers with the size checked first, FFmpeg for the rest.
#include "picture_decode.h"

#include <finbook/model/picture/picture_import.h>
#include <finbook/model/reference/reference_media.h>

#include <QBuffer>
#include <QCoreApplication>
#include <QFileInfo>
#include <QImageReader>

#include <algorithm>

namespace finbook::model::picture_detail {

QString pictureTr(const char *text)
{
    return QCoreApplication::translate("PictureImport", text);
}

QString importRefusal(const QString &path, const QString &why)
{
    return QCoreApplication::translate("PictureImport", "“%1” cannot be imported: %2")
        .arg(QFileInfo(path).fileName(), why);
}

QString sizeRefusal(QSize size, qint64 budget)
{
    if (size.width() <= 0 || size.height() <= 0)
        return pictureTr(QT_TRANSLATE_NOOP("PictureImport", "Its picture has no size."));
    if (size.width() > kMaxPictureSide || size.height() > kMaxPictureSide)
        return QCoreApplication::translate("PictureImport",
                                           "It claims to be %1 × %2 pixels; a picture may be at "
                                           "most %3 pixels wide and high.")
            .arg(size.width())
            .arg(size.height())
            .arg(kMaxPictureSide);
    const qint64 pixels = qint64(size.width()) * size.height();
    if (pixels > kMaxPictureLayerPixels)
        return QCoreApplication::translate("PictureImport",
                                           "It claims to be %1 × %2 pixels; a picture may have "
                                           "at most %3 megapixels.")
            .arg(size.width())
            .arg(size.height())
            .arg(kMaxPictureLayerPixels / (1024 * 1024));
    if (pixels * 4 > budget)
        return QCoreApplication::translate("PictureImport",
                                           "Its pictures together would take more than %1 MB "
                                           "of memory.")
            .arg(kMaxPictureDecodedBytes >> 20);
    return {};
}

namespace {

// Qt's reader, or a null image with `handled` false when Qt does not know the format (or it
// is SVG, which only the reference layer's bounded renderer may draw).
Expected<QImage, QString> readWithQtReader(const QByteArray &bytes, qint64 budget, bool *handled)
{
    QBuffer buffer;
    buffer.setData(bytes);
    buffer.open(QIODevice::ReadOnly);
    QImageReader reader(&buffer);
    reader.setAutoTransform(true);
    *handled = reader.canRead() && reader.format() != "svg" && reader.format() != "svgz";
    if (!*handled)
        return QImage();
    // Qt's JPEG reader fills a cut-short picture's missing rows with grey and only warns; a
    // JPEG ends with an EOI marker (an embedded thumbnail's own may hide a cut, never invent
    // one).
    if (reader.format() == "jpeg" && bytes.lastIndexOf(QByteArrayView("\xff\xd9", 2)) < 0)
        return unexpected(pictureTr(QT_TRANSLATE_NOOP(
            "PictureImport", "Its picture is cut short (the file is incomplete).")));
    if (const QSize claimed = reader.size(); claimed.isValid()) {
        if (QString why = sizeRefusal(claimed, budget); !why.isEmpty())
            return unexpected(why);
    }
    // Formats that do not say their size up front are held to the same bound by Qt itself.
    const qint64 bound = std::min(budget, kMaxPictureLayerPixels * 4);
    reader.setAllocationLimit(int(std::max<qint64>(1, bound >> 20)));
    QImage image = reader.read();
    if (image.isNull())
        return unexpected(pictureTr(QT_TRANSLATE_NOOP(
            "PictureImport", "Its picture cannot be decoded: the file is damaged, cut short or too "
                             "large.")));
    return image;
}

} // namespace

Expected<QImage, QString> decodePicture(const QByteArray &bytes, qint64 *budget, bool ffmpeg)
{
    if (bytes.isEmpty())
        return unexpected(pictureTr(QT_TRANSLATE_NOOP("PictureImport", "It is empty.")));
    bool handled = false;
    auto read = readWithQtReader(bytes, *budget, &handled);
    if (!read)
        return read;
    QImage image = std::move(*read);
    if (!handled) {
        if (!ffmpeg)
            return unexpected(pictureTr(QT_TRANSLATE_NOOP(
                "PictureImport", "It holds a picture of a kind Finbook cannot read.")));
        // FFmpeg checks the size its stream announces before decoding (video_decoder.cpp).
        const auto media = ReferenceMedia::open(ReferenceKind::Image, bytes);
        if (!media)
            return unexpected(media.error());
        image = (*media)->frame(0);
        if (image.isNull())
            return unexpected(
                pictureTr(QT_TRANSLATE_NOOP("PictureImport", "Its picture cannot be decoded.")));
    }
    if (QString why = sizeRefusal(image.size(), *budget); !why.isEmpty())
        return unexpected(why);
    image = image.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    if (image.isNull())
        return unexpected(pictureTr(
            QT_TRANSLATE_NOOP("PictureImport", "There is not enough memory to read it.")));
    *budget -= image.sizeInBytes();
    return image;
}

} // namespace finbook::model::picture_detail
