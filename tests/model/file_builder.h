// Hand-made .finbook bytes for the tests that attack the loader: files no Finbook would write
// (huge claimed counts, thousands of references to one stroke, ids near 2^64), built field by
// field as finbook_file_format.h lays them out. Version 1 (no checksums) is what attackers
// can always fall back on, since version-1 files keep opening.
#pragma once

#include <QByteArray>
#include <QtEndian>

#include <cstdint>
#include <utility>
#include <vector>

namespace file_build {

class Bytes {
public:
    Bytes &u8(quint8 v) { return raw(reinterpret_cast<const char *>(&v), 1); }
    Bytes &u16(quint16 v) { return put(v); }
    Bytes &u32(quint32 v) { return put(v); }
    Bytes &i32(qint32 v) { return put(v); }
    Bytes &u64(quint64 v) { return put(v); }
    Bytes &f32(float v) { return put(std::bit_cast<quint32>(v)); }
    Bytes &f64(double v) { return put(std::bit_cast<quint64>(v)); }
    Bytes &raw(const char *p, qsizetype n)
    {
        m_bytes.append(p, n);
        return *this;
    }
    Bytes &raw(const QByteArray &b) { return raw(b.constData(), b.size()); }
    Bytes &tag(const char (&t)[5]) { return raw(t, 4); }
    // A u32 length followed by `body`.
    Bytes &record(const Bytes &body) { return u32(quint32(body.size())).raw(body.bytes()); }
    Bytes &chunk(const char (&t)[5], const Bytes &body) { return tag(t).record(body); }
    qsizetype size() const { return m_bytes.size(); }
    const QByteArray &bytes() const { return m_bytes; }

private:
    template <class T> Bytes &put(T v)
    {
        char b[sizeof(T)];
        qToLittleEndian<T>(v, b);
        return raw(b, sizeof(T));
    }
    QByteArray m_bytes;
};

struct Point {
    float x, y;
    quint16 pressure = 65535;
};

inline Bytes document(quint32 width = 640, quint32 height = 360, quint64 nextId = 1000)
{
    Bytes b;
    b.u32(width).u32(height).u32(0xffffffffu).u32(12).u8(1).i32(0).i32(-1).u64(nextId);
    return b;
}

inline Bytes points(const std::vector<Point> &pts)
{
    Bytes b;
    b.u32(quint32(pts.size()));
    for (const Point &p : pts)
        b.f32(p.x).f32(p.y).u16(p.pressure);
    return b;
}

inline Bytes strokeTable(const std::vector<std::pair<float, std::vector<Point>>> &entries)
{
    Bytes b;
    b.u32(quint32(entries.size()));
    for (const auto &[width, pts] : entries)
        b.u32(0xff000000u).f32(width).raw(points(pts).bytes());
    return b;
}

inline Bytes emptyTable()
{
    return Bytes().u32(0);
}

// An object: id, flags, density, name, stroke references (stroke id, table index), chunks.
inline Bytes object(quint64 id, const std::vector<std::pair<quint64, quint32>> &refs,
                    const QByteArray &name = "o", const Bytes &chunks = {})
{
    Bytes b;
    b.u64(id).u8(1).f64(1.0).u32(quint32(name.size())).raw(name).u32(quint32(refs.size()));
    for (const auto &[strokeId, index] : refs)
        b.u64(strokeId).u32(index);
    return b.raw(chunks.bytes());
}

inline Bytes frame(quint64 id, const std::vector<Bytes> &objects)
{
    Bytes b;
    b.u64(id).u32(1).u32(quint32(objects.size()));
    for (const Bytes &o : objects)
        b.record(o);
    return b;
}

inline Bytes frameList(const std::vector<Bytes> &frames)
{
    Bytes b;
    b.u32(quint32(frames.size()));
    for (const Bytes &f : frames)
        b.record(f);
    return b;
}

// A version-1 file of the four sections and the end marker.
inline QByteArray fileV1(const Bytes &doc, const Bytes &strokes, const Bytes &poses,
                         const Bytes &frames)
{
    Bytes b;
    b.raw("\x89"
          "FBK\r\n\x1a\n",
          8)
        .u32(1);
    const auto section = [&](const char(&t)[5], const Bytes &body) {
        b.tag(t).u64(quint64(body.size())).raw(body.bytes());
    };
    section("DOCU", doc);
    section("STRK", strokes);
    section("POSE", poses);
    section("FRAM", frames);
    section("FEND", Bytes());
    return b.bytes();
}

} // namespace file_build
