// The first bytes of a .finbook and its last: the magic and format version (and what a
// damaged version word is), and the end marker that tells a complete file from a cut one.
#include "finbook_file_reader.h"
#include "io/crc32c.h"

#include <algorithm>
#include <cstring>

namespace finbook::model::file_format {

// Whether the file's first section (at the cursor, just after the header) ends in a matching
// checksum, as from format 2 on.
bool Reader::firstSectionHasCrc(const Cursor &c)
{
    if (c.remaining() < kSectionHeaderBytes + kSectionCrcBytes)
        return false;
    const char *p = c.position();
    const quint64 length = qFromLittleEndian<quint64>(p + 4);
    if (length > c.remaining() - kSectionHeaderBytes - kSectionCrcBytes)
        return false;
    const std::size_t covered = kSectionHeaderBytes + std::size_t(length);
    return qFromLittleEndian<quint32>(p + covered) == io::crc32c(0, p, covered);
}

// Whether the file ends with its end marker ("FEND", length 0, and from format 2 on its
// checksum): then it is complete, and a section running past its end has a damaged length.
bool Reader::endsWithEndMarker(const QByteArray &bytes)
{
    const qsizetype head = qsizetype(kHeaderBytes);
    if (bytes.size() < head + qsizetype(kSectionHeaderBytes))
        return false;
    const bool hasCrc = qFromLittleEndian<quint32>(bytes.constData() + 8) >= kFirstVersionWithCrc;
    const qsizetype marker = qsizetype(kSectionHeaderBytes + (hasCrc ? kSectionCrcBytes : 0));
    if (bytes.size() < head + marker)
        return false;
    const char *p = bytes.constData() + bytes.size() - marker;
    if (qFromLittleEndian<quint32>(p) != kTagEnd || qFromLittleEndian<quint64>(p + 4) != 0)
        return false;
    return !hasCrc || qFromLittleEndian<quint32>(p + kSectionHeaderBytes) ==
                          io::crc32c(0, p, kSectionHeaderBytes);
}

QString Reader::damagedVersion(quint32 version)
{
    return FinbookFile::tr("its format version %1 is not one any Finbook writes (this version "
                           "reads %2 to %3), so the version number is damaged")
        .arg(version)
        .arg(kOldestVersion)
        .arg(kFinbookFormatVersion);
}

quint32 Reader::readHeader(Cursor &c, bool tolerateDamagedVersion)
{
    if (c.atEnd())
        c.fail(FileErrorCode::NotFinbook, FinbookFile::tr("the file is empty"));
    const std::size_t n = std::min(c.remaining(), sizeof(kMagic));
    const char *magic = c.take(n, QT_TRANSLATE_NOOP("FinbookFile", "the file header"));
    if (std::memcmp(magic, kMagic, n) != 0)
        c.fail(FileErrorCode::NotFinbook, FinbookFile::tr("it is not a Finbook animation"));
    if (n < sizeof(kMagic))
        c.fail(FileErrorCode::Truncated, FinbookFile::tr("the file ends inside its header"));
    const quint32 version = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "the format version"));
    // Formats change a few times in years: only the next few versions are a newer Finbook's.
    // Anything else (a flipped bit makes 0, 6, 10, … 2^31 + 2) is damage.
    if (version > kFinbookFormatVersion && version <= kFinbookFormatVersion + kNewerVersionsKnown)
        c.fail(FileErrorCode::NewerVersion,
               FinbookFile::tr(
                   "it was made by a newer version of Finbook (file format %1; this version "
                   "reads up to %2); please update Finbook to open it")
                   .arg(version)
                   .arg(kFinbookFormatVersion));
    if ((version < kOldestVersion || version > kFinbookFormatVersion) && !tolerateDamagedVersion)
        c.fail(FileErrorCode::Damaged, damagedVersion(version));
    return version;
}

std::optional<ReadFailure> checkHeader(QByteArrayView head)
{
    Where where;
    Cursor c(head.data(), head.data() + head.size(), &where);
    try {
        Reader::readHeader(c);
    } catch (const ReadFailure &failure) {
        return failure;
    }
    return std::nullopt;
}

} // namespace finbook::model::file_format
