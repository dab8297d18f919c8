// The description and thumbnail of a recovery copy, read as File → Open reads a file and
// never more than they need: a regular file only (a link, a device or a pipe is refused
// unopened), of at most kMaxRecoveryCopyBytes, a .finbook header, then section headers only,
// skipping every section but the two small ones that describe the copy. Listing a folder of
// copies costs a few small reads per copy, whatever the copies (or impostors) hold.
#include "../finbook_file_format.h"
#include "../io/crc32c.h"

#include <finbook/model/recovery/recovery_store.h>

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>

#include <cerrno>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace finbook::model {

namespace {
using namespace file_format;

// The description is a short JSON object, the thumbnail a PNG about 160 pixels wide.
constexpr quint64 kMaxDescriptionBytes = 64 << 10;
constexpr quint64 kMaxThumbnailBytes = 4 << 20;
// A copy has the four sections, the two above and the end; more are not looked through.
constexpr int kMaxSectionsLooked = 64;

bool readAt(int fd, char *into, std::size_t size, qint64 offset)
{
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = ::pread(fd, into + done, size - done, off_t(offset) + off_t(done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        done += std::size_t(n);
    }
    return true;
}

struct Sections {
    std::optional<QByteArray> description, thumbnail;
};

// The "rcvy" and "thmb" payloads of the .finbook open on `fd` (`size` bytes), each only with a
// matching checksum (format 2 on) and a sensible size.
Sections describingSections(int fd, qint64 size)
{
    Sections found;
    char head[kHeaderBytes];
    if (size < qint64(kHeaderBytes) || !readAt(fd, head, sizeof(head), 0) ||
        checkHeader(QByteArrayView(head, qsizetype(sizeof(head)))))
        return found;
    const bool hasCrc = qFromLittleEndian<quint32>(head + 8) >= kFirstVersionWithCrc;
    const qint64 crcBytes = hasCrc ? qint64(kSectionCrcBytes) : 0;
    qint64 at = qint64(kHeaderBytes);
    for (int k = 0; k < kMaxSectionsLooked && size - at >= qint64(kSectionHeaderBytes); ++k) {
        char header[kSectionHeaderBytes];
        if (!readAt(fd, header, sizeof(header), at))
            break;
        const quint32 t = qFromLittleEndian<quint32>(header);
        const quint64 length = qFromLittleEndian<quint64>(header + 4);
        if (t == kTagEnd || length > quint64(size - at - qint64(kSectionHeaderBytes) - crcBytes))
            break;
        std::optional<QByteArray> *slot = t == tag("rcvy")   ? &found.description
                                          : t == tag("thmb") ? &found.thumbnail
                                                             : nullptr;
        const quint64 limit =
            slot == &found.description ? kMaxDescriptionBytes : kMaxThumbnailBytes;
        if (slot && !*slot && length <= limit) {
            QByteArray bytes(qsizetype(sizeof(header) + length + quint64(crcBytes)), '\0');
            if (readAt(fd, bytes.data(), std::size_t(bytes.size()), at)) {
                const std::size_t covered = sizeof(header) + std::size_t(length);
                if (!hasCrc || qFromLittleEndian<quint32>(bytes.constData() + covered) ==
                                   io::crc32c(0, bytes.constData(), covered))
                    *slot = bytes.mid(qsizetype(sizeof(header)), qsizetype(length));
            }
        }
        at += qint64(kSectionHeaderBytes + length) + crcBytes;
    }
    return found;
}
} // namespace

std::optional<RecoveryCopy> readRecoveryCopy(const QString &path)
{
    // O_NOFOLLOW: autosave writes copies, never links; O_NONBLOCK: a pipe must not block.
    const int fd = ::open(QFile::encodeName(path).constData(),
                          O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK | O_NOFOLLOW);
    if (fd < 0)
        return std::nullopt;
    struct stat st;
    Sections sections;
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size <= kMaxRecoveryCopyBytes)
        sections = describingSections(fd, qint64(st.st_size));
    ::close(fd);
    if (!sections.description)
        return std::nullopt;
    const QJsonObject o = QJsonDocument::fromJson(*sections.description).object();
    RecoveryCopy copy;
    copy.path = path;
    copy.info.title = o.value(QStringLiteral("title")).toString();
    copy.info.originalPath = o.value(QStringLiteral("original")).toString();
    copy.info.savedAt =
        QDateTime::fromString(o.value(QStringLiteral("saved")).toString(), Qt::ISODateWithMs);
    copy.info.frames = o.value(QStringLiteral("frames")).toInt();
    if (sections.thumbnail)
        copy.thumbnail.loadFromData(*sections.thumbnail, "PNG");
    return copy;
}

} // namespace finbook::model
