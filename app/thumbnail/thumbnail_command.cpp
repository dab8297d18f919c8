#include "thumbnail_command.h"

#include "cli.h"
#include "first_frame.h"

#include <finbook/model/io/printable_text.h>
#include <finbook/model/render.h>
#include <finbook/model/skeleton/cut_out_layers.h>

#include <QBuffer>
#include <QCoreApplication>
#include <QFileInfo>
#include <QSaveFile>
#include <QTextStream>

namespace finbook::app {

namespace {

class Thumbnail {
    Q_DECLARE_TR_FUNCTIONS(Thumbnail)
};

int fail(QTextStream &err, const QString &message, ExitCode code)
{
    err << model::printableText(message.simplified()) << Qt::endl;
    return int(code);
}

// The canvas scaled so that its longer side is `size` (never below one pixel).
QSize thumbnailSize(QSize canvas, int size)
{
    const double scale = double(size) / std::max(canvas.width(), canvas.height());
    return QSize(std::max(1, int(canvas.width() * scale + 0.5)),
                 std::max(1, int(canvas.height() * scale + 0.5)));
}

} // namespace

int runThumbnailCommand(const QStringList &arguments, QTextStream &err)
{
    if (arguments.size() != 3)
        return fail(err, Thumbnail::tr("Usage: finbook thumbnail FILE OUT.png SIZE"),
                    ExitCode::BadInput);
    bool ok = false;
    const int size = arguments[2].toInt(&ok);
    if (!ok || size < 1 || size > kMaxThumbnailSize)
        return fail(err,
                    Thumbnail::tr("The thumbnail size \"%1\" is not a whole number from 1 to %2.")
                        .arg(arguments[2])
                        .arg(kMaxThumbnailSize),
                    ExitCode::BadInput);
    auto loaded = readFirstFrame(arguments[0]);
    if (!loaded)
        return fail(err, loaded.error().message, ExitCode::BadInput);
    if (loaded->frames.empty())
        return fail(err,
                    Thumbnail::tr("Cannot make a thumbnail of \"%1\": it has no frame.")
                        .arg(QFileInfo(arguments[0]).fileName()),
                    ExitCode::BadInput);
    model::restoreCutOutLayers(loaded->frames, loaded->settings.closeGap);
    const QImage image = model::renderFrame(loaded->frames.front(), loaded->settings,
                                            thumbnailSize(loaded->settings.canvasSize, size));
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    if (image.isNull() || !image.save(&buffer, "PNG"))
        return fail(err,
                    Thumbnail::tr("Cannot make a thumbnail of \"%1\": there is not enough memory.")
                        .arg(QFileInfo(arguments[0]).fileName()),
                    ExitCode::Failure);
    QSaveFile out(arguments[1]);
    if (!out.open(QIODevice::WriteOnly) || out.write(png) != png.size() || !out.commit())
        return fail(err,
                    Thumbnail::tr("Cannot write the thumbnail \"%1\": %2.")
                        .arg(arguments[1], out.errorString()),
                    ExitCode::Failure);
    return int(ExitCode::Ok);
}

} // namespace finbook::app
