// readOpenRaster: stack.xml flattened into positioned layers, each layer's PNG read from the zip
// within its bound and decoded within the import's budget.
#include "openraster.h"

#include "picture_decode.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QXmlStreamReader>
#include <quazip/quazip.h>
#include <quazip/quazipfile.h>
#include <quazip/quazipfileinfo.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace finbook::model::picture_detail {

namespace {

// A layer as stack.xml describes it, with its enclosing stacks' offsets, opacity and visibility
// folded in.
struct OraLayerEntry {
    QString src;
    QString name;
    QPoint offset;
    double opacity = 1.0;
    bool visible = true;
};

enum class OraEntryProblem { None, Missing, TooLarge, Damaged };

// Reads the zip entry `name` into `out`, never more than `limit` bytes nor more than the entry
// claims (minizip stops there too; a lie is then caught by the CRC or by the decoder).
OraEntryProblem readOraEntry(QuaZip &zip, const QString &name, qint64 limit, QByteArray *out)
{
    out->clear();
    if (!zip.setCurrentFile(name, QuaZip::csSensitive))
        return OraEntryProblem::Missing;
    QuaZipFileInfo64 info;
    if (!zip.getCurrentFileInfo(&info))
        return OraEntryProblem::Damaged;
    const qint64 claimed = qint64(info.uncompressedSize);
    if (claimed < 0 || claimed > limit)
        return OraEntryProblem::TooLarge;
    QuaZipFile file(&zip);
    if (!file.open(QIODevice::ReadOnly))
        return OraEntryProblem::Damaged;
    out->reserve(qsizetype(claimed));
    char chunk[1 << 16];
    qint64 n = 0;
    while ((n = file.read(chunk, sizeof chunk)) > 0) {
        if (out->size() + n > claimed) { // more than it claims: stop before holding it
            out->clear();
            return OraEntryProblem::Damaged;
        }
        out->append(chunk, qsizetype(n));
    }
    file.close();
    if (n < 0 || file.getZipError() != UNZ_OK || out->size() != claimed) {
        out->clear();
        return OraEntryProblem::Damaged;
    }
    return OraEntryProblem::None;
}

// An x or y attribute: a whole number of pixels (written as a decimal by some programs).
std::optional<int> oraCoordinate(const QXmlStreamAttributes &attributes, const char *name)
{
    const QStringView text = attributes.value(QLatin1String(name));
    if (text.isEmpty())
        return 0;
    bool ok = false;
    const double v = text.toDouble(&ok);
    if (!ok || !std::isfinite(v) || std::abs(v) > 1.0e6)
        return std::nullopt;
    return int(std::lround(v));
}

std::optional<double> oraOpacity(const QXmlStreamAttributes &attributes)
{
    const QStringView text = attributes.value(QLatin1String("opacity"));
    if (text.isEmpty())
        return 1.0;
    bool ok = false;
    const double v = text.toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return std::nullopt;
    return std::clamp(v, 0.0, 1.0);
}

// The enclosing context combined with the element's own x, y, opacity and visibility.
std::optional<OraLayerEntry> oraNested(const OraLayerEntry &outer,
                                       const QXmlStreamAttributes &attributes)
{
    const auto x = oraCoordinate(attributes, "x"), y = oraCoordinate(attributes, "y");
    const auto opacity = oraOpacity(attributes);
    if (!x || !y || !opacity)
        return std::nullopt;
    OraLayerEntry inner;
    inner.offset = outer.offset + QPoint(*x, *y);
    inner.opacity = outer.opacity * *opacity;
    inner.visible =
        outer.visible && attributes.value(QLatin1String("visibility")) != QLatin1String("hidden");
    inner.name = attributes.value(QLatin1String("name")).toString();
    return inner;
}

// Every layer of stack.xml, top first, visible or not.
Expected<std::vector<OraLayerEntry>, QString> parseOraStack(const QByteArray &xml)
{
    QXmlStreamReader reader(xml);
    std::vector<OraLayerEntry> stacks; // the enclosing stacks, innermost last
    std::vector<OraLayerEntry> layers;
    bool inImage = false;
    while (!reader.atEnd() && !reader.hasError()) {
        if (reader.readNext() == QXmlStreamReader::EndElement &&
            reader.name() == QLatin1String("stack") && !stacks.empty())
            stacks.pop_back();
        if (reader.tokenType() != QXmlStreamReader::StartElement)
            continue;
        const QStringView name = reader.name();
        if (!inImage) {
            if (name != QLatin1String("image"))
                return unexpected(pictureTr(QT_TRANSLATE_NOOP(
                    "PictureImport", "Its stack.xml does not describe an OpenRaster image.")));
            inImage = true;
            continue;
        }
        if (name != QLatin1String("stack") && name != QLatin1String("layer"))
            continue; // text, filters and the like: not pictures
        const OraLayerEntry outer = stacks.empty() ? OraLayerEntry() : stacks.back();
        auto entry = oraNested(outer, reader.attributes());
        if (!entry)
            return unexpected(pictureTr(QT_TRANSLATE_NOOP(
                "PictureImport", "Its stack.xml gives a layer an invalid position or "
                                 "opacity.")));
        if (name == QLatin1String("stack")) {
            if (int(stacks.size()) >= kMaxOpenRasterDepth)
                return unexpected(pictureTr(
                    QT_TRANSLATE_NOOP("PictureImport", "Its layer groups are nested too deeply.")));
            stacks.push_back(std::move(*entry));
            continue;
        }
        entry->src = reader.attributes().value(QLatin1String("src")).toString();
        if (entry->src.isEmpty())
            return unexpected(pictureTr(QT_TRANSLATE_NOOP(
                "PictureImport", "Its stack.xml names a layer without a picture.")));
        if (int(layers.size()) >= kMaxOpenRasterLayers)
            return unexpected(
                QCoreApplication::translate("PictureImport", "It has more than %1 layers.")
                    .arg(kMaxOpenRasterLayers));
        if (entry->name.isEmpty())
            entry->name = QFileInfo(entry->src).completeBaseName();
        layers.push_back(std::move(*entry));
    }
    if (reader.hasError())
        return unexpected(QCoreApplication::translate("PictureImport",
                                                      "Its stack.xml is malformed (line %1: %2).")
                              .arg(reader.lineNumber())
                              .arg(reader.errorString()));
    if (!inImage)
        return unexpected(pictureTr(QT_TRANSLATE_NOOP("PictureImport", "Its stack.xml is empty.")));
    if (layers.empty())
        return unexpected(
            pictureTr(QT_TRANSLATE_NOOP("PictureImport", "Its stack of layers is empty.")));
    return layers;
}

// The decoded picture of one layer; a sentence naming the layer when it cannot be had.
Expected<QImage, QString> readOraLayer(QuaZip &zip, const OraLayerEntry &layer, qint64 *budget)
{
    QByteArray bytes;
    switch (readOraEntry(zip, layer.src, kMaxOpenRasterEntryBytes, &bytes)) {
    case OraEntryProblem::Missing:
        return unexpected(QCoreApplication::translate(
                              "PictureImport", "The picture of its layer “%1” (%2) is missing.")
                              .arg(layer.name, layer.src));
    case OraEntryProblem::TooLarge:
        return unexpected(
            QCoreApplication::translate("PictureImport",
                                        "The picture of its layer “%1” is larger than %2 MB.")
                .arg(layer.name)
                .arg(kMaxOpenRasterEntryBytes >> 20));
    case OraEntryProblem::Damaged:
        return unexpected(QCoreApplication::translate(
                              "PictureImport",
                              "The picture of its layer “%1” is damaged or cut short in the file.")
                              .arg(layer.name));
    case OraEntryProblem::None:
        break;
    }
    auto image = decodePicture(bytes, budget, false);
    if (!image)
        return unexpected(QCoreApplication::translate("PictureImport", "Its layer “%1”: %2")
                              .arg(layer.name, image.error()));
    return image;
}

// The zip holds an OpenRaster file: its mimetype entry, when there is one, says so.
QString oraMimetypeProblem(QuaZip &zip)
{
    QByteArray mimetype;
    switch (readOraEntry(zip, QStringLiteral("mimetype"), 256, &mimetype)) {
    case OraEntryProblem::Missing:
        return {}; // some writers leave it out
    case OraEntryProblem::None:
        if (mimetype.trimmed() == "image/openraster")
            return {};
        break;
    default:
        break;
    }
    return pictureTr(
        QT_TRANSLATE_NOOP("PictureImport", "It is a zip archive, but not an OpenRaster picture."));
}

} // namespace

void multiplyOpacity(QImage &image, double opacity)
{
    const int k = int(std::lround(std::clamp(opacity, 0.0, 1.0) * 255.0));
    if (k == 255)
        return;
    for (int y = 0; y < image.height(); ++y) {
        uchar *line = image.scanLine(y);
        for (qsizetype i = 0; i < qsizetype(image.width()) * 4; ++i)
            line[i] = uchar((int(line[i]) * k + 127) / 255);
    }
}

Expected<std::vector<PictureLayer>, QString> readOpenRaster(const QString &path)
{
    QuaZip zip(path);
    if (!zip.open(QuaZip::mdUnzip))
        return unexpected(pictureTr(QT_TRANSLATE_NOOP(
            "PictureImport", "It is not a zip archive, or it is damaged or cut short.")));
    if (QString problem = oraMimetypeProblem(zip); !problem.isEmpty())
        return unexpected(problem);
    QByteArray xml;
    switch (readOraEntry(zip, QStringLiteral("stack.xml"), kMaxOpenRasterStackBytes, &xml)) {
    case OraEntryProblem::Missing:
        return unexpected(pictureTr(QT_TRANSLATE_NOOP(
            "PictureImport", "It has no stack.xml: it is not an OpenRaster picture.")));
    case OraEntryProblem::TooLarge:
        return unexpected(
            QCoreApplication::translate("PictureImport", "Its stack.xml is larger than %1 MB.")
                .arg(kMaxOpenRasterStackBytes >> 20));
    case OraEntryProblem::Damaged:
        return unexpected(pictureTr(
            QT_TRANSLATE_NOOP("PictureImport", "Its stack.xml is damaged or cut short.")));
    case OraEntryProblem::None:
        break;
    }
    const auto entries = parseOraStack(xml);
    if (!entries)
        return unexpected(entries.error());
    std::vector<PictureLayer> layers;
    qint64 budget = kMaxPictureDecodedBytes;
    for (auto it = entries->rbegin(); it != entries->rend(); ++it) { // bottom first
        if (!it->visible || it->opacity <= 0.0)
            continue;
        auto image = readOraLayer(zip, *it, &budget);
        if (!image)
            return unexpected(image.error());
        multiplyOpacity(*image, it->opacity);
        layers.push_back(PictureLayer{it->name, std::move(*image), it->offset});
    }
    if (layers.empty())
        return unexpected(
            pictureTr(QT_TRANSLATE_NOOP("PictureImport", "It has no visible layer.")));
    return layers;
}

} // namespace finbook::model::picture_detail
