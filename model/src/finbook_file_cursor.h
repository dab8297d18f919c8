// A bounds-checked read cursor over .finbook bytes, and the "where" of a read error.
//
// Every read checks the bytes left first; every count is checked against the bytes its
// records need before anything is allocated. Failures unwind as ReadFailure to readFinbook,
// the only place that catches it, which keeps the parsing code free of error plumbing.
#pragma once

#include "finbook_file_format.h"
#include "finbook_file_tr.h"

#include <finbook/model/io/printable_text.h>

namespace finbook::model::file_format {

// Where the reader is, for messages. Numbers are 1-based, as a user counts.
struct Where {
    QString section;
    int frame = 0;
    int object = 0;
    QString objectName;
    bool hasObjectName = false;
    int stroke = 0;
    int strokeData = 0; // table entries, outside any frame
    int pose = 0;
    int layer = 0; // in the layer list

    QString describe() const
    {
        if (layer > 0)
            return FinbookFile::tr("layer %1").arg(layer);
        if (frame > 0) {
            QString s = FinbookFile::tr("frame %1").arg(frame);
            if (object > 0)
                s += hasObjectName
                         ? FinbookFile::tr(", object \"%1\"").arg(printableText(objectName))
                         : FinbookFile::tr(", object %1").arg(object);
            if (stroke > 0)
                s += FinbookFile::tr(", stroke %1").arg(stroke);
            return s;
        }
        if (strokeData > 0)
            return FinbookFile::tr("stroke data %1").arg(strokeData);
        if (pose > 0)
            return FinbookFile::tr("pose %1").arg(pose);
        return section;
    }
    void enterObject(int index)
    {
        object = index;
        hasObjectName = false;
        objectName.clear();
        stroke = 0;
    }
};

class Cursor {
public:
    // `endIsFileEnd`: running out of bytes here can mean the file was cut short. Not so inside
    // a record that ends before the file does, nor in a file that ends with its end marker:
    // there a length that runs past the end is damage, not an incomplete file.
    Cursor(const char *begin, const char *end, const Where *where, bool endIsFileEnd = true)
        : m_p(begin)
        , m_end(end)
        , m_where(where)
        , m_endIsFileEnd(endIsFileEnd)
    {}

    std::size_t remaining() const { return std::size_t(m_end - m_p); }
    const char *position() const { return m_p; }
    const char *end() const { return m_end; }
    // Moves to `p`, which must lie between the current position and the end (recovery skips
    // forward to the next section it can read).
    void skipTo(const char *p)
    {
        if (p >= m_p && p <= m_end)
            m_p = p;
    }
    bool atEnd() const { return m_p == m_end; }
    bool endIsFileEnd() const { return m_endIsFileEnd; }

    [[noreturn]] void fail(FileErrorCode code, const QString &what) const
    {
        const QString where = m_where ? m_where->describe() : QString();
        throw ReadFailure{code,
                          where.isEmpty() ? what : FinbookFile::tr("%1: %2").arg(where, what)};
    }

    // The next `n` bytes, or a Truncated failure naming `what` was cut off.
    const char *take(std::size_t n, const char *what)
    {
        if (n > remaining() && !m_endIsFileEnd)
            fail(FileErrorCode::BadValue,
                 FinbookFile::tr("%1 runs past the end of its record (%2 bytes needed, %3 left), "
                                 "so a length in the file is wrong")
                     .arg(FinbookFile::tr(what))
                     .arg(n)
                     .arg(remaining()));
        if (n > remaining())
            fail(FileErrorCode::Truncated,
                 FinbookFile::tr("the file ends inside %1 (%2 bytes needed, %3 left)")
                     .arg(FinbookFile::tr(what))
                     .arg(n)
                     .arg(remaining()));
        const char *p = m_p;
        m_p += n;
        return p;
    }

    // A count of records of at least `recordBytes` each; refused before any allocation when
    // they cannot fit in what is left of the enclosing record or section.
    quint32 count(std::size_t recordBytes, const char *what)
    {
        const quint32 n = u32(what);
        if (quint64(n) * recordBytes > remaining())
            fail(FileErrorCode::TooLarge,
                 FinbookFile::tr("%1 claims %2 entries but only %3 bytes remain")
                     .arg(FinbookFile::tr(what))
                     .arg(n)
                     .arg(remaining()));
        return n;
    }

    // A sub-cursor over a length-prefixed record, advancing this one past it.
    Cursor record(std::size_t length, const char *what)
    {
        const char *begin = take(length, what);
        return Cursor(begin, begin + length, m_where, m_endIsFileEnd && begin + length == m_end);
    }

    quint8 u8(const char *what) { return quint8(*take(1, what)); }
    quint16 u16(const char *what) { return qFromLittleEndian<quint16>(take(2, what)); }
    quint32 u32(const char *what) { return qFromLittleEndian<quint32>(take(4, what)); }
    qint32 i32(const char *what) { return qFromLittleEndian<qint32>(take(4, what)); }
    quint64 u64(const char *what) { return qFromLittleEndian<quint64>(take(8, what)); }
    float f32(const char *what) { return std::bit_cast<float>(u32(what)); }
    double f64(const char *what) { return std::bit_cast<double>(u64(what)); }

    // Records end exactly where their length says: leftovers mean the length lies.
    void expectEnd(const char *what) const
    {
        if (!atEnd())
            fail(FileErrorCode::BadValue, FinbookFile::tr("%1 has %2 unexpected bytes at its end")
                                              .arg(FinbookFile::tr(what))
                                              .arg(remaining()));
    }

private:
    const char *m_p;
    const char *m_end;
    const Where *m_where;
    bool m_endIsFileEnd;
};

} // namespace finbook::model::file_format
