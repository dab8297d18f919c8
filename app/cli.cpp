#include "cli.h"

#include "cli_export.h"
#include "native_names.h"
#include "thumbnail/thumbnail_command.h"

#include <finbook/model/export/export_plan.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/io/printable_text.h>
#include <finbook/model/picture/picture_object.h>

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include <cstdio>
#include <unistd.h>
#include <unordered_set>

namespace finbook::app {

namespace {
// A class so lupdate files these strings under the context main.cpp uses too.
class CommandLine {
    Q_DECLARE_TR_FUNCTIONS(CommandLine)
};

// Messages may carry newlines (or come from Qt); the contract is one line on stderr.
int fail(QTextStream &err, const QString &message, ExitCode code = ExitCode::BadInput)
{
    // Names from a file or the command line may hold terminal escapes: print them harmless.
    err << model::printableText(message.simplified()) << Qt::endl;
    return int(code);
}

const char *referenceKindName(model::ReferenceKind kind)
{
    switch (kind) {
    case model::ReferenceKind::None:
        return "none";
    case model::ReferenceKind::Image:
        return "image";
    case model::ReferenceKind::Video:
        return "video";
    case model::ReferenceKind::Sequence:
        return "sequence";
    }
    return "none";
}

// The soundtrack and the reference: what a script checking a file before export wants to know.
void summariseMedia(const model::LoadedDocument &doc, QJsonObject &o)
{
    qint64 soundBytes = 0, audible = 0;
    for (const model::SoundClip &clip : doc.sound) {
        soundBytes += clip.bytes.size();
        audible += clip.muted ? 0 : 1;
    }
    o[QStringLiteral("sound_clips")] = qint64(doc.sound.size());
    o[QStringLiteral("sound_clips_audible")] = audible;
    o[QStringLiteral("sound_bytes")] = soundBytes;
    const model::Reference &ref = doc.reference;
    o[QStringLiteral("reference")] =
        QLatin1String(referenceKindName(ref.isEmpty() ? model::ReferenceKind::None : ref.kind));
    qint64 referenceBytes = ref.isEmpty() ? 0 : ref.bytes.size();
    if (!ref.isEmpty() && ref.kind == model::ReferenceKind::Sequence) {
        referenceBytes = 0; // `bytes` is the first of the pictures
        for (const QByteArray &picture : ref.pictures)
            referenceBytes += picture.size();
    }
    o[QStringLiteral("reference_bytes")] = referenceBytes;
    o[QStringLiteral("reference_pictures")] =
        qint64(ref.kind == model::ReferenceKind::Sequence ? ref.pictures.size() : 0);
    o[QStringLiteral("camera_keys")] = qint64(doc.camera.keys.size());
    if (!doc.camera.isEmpty()) {
        o[QStringLiteral("camera_first_tick")] = doc.camera.keys.front().tick;
        o[QStringLiteral("camera_last_tick")] = doc.camera.keys.back().tick;
    }
}

QJsonObject summary(const model::LoadedDocument &doc)
{
    qint64 objects = 0, strokes = 0, points = 0, pins = 0, fills = 0;
    std::unordered_set<const model::StrokeData *> distinct;
    // Picture objects, and the distinct pictures they show (each saved once) with their bytes.
    qint64 pictureObjects = 0, pictureBytes = 0;
    std::unordered_set<const model::PictureData *> pictures;
    for (const model::Frame &f : doc.frames) {
        objects += qint64(f.groups.size());
        for (const model::StrokeGroup &g : f.groups) {
            if (g.picture && g.picture->data) {
                ++pictureObjects;
                if (pictures.insert(g.picture->data.get()).second)
                    pictureBytes += g.picture->data->png.size();
            }
            strokes += qint64(g.strokes.size());
            pins += qint64(g.rig.pins.size());
            fills += qint64(g.fills.size());
            for (const model::Stroke &s : g.strokes) {
                if (!s.data)
                    continue;
                points += qint64(s.data->points.size());
                distinct.insert(s.data.get());
            }
        }
    }
    QJsonObject o;
    o[QStringLiteral("format_version")] = qint64(doc.formatVersion);
    o[QStringLiteral("frames")] = qint64(doc.frames.size());
    o[QStringLiteral("objects")] = objects;
    o[QStringLiteral("strokes")] = strokes;
    o[QStringLiteral("points")] = points;
    o[QStringLiteral("stroke_data")] = qint64(distinct.size());
    o[QStringLiteral("pins")] = pins;
    o[QStringLiteral("fills")] = fills;
    o[QStringLiteral("picture_objects")] = pictureObjects;
    o[QStringLiteral("pictures")] = qint64(pictures.size());
    o[QStringLiteral("picture_bytes")] = pictureBytes;
    o[QStringLiteral("fps")] = doc.settings.fps;
    o[QStringLiteral("canvas_width")] = doc.settings.canvasSize.width();
    o[QStringLiteral("canvas_height")] = doc.settings.canvasSize.height();
    // What playback (and a default export) covers: the play range of the shot, holds included.
    model::LoadedDocument copy = doc;
    const std::vector<model::Layer> layers = model::takeLoadedLayers(copy);
    const qint64 ticks = model::playbackTicks(model::shotFrames(layers), doc.settings);
    QJsonArray list;
    for (const model::Layer &l : layers)
        list.append(QJsonObject{{QStringLiteral("name"), l.properties.name},
                                {QStringLiteral("cels"), qint64(l.cels.size())},
                                {QStringLiteral("ticks"), model::celTicks(l.cels)},
                                {QStringLiteral("visible"), l.properties.visible},
                                {QStringLiteral("locked"), l.properties.locked},
                                {QStringLiteral("opacity"), l.properties.opacity},
                                {QStringLiteral("depth"), l.properties.depth}});
    o[QStringLiteral("layers")] = list;
    o[QStringLiteral("ticks")] = ticks;
    o[QStringLiteral("duration_s")] = double(ticks) / std::max(1, doc.settings.fps);
    summariseMedia(doc, o);
    return o;
}

} // namespace

QString finbookVersion()
{
    return QStringLiteral(FINBOOK_VERSION);
}

bool isHeadlessCommand(const QStringList &arguments)
{
    for (const QString &a : arguments) {
        if (a.startsWith(QLatin1Char('-')))
            continue;
        return a == QLatin1String("info") || a == QLatin1String("export") ||
               a == QLatin1String("thumbnail");
    }
    return false;
}

bool headlessCommandRendersText(const QStringList &arguments)
{
    // The option words come before "--" (main.cpp puts them there); file names after it.
    const qsizetype end = arguments.indexOf(QStringLiteral("--"));
    const QStringList options = end < 0 ? arguments : arguments.mid(0, end);
    return !options.isEmpty() && options.first() == QLatin1String("export") &&
           options.contains(QStringLiteral("--include-reference"));
}

void quietQtMessages(QtMsgType type, const QMessageLogContext &, const QString &message)
{
    if (type == QtFatalMsg)
        QTextStream(stderr) << model::printableText(message.simplified()) << Qt::endl;
}

QByteArray documentInfoJson(const QString &path, QString *error)
{
    const QString openable = openablePath(path); // a name that is not UTF-8: native_names.h
    auto loaded = model::loadFinbook(openable);
    if (!loaded) {
        if (error)
            *error = QString(loaded.error().message).replace(openable, path);
        return {};
    }
    return QJsonDocument(summary(*loaded)).toJson(QJsonDocument::Compact);
}

int runHeadlessCommand(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    QStringList positional = arguments;
    if (positional.isEmpty())
        return fail(err, CommandLine::tr("No command given; see finbook --help."));
    const QString command = positional.takeFirst();
    if (command == QLatin1String("info")) {
        if (positional.size() != 1)
            return fail(err, CommandLine::tr("Usage: finbook info FILE"));
        QString error;
        const QByteArray json = documentInfoJson(positional.first(), &error);
        if (json.isEmpty())
            return fail(err, error);
        out << json << Qt::endl;
        return int(ExitCode::Ok);
    }
    if (command == QLatin1String("export"))
        return runExportCommand(positional, out, err);
    if (command == QLatin1String("thumbnail")) {
        const int code = runThumbnailCommand(positional, err);
        if (thumbnailWorkLeftRunning()) { // the PNG is written; a picture is still painting
            err.flush();
            out.flush();
            std::fflush(nullptr);
            ::_exit(code);
        }
        return code;
    }
    return fail(err, CommandLine::tr("Unknown command \"%1\"; see finbook --help.").arg(command));
}

} // namespace finbook::app
