// ByteWriter: the output buffer of serializeFinbook (private to the model), sized up front and
// filled through a raw pointer; length prefixes and checksums are patched in afterwards.
#pragma once

#include "finbook_file_format.h"
#include "io/crc32c.h"

#include <algorithm>

namespace finbook::model::file_format {

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

    // CRC-32C of everything written since byte `at`.
    quint32 crcSince(qsizetype at) const
    {
        return io::crc32c(0, m_bytes.constData() + at, std::size_t(m_size - at));
    }
    qsizetype size() const { return m_size; }

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

} // namespace finbook::model::file_format
