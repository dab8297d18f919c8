// PNG and SVG sequences: every file is written into a hidden folder inside the target folder
// and moved into place once all of them are on disk.
#include "export_formats.h"
#include "export_text.h"
#include "pending_output.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace finbook::model {

namespace {
QByteArray exposureSheet(const ExportContext &context, const std::vector<SequenceEntry> &entries)
{
    QJsonArray frames;
    qint64 start = 0;
    for (const SequenceEntry &e : entries) {
        const int hold = context.plan.holds[e.planIndex];
        frames.append(QJsonObject{{QStringLiteral("file"), e.name},
                                  {QStringLiteral("frame"), context.plan.frames[e.planIndex] + 1},
                                  {QStringLiteral("start_tick"), start},
                                  {QStringLiteral("hold"), hold}});
        start += hold;
    }
    const QJsonObject sheet{{QStringLiteral("fps"), context.plan.fps},
                            {QStringLiteral("ticks"), context.plan.ticks},
                            {QStringLiteral("width"), context.plan.size.width()},
                            {QStringLiteral("height"), context.plan.size.height()},
                            {QStringLiteral("frames"), frames}};
    return QJsonDocument(sheet).toJson(QJsonDocument::Indented);
}

std::optional<ExportError> refuseExisting(const QString &folder, const QStringList &names)
{
    for (const QString &name : names) {
        const QString path = QDir(folder).filePath(name);
        if (QFileInfo(path).isDir())
            return exportError(ExportErrorCode::BadOptions,
                               Export::tr("\"%1\" is a folder where a file should go; choose "
                                          "another folder.")
                                   .arg(QDir::toNativeSeparators(path)));
        if (QFileInfo::exists(path))
            return targetExists(path);
    }
    return std::nullopt;
}

QByteArray encodeFrame(const ExportContext &context, std::size_t planIndex)
{
    if (context.options.format == ExportFormat::SvgSequence)
        return frameSvg(context.frame(planIndex), context.source.settings, context.plan);
    return context.png(planIndex);
}
} // namespace

ExportOutcome exportSequence(const ExportContext &context)
{
    const QString folder = context.options.target;
    const std::vector<SequenceEntry> entries = sequenceEntries(context.plan, context.options);
    QStringList names;
    for (const SequenceEntry &e : entries)
        names << e.name;
    if (context.options.onePerDrawing)
        names << exposureSheetName(context.options);
    if (QFileInfo(folder).exists() && !QFileInfo(folder).isDir())
        return unexpected(writeFailed(folder, Export::tr("a file is in the way of the folder")));
    if (!context.options.overwrite)
        if (auto error = refuseExisting(folder, names))
            return unexpected(*error);

    FolderGuard guard(folder);
    if (!guard.ok())
        return unexpected(writeFailed(folder, Export::tr("the folder cannot be created")));
    PendingFolder staging(folder);
    if (!staging.isValid())
        return unexpected(writeFailed(folder, staging.errorString()));

    const qint64 total = qint64(entries.size());
    qint64 done = 0;
    QByteArray bytes;
    std::size_t encoded = std::size_t(-1);
    for (const SequenceEntry &e : entries) {
        if (e.planIndex != encoded) { // a held drawing is encoded once, written per tick
            bytes = encodeFrame(context, e.planIndex);
            encoded = e.planIndex;
        }
        if (bytes.isEmpty())
            return unexpected(writeFailed(QDir(folder).filePath(e.name),
                                          Export::tr("there is not enough memory to render it")));
        if (auto reason = writeFileSynced(staging.filePath(e.name), bytes))
            return unexpected(writeFailed(QDir(folder).filePath(e.name), *reason));
        if (context.cancelled(++done, total))
            return unexpected(cancelledError());
    }
    if (context.options.onePerDrawing) {
        const QString sheet = exposureSheetName(context.options);
        if (auto reason = writeFileSynced(staging.filePath(sheet), exposureSheet(context, entries)))
            return unexpected(writeFailed(QDir(folder).filePath(sheet), *reason));
    }
    if (auto reason = staging.commit(names))
        return unexpected(writeFailed(folder, *reason));
    guard.keep();

    ExportResult result;
    for (const QString &name : names)
        result.files << QDir(folder).filePath(name);
    result.images = qint64(context.plan.frames.size());
    result.ticks = context.plan.ticks;
    result.size = context.plan.size;
    return result;
}

} // namespace finbook::model
