// serializeFinbook: the canonical byte form of a document (layout in finbook_file_format.h).
//
// Speed matters here (10M points in well under a second): the output is sized up front and
// filled through a raw pointer, points stroke by stroke in one tight loop.
#include "finbook_file_format.h"

#include <algorithm>
#include <unordered_map>

namespace finbook::model {

namespace {
using namespace file_format;

class ByteWriter {
public:
    explicit ByteWriter(qsizetype expectedBytes) { m_bytes.resize(expectedBytes); }

    void u8(quint8 v) { *claim(1) = char(v); }
    void u16(quint16 v) { qToLittleEndian<quint16>(v, claim(2)); }
    void u32(quint32 v) { qToLittleEndian<quint32>(v, claim(4)); }
    void i32(qint32 v) { qToLittleEndian<qint32>(v, claim(4)); }
    void u64(quint64 v) { qToLittleEndian<quint64>(v, claim(8)); }
    void f32(float v) { u32(std::bit_cast<quint32>(v)); }
    void f64(double v) { u64(std::bit_cast<quint64>(v)); }
    void raw(const char *data, std::size_t size)
    {
        if (size > 0)
            std::memcpy(claim(size), data, size);
    }

    void points(const std::vector<StrokePoint> &points)
    {
        u32(quint32(points.size()));
        char *out = claim(points.size() * kPointBytes);
        for (const StrokePoint &p : points) {
            qToLittleEndian<quint32>(std::bit_cast<quint32>(p.x), out);
            qToLittleEndian<quint32>(std::bit_cast<quint32>(p.y), out + 4);
            qToLittleEndian<quint16>(quantisePressure(p.pressure), out + 8);
            out += kPointBytes;
        }
    }

    // Length prefixes are patched in once the payload is written.
    qsizetype beginLength(std::size_t width)
    {
        const qsizetype at = m_size;
        claim(width);
        return at;
    }
    void endLength32(qsizetype at) { patch<quint32>(at, quint32(m_size - at - 4)); }
    void endLength64(qsizetype at) { patch<quint64>(at, quint64(m_size - at - 8)); }

    QByteArray take()
    {
        m_bytes.truncate(m_size);
        return std::move(m_bytes);
    }

private:
    char *claim(std::size_t n)
    {
        if (m_size + qsizetype(n) > m_bytes.size()) // the estimate was short: grow geometrically
            m_bytes.resize(std::max(m_size + qsizetype(n), m_bytes.size() * 2));
        char *p = m_bytes.data() + m_size;
        m_size += qsizetype(n);
        return p;
    }
    template <class T> void patch(qsizetype at, T value)
    {
        qToLittleEndian<T>(value, m_bytes.data() + at);
    }

    QByteArray m_bytes;
    qsizetype m_size = 0;
};

// A pose is only worth saving while it still matches its object's strokes; a stale one is a
// cache the renderer ignores anyway, and the reader would rightly refuse it.
bool poseMatches(const StrokeGroup &group)
{
    if (!group.deformed || group.deformed->strokes.size() != group.strokes.size())
        return false;
    for (std::size_t i = 0; i < group.strokes.size(); ++i) {
        const std::size_t rest = group.strokes[i].data ? group.strokes[i].data->points.size() : 0;
        if (group.deformed->strokes[i].size() != rest)
            return false;
    }
    return true;
}

const StrokeData &emptyStrokeData()
{
    static const StrokeData empty;
    return empty;
}

// Shared data is stored once: the tables list each distinct pointer in order of first
// appearance (frames, objects, strokes), so the same document always gives the same indices.
struct Tables {
    std::vector<const StrokeData *> strokes;
    std::unordered_map<const StrokeData *, quint32> strokeIndex;
    std::vector<const DeformedStrokes *> poses;
    std::unordered_map<const DeformedStrokes *, quint32> poseIndex;
    Id maxId = kNoId;
    qsizetype expectedBytes = 256;

    explicit Tables(const std::vector<Frame> &frames)
    {
        for (const Frame &f : frames) {
            noteId(f.id);
            expectedBytes += 4 + qsizetype(kFrameFixedBytes);
            for (const StrokeGroup &g : f.groups)
                addGroup(g);
        }
    }

    void noteId(Id id) { maxId = std::max(maxId, id); }

    void addGroup(const StrokeGroup &g)
    {
        noteId(g.id);
        for (const Pin &p : g.pins)
            noteId(p.id);
        expectedBytes += 4 + qsizetype(kObjectFixedBytes) + 3 * qsizetype(kChunkHeaderBytes) +
                         g.name.size() * 3 + qsizetype(g.pins.size() * kPinBytes + 4) +
                         qsizetype(g.strokes.size() * kStrokeRefBytes);
        for (const Stroke &s : g.strokes) {
            noteId(s.id);
            const StrokeData *data = s.data ? s.data.get() : &emptyStrokeData();
            if (strokeIndex.try_emplace(data, quint32(strokes.size())).second) {
                strokes.push_back(data);
                expectedBytes +=
                    qsizetype(kStrokeDataHeaderBytes + data->points.size() * kPointBytes);
            }
        }
        if (poseMatches(g) &&
            poseIndex.try_emplace(g.deformed.get(), quint32(poses.size())).second) {
            poses.push_back(g.deformed.get());
            for (const auto &stroke : g.deformed->strokes)
                expectedBytes += qsizetype(4 + stroke.size() * kPointBytes);
        }
    }
};

void writeDocumentSection(ByteWriter &w, const Document &doc, Id maxId)
{
    const DocumentSettings &s = doc.settings();
    w.u32(quint32(s.canvasSize.width()));
    w.u32(quint32(s.canvasSize.height()));
    w.u32(s.background);
    w.u32(quint32(s.fps));
    w.u8(s.loop ? 1 : 0);
    w.i32(s.playStart);
    w.i32(s.playEnd);
    // The next id is derived from the content, not the in-memory counter: commands allocate
    // ids when they are created, and undo does not give them back, so the counter depends on
    // history. Past every stored id is all a reopened document needs (its undo stack is new).
    w.u64(maxId + 1);
}

void writeStrokeTable(ByteWriter &w, const Tables &tables)
{
    w.u32(quint32(tables.strokes.size()));
    for (const StrokeData *data : tables.strokes) {
        w.u32(data->color);
        w.f32(data->width);
        w.points(data->points);
    }
}

void writePoseTable(ByteWriter &w, const Tables &tables)
{
    w.u32(quint32(tables.poses.size()));
    for (const DeformedStrokes *pose : tables.poses) {
        w.u32(quint32(pose->strokes.size()));
        for (const auto &points : pose->strokes)
            w.points(points);
    }
}

void writePins(ByteWriter &w, const std::vector<Pin> &pins)
{
    w.u32(kTagPins);
    const qsizetype length = w.beginLength(4);
    w.u32(quint32(pins.size()));
    for (const Pin &p : pins) {
        w.u64(p.id);
        w.f64(p.rest.x());
        w.f64(p.rest.y());
        w.f64(p.target.x());
        w.f64(p.target.y());
    }
    w.endLength32(length);
}

void writeObject(ByteWriter &w, const StrokeGroup &g, const Tables &tables)
{
    const qsizetype length = w.beginLength(4);
    w.u64(g.id);
    w.u8((g.visible ? kFlagVisible : 0) | (g.locked ? kFlagLocked : 0));
    w.f64(g.meshDensity);
    const QByteArray name = g.name.toUtf8();
    w.u32(quint32(name.size()));
    w.raw(name.constData(), std::size_t(name.size()));
    w.u32(quint32(g.strokes.size()));
    for (const Stroke &s : g.strokes) {
        w.u64(s.id);
        w.u32(tables.strokeIndex.at(s.data ? s.data.get() : &emptyStrokeData()));
    }
    if (!g.pins.empty())
        writePins(w, g.pins);
    if (poseMatches(g)) {
        w.u32(kTagDeformed);
        w.u32(4);
        w.u32(tables.poseIndex.at(g.deformed.get()));
    }
    w.endLength32(length);
}

void writeFrames(ByteWriter &w, const std::vector<Frame> &frames, const Tables &tables)
{
    w.u32(quint32(frames.size()));
    for (const Frame &f : frames) {
        const qsizetype length = w.beginLength(4);
        w.u64(f.id);
        w.u32(quint32(f.hold));
        w.u32(quint32(f.groups.size()));
        for (const StrokeGroup &g : f.groups)
            writeObject(w, g, tables);
        w.endLength32(length);
    }
}

template <class WriteBody> void writeSection(ByteWriter &w, quint32 sectionTag, WriteBody body)
{
    w.u32(sectionTag);
    const qsizetype length = w.beginLength(8);
    body();
    w.endLength64(length);
}
} // namespace

QByteArray serializeFinbook(const Document &document)
{
    const Tables tables(document.frames());
    ByteWriter w(tables.expectedBytes);
    w.raw(kMagic, sizeof(kMagic));
    w.u32(kFinbookFormatVersion);
    writeSection(w, kTagDocument, [&] { writeDocumentSection(w, document, tables.maxId); });
    writeSection(w, kTagStrokes, [&] { writeStrokeTable(w, tables); });
    writeSection(w, kTagPoses, [&] { writePoseTable(w, tables); });
    writeSection(w, kTagFrames, [&] { writeFrames(w, document.frames(), tables); });
    writeSection(w, kTagEnd, [] {});
    return w.take();
}

} // namespace finbook::model
