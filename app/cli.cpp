#include "cli.h"

#include <finbook/model/finbook_file.h>
#include <finbook/model/render.h>

#include <QCoreApplication>
#include <QDir>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

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
    err << message.simplified() << Qt::endl;
    return int(code);
}

QJsonObject summary(const model::LoadedDocument &doc)
{
    qint64 objects = 0, strokes = 0, points = 0, pins = 0;
    std::unordered_set<const model::StrokeData *> distinct;
    for (const model::Frame &f : doc.frames) {
        objects += qint64(f.groups.size());
        for (const model::StrokeGroup &g : f.groups) {
            strokes += qint64(g.strokes.size());
            pins += qint64(g.pins.size());
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
    o[QStringLiteral("fps")] = doc.settings.fps;
    o[QStringLiteral("canvas_width")] = doc.settings.canvasSize.width();
    o[QStringLiteral("canvas_height")] = doc.settings.canvasSize.height();
    return o;
}

int exportFrames(const QString &path, const QString &outDir, QTextStream &out, QTextStream &err)
{
    auto loaded = model::loadFinbook(path);
    if (!loaded)
        return fail(err, loaded.error().message);
    QDir dir(outDir);
    if (!dir.exists() && !QDir().mkpath(outDir))
        return fail(err, CommandLine::tr("Cannot create the output folder %1.").arg(outDir),
                    ExitCode::Failure);
    const model::DocumentSettings &settings = loaded->settings;
    for (std::size_t i = 0; i < loaded->frames.size(); ++i) {
        const QImage image = model::renderFrame(loaded->frames[i], settings, settings.canvasSize);
        const QString name = QStringLiteral("frame_%1.png").arg(i + 1, 4, 10, QLatin1Char('0'));
        const QString file = dir.filePath(name);
        if (!image.save(file, "PNG"))
            return fail(
                err, CommandLine::tr("Cannot write %1 (is the disk full or read-only?).").arg(file),
                ExitCode::Failure);
        out << file << Qt::endl;
    }
    return int(ExitCode::Ok);
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
        return a == QLatin1String("info") || a == QLatin1String("export");
    }
    return false;
}

QByteArray documentInfoJson(const QString &path, QString *error)
{
    auto loaded = model::loadFinbook(path);
    if (!loaded) {
        if (error)
            *error = loaded.error().message;
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
    if (command == QLatin1String("export")) {
        if (positional.size() != 2)
            return fail(err, CommandLine::tr("Usage: finbook export FILE OUTDIR"));
        return exportFrames(positional[0], positional[1], out, err);
    }
    return fail(err, CommandLine::tr("Unknown command \"%1\"; see finbook --help.").arg(command));
}

} // namespace finbook::app
