// readFinbook: the frame list, objects, their stroke references and chunks, ids.
//
// Recovering, a frame or object whose record does not read is left out as a whole (records
// are length-prefixed, so the next one is found), a chunk that does not read is dropped, a
// stroke referring to stroke data that does not exist is dropped, and bad ids are noted for
// renumberClashingIds().
#include "finbook_file_reader.h"

#include <finbook/model/pins/pin_commands.h>

#include <QStringDecoder>

#include <algorithm>
#include <climits>
#include <cmath>

namespace finbook::model::file_format {

namespace {
// Bytes one object costs in memory beyond its strokes (for the budget).
constexpr qint64 kObjectBytes = qint64(sizeof(StrokeGroup));
// An id in the list of claimed ids.
constexpr qint64 kClaimedIdBytes = qint64(sizeof(Id));
} // namespace

// New object chunks go here: one row, one read function.
const Reader::ObjectChunk Reader::kObjectChunks[] = {
    {kTagPins, true, &Reader::readPinsChunk},
    {kTagCage, true, &Reader::readCageChunk},
    {kTagSkeleton, true, &Reader::readSkeletonChunk},
    {kTagJoin, false, &Reader::readJoinChunk},
    {kTagDeformed, false, &Reader::readPoseChunk},
    {kTagFills, false, &Reader::readFillsChunk},
    {kTagFillPlaces, false, &Reader::readFillPlacesChunk},
    {kTagShading, false, &Reader::readShadingChunk},
    {kTagLimbBases, false, &Reader::readLimbBasesChunk},
    {kTagPictureObject, false, &Reader::readPictureChunk}, // picture/picture_section.cpp
};

quint32 Reader::count(Cursor &c, std::size_t recordBytes, const char *what)
{
    if (!recovering())
        return c.count(recordBytes, what);
    const quint32 n = c.u32(what);
    const quint64 fits = c.remaining() / recordBytes;
    if (n <= fits)
        return n;
    problem(c, FileErrorCode::TooLarge,
            FinbookFile::tr("%1 claims %2 entries; the %3 that fit are read")
                .arg(FinbookFile::tr(what))
                .arg(n)
                .arg(fits));
    return quint32(fits);
}

void Reader::readFrames(Cursor &c)
{
    m_where.section = FinbookFile::tr("the frame list");
    const quint32 n =
        count(c, 4 + kFrameFixedBytes, QT_TRANSLATE_NOOP("FinbookFile", "the frame list"));
    charge(c, qint64(n) * qint64(sizeof(Frame)));
    m_doc.frames.reserve(n);
    for (quint32 i = 0; i < n; ++i) {
        m_where.frame = int(i + 1);
        m_where.enterObject(0);
        if (recovering() && c.remaining() < 4 + kFrameFixedBytes)
            break; // a cut-off file: the frames that are there were read
        const quint32 length = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a frame"));
        if (recovering() && length > c.remaining()) {
            problem(c, FileErrorCode::Truncated,
                    FinbookFile::tr("the frame is cut off and is left out, with any after it"));
            break;
        }
        Cursor record = c.record(length, QT_TRANSLATE_NOOP("FinbookFile", "a frame"));
        try {
            m_doc.frames.push_back(readFrame(record));
        } catch (const ReadFailure &failure) {
            if (!recovering())
                throw;
            m_problems << FinbookFile::tr("%1; the frame is left out").arg(failure.what);
        }
    }
    m_where.frame = 0;
}

Frame Reader::readFrame(Cursor &c)
{
    Frame frame;
    frame.id = c.u64(QT_TRANSLATE_NOOP("FinbookFile", "a frame id"));
    claimId(c, frame.id, FinbookFile::tr("the frame"));
    const quint32 hold = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a frame hold"));
    frame.hold = int(std::clamp<quint32>(hold, 1, quint32(kMaxHold)));
    if (hold < 1 || hold > quint32(kMaxHold))
        problem(c, FileErrorCode::BadValue,
                FinbookFile::tr("the hold %1 is outside 1 to %2").arg(hold).arg(kMaxHold));
    const quint32 n =
        count(c, 4 + kObjectFixedBytes, QT_TRANSLATE_NOOP("FinbookFile", "the object list"));
    charge(c, qint64(n) * kObjectBytes);
    frame.groups.reserve(n);
    for (quint32 i = 0; i < n; ++i) {
        m_where.enterObject(int(i + 1));
        if (recovering() && c.remaining() < 4 + kObjectFixedBytes)
            break; // the count was damaged: the objects that are there were read
        const quint32 length = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "an object"));
        if (recovering() && length > c.remaining()) {
            problem(c, FileErrorCode::Truncated,
                    FinbookFile::tr("the object is cut off and is left out, with any after it"));
            break;
        }
        Cursor record = c.record(length, QT_TRANSLATE_NOOP("FinbookFile", "an object"));
        try {
            frame.groups.push_back(readObject(record));
        } catch (const ReadFailure &failure) {
            if (!recovering())
                throw;
            m_problems << FinbookFile::tr("%1; the object is left out").arg(failure.what);
        }
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
        problem(c, FileErrorCode::BadValue,
                FinbookFile::tr("the object flags 0x%1 are unknown").arg(flags, 0, 16));
    g.visible = flags & kFlagVisible;
    g.locked = flags & kFlagLocked;
    g.meshDensity = c.f64(QT_TRANSLATE_NOOP("FinbookFile", "the mesh density"));
    if (!(std::isfinite(g.meshDensity) && g.meshDensity > 0.0 && g.meshDensity <= 1000.0)) {
        problem(c, FileErrorCode::BadValue,
                FinbookFile::tr("the mesh density %1 is not a number from 0 to 1000")
                    .arg(g.meshDensity));
        g.meshDensity = kDefaultMeshDensity;
    }
    // The editor sets densities from kMinMeshDensity to kMaxMeshDensity and always has; a file
    // asking for finer meshes (work and memory grow with the square) gets the finest it makes.
    g.meshDensity = std::clamp(g.meshDensity, kMinMeshDensity, kMaxMeshDensity);
    g.name = readName(c);
    m_where.objectName = g.name;
    m_where.hasObjectName = true;
    readStrokeRefs(c, g);
    readObjectChunks(c, g);
    return g;
}

QString Reader::readName(Cursor &c)
{
    const quint32 nameBytes = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "the object name"));
    if (nameBytes > kMaxNameBytes)
        c.fail(FileErrorCode::TooLarge,
               FinbookFile::tr("the object name is %1 bytes long (at most %2)")
                   .arg(nameBytes)
                   .arg(kMaxNameBytes));
    const char *name = c.take(nameBytes, QT_TRANSLATE_NOOP("FinbookFile", "the object name"));
    charge(c, 32 + 2 * qint64(nameBytes));
    // Strict UTF-8, a leading BOM kept: a name must survive open → save byte for byte.
    QStringDecoder utf8(QStringConverter::Utf8, QStringConverter::Flag::ConvertInitialBom |
                                                    QStringConverter::Flag::Stateless);
    QString text = utf8(QByteArrayView(name, nameBytes));
    if (utf8.hasError())
        problem(c, FileErrorCode::BadValue,
                FinbookFile::tr("the object name is not valid UTF-8 text"));
    return text;
}

void Reader::readStrokeRefs(Cursor &c, StrokeGroup &g)
{
    const quint32 n =
        count(c, kStrokeRefBytes, QT_TRANSLATE_NOOP("FinbookFile", "the stroke list"));
    charge(c, qint64(n) * (qint64(sizeof(Stroke)) + kClaimedIdBytes + 4));
    g.strokes.reserve(n);
    m_strokeRefs.clear();
    for (quint32 i = 0; i < n; ++i) {
        m_where.stroke = int(i + 1);
        Stroke s;
        s.id = c.u64(QT_TRANSLATE_NOOP("FinbookFile", "a stroke id"));
        const quint32 index = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a stroke reference"));
        if (index >= m_strokeData.size()) {
            problem(c, FileErrorCode::BadValue,
                    FinbookFile::tr("it refers to stroke data %1 of %2")
                        .arg(quint64(index) + 1)
                        .arg(m_strokeData.size()));
            continue;
        }
        if (index == m_badStrokeData.index)
            c.fail(FileErrorCode::BadValue, m_badStrokeData.what);
        claimId(c, s.id, FinbookFile::tr("the stroke"));
        s.data = m_strokeData[index];
        m_strokeRefs.push_back(index);
        g.strokes.push_back(std::move(s));
    }
    m_where.stroke = 0;
}

void Reader::readObjectChunks(Cursor &c, StrokeGroup &g)
{
    std::vector<quint32> seen;
    bool seenRig = false;
    while (!c.atEnd()) {
        const quint32 t = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a chunk header"));
        Cursor body = c.record(c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a chunk header")),
                               QT_TRANSLATE_NOOP("FinbookFile", "a chunk"));
        const auto *kind = std::find_if(std::begin(kObjectChunks), std::end(kObjectChunks),
                                        [t](const ObjectChunk &chunk) { return chunk.tag == t; });
        if (kind == std::end(kObjectChunks)) {
            if (recovering() && !isAncillary(t))
                problem(c, FileErrorCode::BadValue,
                        FinbookFile::tr("an unknown chunk is left out"));
            else
                skipUnknown(c, t, QT_TRANSLATE_NOOP("FinbookFile", "chunk"));
            continue;
        }
        if (std::find(seen.begin(), seen.end(), t) != seen.end() || (kind->isRig && seenRig)) {
            problem(c, FileErrorCode::BadValue,
                    FinbookFile::tr("chunk %1 appears twice or with another rig").arg(tagName(t)));
            continue;
        }
        try {
            (this->*(kind->read))(body, g);
            body.expectEnd(QT_TRANSLATE_NOOP("FinbookFile", "a chunk"));
        } catch (const ReadFailure &failure) {
            if (!recovering())
                throw;
            m_problems << FinbookFile::tr("%1; the chunk is left out").arg(failure.what);
            if (kind->isRig)
                g.rig = Rig();
            continue;
        }
        seen.push_back(t);
        seenRig = seenRig || kind->isRig;
    }
}

void Reader::readPinsChunk(Cursor &c, StrokeGroup &g)
{
    g.rig.pins = readPins(c);
}

void Reader::readCageChunk(Cursor &c, StrokeGroup &g)
{
    g.rig.cage = readCage(c);
}

void Reader::readSkeletonChunk(Cursor &c, StrokeGroup &g)
{
    charge(c, qint64(c.remaining()) * 2);
    g.rig.skeleton = readSkeleton(c);
}

void Reader::readJoinChunk(Cursor &c, StrokeGroup &g)
{
    const char *what = QT_TRANSLATE_NOOP("FinbookFile", "the skeleton's join");
    if (g.rig.skeleton.empty())
        c.fail(FileErrorCode::BadValue, FinbookFile::tr("a join comes without a skeleton"));
    SkeletonJoin j;
    j.parent = c.u64(what);
    double v[4];
    for (double &x : v)
        x = c.f64(what);
    if (j.parent == kNoId ||
        !std::all_of(std::begin(v), std::end(v), [](double x) { return std::isfinite(x); }))
        c.fail(FileErrorCode::BadValue, FinbookFile::tr("the skeleton's join is damaged"));
    j.childAt = QPointF(v[0], v[1]);
    j.parentAt = QPointF(v[2], v[3]);
    g.rig.skeleton.join = j;
}

void Reader::readPoseChunk(Cursor &c, StrokeGroup &g)
{
    g.deformed = readPoseRef(c, g);
}

std::vector<Pin> Reader::readPins(Cursor &c)
{
    const quint32 n = c.count(kPinBytes, QT_TRANSLATE_NOOP("FinbookFile", "the pin list"));
    charge(c, qint64(n) * (qint64(sizeof(Pin)) + kClaimedIdBytes));
    std::vector<Pin> pins(n);
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

CageRig Reader::readCage(Cursor &c)
{
    CageRig cage;
    const std::size_t n =
        c.count(kCageCornerBytes, QT_TRANSLATE_NOOP("FinbookFile", "the cage corner list"));
    if (n < 3)
        c.fail(FileErrorCode::BadValue, FinbookFile::tr("the cage has fewer than 3 corners"));
    charge(c, qint64(n) * 2 * qint64(sizeof(QPointF)));
    cage.rest.reserve(n);
    cage.posed.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        double v[4];
        for (double &x : v)
            x = c.f64(QT_TRANSLATE_NOOP("FinbookFile", "a cage corner"));
        if (!std::all_of(std::begin(v), std::end(v), [](double x) { return std::isfinite(x); }))
            c.fail(FileErrorCode::BadValue,
                   FinbookFile::tr("cage corner %1 has a non-finite position").arg(i + 1));
        cage.rest.emplace_back(v[0], v[1]);
        cage.posed.emplace_back(v[2], v[3]);
    }
    return cage;
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
               FinbookFile::tr("its pose has %n stroke(s) but the object has %1", nullptr,
                               int(std::min<std::size_t>(sizes.size(), INT_MAX)))
                   .arg(g.strokes.size()));
    for (std::size_t i = 0; i < g.strokes.size(); ++i) {
        const quint32 rest = m_strokeDataSizes[m_strokeRefs[i]];
        if (sizes[i] != rest)
            c.fail(FileErrorCode::BadValue,
                   FinbookFile::tr("stroke %1 has %n point(s) but its pose has %2", nullptr,
                                   int(std::min<quint32>(rest, INT_MAX)))
                       .arg(i + 1)
                       .arg(sizes[i]));
    }
    return m_poses[index];
}

void Reader::claimId(Cursor &c, Id id, const QString &owner)
{
    if (id == kNoId || id > kMaxId) {
        problem(c, FileErrorCode::BadValue,
                id == kNoId ? FinbookFile::tr("%1 has no id").arg(owner)
                            : FinbookFile::tr("%1 has the id %2, larger than any id can be")
                                  .arg(owner)
                                  .arg(id));
        m_idsClash = true;
        return;
    }
    if (id == m_huntedId && std::exchange(m_huntedSeen, true))
        c.fail(FileErrorCode::BadValue,
               FinbookFile::tr("%1 has the id %2, which is already used").arg(owner).arg(id));
    m_ids.push_back(id);
    m_maxId = std::max(m_maxId, id);
}

} // namespace finbook::model::file_format
