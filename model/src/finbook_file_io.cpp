// Loading and saving .finbook files on disk, and the sentences users see when that fails.
//
// Saving never leaves a half-written file: the bytes go through writeFileAtomically (a
// temporary file, written and synced with every error checked, then renamed over the
// target), and the previous file is kept as "<path>~" just before the rename.
#include "command_text.h"
#include "finbook_file_cursor.h"
#include "finbook_file_ids.h"

#include <finbook/model/io/atomic_file.h>
#include <finbook/model/reference/reference_layer.h>
#include <finbook/model/sound/soundtrack.h>

#include <QFile>
#include <QFileInfo>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <memory>
#include <new>
#include <sys/stat.h>
#include <unistd.h>

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
    case FileErrorCode::Damaged:
        return FinbookFile::tr(
                   "%1 The file is damaged; Finbook can open what is still readable of it, or "
                   "open the backup with the same name ending in ~ if there is one.")
            .arg(sentence);
    case FileErrorCode::OutOfMemory:
        return FinbookFile::tr("%1 Close other programs or documents and try again.").arg(sentence);
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

// The sentence for a save that failed; the previous file is always unchanged (atomic_file.h).
FileError writeFailed(const QString &path, const WriteFailure &failure)
{
    const QString name = displayName(path);
    const QString reason = describeWriteFailure(failure, QFileInfo(path).absolutePath());
    switch (failure.problem) {
    case WriteProblem::DiskFull:
        return FileError{FileErrorCode::DiskFull,
                         FinbookFile::tr("Could not save \"%1\": %2. The previous file is "
                                         "unchanged; free some disk space or choose another "
                                         "folder, then save again.")
                             .arg(name, reason)};
    default:
        return FileError{FileErrorCode::WriteFailed,
                         FinbookFile::tr("Could not save \"%1\": %2. The previous file is "
                                         "unchanged; choose another folder, then save again.")
                             .arg(name, reason)};
    }
}

FileError cannotOpen(const QString &path, const QString &reason)
{
    return FileError{
        FileErrorCode::OpenFailed,
        FinbookFile::tr(
            "Cannot open \"%1\": %2. Check that the file exists and that you may read it.")
            .arg(displayName(path), reason)};
}

// Reads until `size` bytes or the end of the file; -1 on a read error (errno set).
qint64 readFully(int fd, char *into, qint64 size)
{
    qint64 done = 0;
    while (done < size) {
        const ssize_t n = ::read(fd, into + done, std::size_t(size - done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            return -1;
        if (n == 0)
            break;
        done += n;
    }
    return done;
}

// The bytes of the .finbook at `path`. Only a regular file is read (a pipe or a device could
// block or never end), and only after its first bytes proved it a .finbook of a version this
// Finbook reads: a 10 GB video or a newer file is refused after 12 bytes. So is a damaged
// version word, unless `recovering` ("open anyway" reads past it).
Expected<QByteArray, FileError> readFinbookBytes(const QString &path, bool recovering = false)
{
    // O_NONBLOCK: opening a pipe nobody writes to would otherwise wait for ever.
    const int fd =
        ::open(QFile::encodeName(path).constData(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
    if (fd < 0)
        return unexpected(cannotOpen(path, QString::fromLocal8Bit(std::strerror(errno))));
    const std::unique_ptr<int, void (*)(int *)> closer(new int(fd), [](int *p) {
        ::close(*p);
        delete p;
    });
    struct stat st;
    if (::fstat(fd, &st) != 0)
        return unexpected(cannotOpen(path, QString::fromLocal8Bit(std::strerror(errno))));
    if (S_ISDIR(st.st_mode))
        return unexpected(cannotOpen(path, FinbookFile::tr("it is a folder")));
    if (!S_ISREG(st.st_mode))
        return unexpected(FileError{
            FileErrorCode::OpenFailed,
            FinbookFile::tr("Cannot open \"%1\": it is a device, a pipe or a socket, not a "
                            "file. Choose a .finbook file.")
                .arg(displayName(path))});
    char head[file_format::kHeaderBytes];
    const qint64 headBytes = readFully(fd, head, qint64(sizeof(head)));
    if (headBytes < 0)
        return unexpected(cannotOpen(path, QString::fromLocal8Bit(std::strerror(errno))));
    if (auto failure = file_format::checkHeader(QByteArrayView(head, headBytes));
        failure && !(recovering && failure->code == FileErrorCode::Damaged))
        return unexpected(FileError{
            failure->code, FinbookFile::tr("Cannot open \"%1\". %2")
                               .arg(displayName(path),
                                    file_format::failureSentence(failure->code, failure->what))});
    QByteArray bytes;
    try {
        bytes.resize(std::max<qint64>(st.st_size, headBytes));
    } catch (const std::bad_alloc &) {
        return unexpected(FileError{
            FileErrorCode::OutOfMemory,
            FinbookFile::tr("Cannot open \"%1\": there is not enough memory for its %2 MB. Close "
                            "other programs or documents and try again.")
                .arg(displayName(path))
                .arg(st.st_size >> 20)});
    }
    std::memcpy(bytes.data(), head, std::size_t(headBytes));
    const qint64 rest = readFully(fd, bytes.data() + headBytes, bytes.size() - headBytes);
    if (rest < 0)
        return unexpected(
            FileError{FileErrorCode::OpenFailed,
                      FinbookFile::tr("Cannot read \"%1\": %2.")
                          .arg(displayName(path), QString::fromLocal8Bit(std::strerror(errno)))});
    bytes.truncate(headBytes + rest); // it may have shrunk meanwhile
    return bytes;
}

Expected<LoadedDocument, FileError> withPath(const QString &path,
                                             Expected<LoadedDocument, FileError> loaded)
{
    if (!loaded)
        return unexpected(
            FileError{loaded.error().code, FinbookFile::tr("Cannot open \"%1\". %2")
                                               .arg(displayName(path), loaded.error().message)});
    return loaded;
}
} // namespace

QString finbookBackupPath(const QString &path)
{
    return path + QLatin1Char('~');
}

Expected<LoadedDocument, FileError> loadFinbook(const QString &path)
{
    auto bytes = readFinbookBytes(path);
    if (!bytes)
        return unexpected(bytes.error());
    return withPath(path, readFinbook(*bytes));
}

Expected<LoadedDocument, FileError> loadFinbookRecovering(const QString &path,
                                                          QStringList *problems)
{
    auto bytes = readFinbookBytes(path, true);
    if (!bytes)
        return unexpected(bytes.error());
    return withPath(path, recoverFinbook(*bytes, problems));
}

std::optional<FileError> openFinbook(Document &document, const QString &path)
{
    auto loaded = loadFinbook(path);
    if (!loaded)
        return loaded.error();
    adoptLoadedDocument(document, std::move(*loaded));
    return std::nullopt;
}

std::vector<Layer> takeLoadedLayers(LoadedDocument &loaded)
{
    std::vector<Layer> layers;
    if (loaded.layers.empty()) {
        Layer only;
        if (loaded.nextId <= kMaxId) {
            only.id = std::max<Id>(loaded.nextId, 1);
            loaded.nextId = only.id + 1;
        } else { // the ids reach the largest there is: the lowest one free
            std::unordered_set<Id> used = idsIn(loaded);
            Id below = kNoId;
            only.id = lowestFreeId(used, below);
        }
        only.properties.name = Command::tr("Layer 1"); // a file from before layers
        only.cels = std::move(loaded.frames);
        layers.push_back(std::move(only));
        return layers;
    }
    auto next = loaded.frames.begin();
    for (const LoadedLayer &l : loaded.layers) {
        Layer layer;
        layer.id = l.id;
        layer.properties = l.properties;
        const auto end = next + std::min<std::ptrdiff_t>(l.cels, loaded.frames.end() - next);
        layer.cels.assign(std::make_move_iterator(next), std::make_move_iterator(end));
        next = end;
        layers.push_back(std::move(layer));
    }
    // Frames no layer claims (a damaged list opened anyway) are not lost: the last layer
    // takes them.
    layers.back().cels.insert(layers.back().cels.end(), std::make_move_iterator(next),
                              std::make_move_iterator(loaded.frames.end()));
    loaded.frames.clear();
    return layers;
}

void adoptLoadedDocument(Document &document, LoadedDocument loaded)
{
    std::vector<Layer> layers = takeLoadedLayers(loaded);
    document.reset(std::move(layers), loaded.settings, loaded.nextId, std::move(loaded.swapSets));
    document.referenceLayer().setReference(std::move(loaded.reference));
    document.soundtrack().reset(std::move(loaded.sound));
    document.setCamera(std::move(loaded.camera));
    document.setPalette(std::move(loaded.palette));
}

std::optional<FileError> saveFinbook(const Document &document, const QString &path,
                                     const WriteFunction &write)
{
    const QByteArray bytes = serializeFinbook(document);
    // Never replace a file with one that would not open again.
    if (auto check = file_format::parseFinbook(bytes, file_format::ParseMode::Check); !check)
        return FileError{FileErrorCode::WriteFailed,
                         FinbookFile::tr("Could not save \"%1\": the drawing holds invalid data "
                                         "(%2). The previous file is unchanged.")
                             .arg(displayName(path), check.error().what)};
    AtomicWriteOptions options;
    options.backupPath = finbookBackupPath(path);
    options.write = write;
    if (auto failure = writeFileAtomically(path, bytes, options))
        return writeFailed(path, *failure);
    return std::nullopt;
}

} // namespace finbook::model
