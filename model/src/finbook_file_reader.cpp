// readFinbook: header, sections and their checksums, document settings, the final checks
// (layout in finbook_file_format.h).
//
// The parser trusts nothing: lengths and counts are bounded by the bytes left before any
// allocation, everything allocated is counted against a budget set by the file's size, values
// are range-checked, ids must be unique, below 2^63, and the next free id above them all. A
// file of an older format version is parsed as that version, then migrated.
#include "finbook_file_reader.h"

#include "io/crc32c.h"
#include "skeleton/join_resolution.h"

#include <finbook/model/skeleton/skeleton_join.h>

#include <algorithm>
#include <cctype>
#include <iterator>
#include <new>

namespace finbook::model {

namespace file_format {

namespace {
constexpr quint32 kOrder[] = {kTagDocument, kTagStrokes, kTagPoses, kTagFrames};
constexpr int kMaxProblemsListed = 200;
} // namespace

QString tagName(quint32 t)
{
    QByteArray text(4, '\0');
    qToLittleEndian<quint32>(t, text.data());
    for (char ch : text)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != ' ')
            return QStringLiteral("0x%1").arg(t, 8, 16, QLatin1Char('0'));
    return QString::fromLatin1(text);
}

void skipUnknown(Cursor &c, quint32 t, const char *kind)
{
    const QString name = tagName(t);
    if (name.startsWith(QLatin1String("0x")))
        c.fail(FileErrorCode::BadValue,
               FinbookFile::tr("unknown %1 %2").arg(FinbookFile::tr(kind), name));
    if (!isAncillary(t))
        c.fail(FileErrorCode::NewerVersion,
               FinbookFile::tr(
                   "it holds data (\"%1\") that this version of Finbook does not know, so it was "
                   "probably made by a newer Finbook; please update Finbook to open it")
                   .arg(name));
}

Reader::Reader(ParseMode mode, qint64 fileBytes, Id huntedId)
    : m_mode(mode)
    , m_budget(kLoadMemoryFactor * fileBytes + kLoadMemorySlack)
    , m_huntedId(huntedId)
{}

void Reader::problem(Cursor &c, FileErrorCode code, const QString &what)
{
    if (!recovering())
        c.fail(code, what);
    if (m_problems.size() < kMaxProblemsListed) {
        const QString where = m_where.describe();
        m_problems << (where.isEmpty() ? what : FinbookFile::tr("%1: %2").arg(where, what));
    } else if (m_problems.size() == kMaxProblemsListed) {
        m_problems << FinbookFile::tr("more problems were found and repaired the same way");
    }
}

void Reader::charge(Cursor &c, qint64 bytes)
{
    m_charged += bytes;
    if (m_charged > m_budget)
        c.fail(FileErrorCode::TooLarge,
               FinbookFile::tr("it describes more than a file of its size can hold (opening it "
                               "would take more than %1 MB of memory)")
                   .arg(m_budget >> 20));
}

LoadedDocument Reader::read(const QByteArray &bytes)
{
    Cursor c(bytes.constData(), bytes.constData() + bytes.size(), &m_where,
             !endsWithEndMarker(bytes));
    // Header problems need no location: they are about the file as a whole.
    m_version = readHeader(c, recovering());
    if (m_version < kOldestVersion || m_version > kFinbookFormatVersion) {
        // Recovering a file whose version word is damaged: read it as the version its first
        // section's checksum says it has.
        problem(c, FileErrorCode::Damaged, damagedVersion(m_version));
        m_version = firstSectionHasCrc(c) ? kFinbookFormatVersion : kOldestVersion;
    }
    readSections(c);
    m_doc.formatVersion = m_version;
    if (m_version < kFinbookFormatVersion)
        migrateLoadedDocument(m_doc, m_version);
    return std::move(m_doc);
}

void Reader::readSections(Cursor &c)
{
    std::size_t next = 0; // index in kOrder of the section expected next
    while (readSection(c, next)) {
    }
    finish(c);
}

// One section, its checksum checked before anything in it is believed. False after the end
// marker (or, recovering, where nothing more can be read).
bool Reader::readSection(Cursor &c, std::size_t &next)
{
    m_where = Where();
    m_where.section = FinbookFile::tr("the file's section list");
    const bool hasCrc = m_version >= kFirstVersionWithCrc;
    if (recovering() && c.remaining() < kSectionHeaderBytes) {
        problem(c, FileErrorCode::Truncated, FinbookFile::tr("the file ends before its end"));
        return false;
    }
    const char *start = c.position();
    const quint32 t = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a section header"));
    const quint64 length = c.u64(QT_TRANSLATE_NOOP("FinbookFile", "a section header"));
    m_where.section = FinbookFile::tr("section %1").arg(tagName(t));
    const auto *known = std::find(std::begin(kOrder), std::end(kOrder), t);
    const bool sound = t == kTagSound;
    const bool camera = t == kTagCamera;
    const bool layers = t == kTagLayers;
    const bool swap = t == kTagSwap;
    const bool pictures = t == kTagPictures;
    const bool expected =
        t == kTagEnd || sound || camera || layers || swap || pictures ||
        (known != std::end(kOrder) && std::size_t(known - std::begin(kOrder)) >= next);
    const bool text = !tagName(t).startsWith(QLatin1String("0x"));
    if (recovering() && (!text || (!expected && !isAncillary(t)))) {
        // Damage in a section header: look for the next section that reads.
        c.skipTo(start);
        return findNextSection(c, next);
    }
    bool cut = false;
    if (length > c.remaining()) {
        if (recovering() && t == kTagEnd) {
            problem(c, FileErrorCode::Truncated, FinbookFile::tr("the file's end is damaged"));
            return false;
        }
        if (!recovering() && !c.endIsFileEnd())
            c.fail(FileErrorCode::Damaged,
                   FinbookFile::tr("its length (%1 bytes) runs past the end of the file (%2 bytes "
                                   "left), yet the file ends with its end marker, so the length "
                                   "is damaged")
                       .arg(length)
                       .arg(c.remaining()));
        if (!recovering())
            c.fail(
                FileErrorCode::Truncated,
                FinbookFile::tr("the file ends inside this section (%1 bytes announced, %2 left)")
                    .arg(length)
                    .arg(c.remaining()));
        problem(c, FileErrorCode::Truncated,
                FinbookFile::tr("the file ends inside this section; what it holds is read"));
        cut = true;
    }
    Cursor body = c.record(cut ? c.remaining() : std::size_t(length),
                           QT_TRANSLATE_NOOP("FinbookFile", "a section"));
    if (hasCrc && !cut) {
        if (recovering() && c.remaining() < kSectionCrcBytes) {
            problem(c, FileErrorCode::Truncated,
                    FinbookFile::tr("the file ends before this section's checksum"));
        } else {
            const quint32 stored = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a section checksum"));
            if (stored != io::crc32c(0, start, kSectionHeaderBytes + std::size_t(length)))
                problem(c, FileErrorCode::Damaged,
                        FinbookFile::tr("its checksum does not match, so its bytes changed after "
                                        "it was saved"));
        }
    }
    if (t == kTagEnd) {
        if (next < std::size(kOrder))
            problem(c, FileErrorCode::BadValue,
                    FinbookFile::tr("section %1 is missing").arg(tagName(kOrder[next])));
        if (!recovering()) {
            body.expectEnd(QT_TRANSLATE_NOOP("FinbookFile", "the end marker"));
            c.expectEnd(QT_TRANSLATE_NOOP("FinbookFile", "the file"));
        }
        return false;
    }
    if (t == kTagReference && next == std::size(kOrder)) {
        readReferenceSection(body);
        return !cut;
    }
    if (t == kTagReferenceSequence && next == std::size(kOrder)) {
        readReferenceSequenceSection(body);
        return !cut;
    }
    // The light and the palette: when recovering, a damaged one is left out (the default
    // kept) and said; otherwise it fails the file.
    const auto settingSection = [&](void (Reader::*section)(Cursor &)) {
        if (!recovering()) {
            (this->*section)(body);
            return;
        }
        try {
            (this->*section)(body);
        } catch (const ReadFailure &failure) {
            m_problems << failure.what;
        }
    };
    if (t == kTagPalette && next == std::size(kOrder)) {
        settingSection(&Reader::readPaletteSection);
        return !cut;
    }
    if (t == kTagLight && next == std::size(kOrder)) {
        settingSection(&Reader::readLightSection);
        return !cut;
    }
    if (sound) {
        if (next < std::size(kOrder))
            problem(c, FileErrorCode::BadValue,
                    FinbookFile::tr("a sound clip comes before the frames"));
        readSoundSection(body);
        return !cut;
    }
    if (layers) {
        if (next < std::size(kOrder))
            problem(c, FileErrorCode::BadValue,
                    FinbookFile::tr("the layers come before the frames"));
        if (m_sawLayers)
            problem(c, FileErrorCode::BadValue, FinbookFile::tr("the layers are repeated"));
        else
            readLayersSection(body);
        m_sawLayers = true;
        return !cut;
    }
    if (pictures) {
        if (next < std::size(kOrder))
            problem(c, FileErrorCode::BadValue,
                    FinbookFile::tr("the pictures come before the frames"));
        if (m_sawPictures)
            problem(c, FileErrorCode::BadValue, FinbookFile::tr("the pictures are repeated"));
        else
            readPictureSection(body);
        m_sawPictures = true;
        return !cut;
    }
    if (camera) {
        if (next < std::size(kOrder))
            problem(c, FileErrorCode::BadValue,
                    FinbookFile::tr("the camera comes before the frames"));
        if (m_sawCamera)
            problem(c, FileErrorCode::BadValue, FinbookFile::tr("the camera is repeated"));
        else
            readCameraSection(body);
        m_sawCamera = true;
        return !cut;
    }
    if (swap) {
        if (next < std::size(kOrder))
            problem(c, FileErrorCode::BadValue,
                    FinbookFile::tr("the swap sets come before the frames"));
        if (m_sawSwap)
            problem(c, FileErrorCode::BadValue, FinbookFile::tr("the swap sets are repeated"));
        else
            readSwapSection(body);
        m_sawSwap = true;
        return !cut;
    }
    if (known == std::end(kOrder)) {
        if (recovering() && !isAncillary(t))
            problem(c, FileErrorCode::BadValue, FinbookFile::tr("an unknown section is left out"));
        else
            skipUnknown(c, t, QT_TRANSLATE_NOOP("FinbookFile", "section"));
        return !cut;
    }
    const std::size_t index = std::size_t(known - std::begin(kOrder));
    if (index != next) {
        if (!recovering() || index < next)
            problem(c, FileErrorCode::BadValue,
                    FinbookFile::tr("the section is repeated or out of order"));
        if (index < next)
            return !cut; // recovering: the first copy counts
        for (std::size_t missing = next; missing < index; ++missing)
            problem(c, FileErrorCode::BadValue,
                    FinbookFile::tr("section %1 is missing").arg(tagName(kOrder[missing])));
    }
    next = index + 1;
    readSectionBody(body, index);
    return !cut;
}

void Reader::readPaletteSection(Cursor &c)
{
    const char *what = QT_TRANSLATE_NOOP("FinbookFile", "the palette");
    const std::size_t size = c.remaining();
    const QByteArray payload(c.take(size, what), qsizetype(size));
    Expected<Palette, QString> palette = model::readPaletteSection(payload);
    if (!palette)
        c.fail(FileErrorCode::BadValue, palette.error());
    m_doc.palette = std::move(*palette);
}

void Reader::readSectionBody(Cursor &body, std::size_t index)
{
    try {
        switch (index) {
        case 0:
            readDocument(body);
            break;
        case 1:
            readStrokeTable(body);
            break;
        case 2:
            readPoseTable(body);
            break;
        default:
            readFrames(body);
            break;
        }
        if (recovering() && !body.atEnd())
            problem(body, FileErrorCode::BadValue,
                    FinbookFile::tr("the end of the section could not be read"));
        body.expectEnd(QT_TRANSLATE_NOOP("FinbookFile", "the section"));
    } catch (const ReadFailure &failure) {
        if (!recovering())
            throw;
        m_problems << failure.what;
    }
}

void Reader::readDocument(Cursor &c)
{
    m_where.section = FinbookFile::tr("the document settings");
    DocumentSettings &s = m_doc.settings;
    const DocumentSettings defaults;
    const quint32 w = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "the canvas size"));
    const quint32 h = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "the canvas size"));
    s.canvasSize = QSize(int(w), int(h));
    if (w < 1 || h < 1 || w > quint32(kMaxCanvasSide) || h > quint32(kMaxCanvasSide)) {
        problem(c, FileErrorCode::BadValue,
                FinbookFile::tr("the canvas size %1×%2 is outside 1 to %3 pixels")
                    .arg(w)
                    .arg(h)
                    .arg(kMaxCanvasSide));
        s.canvasSize = defaults.canvasSize;
    }
    s.background = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "the background colour"));
    const quint32 fps = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "the frame rate"));
    s.fps = int(fps);
    if (fps < quint32(kMinFps) || fps > quint32(kMaxFps)) {
        problem(c, FileErrorCode::BadValue,
                FinbookFile::tr("the frame rate %1 is outside %2 to %3")
                    .arg(fps)
                    .arg(kMinFps)
                    .arg(kMaxFps));
        s.fps = defaults.fps;
    }
    const quint8 loop = c.u8(QT_TRANSLATE_NOOP("FinbookFile", "the loop flag"));
    if (loop > 1)
        problem(c, FileErrorCode::BadValue,
                FinbookFile::tr("the loop flag %1 is neither 0 nor 1").arg(loop));
    s.loop = loop != 0;
    s.playStart = c.i32(QT_TRANSLATE_NOOP("FinbookFile", "the play range"));
    s.playEnd = c.i32(QT_TRANSLATE_NOOP("FinbookFile", "the play range"));
    if (s.playStart < 0 || s.playEnd < -1) {
        problem(
            c, FileErrorCode::BadValue,
            FinbookFile::tr("the play range %1 to %2 is invalid").arg(s.playStart).arg(s.playEnd));
        s.playStart = defaults.playStart;
        s.playEnd = defaults.playEnd;
    }
    m_doc.nextId = c.u64(QT_TRANSLATE_NOOP("FinbookFile", "the next id"));
    if (m_version >= kFirstVersionWithFills) {
        s.closeGap = c.f64(QT_TRANSLATE_NOOP("FinbookFile", "the close-gap setting"));
        if (!(s.closeGap <= kMaxCloseGap) || (s.closeGap < 0.0 && s.closeGap != -1.0)) {
            problem(c, FileErrorCode::BadValue,
                    FinbookFile::tr("the close-gap setting %1 is outside 0 to %2 pixels")
                        .arg(s.closeGap)
                        .arg(kMaxCloseGap));
            s.closeGap = defaults.closeGap;
        }
    }
    if (m_doc.nextId > kMaxId + 1) {
        problem(
            c, FileErrorCode::BadValue,
            FinbookFile::tr("the next free id %1 is larger than any id can be").arg(m_doc.nextId));
        m_doc.nextId = kNoId; // finish() puts it past the largest id
    }
}

// Checks that need the whole file: table entries no frame uses, and the id counter.
void Reader::finish(Cursor &c)
{
    m_where = Where();
    m_where.section = FinbookFile::tr("the document settings");
    std::sort(m_ids.begin(), m_ids.end());
    if (!m_sharedIds.empty()) {
        // A drawing shown in several frames has its stroke ids in each: one use each counts.
        std::sort(m_sharedIds.begin(), m_sharedIds.end());
        std::vector<Id> own;
        own.reserve(m_ids.size());
        std::set_difference(m_ids.begin(), m_ids.end(), m_sharedIds.begin(), m_sharedIds.end(),
                            std::back_inserter(own));
        m_ids.swap(own);
        std::vector<Id>().swap(m_sharedIds);
    }
    const auto twice = std::adjacent_find(m_ids.begin(), m_ids.end());
    if (twice != m_ids.end() && !recovering())
        throw DuplicateId{*twice};
    m_idsClash = m_idsClash || twice != m_ids.end();
    std::vector<Id>().swap(m_ids);
    resolvePictures(c);
    // Joins are stored, anchors derived: every reader of the file sees them resolved, as a
    // Document holding these frames would have them.
    const auto resolveAll = [this, &c] {
        // Bounded: a file must not make opening cost more than its size can honestly ask
        // (parts on a huge skeleton at points nearly equally near thousands of its bones).
        std::int64_t budget = join_detail::joinWorkAllowance(m_doc.frames);
        for (std::size_t k = 0; k < m_doc.frames.size(); ++k) {
            Frame &f = m_doc.frames[k];
            if (join_detail::resolveJoinsWithin(f, budget))
                continue;
            m_where.frame = int(k + 1);
            problem(c, FileErrorCode::TooLarge,
                    FinbookFile::tr("its parts are joined in a way too costly to work out"));
            for (StrokeGroup &g : f.groups) { // recovering: the parts stand alone
                g.rig.skeleton.join = {};
                g.rig.skeleton.anchor = {};
            }
            m_where.frame = 0;
        }
    };
    if (recovering()) {
        // Nothing in the file refers to a layer's id: fresh ones cannot clash.
        for (LoadedLayer &l : m_doc.layers)
            l.id = freshId();
        if (m_idsClash)
            renumberClashingIds();
        resolveAll();
        m_doc.nextId = std::max(m_doc.nextId, m_maxId + 1);
        return;
    }
    if (m_badStrokeData.index != Deferred::kNone) {
        m_where.strokeData = int(m_badStrokeData.index + 1);
        c.fail(FileErrorCode::BadValue, m_badStrokeData.what);
    }
    if (m_badPose.index != Deferred::kNone) {
        m_where.pose = int(m_badPose.index + 1);
        c.fail(FileErrorCode::BadValue, m_badPose.what);
    }
    if (m_doc.nextId <= m_maxId)
        c.fail(FileErrorCode::BadValue,
               FinbookFile::tr("the next free id %1 is not above the largest id %2")
                   .arg(m_doc.nextId)
                   .arg(m_maxId));
    resolveAll();
}

Expected<LoadedDocument, ReadFailure> parseFinbook(const QByteArray &bytes, ParseMode mode,
                                                   QStringList *problems)
{
    try {
        Reader reader(mode, bytes.size());
        LoadedDocument doc;
        try {
            doc = reader.read(bytes);
        } catch (const Reader::DuplicateId &duplicate) {
            // Read again to say where the id is used the second time (this throws).
            Reader(mode, bytes.size(), duplicate.id).read(bytes);
            throw ReadFailure{FileErrorCode::BadValue,
                              FinbookFile::tr("the id %1 is used twice").arg(duplicate.id)};
        }
        if (mode == ParseMode::Recover && doc.frames.empty())
            return unexpected(ReadFailure{
                FileErrorCode::BadValue,
                FinbookFile::tr("no frame of it could be read; there is nothing to recover")});
        if (problems)
            *problems = reader.problems();
        return doc;
    } catch (const ReadFailure &failure) {
        return unexpected(failure);
    } catch (const std::bad_alloc &) {
        return unexpected(
            ReadFailure{FileErrorCode::OutOfMemory,
                        FinbookFile::tr("there is not enough memory to open this file")});
    }
}

} // namespace file_format

bool isRecoverable(FileErrorCode code)
{
    return code == FileErrorCode::Truncated || code == FileErrorCode::BadValue ||
           code == FileErrorCode::TooLarge || code == FileErrorCode::Damaged;
}

Expected<LoadedDocument, FileError> readFinbook(const QByteArray &bytes)
{
    using namespace file_format;
    auto parsed = parseFinbook(bytes);
    if (!parsed)
        return unexpected(FileError{parsed.error().code,
                                    failureSentence(parsed.error().code, parsed.error().what)});
    return std::move(*parsed);
}

Expected<LoadedDocument, FileError> recoverFinbook(const QByteArray &bytes, QStringList *problems)
{
    using namespace file_format;
    auto parsed = parseFinbook(bytes, ParseMode::Recover, problems);
    if (!parsed)
        return unexpected(FileError{parsed.error().code,
                                    failureSentence(parsed.error().code, parsed.error().what)});
    return std::move(*parsed);
}

} // namespace finbook::model
