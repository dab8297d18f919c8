// The .finbook file: one binary file with an integer format version.
//
// Reading validates structure and bounds every size and count before allocating; a failure
// is a typed FileError whose message names what is wrong and where (frame, object, field).
// From format 2 on every section carries a CRC-32C, so damage is found even where the bytes
// still look plausible; recoverFinbook then opens what is still readable. The memory a file
// may need is bounded by its size (kLoadMemoryFactor), checked before each allocation.
// Writing is canonical: the same document always gives the same bytes, so save → open → save
// is byte-identical. Saving is atomic (io/atomic_file.h) and keeps the previous file as
// "<path>~".
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/model/document.h>
#include <finbook/model/io/atomic_file.h>
#include <finbook/model/reference/reference.h>
#include <finbook/model/sound/sound_clip.h>

#include <QByteArray>
#include <QString>

#include <optional>

namespace finbook::model {

// 1: the first format. 2: a CRC-32C after every section. 3: fills (a FILL chunk per object)
// and the document's "close gaps" setting. Older files keep opening; a Finbook that reads only
// format 2 refuses format-3 files as made by a newer Finbook.
constexpr quint32 kFinbookFormatVersion = 4;

// Opening a file of n bytes may allocate at most kLoadMemoryFactor × n + kLoadMemorySlack
// bytes for the document (the file's own bytes not counted). A real drawing needs about 1.2 × n
// (its points); a file that would need more describes things its size cannot honestly hold
// (millions of empty objects, poses or strokes) and is refused before it fills the memory.
constexpr qint64 kLoadMemoryFactor = 3;
constexpr qint64 kLoadMemorySlack = qint64(150) << 20;

// Ids are at most 2^63 - 1, so the next id never wraps around however many are allocated.
constexpr Id kMaxId = (Id(1) << 63) - 1;

enum class FileErrorCode {
    OpenFailed,   // cannot read the file (missing, permissions)
    NotFinbook,   // wrong magic: some other kind of file
    NewerVersion, // written by a newer Finbook
    Truncated,    // ends before the data it announces
    BadValue,     // a field holds a value out of range or of the wrong kind
    TooLarge,     // an absurd count or size, refused before allocating
    WriteFailed,  // permissions, read-only disk, rename failure: the old file is untouched
    DiskFull,     // no space left (or over quota): the old file is untouched
    Damaged,      // a section's checksum does not match: the bytes changed after saving
    OutOfMemory,  // the machine has not enough memory for a file that is itself fine
};

// Whether "open anyway" (recoverFinbook) can get something out of a file that failed so.
bool isRecoverable(FileErrorCode code);

struct FileError {
    FileErrorCode code;
    QString message; // one translated sentence for the user: what happened, where, what to do
};

// A layer as the file lists it: its cels are the next `cels` frames of LoadedDocument::frames.
struct LoadedLayer {
    Id id = kNoId;
    LayerProperties properties;
    int cels = 0;
};

struct LoadedDocument {
    std::vector<Frame> frames; // every layer's cels, one layer after the other
    // Back to front. Empty (a file from before layers): one layer holds all the frames.
    std::vector<LoadedLayer> layers;
    DocumentSettings settings;
    Id nextId = 1;
    Reference reference; // the reference layer (empty when the file has none)
    quint32 formatVersion = kFinbookFormatVersion;
    std::vector<SoundClip> sound;       // the soundtrack's clips ("SOND" sections)
    CameraTrack camera;                 // the camera's keys ("CAMR" section)
    Palette palette = defaultPalette(); // the swatches ("palt" section)
    std::vector<SwapSet> swapSets;      // "SWAP"; the frames' objects carry their links
};

// Puts what was loaded into `document` (Document::reset, then its soundtrack).
void adoptLoadedDocument(Document &document, LoadedDocument loaded);

Expected<LoadedDocument, FileError> readFinbook(const QByteArray &bytes);
// Reads the file at `path`: only a regular file (a pipe or a device is refused unread), only
// after its header proved it a .finbook of a version this Finbook reads.
Expected<LoadedDocument, FileError> loadFinbook(const QString &path);

// "Open anyway": what is still readable of a damaged or cut-off file. Damaged sections are
// read record by record; a frame, object, stroke or rig that does not read is left out, bad
// numbers get defaults, clashing ids get new ones. `problems` gets one translated sentence per
// thing left out or repaired. Fails only when the file is not a readable .finbook at all (not
// a .finbook, newer version, no frame left).
Expected<LoadedDocument, FileError> recoverFinbook(const QByteArray &bytes, QStringList *problems);
Expected<LoadedDocument, FileError> loadFinbookRecovering(const QString &path,
                                                          QStringList *problems);
// Loads into `document` (reset, undo stack cleared) or leaves it untouched on error.
std::optional<FileError> openFinbook(Document &document, const QString &path);

QByteArray serializeFinbook(const Document &document);

// Extra data a writer may add to a file: a section whose tag starts with a lower-case letter,
// which readers that do not know it skip (e.g. "rcvy", the description of a recovery copy).
struct AncillarySection {
    char tag[5]; // four letters, the first lower case
    QByteArray payload;
};
// The "palt" section of a palette (a snapshot's; serializeFinbook(document) adds it itself
// when the document's palette is not the default one).
AncillarySection paletteSection(const Palette &palette);
// The same bytes serializeFinbook(document) gives for a document holding `frames`,
// `settings`, the sound clips `sound` and the camera `camera` (a snapshot; safe on any
// thread), plus `ancillary` sections before the end.
QByteArray serializeFinbook(const std::vector<Layer> &layers, const DocumentSettings &settings,
                            const std::vector<AncillarySection> &ancillary = {},
                            const std::vector<SoundClip> &sound = {},
                            const CameraTrack &camera = {},
                            const std::vector<SwapSet> &swapSets = {});
// One layer holding `frames` (its id one above the largest id in them).
QByteArray serializeFinbook(const std::vector<Frame> &frames, const DocumentSettings &settings,
                            const std::vector<AncillarySection> &ancillary = {},
                            const std::vector<SoundClip> &sound = {},
                            const CameraTrack &camera = {});
// The layers `loaded` describes, its frames moved into them (one layer with the id
// loaded.nextId when it lists none: nextId then grows by one).
std::vector<Layer> takeLoadedLayers(LoadedDocument &loaded);
// The payload of the ancillary section `tag` of a file, if it has one with a correct checksum.
std::optional<QByteArray> readAncillarySection(const QByteArray &bytes, const char (&tag)[5]);
// Refuses to replace a file with bytes that would not open again (a document holding NaN or
// duplicate ids after a bug elsewhere): the old file stays as it was. On any failure (code
// DiskFull or WriteFailed) the file at `path` and its backup are byte for byte as before.
// `write` is a test seam (see io/atomic_file.h); leave it empty.
std::optional<FileError> saveFinbook(const Document &document, const QString &path,
                                     const WriteFunction &write = {});

// Where saveFinbook keeps the previous version of `path`.
QString finbookBackupPath(const QString &path);

} // namespace finbook::model
