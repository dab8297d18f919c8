#include "export_formats.h"
#include "export_text.h"

#include <finbook/model/export/exporter.h>

#include <QBuffer>
#include <QDir>
#include <QFileInfo>
#include <QImageWriter>

namespace finbook::model {

ExportError targetExists(const QString &path)
{
    return exportError(ExportErrorCode::TargetExists,
                       Export::tr("\"%1\" already exists; nothing was exported.")
                           .arg(QDir::toNativeSeparators(path)));
}

ExportError writeFailed(const QString &path, const QString &reason)
{
    return exportError(ExportErrorCode::WriteFailed,
                       Export::tr("Could not write \"%1\": %2. Nothing was exported; free some "
                                  "disk space or choose another folder, then export again.")
                           .arg(QDir::toNativeSeparators(path), reason));
}

ExportError cancelledError()
{
    return exportError(ExportErrorCode::Cancelled,
                       Export::tr("The export was cancelled; nothing was written."));
}

std::optional<ExportError> checkFileTarget(const ExportOptions &options)
{
    const QFileInfo info(options.target);
    if (info.isDir())
        return exportError(
            ExportErrorCode::BadOptions,
            Export::tr("\"%1\" is a folder; give a file name ending in .%2.")
                .arg(QDir::toNativeSeparators(options.target), exportFormatSuffix(options.format)));
    if ((info.exists() || info.isSymLink()) && !options.overwrite)
        return targetExists(options.target);
    return std::nullopt;
}

QString exposureSheetName(const ExportOptions &options)
{
    return options.baseName + QStringLiteral("_exposures.json");
}

std::vector<SequenceEntry> sequenceEntries(const ExportPlan &plan, const ExportOptions &options)
{
    const qint64 count = options.onePerDrawing ? qint64(plan.frames.back()) + 1 : plan.ticks;
    const int digits = std::max(4, int(QString::number(count).size()));
    const QString suffix = exportFormatSuffix(options.format);
    const auto name = [&](qint64 number) {
        return QStringLiteral("%1_%2.%3")
            .arg(options.baseName)
            .arg(number, digits, 10, QLatin1Char('0'))
            .arg(suffix);
    };
    std::vector<SequenceEntry> entries;
    qint64 tick = 0;
    for (std::size_t i = 0; i < plan.frames.size(); ++i) {
        if (options.onePerDrawing) {
            entries.push_back({name(plan.frames[i] + 1), i});
            continue;
        }
        for (int r = 0; r < plan.holds[i]; ++r)
            entries.push_back({name(++tick), i});
    }
    return entries;
}

QStringList exportTargetFiles(const ExportSource &source, const ExportOptions &options)
{
    if (!exportsSequence(options.format))
        return {options.target};
    const auto plan = planExport(source, options);
    if (!plan)
        return {};
    QStringList names;
    for (const SequenceEntry &e : sequenceEntries(*plan, options))
        names << e.name;
    if (options.onePerDrawing)
        names << exposureSheetName(options);
    return names;
}

Expected<ExportResult, ExportError> exportAnimation(const ExportSource &source,
                                                    const ExportOptions &options,
                                                    const ExportProgress &progress)
{
    if (options.target.trimmed().isEmpty())
        return unexpected(exportError(ExportErrorCode::BadOptions,
                                      Export::tr("Choose where to export the animation to.")));
    const auto plan = planExport(source, options);
    if (!plan)
        return unexpected(plan.error());
    const ExportContext context{source, options, *plan, progress};
    if (exportsSequence(options.format))
        return exportSequence(context);
    if (options.format == ExportFormat::Html)
        return exportFlipbook(context);
    return exportEncoded(context);
}

} // namespace finbook::model
