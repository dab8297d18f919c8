// The .finbook file: one binary file with an integer format version.
//
// Reading validates structure and bounds every size and count before allocating; a failure
// is a typed FileError whose message names what is wrong and where (frame, object, field).
// Writing is canonical: the same document always gives the same bytes, so save → open → save
// is byte-identical. Saving goes through QSaveFile and keeps the previous file as "<path>~".
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/model/document.h>

#include <QByteArray>
#include <QString>

#include <optional>

namespace finbook::model {

constexpr quint32 kFinbookFormatVersion = 1;

enum class FileErrorCode {
    OpenFailed,   // cannot read the file (missing, permissions)
    NotFinbook,   // wrong magic: some other kind of file
    NewerVersion, // written by a newer Finbook
    Truncated,    // ends before the data it announces
    BadValue,     // a field holds a value out of range or of the wrong kind
    TooLarge,     // an absurd count or size, refused before allocating
    WriteFailed,  // disk full, permissions, rename failure: the old file is untouched
};

struct FileError {
    FileErrorCode code;
    QString message; // one translated sentence for the user: what happened, where, what to do
};

struct LoadedDocument {
    std::vector<Frame> frames;
    DocumentSettings settings;
    Id nextId = 1;
    quint32 formatVersion = kFinbookFormatVersion;
};

Expected<LoadedDocument, FileError> readFinbook(const QByteArray &bytes);
Expected<LoadedDocument, FileError> loadFinbook(const QString &path);
// Loads into `document` (reset, undo stack cleared) or leaves it untouched on error.
std::optional<FileError> openFinbook(Document &document, const QString &path);

QByteArray serializeFinbook(const Document &document);
// Refuses to replace a file with bytes that would not open again (a document holding NaN or
// duplicate ids after a bug elsewhere): the old file stays as it was.
std::optional<FileError> saveFinbook(const Document &document, const QString &path);

// Where saveFinbook keeps the previous version of `path`.
QString finbookBackupPath(const QString &path);

} // namespace finbook::model
