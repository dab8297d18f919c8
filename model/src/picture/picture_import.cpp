// readPictureLayers: an OpenRaster stack or one plain picture, refused with a sentence that
// names the file when it cannot be read within the import's limits.
#include "openraster.h"
#include "picture_decode.h"

#include <finbook/model/picture/picture_import.h>

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

namespace finbook::model {

namespace {

// OpenRaster by its name, or by its content (a zip) whatever it is called.
bool isOpenRaster(const QString &path, const QByteArray &start)
{
    return QFileInfo(path).suffix().compare(QLatin1String("ora"), Qt::CaseInsensitive) == 0 ||
           start.startsWith("PK\x03\x04");
}

} // namespace

Expected<std::vector<PictureLayer>, QString> readPictureLayers(const QString &path)
{
    using namespace picture_detail;
    const auto refuse = [&path](const QString &why) {
        return unexpected(importRefusal(path, why));
    };
    QFile file(path);
    if (!QFileInfo(path).isFile() || !file.open(QIODevice::ReadOnly))
        return refuse(pictureTr(QT_TRANSLATE_NOOP(
            "PictureImport", "It cannot be read (is it there, and may Finbook read it?).")));
    if (file.size() == 0)
        return refuse(pictureTr(QT_TRANSLATE_NOOP("PictureImport", "It is empty.")));
    if (isOpenRaster(path, file.peek(4))) {
        file.close();
        auto layers = readOpenRaster(path);
        if (!layers)
            return refuse(layers.error());
        return layers;
    }
    if (file.size() > kMaxPictureFileBytes)
        return refuse(QCoreApplication::translate("PictureImport", "It is larger than %1 MB.")
                          .arg(kMaxPictureFileBytes >> 20));
    const QByteArray bytes = file.readAll();
    if (bytes.size() > kMaxPictureFileBytes) // it grew while being read
        return refuse(QCoreApplication::translate("PictureImport", "It is larger than %1 MB.")
                          .arg(kMaxPictureFileBytes >> 20));
    qint64 budget = kMaxPictureDecodedBytes;
    auto image = decodePicture(bytes, &budget, true);
    if (!image)
        return refuse(image.error());
    std::vector<PictureLayer> layers;
    layers.push_back(PictureLayer{QFileInfo(path).completeBaseName(), std::move(*image), {}});
    return layers;
}

} // namespace finbook::model
