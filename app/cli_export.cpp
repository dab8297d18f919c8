#include "cli_export.h"

#include "cli.h"
#include "cli_terminal.h"
#include "native_names.h"
#include "native_target.h"

#include <finbook/model/export/exporter.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/io/printable_text.h>
#include <finbook/model/skeleton/cut_out_layers.h>

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QTextStream>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <sys/stat.h>

namespace finbook::app {

namespace {
class CommandLine {
    Q_DECLARE_TR_FUNCTIONS(CommandLine)
};

struct OptionSpec {
    const char *name;
    const char *valueName; // nullptr: a flag
    const char *help;
};

// QT_TRANSLATE_NOOP: the help texts are translated when --help prints them.
const OptionSpec kOptions[] = {
    {"format", "FORMAT",
     QT_TRANSLATE_NOOP("CommandLine",
                       "export: png, svg, gif, mp4, webm, apng, html, obj, glb, json (Lottie) or "
                       "lottie (dotLottie).")},
    {"range", "A-B",
     QT_TRANSLATE_NOOP("CommandLine", "export: frames A to B (default: the play range).")},
    {"frame", "N",
     QT_TRANSLATE_NOOP("CommandLine",
                       "export: frame N only; a 3D model (obj, glb) is one frame, by default the "
                       "first of the play range.")},
    {"scale", "S", QT_TRANSLATE_NOOP("CommandLine", "export: multiply the canvas size by S.")},
    {"fps", "N",
     QT_TRANSLATE_NOOP("CommandLine", "export: N frames per second (default: the document's).")},
    {"background", "COLOR",
     QT_TRANSLATE_NOOP("CommandLine", "export: this background colour (#rrggbb).")},
    {"transparent", nullptr, QT_TRANSLATE_NOOP("CommandLine", "export: no background.")},
    {"one-per-drawing", nullptr,
     QT_TRANSLATE_NOOP("CommandLine",
                       "export png/svg: one file per drawing plus an exposure sheet.")},
    {"include-reference", nullptr,
     QT_TRANSLATE_NOOP("CommandLine",
                       "export: paint the document's reference picture or video under the "
                       "drawing.")},
    {"no-camera", nullptr,
     QT_TRANSLATE_NOOP("CommandLine",
                       "export: the whole page, not the shot the document's camera frames.")},
    {"layers", "A,B",
     QT_TRANSLATE_NOOP("CommandLine",
                       "export: only the layers named A, B, ... (hidden ones too), not every "
                       "visible layer.")},
    {"strict", nullptr,
     QT_TRANSLATE_NOOP("CommandLine",
                       "export: fail (exit code 2, nothing written) when a sound clip or the "
                       "reference cannot be used, instead of leaving it out with a warning.")},
    {"overwrite", nullptr, QT_TRANSLATE_NOOP("CommandLine", "export: replace existing files.")},
    {"out-dir", "DIR", QT_TRANSLATE_NOOP("CommandLine", "export: write each FILE into DIR.")},
    {"max-frames", "N",
     QT_TRANSLATE_NOOP("CommandLine",
                       "export: allow up to N frames (default: 100000 files, 3 hours of video).")},
};

QString optionName(const OptionSpec &spec)
{
    return QString::fromLatin1(spec.name);
}

struct Request {
    QStringList inputs;
    QString output; // without --out-dir
    QString outDir; // with it
    std::optional<model::ExportFormat> format;
    model::ExportOptions options;
    QStringList layers; // --layers: names; empty = every visible layer
};

int fail(QTextStream &err, const QString &message, ExitCode code = ExitCode::BadInput)
{
    // Names from a file or the command line may hold terminal escapes: print them harmless.
    err << model::printableText(message.simplified()) << Qt::endl;
    return int(code);
}

std::optional<QString> parseRange(const QString &text, model::ExportOptions &options)
{
    const QStringList parts = text.split(QLatin1Char('-'));
    bool okA = false, okB = false;
    const int a = parts.value(0).trimmed().toInt(&okA);
    const int b = parts.size() == 2 ? parts[1].trimmed().toInt(&okB) : a;
    if (parts.size() > 2 || !okA || (parts.size() == 2 && !okB) || a < 1 || b < a)
        return CommandLine::tr("--range needs A-B with 1 <= A <= B, not \"%1\".").arg(text);
    options.firstFrame = a - 1;
    options.lastFrame = b - 1;
    return std::nullopt;
}

std::optional<QString> parseNumbers(const QCommandLineParser &p, model::ExportOptions &options)
{
    if (p.isSet(QStringLiteral("range")))
        if (auto error = parseRange(p.value(QStringLiteral("range")), options))
            return error;
    bool ok = true;
    if (p.isSet(QStringLiteral("frame"))) {
        if (p.isSet(QStringLiteral("range")))
            return CommandLine::tr("--frame and --range cannot be used together.");
        const int frame = p.value(QStringLiteral("frame")).trimmed().toInt(&ok);
        if (!ok || frame < 1)
            return CommandLine::tr("--frame needs a frame number from 1, not \"%1\".")
                .arg(p.value(QStringLiteral("frame")));
        options.firstFrame = options.lastFrame = frame - 1;
    }
    if (p.isSet(QStringLiteral("scale"))) {
        options.scale = p.value(QStringLiteral("scale")).toDouble(&ok);
        if (!ok || !(options.scale > 0))
            return CommandLine::tr("--scale needs a number above 0, not \"%1\".")
                .arg(p.value(QStringLiteral("scale")));
    }
    if (p.isSet(QStringLiteral("fps"))) {
        options.fps = p.value(QStringLiteral("fps")).toInt(&ok);
        if (!ok || options.fps < model::kMinFps || options.fps > model::kMaxFps)
            return CommandLine::tr("--fps needs a whole number from %1 to %2, not \"%3\".")
                .arg(model::kMinFps)
                .arg(model::kMaxFps)
                .arg(p.value(QStringLiteral("fps")));
    }
    if (p.isSet(QStringLiteral("max-frames"))) {
        options.maxFrames = p.value(QStringLiteral("max-frames")).toLongLong(&ok);
        if (!ok || options.maxFrames < 1)
            return CommandLine::tr("--max-frames needs a whole number above 0, not \"%1\".")
                .arg(p.value(QStringLiteral("max-frames")));
    }
    if (p.isSet(QStringLiteral("background"))) {
        const QColor color = QColor::fromString(p.value(QStringLiteral("background")));
        if (!color.isValid())
            return CommandLine::tr("--background needs a colour such as #ffffff, not \"%1\".")
                .arg(p.value(QStringLiteral("background")));
        options.background = color.rgb();
    }
    return std::nullopt;
}

std::optional<QString> parseFormat(const QCommandLineParser &p, Request &r)
{
    if (p.isSet(QStringLiteral("format"))) {
        r.format = model::exportFormatFromName(p.value(QStringLiteral("format")));
        if (!r.format)
            return CommandLine::tr("Unknown export format \"%1\"; use png, svg, gif, mp4, webm, "
                                   "apng, html, obj, glb, json (Lottie) or lottie (dotLottie).")
                .arg(p.value(QStringLiteral("format")));
    }
    if (!r.outDir.isEmpty()) {
        r.options.format = r.format.value_or(model::ExportFormat::PngSequence);
        return std::nullopt;
    }
    const QString suffix = QFileInfo(r.output).suffix();
    const auto named = model::exportFormatForPath(r.output);
    struct stat status {}; // by its bytes: the text of a name that is not UTF-8 names another
    const bool isFolder =
        ::stat(argumentBytes(r.output).constData(), &status) == 0 && S_ISDIR(status.st_mode);
    if (!r.format && isFolder) { // an existing folder: PNG frames into it
        // ... unless its name asks for one file: "anim.gif/" receiving PNGs surprises.
        if (named && !model::exportsSequence(*named))
            return CommandLine::tr("\"%1\" is a folder, not a %2 file; give a file name, or "
                                   "--format png to write PNG frames into the folder.")
                .arg(r.output, model::exportFormatName(*named).toUpper());
        r.options.format = model::ExportFormat::PngSequence;
        return std::nullopt;
    }
    if (!r.format && !suffix.isEmpty() && (!named || model::exportsSequence(*named)))
        return CommandLine::tr("Cannot tell the format from \"%1\": end it in .gif, .mp4, .webm, "
                               ".apng, .html, .obj, .glb, .json (Lottie) or .lottie, give a "
                               "folder for PNG frames, or use --format.")
            .arg(r.output);
    if (r.format && named && !model::exportsSequence(*r.format) && *named != *r.format)
        return CommandLine::tr("--format %1 does not match \"%2\".")
            .arg(model::exportFormatName(*r.format), r.output);
    r.options.format = r.format.value_or(named.value_or(model::ExportFormat::PngSequence));
    return std::nullopt;
}

std::optional<QString> parseRequest(const QStringList &arguments, Request &r)
{
    QCommandLineParser p;
    addExportOptions(p);
    if (!p.parse(QStringList{QStringLiteral("finbook")} + arguments))
        return p.errorText();
    r.outDir = p.value(QStringLiteral("out-dir"));
    r.inputs = p.positionalArguments();
    if (r.outDir.isEmpty()) {
        if (r.inputs.size() != 2)
            return CommandLine::tr("Usage: finbook export FILE OUT, or finbook export FILE... "
                                   "--out-dir DIR");
        r.output = r.inputs.takeLast();
    } else if (r.inputs.isEmpty()) {
        return CommandLine::tr("Usage: finbook export FILE... --out-dir DIR");
    }
    if (auto error = parseFormat(p, r))
        return error;
    if (auto error = parseNumbers(p, r.options))
        return error;
    r.options.transparent = p.isSet(QStringLiteral("transparent"));
    r.options.onePerDrawing = p.isSet(QStringLiteral("one-per-drawing"));
    r.options.includeReference = p.isSet(QStringLiteral("include-reference"));
    r.options.overwrite = p.isSet(QStringLiteral("overwrite"));
    r.options.strictMedia = p.isSet(QStringLiteral("strict"));
    r.options.camera = !p.isSet(QStringLiteral("no-camera"));
    if (p.isSet(QStringLiteral("layers"))) {
        for (const QString &name : p.value(QStringLiteral("layers")).split(QLatin1Char(',')))
            if (!name.trimmed().isEmpty())
                r.layers << name.trimmed();
        if (r.layers.isEmpty())
            return CommandLine::tr("--layers needs the names of layers, separated by commas.");
    }
    if (r.options.transparent && r.options.background)
        return CommandLine::tr("--transparent and --background cannot be used together.");
    if (r.options.onePerDrawing && !model::exportsSequence(r.options.format))
        return CommandLine::tr("--one-per-drawing is for png and svg exports only.");
    return std::nullopt;
}

QString targetFor(const Request &r, const QString &input)
{
    if (r.outDir.isEmpty())
        return r.output;
    const QString name = QFileInfo(input).completeBaseName();
    if (model::exportsSequence(r.options.format))
        return QDir(r.outDir).filePath(name);
    return QDir(r.outDir).filePath(name + QLatin1Char('.') +
                                   model::exportFormatSuffix(r.options.format));
}

// targetFor as bytes: the names given on the command line as they were given, so that an
// output or input named by bytes that are not UTF-8 gives its bytes to the output.
QByteArray targetBytes(const Request &r, const QString &input)
{
    if (r.outDir.isEmpty())
        return argumentBytes(r.output);
    QByteArray name = argumentBytes(input);
    name = name.mid(name.lastIndexOf('/') + 1);
    if (name.contains('.'))
        name.truncate(name.lastIndexOf('.'));
    if (!model::exportsSequence(r.options.format))
        name += '.' + model::exportFormatSuffix(r.options.format).toLatin1();
    QByteArray folder = argumentBytes(r.outDir);
    return folder.endsWith('/') ? folder + name : folder + '/' + name;
}

// The files written, one a line: a long sequence's names are made again one at a time.
void printWrittenFiles(const model::ExportResult &result, const model::ExportOptions &options,
                       const model::ExportSource &source, const NativeTarget &native,
                       QTextStream &out)
{
    // Written as they are for a program reading them (the bytes of a name that is not UTF-8
    // too); on a terminal harmless, as ls does.
    const bool terminal = stdoutIsTerminal();
    const auto print = [&](const QString &path) {
        const QByteArray bytes = native.bytes(path);
        if (terminal || isValidFileName(bytes) || !out.device()) {
            const QString text = QFile::decodeName(bytes);
            out << (terminal ? model::printableText(text) : text) << '\n';
            return;
        }
        out.flush();
        out.device()->write(bytes + '\n');
    };
    if (result.fileCount <= result.files.size())
        std::for_each(result.files.begin(), result.files.end(), print);
    else
        model::forEachExportTarget(source, options, print);
    out.flush();
}

// "walk.gif: 37/120" rewritten in place, only for people watching a terminal. The name is
// printed harmless (a file name may hold terminal escapes). Returns false once SIGINT,
// SIGTERM or SIGHUP arrived, which stops the export and removes what it wrote.
model::ExportProgress exportProgress(const QString &name)
{
    const bool terminal = stderrIsTerminal();
    const QByteArray shownName = model::printableText(name).toLocal8Bit();
    return [terminal, shownName, shown = -1](qint64 done, qint64 total) mutable {
        if (interrupted())
            return false;
        const int percent = total > 0 ? int(done * 100 / total) : 100;
        if (terminal && percent != shown) {
            shown = percent;
            std::fprintf(stderr, "\r%s: %lld/%lld (%d%%)", shownName.constData(), done, total,
                         percent);
            std::fflush(stderr);
        }
        return true;
    };
}

void clearProgressLine()
{
    if (stderrIsTerminal())
        std::fprintf(stderr, "\r\033[K");
}

int exportOne(const Request &request, const QString &input, QTextStream &out, QTextStream &err)
{
    const QString openable = openablePath(input);
    auto loaded = model::loadFinbook(openable);
    if (!loaded)
        return fail(err, QString(loaded.error().message).replace(openable, input));
    model::ExportOptions options = request.options;
    options.target = targetFor(request, input);
    NativeTarget native; // a name that is not UTF-8 is written by its bytes
    QString reason;
    if (!native.prepare(targetBytes(request, input), model::exportsSequence(options.format),
                        options, &reason))
        return fail(err,
                    CommandLine::tr("Could not write \"%1\": %2. Nothing was exported.")
                        .arg(options.target, reason),
                    ExitCode::Failure);
    options.title = QFileInfo(input).completeBaseName();
    model::restoreCutOutLayers(loaded->frames, loaded->settings.closeGap);
    const std::vector<model::Layer> layers = model::takeLoadedLayers(*loaded);
    model::ShotFilter filter;
    for (const QString &name : request.layers) {
        const auto named = std::find_if(layers.begin(), layers.end(), [&](const model::Layer &l) {
            return l.properties.name == name;
        });
        if (named == layers.end()) {
            QStringList names;
            for (const model::Layer &l : layers)
                names << QLatin1Char('"') + l.properties.name + QLatin1Char('"');
            return fail(err, CommandLine::tr("\"%1\" has no layer named \"%2\"; its layers are "
                                             "%3. Nothing was exported.")
                                 .arg(input, name, names.join(QStringLiteral(", "))));
        }
        filter.onlyLayers.push_back(named->id);
        filter.hiddenToo = true;
    }
    const model::ExportSource source{
        model::shotFrames(layers, filter), loaded->settings,          std::move(loaded->reference),
        std::move(loaded->sound),          std::move(loaded->camera), model::layerNamesOf(layers)};
    const auto result = model::exportAnimation(
        source, options, exportProgress(QFileInfo(native.shown(options.target)).fileName()));
    clearProgressLine();
    if (!result) {
        const model::ExportErrorCode code = result.error().code;
        if (code == model::ExportErrorCode::Cancelled && interrupted())
            return fail(err, CommandLine::tr("Interrupted; nothing was exported."),
                        ExitCode(128 + interruptSignal()));
        const bool badInput = code == model::ExportErrorCode::BadOptions ||
                              code == model::ExportErrorCode::TargetExists ||
                              code == model::ExportErrorCode::TooLarge ||
                              code == model::ExportErrorCode::MediaUnusable;
        QString message = native.shown(result.error().message);
        if (code == model::ExportErrorCode::TargetExists)
            message += QLatin1Char(' ') + CommandLine::tr("Use --overwrite to replace it.");
        if (code == model::ExportErrorCode::TooLarge)
            message += QLatin1Char(' ') + CommandLine::tr("Use --max-frames N to allow N frames.");
        return fail(err, message, badInput ? ExitCode::BadInput : ExitCode::Failure);
    }
    native.keep();
    printWrittenFiles(*result, options, source, native, out);
    if (!result->note.isEmpty()) // stdout lists the files only, for scripts
        err << model::printableText(result->note.simplified()) << Qt::endl;
    return int(ExitCode::Ok);
}
} // namespace

void addExportOptions(QCommandLineParser &parser)
{
    for (const OptionSpec &spec : kOptions) {
        const QString help = QCoreApplication::translate("CommandLine", spec.help);
        if (spec.valueName)
            parser.addOption(
                QCommandLineOption(optionName(spec), help, QString::fromLatin1(spec.valueName)));
        else
            parser.addOption(QCommandLineOption(optionName(spec), help));
    }
}

QStringList exportOptionArguments(const QCommandLineParser &parser)
{
    QStringList words;
    for (const OptionSpec &spec : kOptions) {
        if (!parser.isSet(optionName(spec)))
            continue;
        QString word = QStringLiteral("--") + optionName(spec);
        if (spec.valueName)
            word += QLatin1Char('=') + parser.value(optionName(spec));
        words << word;
    }
    return words;
}

int runExportCommand(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    Request request;
    if (auto error = parseRequest(arguments, request))
        return fail(err, *error);
    catchInterrupts();
    for (const QString &input : request.inputs)
        if (const int code = exportOne(request, input, out, err); code != int(ExitCode::Ok))
            return code;
    return int(ExitCode::Ok);
}

} // namespace finbook::app
