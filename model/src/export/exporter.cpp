#include "export_formats.h"
#include "export_text.h"
#include "pending_output.h"
#include "target_lock.h"

#include <finbook/model/export/exporter.h>

#include <QBuffer>
#include <QDir>
#include <QDirIterator>
#include <QFileInfo>
#include <QImageWriter>

#include <algorithm>
#include <limits>
#include <sys/stat.h>

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

ExportError targetBusy(const QString &path)
{
    return exportError(ExportErrorCode::TargetBusy,
                       Export::tr("Another export is writing to \"%1\"; wait until it has "
                                  "finished, or choose another target.")
                           .arg(QDir::toNativeSeparators(path)));
}

std::optional<ExportError> claimFileTarget(const QString &target, const FolderGuard &guard,
                                           std::initializer_list<TargetLock *> locks)
{
    if (!guard.ok())
        return writeFailed(target, Export::tr("its folder cannot be created"));
    for (TargetLock *lock : locks)
        if (!lock->tryLock())
            return targetBusy(target);
    for (TargetLock *lock : locks)
        lock->removeLeftovers();
    return std::nullopt;
}

QByteArray nativeTargetPath(const ExportOptions &options)
{
    if (options.nativeName.isEmpty())
        return QFile::encodeName(options.target);
    return QFile::encodeName(QFileInfo(options.target).path()) + '/' + options.nativeName;
}

std::optional<ExportError> commitFile(PendingFile &pending, const ExportOptions &options)
{
    bool appeared = false;
    if (auto reason = pending.commit(nativeTargetPath(options), options.overwrite, &appeared))
        return appeared ? targetExists(options.target) : writeFailed(options.target, *reason);
    return std::nullopt;
}

std::optional<ExportError>
writeSingleFile(const ExportOptions &options,
                const std::function<Expected<QByteArray, ExportError>()> &make)
{
    const QString target = options.target;
    if (auto error = checkFileTarget(options))
        return error;
    FolderGuard guard(QFileInfo(target).path());
    TargetLock lock(target, false);
    if (auto error = claimFileTarget(target, guard, {&lock}))
        return error;
    const auto bytes = make();
    if (!bytes)
        return bytes.error();
    PendingFile pending(target);
    QString reason;
    if (!pending.open(&reason))
        return writeFailed(target, reason);
    if (auto failed = writeSynced(pending.file(), *bytes))
        return writeFailed(target, *failed);
    if (auto error = commitFile(pending, options))
        return error;
    guard.keep();
    return std::nullopt;
}

std::optional<ExportError> checkFileTarget(const ExportOptions &options)
{
    // By its bytes: the name as text may stand for another file (nativeName).
    const QByteArray path = nativeTargetPath(options);
    struct stat link {
    }, followed{};
    const bool exists = ::lstat(path.constData(), &link) == 0;
    if (exists && ::stat(path.constData(), &followed) == 0 && S_ISDIR(followed.st_mode))
        return exportError(
            ExportErrorCode::BadOptions,
            Export::tr("\"%1\" is a folder; give a file name ending in .%2.")
                .arg(QDir::toNativeSeparators(options.target), exportFormatSuffix(options.format)));
    if (exists && !options.overwrite)
        return targetExists(options.target);
    return std::nullopt;
}

QString exposureSheetName(const ExportOptions &options)
{
    return options.baseName + QStringLiteral("_exposures.json");
}

SequenceFiles::SequenceFiles(const ExportPlan &plan, const ExportOptions &options)
    : m_plan(plan)
    , m_options(options)
    , m_count(exportFrameCount(plan, options))
{
    const qint64 largest = options.onePerDrawing ? qint64(plan.frames.back()) + 1 : plan.ticks;
    m_digits = std::max(4, int(QString::number(largest).size()));
}

QString SequenceFiles::name(qint64 index) const
{
    if (m_options.onePerDrawing && index == m_count - 1)
        return exposureSheetName(m_options);
    const qint64 number =
        m_options.onePerDrawing ? qint64(m_plan.frames[std::size_t(index)]) + 1 : index + 1;
    return QStringLiteral("%1_%2.%3")
        .arg(m_options.baseName)
        .arg(number, m_digits, 10, QLatin1Char('0'))
        .arg(exportFormatSuffix(m_options.format));
}

bool SequenceFiles::contains(const QString &fileName) const
{
    if (m_options.onePerDrawing && fileName == exposureSheetName(m_options))
        return true;
    const QString prefix = m_options.baseName + QLatin1Char('_');
    const QString suffix = QLatin1Char('.') + exportFormatSuffix(m_options.format);
    if (!fileName.startsWith(prefix) || !fileName.endsWith(suffix))
        return false;
    const QStringView digits =
        QStringView(fileName).mid(prefix.size(), fileName.size() - prefix.size() - suffix.size());
    bool ok = false;
    const qint64 number = digits.toLongLong(&ok);
    if (!ok || digits.size() != std::max<qsizetype>(m_digits, QString::number(number).size()) ||
        !digits.front().isDigit())
        return false;
    if (!m_options.onePerDrawing)
        return number >= 1 && number <= m_count;
    return std::binary_search(m_plan.frames.begin(), m_plan.frames.end(), int(number - 1)) &&
           number - 1 <= std::numeric_limits<int>::max();
}

bool SequenceFiles::isSequenceName(const QString &fileName) const
{
    const QString prefix = m_options.baseName + QLatin1Char('_');
    const QString suffix = QLatin1Char('.') + exportFormatSuffix(m_options.format);
    if (fileName.size() <= prefix.size() + suffix.size() || !fileName.startsWith(prefix) ||
        !fileName.endsWith(suffix))
        return false;
    const QStringView digits =
        QStringView(fileName).mid(prefix.size(), fileName.size() - prefix.size() - suffix.size());
    return std::all_of(digits.begin(), digits.end(),
                       [](QChar c) { return c >= QLatin1Char('0') && c <= QLatin1Char('9'); });
}

QStringList exportTargetFiles(const ExportSource &source, const ExportOptions &options)
{
    if (options.format == ExportFormat::Obj)
        return {options.target, objMaterialPath(options.target)};
    if (!exportsSequence(options.format))
        return {options.target};
    const auto plan = planExport(source, options);
    if (!plan)
        return {};
    if (checkExportSize(*plan, options))
        return {};
    const SequenceFiles files(*plan, options);
    QStringList names;
    for (qint64 i = 0; i < files.count(); ++i)
        names << files.name(i);
    return names;
}

void forEachExportTarget(const ExportSource &source, const ExportOptions &options,
                         const std::function<void(const QString &path)> &visit)
{
    if (!exportsSequence(options.format)) {
        visit(options.target);
        if (options.format == ExportFormat::Obj)
            visit(objMaterialPath(options.target));
        return;
    }
    const auto plan = planExport(source, options);
    if (!plan)
        return;
    const SequenceFiles files(*plan, options);
    const QDir folder(options.target);
    for (qint64 i = 0; i < files.count(); ++i)
        visit(folder.filePath(files.name(i)));
}

QStringList existingExportTargets(const ExportSource &source, const ExportOptions &options)
{
    struct stat file {};
    if (options.format == ExportFormat::Obj) {
        QStringList existing;
        if (::stat(nativeTargetPath(options).constData(), &file) == 0)
            existing << options.target;
        if (::stat(QFile::encodeName(objMaterialPath(options.target)).constData(), &file) == 0)
            existing << objMaterialPath(options.target);
        return existing;
    }
    if (!exportsSequence(options.format))
        return ::stat(nativeTargetPath(options).constData(), &file) == 0
                   ? QStringList{options.target}
                   : QStringList();
    const auto plan = planExport(source, options);
    if (!plan || !QFileInfo(options.target).isDir())
        return {};
    // The folder's entries, not every name of a sequence that may be millions long.
    const SequenceFiles files(*plan, options);
    QStringList existing;
    QDirIterator entries(options.target,
                         QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot);
    while (entries.hasNext()) {
        const QString path = entries.next();
        if (files.contains(QFileInfo(path).fileName()))
            existing << path;
    }
    existing.sort();
    return existing;
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
    if (auto error = checkExportSize(*plan, options))
        return unexpected(*error);
    const ExportReference reference(source, options);
    const ExportSoundtrack sound(source, options, *plan);
    // Media that cannot be used is said once, whatever the format: left out with a note, or
    // (strict) the export refused before anything is written.
    QStringList problems = sound.problems();
    if (problems.size() > 3) { // one line on a terminal, not one per clip of 256
        const auto more = int(problems.size() - 2);
        problems.resize(2);
        problems << Export::tr("%n more sound clip(s) are left out too.", nullptr, more);
    }
    if (!reference.problem().isEmpty())
        problems << reference.problem();
    if (options.strictMedia && !problems.isEmpty())
        return unexpected(exportError(ExportErrorCode::MediaUnusable,
                                      problems.join(QLatin1Char(' ')) + QLatin1Char(' ') +
                                          Export::tr("Nothing was exported.")));
    const ExportContext context{source, options, *plan, progress, reference, sound};
    auto result = [&]() -> Expected<ExportResult, ExportError> {
        if (exportsSequence(options.format))
            return exportSequence(context);
        if (options.format == ExportFormat::Html)
            return exportFlipbook(context);
        if (options.format == ExportFormat::Obj)
            return exportObj(context);
        if (options.format == ExportFormat::Glb)
            return exportGlb(context);
        if (options.format == ExportFormat::Lottie || options.format == ExportFormat::DotLottie)
            return exportLottie(context);
        return exportEncoded(context);
    }();
    if (result && !problems.isEmpty()) {
        if (!result->note.isEmpty())
            problems.prepend(result->note);
        result->note = problems.join(QLatin1Char(' '));
    }
    return result;
}

} // namespace finbook::model
