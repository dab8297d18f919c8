// readFinbook: header, sections, frames and objects (layout in finbook_file_format.h).
//
// The parser trusts nothing: lengths and counts are bounded by the bytes left before any
// allocation, values are range-checked, ids must be unique and the next free id above them
// all. A file of an older format version is parsed as that version, then migrated.
#include "finbook_file_reader.h"

#include <QStringDecoder>

#include <algorithm>
#include <cctype>
#include <new>

namespace finbook::model {

namespace file_format {

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

LoadedDocument Reader::read(const QByteArray &bytes)
{
    Cursor c(bytes.constData(), bytes.constData() + bytes.size(), &m_where);
    // Header problems need no location: they are about the file as a whole.
    m_version = readHeader(c);
    readSections(c);
    m_doc.formatVersion = m_version;
    if (m_version < kFinbookFormatVersion)
        migrateLoadedDocument(m_doc, m_version);
    return std::move(m_doc);
}

quint32 Reader::readHeader(Cursor &c)
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
    if (version > kFinbookFormatVersion)
        c.fail(FileErrorCode::NewerVersion,
               FinbookFile::tr(
                   "it was made by a newer version of Finbook (file format %1; this version "
                   "reads up to %2); please update Finbook to open it")
                   .arg(version)
                   .arg(kFinbookFormatVersion));
    if (version < kOldestVersion)
        c.fail(FileErrorCode::BadValue,
               FinbookFile::tr("the format version %1 does not exist").arg(version));
    return version;
}

void Reader::readSections(Cursor &c)
{
    static constexpr quint32 kOrder[] = {kTagDocument, kTagStrokes, kTagPoses, kTagFrames};
    std::size_t next = 0;
    for (;;) {
        m_where = Where();
        m_where.section = FinbookFile::tr("the file's section list");
        const quint32 t = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a section header"));
        const quint64 length = c.u64(QT_TRANSLATE_NOOP("FinbookFile", "a section header"));
        m_where.section = FinbookFile::tr("section %1").arg(tagName(t));
        if (length > c.remaining())
            c.fail(
                FileErrorCode::Truncated,
                FinbookFile::tr("the file ends inside this section (%1 bytes announced, %2 left)")
                    .arg(length)
                    .arg(c.remaining()));
        Cursor body = c.record(std::size_t(length), QT_TRANSLATE_NOOP("FinbookFile", "a section"));
        if (t == kTagEnd) {
            if (next < std::size(kOrder))
                c.fail(FileErrorCode::BadValue,
                       FinbookFile::tr("section %1 is missing").arg(tagName(kOrder[next])));
            body.expectEnd(QT_TRANSLATE_NOOP("FinbookFile", "the end marker"));
            c.expectEnd(QT_TRANSLATE_NOOP("FinbookFile", "the file"));
            return finish(c);
        }
        const auto *known = std::find(std::begin(kOrder), std::end(kOrder), t);
        if (known == std::end(kOrder)) {
            skipUnknown(c, t, QT_TRANSLATE_NOOP("FinbookFile", "section"));
            continue;
        }
        if (std::size_t(known - std::begin(kOrder)) != next)
            c.fail(FileErrorCode::BadValue,
                   FinbookFile::tr("the section is repeated or out of order"));
        switch (next++) {
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
        body.expectEnd(QT_TRANSLATE_NOOP("FinbookFile", "the section"));
    }
}

void Reader::readDocument(Cursor &c)
{
    m_where.section = FinbookFile::tr("the document settings");
    DocumentSettings &s = m_doc.settings;
    const quint32 w = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "the canvas size"));
    const quint32 h = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "the canvas size"));
    if (w < 1 || h < 1 || w > quint32(kMaxCanvasSide) || h > quint32(kMaxCanvasSide))
        c.fail(FileErrorCode::BadValue,
               FinbookFile::tr("the canvas size %1×%2 is outside 1 to %3 pixels")
                   .arg(w)
                   .arg(h)
                   .arg(kMaxCanvasSide));
    s.canvasSize = QSize(int(w), int(h));
    s.background = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "the background colour"));
    const quint32 fps = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "the frame rate"));
    if (fps < quint32(kMinFps) || fps > quint32(kMaxFps))
        c.fail(FileErrorCode::BadValue, FinbookFile::tr("the frame rate %1 is outside %2 to %3")
                                            .arg(fps)
                                            .arg(kMinFps)
                                            .arg(kMaxFps));
    s.fps = int(fps);
    const quint8 loop = c.u8(QT_TRANSLATE_NOOP("FinbookFile", "the loop flag"));
    if (loop > 1)
        c.fail(FileErrorCode::BadValue,
               FinbookFile::tr("the loop flag %1 is neither 0 nor 1").arg(loop));
    s.loop = loop == 1;
    s.playStart = c.i32(QT_TRANSLATE_NOOP("FinbookFile", "the play range"));
    s.playEnd = c.i32(QT_TRANSLATE_NOOP("FinbookFile", "the play range"));
    if (s.playStart < 0 || s.playEnd < -1)
        c.fail(
            FileErrorCode::BadValue,
            FinbookFile::tr("the play range %1 to %2 is invalid").arg(s.playStart).arg(s.playEnd));
    m_doc.nextId = c.u64(QT_TRANSLATE_NOOP("FinbookFile", "the next id"));
}

void Reader::readFrames(Cursor &c)
{
    m_where.section = FinbookFile::tr("the frame list");
    const quint32 n =
        c.count(4 + kFrameFixedBytes, QT_TRANSLATE_NOOP("FinbookFile", "the frame list"));
    m_doc.frames.reserve(n);
    for (quint32 i = 0; i < n; ++i) {
        m_where.frame = int(i + 1);
        m_where.enterObject(0);
        const quint32 length = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a frame"));
        Cursor record = c.record(length, QT_TRANSLATE_NOOP("FinbookFile", "a frame"));
        m_doc.frames.push_back(readFrame(record));
    }
    m_where.frame = 0;
}

Frame Reader::readFrame(Cursor &c)
{
    Frame frame;
    frame.id = c.u64(QT_TRANSLATE_NOOP("FinbookFile", "a frame id"));
    claimId(c, frame.id, FinbookFile::tr("the frame"));
    const quint32 hold = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a frame hold"));
    if (hold < 1 || hold > quint32(kMaxHold))
        c.fail(FileErrorCode::BadValue,
               FinbookFile::tr("the hold %1 is outside 1 to %2").arg(hold).arg(kMaxHold));
    frame.hold = int(hold);
    const quint32 n =
        c.count(4 + kObjectFixedBytes, QT_TRANSLATE_NOOP("FinbookFile", "the object list"));
    frame.groups.reserve(n);
    for (quint32 i = 0; i < n; ++i) {
        m_where.enterObject(int(i + 1));
        const quint32 length = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "an object"));
        Cursor record = c.record(length, QT_TRANSLATE_NOOP("FinbookFile", "an object"));
        frame.groups.push_back(readObject(record));
    }
    m_where.enterObject(0);
    while (!c.atEnd()) { // frames have no chunks yet; later formats may add some
        const quint32 t = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a chunk header"));
        c.record(c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a chunk header")),
                 QT_TRANSLATE_NOOP("FinbookFile", "a chunk"));
        skipUnknown(c, t, QT_TRANSLATE_NOOP("FinbookFile", "chunk"));
    }
    return frame;
}

StrokeGroup Reader::readObject(Cursor &c)
{
    StrokeGroup g;
    g.id = c.u64(QT_TRANSLATE_NOOP("FinbookFile", "an object id"));
    claimId(c, g.id, FinbookFile::tr("the object"));
    const quint8 flags = c.u8(QT_TRANSLATE_NOOP("FinbookFile", "the object flags"));
    if (flags & ~kKnownFlags)
        c.fail(FileErrorCode::BadValue,
               FinbookFile::tr("the object flags 0x%1 are unknown").arg(flags, 0, 16));
    g.visible = flags & kFlagVisible;
    g.locked = flags & kFlagLocked;
    g.meshDensity = c.f64(QT_TRANSLATE_NOOP("FinbookFile", "the mesh density"));
    if (!(std::isfinite(g.meshDensity) && g.meshDensity > 0.0 && g.meshDensity <= 1000.0))
        c.fail(FileErrorCode::BadValue,
               FinbookFile::tr("the mesh density %1 is not a number from 0 to 1000")
                   .arg(g.meshDensity));
    const quint32 nameBytes = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "the object name"));
    if (nameBytes > kMaxNameBytes)
        c.fail(FileErrorCode::TooLarge,
               FinbookFile::tr("the object name is %1 bytes long (at most %2)")
                   .arg(nameBytes)
                   .arg(kMaxNameBytes));
    const char *name = c.take(nameBytes, QT_TRANSLATE_NOOP("FinbookFile", "the object name"));
    // Strict UTF-8, a leading BOM kept: a name must survive open → save byte for byte.
    QStringDecoder utf8(QStringConverter::Utf8, QStringConverter::Flag::ConvertInitialBom |
                                                    QStringConverter::Flag::Stateless);
    g.name = utf8(QByteArrayView(name, nameBytes));
    if (utf8.hasError())
        c.fail(FileErrorCode::BadValue, FinbookFile::tr("the object name is not valid UTF-8 text"));
    m_where.objectName = g.name;
    m_where.hasObjectName = true;

    const quint32 n = c.count(kStrokeRefBytes, QT_TRANSLATE_NOOP("FinbookFile", "the stroke list"));
    g.strokes.reserve(n);
    m_strokeRefs.clear();
    for (quint32 i = 0; i < n; ++i) {
        m_where.stroke = int(i + 1);
        Stroke s;
        s.id = c.u64(QT_TRANSLATE_NOOP("FinbookFile", "a stroke id"));
        claimId(c, s.id, FinbookFile::tr("the stroke"));
        const quint32 index = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a stroke reference"));
        if (index >= m_strokeData.size())
            c.fail(FileErrorCode::BadValue, FinbookFile::tr("it refers to stroke data %1 of %2")
                                                .arg(quint64(index) + 1)
                                                .arg(m_strokeData.size()));
        if (index == m_badStrokeData.index)
            c.fail(FileErrorCode::BadValue, m_badStrokeData.what);
        s.data = m_strokeData[index];
        m_strokeRefs.push_back(index);
        g.strokes.push_back(std::move(s));
    }
    m_where.stroke = 0;
    readObjectChunks(c, g);
    return g;
}

void Reader::readObjectChunks(Cursor &c, StrokeGroup &g)
{
    bool seenPins = false;
    while (!c.atEnd()) {
        const quint32 t = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a chunk header"));
        Cursor body = c.record(c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a chunk header")),
                               QT_TRANSLATE_NOOP("FinbookFile", "a chunk"));
        if ((t == kTagPins && seenPins) || (t == kTagDeformed && g.deformed))
            c.fail(FileErrorCode::BadValue,
                   FinbookFile::tr("chunk %1 appears twice").arg(tagName(t)));
        if (t == kTagPins) {
            g.pins = readPins(body);
            seenPins = true;
        } else if (t == kTagDeformed) {
            g.deformed = readPoseRef(body, g);
        } else {
            skipUnknown(c, t, QT_TRANSLATE_NOOP("FinbookFile", "chunk"));
            continue;
        }
        body.expectEnd(QT_TRANSLATE_NOOP("FinbookFile", "a chunk"));
    }
}

std::vector<Pin> Reader::readPins(Cursor &c)
{
    std::vector<Pin> pins(c.count(kPinBytes, QT_TRANSLATE_NOOP("FinbookFile", "the pin list")));
    for (std::size_t i = 0; i < pins.size(); ++i) {
        Pin &p = pins[i];
        p.id = c.u64(QT_TRANSLATE_NOOP("FinbookFile", "a pin id"));
        claimId(c, p.id, FinbookFile::tr("pin %1").arg(i + 1));
        double v[4];
        for (double &x : v)
            x = c.f64(QT_TRANSLATE_NOOP("FinbookFile", "a pin position"));
        if (!std::all_of(std::begin(v), std::end(v), [](double x) { return std::isfinite(x); }))
            c.fail(FileErrorCode::BadValue,
                   FinbookFile::tr("pin %1 has a non-finite position").arg(i + 1));
        p.rest = QPointF(v[0], v[1]);
        p.target = QPointF(v[2], v[3]);
    }
    return pins;
}

DeformedStrokesPtr Reader::readPoseRef(Cursor &c, const StrokeGroup &g)
{
    const quint32 index = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a pose reference"));
    if (index >= m_poses.size())
        c.fail(FileErrorCode::BadValue, FinbookFile::tr("its pose refers to pose %1 of %2")
                                            .arg(quint64(index) + 1)
                                            .arg(m_poses.size()));
    if (index == m_badPose.index)
        c.fail(FileErrorCode::BadValue, FinbookFile::tr("its pose: %1").arg(m_badPose.what));
    const std::vector<quint32> &sizes = m_poseSizes[index];
    if (sizes.size() != g.strokes.size())
        c.fail(FileErrorCode::BadValue,
               FinbookFile::tr("its pose has %1 strokes but the object has %2")
                   .arg(sizes.size())
                   .arg(g.strokes.size()));
    for (std::size_t i = 0; i < g.strokes.size(); ++i) {
        const quint32 rest = m_strokeDataSizes[m_strokeRefs[i]];
        if (sizes[i] != rest)
            c.fail(FileErrorCode::BadValue,
                   FinbookFile::tr("stroke %1 has %2 points but its pose has %3")
                       .arg(i + 1)
                       .arg(rest)
                       .arg(sizes[i]));
    }
    const DeformedStrokesPtr &pose = m_poses[index];
    return pose;
}

void Reader::claimId(Cursor &c, Id id, const QString &owner)
{
    if (id == kNoId)
        c.fail(FileErrorCode::BadValue, FinbookFile::tr("%1 has no id").arg(owner));
    if (!m_ids.insert(id).second)
        c.fail(FileErrorCode::BadValue,
               FinbookFile::tr("%1 has the id %2, which is already used").arg(owner).arg(id));
    m_maxId = std::max(m_maxId, id);
}

// Checks that need the whole file: table entries no frame uses, and the id counter.
void Reader::finish(Cursor &c)
{
    m_where = Where();
    m_where.section = FinbookFile::tr("the document settings");
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
}

Expected<LoadedDocument, ReadFailure> parseFinbook(const QByteArray &bytes, ParseMode mode)
{
    try {
        return Reader(mode).read(bytes);
    } catch (const ReadFailure &failure) {
        return unexpected(failure);
    } catch (const std::bad_alloc &) {
        return unexpected(
            ReadFailure{FileErrorCode::TooLarge,
                        FinbookFile::tr("there is not enough memory to open this file")});
    }
}

} // namespace file_format

Expected<LoadedDocument, FileError> readFinbook(const QByteArray &bytes)
{
    using namespace file_format;
    auto parsed = parseFinbook(bytes);
    if (!parsed)
        return unexpected(FileError{parsed.error().code,
                                    failureSentence(parsed.error().code, parsed.error().what)});
    return std::move(*parsed);
}

} // namespace finbook::model
