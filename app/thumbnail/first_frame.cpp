#include "first_frame.h"

#include "finbook_file_byte_writer.h"
#include "finbook_file_format.h"
#include "io/crc32c.h"
#include "picture/picture_section.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <new>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace finbook::app {

namespace {

using namespace model::file_format;
using model::FileError;
using model::FileErrorCode;

class Thumbnail {
    Q_DECLARE_TR_FUNCTIONS(Thumbnail)
};

// A failure of the walk over the file's layout: the sentence comes at the end, with the name.
struct Broken {
    FileErrorCode code;
};

// The bytes of a regular file, read at offsets; every read is checked against the file's
// size first, so a length in the file cannot make it allocate more than the file holds.
class FileReader {
public:
    explicit FileReader(const QString &path)
    {
        // O_NONBLOCK: a pipe nobody writes to would otherwise block for ever.
        m_fd = ::open(QFile::encodeName(path).constData(),
                      O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
        if (m_fd < 0) {
            m_error = QString::fromLocal8Bit(std::strerror(errno));
            return;
        }
        struct stat st;
        if (::fstat(m_fd, &st) != 0)
            m_error = QString::fromLocal8Bit(std::strerror(errno));
        else if (!S_ISREG(st.st_mode))
            m_error = Thumbnail::tr("it is not a regular file");
        else
            m_size = st.st_size;
    }
    ~FileReader()
    {
        if (m_fd >= 0)
            ::close(m_fd);
    }
    FileReader(const FileReader &) = delete;
    FileReader &operator=(const FileReader &) = delete;

    QString error() const { return m_error; }
    int descriptor() const { return m_fd; }
    qint64 size() const { return m_size; }
    qint64 bytesRead() const { return m_read; }

    // `n` bytes at `offset`, or Truncated when the file ends before them.
    QByteArray read(qint64 offset, qint64 n)
    {
        if (offset < 0 || n < 0 || n > m_size - offset)
            throw Broken{FileErrorCode::Truncated};
        QByteArray bytes;
        bytes.resize(n);
        qint64 done = 0;
        while (done < n) {
            const ssize_t got =
                ::pread(m_fd, bytes.data() + done, std::size_t(n - done), offset + done);
            if (got < 0 && errno == EINTR)
                continue;
            if (got < 0) {
                m_error = QString::fromLocal8Bit(std::strerror(errno));
                throw Broken{FileErrorCode::OpenFailed};
            }
            if (got == 0) // the file shrank meanwhile
                throw Broken{FileErrorCode::Truncated};
            done += got;
        }
        m_read += n;
        return bytes;
    }

private:
    int m_fd = -1;
    qint64 m_size = 0;
    qint64 m_read = 0;
    QString m_error;
};

quint32 u32At(const QByteArray &bytes, qint64 at)
{
    if (at < 0 || at + 4 > bytes.size())
        throw Broken{FileErrorCode::Truncated};
    return qFromLittleEndian<quint32>(bytes.constData() + at);
}

// Where a section's payload is in the file, and the payload itself when it was read whole.
struct Section {
    qint64 payload = -1; // offset of the payload; -1 while not found
    qint64 length = 0;
    QByteArray whole; // the payload, when the section was read whole (checksum checked)
};

// Reads from a section's payload, from memory when it was read whole, else from the file,
// never past the section's end.
class SectionReader {
public:
    SectionReader(FileReader &file, const Section &section)
        : m_file(file)
        , m_section(section)
    {}
    QByteArray read(qint64 n)
    {
        if (n < 0 || n > m_section.length - m_at)
            throw Broken{FileErrorCode::Truncated};
        QByteArray bytes = m_section.whole.isNull() ? m_file.read(m_section.payload + m_at, n)
                                                    : m_section.whole.mid(m_at, n);
        m_at += n;
        return bytes;
    }
    quint32 u32() { return u32At(read(4), 0); }

private:
    FileReader &m_file;
    const Section &m_section;
    qint64 m_at = 0;
};

// The largest stroke-data and pose indices the first frame's record uses (-1: none).
struct FrameUses {
    qint64 lastStroke = -1;
    qint64 lastPose = -1;
    qint64 lastPicture = -1; // of PICT, by the objects' PICO chunks
};

// Walks the frame record (layout in finbook_file_format.h) only as far as needed to find the
// table entries it refers to; the model's reader checks everything else.
FrameUses frameUses(const QByteArray &frame)
{
    FrameUses uses;
    qint64 at = kFrameFixedBytes;
    const quint32 objects = u32At(frame, at - 4);
    for (quint32 i = 0; i < objects; ++i) {
        const qint64 length = u32At(frame, at);
        const qint64 begin = at + 4, end = begin + length;
        if (end > frame.size())
            throw Broken{FileErrorCode::Truncated};
        qint64 p = begin + 8 + 1 + 8;
        p += 4 + qint64(u32At(frame, p)); // the name
        const quint32 strokes = u32At(frame, p);
        p += 4;
        if (qint64(strokes) * qint64(kStrokeRefBytes) > end - p)
            throw Broken{FileErrorCode::Truncated};
        for (quint32 s = 0; s < strokes; ++s, p += kStrokeRefBytes)
            uses.lastStroke = std::max<qint64>(uses.lastStroke, u32At(frame, p + 8));
        while (p + qint64(kChunkHeaderBytes) <= end) {
            const quint32 chunk = u32At(frame, p);
            const qint64 chunkLength = u32At(frame, p + 4);
            if (chunk == kTagDeformed && chunkLength >= 4 && p + 12 <= end)
                uses.lastPose = std::max<qint64>(uses.lastPose, u32At(frame, p + 8));
            if (chunk == kTagPictureObject && chunkLength >= 4 && p + 12 <= end)
                uses.lastPicture = std::max<qint64>(uses.lastPicture, u32At(frame, p + 8));
            p += qint64(kChunkHeaderBytes) + chunkLength;
        }
        at = end;
    }
    return uses;
}

// The first `count` entries of a table section (its u32 count, then the entries), with the
// count rewritten; `entry` reads one entry from the section and returns its bytes.
template <class ReadEntry>
QByteArray tablePrefix(FileReader &file, const Section &section, qint64 count, qint64 minEntryBytes,
                       ReadEntry entry)
{
    SectionReader in(file, section);
    const quint32 stored = in.u32();
    // As opening checks it: the entries claimed must fit in the section.
    if (qint64(stored) * minEntryBytes > section.length - 4)
        throw Broken{FileErrorCode::TooLarge};
    count = std::min<qint64>(count, stored); // a bad index is for the model's reader to report
    QByteArray out(4, '\0');
    qToLittleEndian<quint32>(quint32(count), out.data());
    for (qint64 i = 0; i < count; ++i)
        out += entry(in);
    return out;
}

QByteArray strokeEntry(SectionReader &in)
{
    QByteArray head = in.read(kStrokeDataHeaderBytes);
    const quint32 points = u32At(head, 8);
    return head + in.read(qint64(points) * qint64(kPointBytes));
}

QByteArray poseEntry(SectionReader &in)
{
    QByteArray bytes = in.read(4);
    const quint32 strokes = u32At(bytes, 0);
    for (quint32 s = 0; s < strokes; ++s) {
        const QByteArray count = in.read(4);
        bytes += count;
        bytes += in.read(qint64(u32At(count, 0)) * qint64(kPointBytes));
    }
    return bytes;
}

// One picture of "PICT" (picture/picture_section.h): its size, PNG and texture mesh.
QByteArray pictureEntry(SectionReader &in)
{
    QByteArray bytes = in.read(4 + 4 + 8);
    bytes += in.read(qint64(qFromLittleEndian<quint64>(bytes.constData() + 8)));
    const QByteArray vertices = in.read(4);
    bytes += vertices;
    bytes += in.read(qint64(u32At(vertices, 0)) * qint64(kPictureVertexBytes));
    const QByteArray triangles = in.read(4);
    bytes += triangles;
    bytes += in.read(qint64(u32At(triangles, 0)) * qint64(kPictureTriangleBytes));
    return bytes;
}

struct Layout {
    quint32 version = 0;
    Section document, strokes, poses, frames;
    Section pictures; // "PICT", when objects show pictures: located, read as far as needed
    Section light;    // "lite" (shaded fills' light), when the file has one
};

// The section list up to the frames: the header checked, each section's bounds checked,
// small sections read whole with their checksum checked, big ones only located.
Layout readLayout(FileReader &file, qint64 wholeSectionBytes)
{
    Layout layout;
    const QByteArray head = file.read(0, qint64(kHeaderBytes));
    if (auto failure = checkHeader(head))
        throw *failure;
    layout.version = u32At(head, sizeof(kMagic));
    const bool hasCrc = layout.version >= kFirstVersionWithCrc;
    const qint64 crcBytes = hasCrc ? qint64(kSectionCrcBytes) : 0;
    Section *order[] = {&layout.document, &layout.strokes, &layout.poses, &layout.frames};
    const quint32 tags[] = {kTagDocument, kTagStrokes, kTagPoses, kTagFrames};
    std::size_t next = 0;
    qint64 at = qint64(kHeaderBytes);
    for (;;) {
        const QByteArray header = file.read(at, qint64(kSectionHeaderBytes));
        const quint32 t = u32At(header, 0);
        const quint64 length = qFromLittleEndian<quint64>(header.constData() + 4);
        const qint64 payload = at + qint64(kSectionHeaderBytes);
        if (length > quint64(file.size() - payload - crcBytes))
            throw Broken{FileErrorCode::Truncated};
        const qint64 end = payload + qint64(length) + crcBytes;
        const bool known = std::find(std::begin(tags), std::end(tags), t) != std::end(tags);
        const bool wanted = next < std::size(order) && t == tags[next];
        const bool ends = t == kTagEnd && next == std::size(order);
        if (wanted || ends) {
            Section scratch;
            Section &s = wanted ? *order[next++] : scratch;
            s.payload = payload;
            s.length = qint64(length);
            // The end marker is read too: the sections must add up to the file, so a file cut
            // anywhere is refused, as opening refuses it.
            if (s.length <= wholeSectionBytes || t == kTagDocument || ends) {
                QByteArray bytes = file.read(payload, end - payload);
                if (hasCrc &&
                    u32At(bytes, s.length) !=
                        model::io::crc32c(model::io::crc32c(0, header.constData(), header.size()),
                                          bytes.constData(), std::size_t(s.length)))
                    throw Broken{FileErrorCode::Damaged};
                bytes.truncate(s.length);
                s.whole = bytes;
            }
            if (ends) {
                if (length != 0 || end != file.size())
                    throw Broken{FileErrorCode::BadValue};
                break;
            }
        } else if ((t == kTagCamera || t == kTagLayers || t == kTagSwap) &&
                   next == std::size(order) && length <= quint64(wholeSectionBytes)) {
            // The camera, the layer list or the swap sets (after the frames, as the reader
            // wants them): a thumbnail shows the first drawing on its page (the back layer's
            // first cel, whose swappable objects are saved showing their drawings), so they
            // are only checked, as opening checks them.
            const QByteArray bytes = file.read(payload, end - payload);
            if (hasCrc &&
                u32At(bytes, qint64(length)) !=
                    model::io::crc32c(model::io::crc32c(0, header.constData(), header.size()),
                                      bytes.constData(), std::size_t(length)))
                throw Broken{FileErrorCode::Damaged};
        } else if (t == kTagPictures && next == std::size(order) && layout.pictures.payload < 0) {
            // The pictures: the first frame's are taken from it (firstFrameFile).
            layout.pictures.payload = payload;
            layout.pictures.length = qint64(length);
        } else if ((t == kTagSound || t == kTagCamera || t == kTagLayers || t == kTagSwap) &&
                   next == std::size(order)) {
            // A sound clip (or a huge camera, layer list or set of swap drawings): its bytes
            // are skipped unread.
        } else if (t == kTagLight && next == std::size(order) && length <= 64) {
            // The light of shaded fills: the thumbnail is lit as the opened file is. Read
            // whole (16 bytes) and checked as the model's reader checks it; the last one
            // counts, as there.
            QByteArray bytes = file.read(payload, end - payload);
            if (hasCrc &&
                u32At(bytes, qint64(length)) !=
                    model::io::crc32c(model::io::crc32c(0, header.constData(), header.size()),
                                      bytes.constData(), std::size_t(length)))
                throw Broken{FileErrorCode::Damaged};
            bytes.truncate(qint64(length));
            layout.light.payload = payload;
            layout.light.length = qint64(length);
            layout.light.whole = bytes;
        } else if (t == kTagEnd || known || !isAncillary(t)) {
            // A section missing, repeated or out of order, or one a newer Finbook wrote: the
            // model's reader would refuse the file.
            throw Broken{t == kTagEnd || known ? FileErrorCode::BadValue
                                               : FileErrorCode::NewerVersion};
        }
        at = end;
    }
    return layout;
}

// A section as the writer lays it out: tag, length, payload and (format 2 on) its CRC-32C.
void writeSection(ByteWriter &w, quint32 sectionTag, const QByteArray &payload, bool crc)
{
    const qsizetype start = w.size();
    w.u32(sectionTag);
    w.u64(quint64(payload.size()));
    w.raw(payload.constData(), std::size_t(payload.size()));
    if (crc)
        w.u32(w.crcSince(start));
}

// The first frame of the file as the bytes of a one-frame .finbook of the same version.
QByteArray firstFrameFile(FileReader &file, qint64 wholeSectionBytes)
{
    const Layout layout = readLayout(file, wholeSectionBytes);
    SectionReader frames(file, layout.frames);
    const quint32 frameCount = frames.u32();
    QByteArray frame;
    if (frameCount > 0)
        frame = frames.read(frames.u32());
    const FrameUses uses =
        frame.size() >= qint64(kFrameFixedBytes) ? frameUses(frame) : FrameUses{};
    const QByteArray strokes = tablePrefix(file, layout.strokes, uses.lastStroke + 1,
                                           qint64(kStrokeDataHeaderBytes), strokeEntry);
    const QByteArray poses = tablePrefix(file, layout.poses, uses.lastPose + 1, 4, poseEntry);
    // The pictures the first frame shows (and those before them in the table); none when it
    // shows none. A frame naming pictures the file lacks is the model reader's to refuse.
    const QByteArray pictures = uses.lastPicture >= 0 && layout.pictures.payload >= 0
                                    ? tablePrefix(file, layout.pictures, uses.lastPicture + 1,
                                                  qint64(kPictureFixedBytes), pictureEntry)
                                    : QByteArray();
    QByteArray frameList(4, '\0');
    qToLittleEndian<quint32>(frameCount > 0 ? 1 : 0, frameList.data());
    if (frameCount > 0) {
        QByteArray length(4, '\0');
        qToLittleEndian<quint32>(quint32(frame.size()), length.data());
        frameList += length + frame;
    }
    const bool crc = layout.version >= kFirstVersionWithCrc;
    ByteWriter w(qsizetype(kHeaderBytes) + 6 * qsizetype(kSectionHeaderBytes + 4) +
                 layout.document.whole.size() + strokes.size() + poses.size() + frameList.size() +
                 pictures.size());
    w.raw(kMagic, sizeof(kMagic));
    w.u32(layout.version);
    writeSection(w, kTagDocument, layout.document.whole, crc);
    writeSection(w, kTagStrokes, strokes, crc);
    writeSection(w, kTagPoses, poses, crc);
    writeSection(w, kTagFrames, frameList, crc);
    if (!pictures.isNull())
        writeSection(w, kTagPictures, pictures, crc);
    if (!layout.light.whole.isNull())
        writeSection(w, kTagLight, layout.light.whole, crc);
    writeSection(w, kTagEnd, QByteArray(), crc);
    return w.take();
}

FileError thumbnailError(const QString &path, FileErrorCode code, const QString &reason)
{
    return FileError{code, Thumbnail::tr("Cannot make a thumbnail of \"%1\": %2")
                               .arg(QFileInfo(path).fileName(), reason)};
}

// Every check opening makes, on the whole file mapped into memory (the pages are the file's,
// read once), keeping nothing of what it holds (ParseMode::Check).
std::optional<FileError> checkWhole(const QString &path, FileReader &file)
{
    if (file.size() == 0)
        return std::nullopt; // the walk says what is wrong with an empty file
    void *mapped =
        ::mmap(nullptr, std::size_t(file.size()), PROT_READ, MAP_PRIVATE, file.descriptor(), 0);
    if (mapped == MAP_FAILED)
        return thumbnailError(path, FileErrorCode::OpenFailed,
                              QString::fromLocal8Bit(std::strerror(errno)) + QLatin1Char('.'));
    ::madvise(mapped, std::size_t(file.size()), MADV_SEQUENTIAL);
    std::optional<FileError> error;
    {
        const QByteArray bytes =
            QByteArray::fromRawData(static_cast<const char *>(mapped), qsizetype(file.size()));
        auto checked = parseFinbook(bytes, ParseMode::Check);
        if (!checked)
            error = thumbnailError(path, checked.error().code,
                                   failureSentence(checked.error().code, checked.error().what));
    }
    ::munmap(mapped, std::size_t(file.size()));
    return error;
}

} // namespace

Expected<model::LoadedDocument, FileError> readFirstFrame(const QString &path,
                                                          qint64 wholeSectionBytes,
                                                          qint64 *bytesRead, qint64 wholeCheckBytes)
{
    FileReader file(path);
    if (!file.error().isEmpty())
        return unexpected(thumbnailError(path, FileErrorCode::OpenFailed, file.error()));
    if (file.size() <= wholeCheckBytes)
        if (auto error = checkWhole(path, file))
            return unexpected(*error);
    QByteArray bytes;
    try {
        bytes = firstFrameFile(file, wholeSectionBytes);
    } catch (const Broken &broken) {
        if (bytesRead)
            *bytesRead = file.bytesRead();
        const QString reason =
            broken.code == FileErrorCode::Damaged
                ? Thumbnail::tr("a checksum does not match, so the file is damaged.")
            : broken.code == FileErrorCode::NewerVersion
                ? Thumbnail::tr("it holds data that this version of Finbook does not know.")
            : broken.code == FileErrorCode::OpenFailed
                ? file.error() + QLatin1Char('.')
                : Thumbnail::tr("the file is damaged or incomplete.");
        return unexpected(thumbnailError(path, broken.code, reason));
    } catch (const ReadFailure &failure) { // the header
        return unexpected(
            thumbnailError(path, failure.code, failureSentence(failure.code, failure.what)));
    } catch (const std::bad_alloc &) {
        return unexpected(thumbnailError(path, FileErrorCode::OutOfMemory,
                                         failureSentence(FileErrorCode::OutOfMemory, QString())));
    }
    if (bytesRead)
        *bytesRead = file.bytesRead();
    auto loaded = model::readFinbook(bytes);
    if (!loaded)
        return unexpected(thumbnailError(path, loaded.error().code, loaded.error().message));
    return loaded;
}

} // namespace finbook::app
