// importReferenceFile: reading a picture or video file into a Reference, refusing what does
// not decode before anything in the document changes.
#include "reference_files.h"
#include "reference_svg.h"
#include "video_decoder.h"

#include <finbook/model/reference/reference_media.h>

#include <QBuffer>
#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QImageReader>

namespace finbook::model {

namespace {

// Qt reads it as one still picture (an animated GIF counts as a video for FFmpeg instead).
bool qtReadsStill(const QByteArray &bytes)
{
    QBuffer buffer;
    buffer.setData(bytes);
    buffer.open(QIODevice::ReadOnly);
    QImageReader reader(&buffer);
    return reader.canRead() && reader.imageCount() <= 1;
}
} // namespace

namespace reference_detail {

QString referenceRefusal(const QString &path, const QString &why)
{
    return QCoreApplication::translate("Reference", "“%1” cannot be used as a reference: %2")
        .arg(QFileInfo(path).fileName(), why);
}

Expected<QByteArray, QString> readReferenceFile(const QString &path, qint64 limit,
                                                const QString &tooLarge)
{
    QFile file(path);
    if (!QFileInfo(path).isFile() || !file.open(QIODevice::ReadOnly))
        return unexpected(referenceRefusal(
            path, QCoreApplication::translate(
                      "Reference", "It cannot be read (is it there, and may Finbook read it?).")));
    if (file.size() > limit)
        return unexpected(referenceRefusal(path, tooLarge));
    QByteArray bytes = file.readAll();
    if (bytes.size() > limit) // it grew while being read
        return unexpected(referenceRefusal(path, tooLarge));
    if (bytes.isEmpty())
        return unexpected(
            referenceRefusal(path, QCoreApplication::translate("Reference", "It is empty.")));
    return bytes;
}

} // namespace reference_detail

Expected<Reference, QString> importReferenceFile(const QString &path, QSizeF canvas)
{
    const QString name = QFileInfo(path).fileName();
    const auto refuse = [&path](const QString &why) {
        return unexpected(reference_detail::referenceRefusal(path, why));
    };
    const auto read = reference_detail::readReferenceFile(
        path, kMaxReferenceBytes,
        QCoreApplication::translate("Reference", "It is larger than %1 MB.")
            .arg(kMaxReferenceBytes >> 20));
    if (!read)
        return unexpected(read.error());
    const QByteArray &bytes = *read;

    Reference reference;
    reference.name = name;
    reference.bytes = bytes;
    reference.kind = ReferenceKind::Image;
    if (!reference_detail::looksLikeSvg(bytes) && !qtReadsStill(bytes)) {
        QString error;
        const auto decoder = reference_detail::VideoDecoder::open(bytes, &error);
        if (!decoder)
            return refuse(error);
        if (decoder->duration() > 0.0 && decoder->duration() * decoder->frameRate() > 1.5)
            reference.kind = ReferenceKind::Video;
    }
    const auto media = ReferenceMedia::open(reference.kind, bytes);
    if (!media)
        return refuse(media.error());
    reference.mediaSize = QSizeF((*media)->size());
    fitReferenceToCanvas(reference, canvas);
    return reference;
}

} // namespace finbook::model
