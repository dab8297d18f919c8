// Loading and saving .finbook files on disk, and the sentences users see when that fails.
//
// Saving never leaves a half-written file: the bytes go to a QSaveFile (a temporary file
// renamed over the target on commit), and the previous file is kept as "<path>~" first.
#include "finbook_file_cursor.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

#include <new>

#ifdef Q_OS_UNIX
#include <fcntl.h>
#include <unistd.h>
#endif

namespace finbook::model {

namespace file_format {
QString failureSentence(FileErrorCode code, const QString &what)
{
    QString sentence = what;
    if (!sentence.isEmpty())
        sentence[0] = sentence[0].toUpper();
    sentence += QLatin1Char('.');
    switch (code) {
    case FileErrorCode::Truncated:
        return FinbookFile::tr(
                   "%1 The file is incomplete (perhaps an interrupted copy or save); if there is "
                   "a backup with the same name ending in ~, open that instead.")
            .arg(sentence);
    case FileErrorCode::BadValue:
    case FileErrorCode::TooLarge:
        return FinbookFile::tr(
                   "%1 The file is damaged; if there is a backup with the same name ending in ~, "
                   "open that instead.")
            .arg(sentence);
    default:
        return sentence;
    }
}
} // namespace file_format

namespace {
using file_format::FinbookFile;

QString displayName(const QString &path)
{
    return QFileInfo(path).fileName();
}

FileError writeFailed(const QString &path, const QString &reason)
{
    return FileError{
        FileErrorCode::WriteFailed,
        FinbookFile::tr("Could not save \"%1\": %2. The previous file is unchanged; free some "
                        "disk space or choose another folder, then save again.")
            .arg(displayName(path), reason)};
}

// Keeps the file about to be replaced as "<path>~". A hard link costs nothing even for a
// huge file; file systems without links get a copy.
std::optional<QString> keepBackup(const QString &path)
{
    if (!QFileInfo::exists(path))
        return std::nullopt;
    const QString backup = finbookBackupPath(path);
    const QFileInfo backupInfo(backup);
    if ((backupInfo.exists() || backupInfo.isSymLink()) && !QFile::remove(backup))
        return FinbookFile::tr("the old backup \"%1\" cannot be replaced")
            .arg(backupInfo.fileName());
#ifdef Q_OS_UNIX
    if (::linkat(AT_FDCWD, QFile::encodeName(path).constData(), AT_FDCWD,
                 QFile::encodeName(backup).constData(), AT_SYMLINK_FOLLOW) == 0)
        return std::nullopt;
#endif
    QFile original(path);
    if (original.copy(backup))
        return std::nullopt;
    return FinbookFile::tr("the backup \"%1\" cannot be written (%2)")
        .arg(backupInfo.fileName(), original.errorString());
}
// Reads a whole file only when it starts like a .finbook: "finbook info" on a 10 GB video or
// on /dev/zero is refused after 8 bytes instead of filling memory.
QByteArray readAllOfFinbook(QFile &file)
{
    const QByteArray head = file.peek(sizeof(file_format::kMagic));
    if (std::memcmp(head.constData(), file_format::kMagic, std::size_t(head.size())) != 0)
        return head;
    return file.readAll();
}
} // namespace

QString finbookBackupPath(const QString &path)
{
    return path + QLatin1Char('~');
}

Expected<LoadedDocument, FileError> loadFinbook(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly) || QFileInfo(path).isDir())
        return unexpected(FileError{
            FileErrorCode::OpenFailed,
            FinbookFile::tr(
                "Cannot open \"%1\": %2. Check that the file exists and that you may read it.")
                .arg(displayName(path), QFileInfo(path).isDir() ? FinbookFile::tr("it is a folder")
                                                                : file.errorString())});
    QByteArray bytes;
    try {
        bytes = readAllOfFinbook(file);
    } catch (const std::bad_alloc &) {
        return unexpected(FileError{
            FileErrorCode::TooLarge,
            FinbookFile::tr("Cannot open \"%1\": it is too large for the memory available.")
                .arg(displayName(path))});
    }
    if (file.error() != QFileDevice::NoError)
        return unexpected(FileError{
            FileErrorCode::OpenFailed,
            FinbookFile::tr("Cannot read \"%1\": %2.").arg(displayName(path), file.errorString())});
    auto loaded = readFinbook(bytes);
    if (!loaded)
        return unexpected(
            FileError{loaded.error().code, FinbookFile::tr("Cannot open \"%1\". %2")
                                               .arg(displayName(path), loaded.error().message)});
    return loaded;
}

std::optional<FileError> openFinbook(Document &document, const QString &path)
{
    auto loaded = loadFinbook(path);
    if (!loaded)
        return loaded.error();
    document.reset(std::move(loaded->frames), loaded->settings, loaded->nextId);
    return std::nullopt;
}

std::optional<FileError> saveFinbook(const Document &document, const QString &path)
{
    const QByteArray bytes = serializeFinbook(document);
    // Never replace a file with one that would not open again.
    if (auto check = file_format::parseFinbook(bytes, file_format::ParseMode::Check); !check)
        return writeFailed(
            path, FinbookFile::tr("the drawing holds invalid data (%1)").arg(check.error().what));
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return writeFailed(path, file.errorString());
    if (file.write(bytes) != bytes.size()) {
        const QString reason = file.errorString();
        file.cancelWriting();
        return writeFailed(path, reason);
    }
    if (const auto reason = keepBackup(path)) {
        file.cancelWriting();
        return writeFailed(path, *reason);
    }
    if (!file.commit())
        return writeFailed(path, file.errorString());
    return std::nullopt;
}

} // namespace finbook::model
