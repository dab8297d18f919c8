// Writing and reading the reference layer's "refr" section. Reading trusts nothing: the kind
// and flags must be known, every number finite and in range (referenceValuesValid), the name
// and the media bytes no longer than what is left, and the bytes are charged against the
// file's memory budget before they are copied. Recovering, a bad section is left out (the
// drawing opens without its reference) with a note.
#include "reference_section.h"

#include "../finbook_file_byte_writer.h"
#include "../finbook_file_reader.h"

namespace finbook::model::file_format {

std::vector<AncillarySection> referenceSections(const Reference &r)
{
    const QByteArray name = r.name.toUtf8().left(qsizetype(kMaxNameBytes));
    ByteWriter w(qsizetype(kReferenceFixedBytes) + name.size() + r.bytes.size());
    // A sequence is written as its first picture, which is what a reader without rseq shows.
    const bool sequence = r.kind == ReferenceKind::Sequence;
    w.u8(quint8(sequence ? ReferenceKind::Image : r.kind));
    w.u8((r.visible ? kFlagVisible : 0) | (r.locked ? kFlagLocked : 0));
    for (double v : {r.mediaSize.width(), r.mediaSize.height(), r.center.x(), r.center.y(), r.scale,
                     r.rotation, r.opacity, r.rate})
        w.f64(v);
    w.u32(quint32(name.size()));
    w.raw(name.constData(), std::size_t(name.size()));
    w.u64(quint64(r.bytes.size()));
    w.raw(r.bytes.constData(), std::size_t(r.bytes.size()));
    std::vector<AncillarySection> sections;
    sections.push_back({{'r', 'e', 'f', 'r', '\0'}, w.take()});
    if (sequence && r.pictures.size() > 1) {
        qsizetype size = 4;
        for (qsizetype i = 1; i < r.pictures.size(); ++i)
            size += 8 + r.pictures[i].size();
        ByteWriter more(size);
        more.u32(quint32(r.pictures.size() - 1));
        for (qsizetype i = 1; i < r.pictures.size(); ++i) {
            more.u64(quint64(r.pictures[i].size()));
            more.raw(r.pictures[i].constData(), std::size_t(r.pictures[i].size()));
        }
        sections.push_back({{'r', 's', 'e', 'q', '\0'}, more.take()});
    }
    return sections;
}

void Reader::readReferenceSection(Cursor &c)
{
    m_where = Where();
    m_where.section = FinbookFile::tr("the reference layer");
    try {
        const char *what = QT_TRANSLATE_NOOP("FinbookFile", "the reference layer");
        if (!m_doc.reference.isEmpty())
            c.fail(FileErrorCode::BadValue, FinbookFile::tr("the section is repeated"));
        Reference r;
        const quint8 kind = c.u8(what);
        if (kind != quint8(ReferenceKind::Image) && kind != quint8(ReferenceKind::Video))
            c.fail(FileErrorCode::BadValue,
                   FinbookFile::tr("the reference is of an unknown kind (%1)").arg(kind));
        r.kind = ReferenceKind(kind);
        const quint8 flags = c.u8(what);
        if (flags & ~kKnownFlags)
            c.fail(FileErrorCode::BadValue, FinbookFile::tr("the reference has unknown flags"));
        r.visible = flags & kFlagVisible;
        r.locked = flags & kFlagLocked;
        const double width = c.f64(what);
        const double height = c.f64(what);
        r.mediaSize = QSizeF(width, height);
        const double x = c.f64(what);
        const double y = c.f64(what);
        r.center = QPointF(x, y);
        r.scale = c.f64(what);
        r.rotation = c.f64(what);
        r.opacity = c.f64(what);
        r.rate = c.f64(what);
        if (!referenceValuesValid(r))
            c.fail(FileErrorCode::BadValue,
                   FinbookFile::tr("the reference's place, scale, rotation, opacity or rate "
                                   "is not a number or out of range"));
        const quint32 nameBytes = c.count(1, what);
        if (nameBytes > kMaxNameBytes)
            c.fail(FileErrorCode::TooLarge, FinbookFile::tr("the reference's name is too long"));
        r.name = QString::fromUtf8(c.take(nameBytes, what), qsizetype(nameBytes));
        const quint64 mediaBytes = c.u64(what);
        if (mediaBytes == 0 || mediaBytes > quint64(kMaxReferenceBytes) ||
            mediaBytes > c.remaining())
            c.fail(FileErrorCode::Truncated,
                   FinbookFile::tr("the reference claims %1 bytes but only %2 remain")
                       .arg(mediaBytes)
                       .arg(c.remaining()));
        const char *media = c.take(std::size_t(mediaBytes), what);
        c.expectEnd(what);
        if (m_mode != ParseMode::Check) {
            charge(c, qint64(mediaBytes));
            r.bytes = QByteArray(media, qsizetype(mediaBytes));
            m_doc.reference = std::move(r);
        }
    } catch (const ReadFailure &failure) {
        if (!recovering())
            throw;
        m_problems << FinbookFile::tr("the reference layer is left out: %1").arg(failure.what);
    }
}

void Reader::readReferenceSequenceSection(Cursor &c)
{
    m_where = Where();
    m_where.section = FinbookFile::tr("the reference's picture sequence");
    try {
        const char *what = QT_TRANSLATE_NOOP("FinbookFile", "the reference's picture sequence");
        Reference &r = m_doc.reference;
        if (m_mode != ParseMode::Check && r.kind != ReferenceKind::Image)
            c.fail(FileErrorCode::BadValue,
                   FinbookFile::tr("it does not follow a reference picture, or is repeated"));
        const quint32 count = c.count(8, what);
        if (count == 0 || qsizetype(count) >= kMaxReferencePictures)
            c.fail(FileErrorCode::TooLarge, FinbookFile::tr("it claims %1 pictures").arg(count));
        QList<QByteArray> pictures;
        quint64 total = quint64(r.bytes.size());
        for (quint32 i = 0; i < count; ++i) {
            const quint64 bytes = c.u64(what);
            total += bytes;
            if (bytes == 0 || bytes > c.remaining() || total > quint64(kMaxReferenceBytes))
                c.fail(FileErrorCode::Truncated,
                       FinbookFile::tr("picture %1 claims %2 bytes but only %3 remain")
                           .arg(i + 2)
                           .arg(bytes)
                           .arg(c.remaining()));
            const char *data = c.take(std::size_t(bytes), what);
            if (m_mode != ParseMode::Check) {
                charge(c, qint64(bytes));
                pictures << QByteArray(data, qsizetype(bytes));
            }
        }
        c.expectEnd(what);
        if (m_mode != ParseMode::Check) {
            pictures.prepend(r.bytes);
            r.pictures = std::move(pictures);
            r.kind = ReferenceKind::Sequence;
        }
    } catch (const ReadFailure &failure) {
        if (!recovering())
            throw;
        m_problems << FinbookFile::tr("the reference's further pictures are left out: %1")
                          .arg(failure.what);
    }
}

} // namespace finbook::model::file_format
