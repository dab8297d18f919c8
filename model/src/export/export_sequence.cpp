// PNG and SVG sequences: every file is written into a hidden folder inside the target folder
// and moved into place once all of them are on disk.
#include "export_formats.h"
#include "export_text.h"
#include "pending_output.h"
#include "target_lock.h"

#include <QDir>
#include <QDirIterator>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace finbook::model {

namespace {
// One entry per drawing (the sheet only exists with one file per drawing).
QByteArray exposureSheet(const ExportContext &context, const SequenceFiles &files)
{
    QJsonArray frames;
    qint64 start = 0;
    for (std::size_t i = 0; i < context.plan.frames.size(); ++i) {
        const int hold = context.plan.holds[i];
        frames.append(QJsonObject{{QStringLiteral("file"), files.name(qint64(i))},
                                  {QStringLiteral("frame"), context.plan.frames[i] + 1},
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

// A folder where a file should go is refused even with overwrite (it is never replaced);
// other files in the way only without it. The folder's entries are read, not the sequence's
// names tried one by one: a long sequence (millions of ticks) costs what the folder holds.
// With overwrite, `stale` gets the files of an earlier sequence of the same name that this
// one does not replace (frames past its end, other numbers): the swap removes them, so the
// folder never mixes two exports.
std::optional<ExportError> refuseExisting(const QString &folder, const SequenceFiles &files,
                                          bool overwrite, QStringList *stale)
{
    if (!QFileInfo(folder).isDir())
        return std::nullopt;
    QDirIterator entries(folder,
                         QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot);
    QStringList ours;
    while (entries.hasNext()) {
        const QFileInfo entry(entries.next());
        const QString name = entry.fileName();
        if (files.contains(name))
            ours << name;
        else if (overwrite && stale && files.isSequenceName(name) &&
                 (!entry.isDir() || entry.isSymLink()))
            *stale << name;
    }
    ours.sort(); // the first in writing order is named (same width numbers sort as they count)
    for (const QString &name : ours) {
        const QString path = QDir(folder).filePath(name);
        const QFileInfo info(path);
        if (info.isDir() && !info.isSymLink())
            return exportError(ExportErrorCode::BadOptions,
                               Export::tr("\"%1\" is a folder where a file should go; choose "
                                          "another folder.")
                                   .arg(QDir::toNativeSeparators(path)));
    }
    if (!overwrite && !ours.isEmpty())
        return targetExists(QDir(folder).filePath(ours.first()));
    return std::nullopt;
}

QByteArray encodeFrame(const ExportContext &context, std::size_t planIndex)
{
    if (context.options.format == ExportFormat::SvgSequence)
        return frameSvg(context.frame(planIndex), context.source.settings, context.plan,
                        context.camera(planIndex));
    return context.png(planIndex);
}

// Writes every image into the staging folder: a held drawing is encoded once and written
// once per tick.
std::optional<ExportError> writeImages(const ExportContext &context, const SequenceFiles &files,
                                       const PendingFolder &staging)
{
    const QString folder = context.options.target;
    const ExportPlan &plan = context.plan;
    const qint64 total = files.count();
    qint64 done = 0;
    for (std::size_t i = 0; i < plan.frames.size(); ++i) {
        const QByteArray bytes = encodeFrame(context, i);
        const int repeats = context.options.onePerDrawing ? 1 : plan.holds[i];
        for (int r = 0; r < repeats; ++r) {
            const QString name = files.name(done);
            if (bytes.isEmpty())
                return writeFailed(QDir(folder).filePath(name),
                                   Export::tr("there is not enough memory to render it"));
            if (auto reason = writeFileSynced(staging.filePath(name), bytes))
                return writeFailed(QDir(folder).filePath(name), *reason);
            if (context.cancelled(++done, total))
                return cancelledError();
        }
    }
    return std::nullopt;
}
} // namespace

ExportOutcome exportSequence(const ExportContext &context)
{
    const QString folder = context.options.target;
    const SequenceFiles files(context.plan, context.options);
    if (QFileInfo(folder).exists() && !QFileInfo(folder).isDir())
        return unexpected(
            exportError(ExportErrorCode::BadOptions,
                        Export::tr("\"%1\" is a file, not a folder; choose a folder for the %2 "
                                   "files, or remove the file.")
                            .arg(QDir::toNativeSeparators(folder),
                                 exportFormatSuffix(context.options.format).toUpper())));
    // Frames strewn over the root of the file system are never what was meant (a slip such
    // as "export walk.finbook /"); they would also mix with the system's own files.
    if (QDir(folder).isRoot())
        return unexpected(exportError(
            ExportErrorCode::BadOptions,
            Export::tr("\"%1\" is the top folder of the disk; choose "
                       "or name a folder for the frames, such as "
                       "\"%2\".")
                .arg(QDir::toNativeSeparators(folder),
                     QDir::toNativeSeparators(QDir(folder).filePath(context.options.baseName)))));
    // The lock first, and the leftovers of a killed export to this folder cleared (its swap
    // finished or undone), so that what is in the way is seen as it really is.
    FolderGuard guard(folder);
    if (!guard.ok())
        return unexpected(writeFailed(folder, Export::tr("the folder cannot be created")));
    TargetLock lock(folder, true);
    if (!lock.tryLock())
        return unexpected(targetBusy(folder));
    lock.removeLeftovers();
    QStringList stale;
    if (auto error = refuseExisting(folder, files, context.options.overwrite, &stale))
        return unexpected(*error);
    PendingFolder staging(folder);
    if (!staging.isValid())
        return unexpected(writeFailed(folder, staging.errorString()));

    if (auto error = writeImages(context, files, staging))
        return unexpected(*error);
    if (context.options.onePerDrawing) {
        const QString sheet = exposureSheetName(context.options);
        if (auto reason = writeFileSynced(staging.filePath(sheet), exposureSheet(context, files)))
            return unexpected(writeFailed(QDir(folder).filePath(sheet), *reason));
    }
    QString appeared;
    if (auto reason = staging.commit(
            files.count(), [&](qint64 i) { return files.name(i); }, context.options.overwrite,
            &appeared, stale))
        return unexpected(appeared.isEmpty() ? writeFailed(folder, *reason)
                                             : targetExists(appeared));
    guard.keep();

    ExportResult result;
    result.fileCount = files.count();
    for (qint64 i = 0; i < std::min<qint64>(files.count(), kListedExportFiles); ++i)
        result.files << QDir(folder).filePath(files.name(i));
    result.images = qint64(context.plan.frames.size());
    result.ticks = context.plan.ticks;
    result.size = context.plan.size;
    return result;
}

} // namespace finbook::model
