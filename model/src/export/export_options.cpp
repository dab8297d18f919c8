#include <finbook/model/document.h>
#include <finbook/model/export/export_options.h>
#include <finbook/model/reference/reference_layer.h>
#include <finbook/model/sound/soundtrack.h>

#include <QFileInfo>

#include <array>

namespace finbook::model {

namespace {
struct FormatInfo {
    ExportFormat format;
    const char *name;
    const char *suffix;
};
constexpr std::array kFormats{
    FormatInfo{ExportFormat::PngSequence, "png", "png"},
    FormatInfo{ExportFormat::SvgSequence, "svg", "svg"},
    FormatInfo{ExportFormat::Gif, "gif", "gif"},
    FormatInfo{ExportFormat::Mp4, "mp4", "mp4"},
    FormatInfo{ExportFormat::WebM, "webm", "webm"},
    FormatInfo{ExportFormat::Apng, "apng", "apng"},
    FormatInfo{ExportFormat::Html, "html", "html"},
    FormatInfo{ExportFormat::Obj, "obj", "obj"},
    FormatInfo{ExportFormat::Glb, "glb", "glb"},
    FormatInfo{ExportFormat::Lottie, "json", "json"},
    FormatInfo{ExportFormat::DotLottie, "lottie", "lottie"},
};

const FormatInfo &info(ExportFormat format)
{
    for (const FormatInfo &f : kFormats)
        if (f.format == format)
            return f;
    return kFormats.front();
}
} // namespace

std::vector<Frame> shotFrames(const std::vector<Layer> &layers, const ShotFilter &filter)
{
    // One plain layer exports its cels as they are (the frames of files before layers); a
    // scene exports its composed shot.
    const LayerProperties plain;
    const bool onePlainLayer = layers.size() == 1 && filter.admits(layers.front()) &&
                               layers.front().properties.opacity == plain.opacity &&
                               layers.front().properties.depth == plain.depth;
    return onePlainLayer ? layers.front().cels : composeShots(layers, filter);
}

std::vector<std::pair<Id, QString>> layerNamesOf(const std::vector<Layer> &layers)
{
    std::vector<std::pair<Id, QString>> names;
    for (const Layer &layer : layers)
        names.emplace_back(layer.id, layer.properties.name);
    return names;
}

ExportSource exportSource(const Document &document, const ShotFilter &filter)
{
    return ExportSource{shotFrames(document.layers(), filter),
                        document.settings(),
                        document.referenceLayer().reference(),
                        document.soundtrack().clips(),
                        document.camera(),
                        layerNamesOf(document.layers())};
}

std::optional<ExportFormat> exportFormatFromName(const QString &name)
{
    const QString n = name.trimmed().toLower();
    if (n == QLatin1String("htm"))
        return ExportFormat::Html;
    for (const FormatInfo &f : kFormats)
        if (n == QLatin1String(f.name))
            return f.format;
    return std::nullopt;
}

std::optional<ExportFormat> exportFormatForPath(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix();
    if (suffix.isEmpty())
        return std::nullopt;
    return exportFormatFromName(suffix);
}

QString exportFormatName(ExportFormat format)
{
    return QString::fromLatin1(info(format).name);
}

QString exportFormatSuffix(ExportFormat format)
{
    return QString::fromLatin1(info(format).suffix);
}

QString objMaterialPath(const QString &objTarget)
{
    // The name's own text with its suffix replaced: "walk.obj" stays relative, "a.b/c" gets
    // "a.b/c.mtl".
    // A name ending in a dot ("walk.") has an empty suffix: "walk.mtl", not "walk..mtl".
    const QString suffix = QFileInfo(objTarget).suffix();
    QString stem = objTarget.chopped(suffix.size());
    if (stem.endsWith(QLatin1Char('.')))
        stem.chop(1);
    return stem + QStringLiteral(".mtl");
}

bool exportsSequence(ExportFormat format)
{
    return format == ExportFormat::PngSequence || format == ExportFormat::SvgSequence;
}

bool exportsModel(ExportFormat format)
{
    return format == ExportFormat::Obj || format == ExportFormat::Glb;
}

bool exportNeedsFfmpeg(ExportFormat format)
{
    return format == ExportFormat::Gif || format == ExportFormat::Mp4 ||
           format == ExportFormat::WebM || format == ExportFormat::Apng;
}

bool exportSupportsTransparency(ExportFormat format)
{
    return format != ExportFormat::Mp4;
}

bool exportSupportsLoop(ExportFormat format)
{
    return format == ExportFormat::Gif || format == ExportFormat::Apng ||
           format == ExportFormat::Html || format == ExportFormat::DotLottie;
}

} // namespace finbook::model
