// Writing and reading the reference layer's "refr" section. Reading trusts nothing: the kind
// and flags must be known, every number finite and in range (referenceValuesValid), the name
// and the media bytes no longer than what is left, and the bytes are charged against the
// file's memory budget before they are copied. Recovering, a bad section is left out (the
// drawing opens without its reference) with a note.
#include "reference_section.h"

#include "../finbook_file_byte_writer.h"
#include "../finbook_file_reader.h"

namespace finbook::model::file_format {

AncillarySection referenceSection(const Reference &r)
{
    const QByteArray name = r.name.toUtf8().left(qsizetype(kMaxNameBytes));
    ByteWriter w(qsizetype(kReferenceFixedBytes) + name.size() + r.bytes.size());
    w.u8(quint8(r.kind));
    w.u8((r.visible ? kFlagVisible : 0) | (r.locked ? kFlagLocked : 0));
    for (double v : {r.mediaSize.width(), r.mediaSize.height(), r.center.x(), r.center.y(), r.scale,
                     r.rotation, r.opacity, r.rate})
        w.f64(v);
    w.u32(quint32(name.size()));
    w.raw(name.constData(), std::size_t(name.size()));
    w.u64(quint64(r.bytes.size()));
    w.raw(r.bytes.constData(), std::size_t(r.bytes.size()));
    return {{'r', 'e', 'f', 'r', '\0'}, w.take()};
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

} // namespace finbook::model::file_format
