// Reading a "SOND" section: one clip of the soundtrack (layout in finbook_file_format.h).
// The encoded bytes are taken as they are (decoding is the player's business, and a clip that
// does not decode stays in the file untouched); the byte count is checked against the
// section's bytes before anything is copied, and counted against the load budget.
#include "../finbook_file_reader.h"

#include <QStringDecoder>

#include <algorithm>
#include <cmath>

namespace finbook::model::file_format {

void Reader::readSoundSection(Cursor &body)
{
    m_where = Where();
    m_where.section = FinbookFile::tr("sound clip %1").arg(m_doc.sound.size() + 1);
    try {
        readSoundClip(body);
        body.expectEnd(QT_TRANSLATE_NOOP("FinbookFile", "the sound clip"));
    } catch (const ReadFailure &failure) {
        if (!recovering())
            throw;
        m_problems << FinbookFile::tr("%1; the sound clip is left out").arg(failure.what);
    }
}

void Reader::readSoundClip(Cursor &c)
{
    if (m_doc.sound.size() >= std::size_t(kMaxSoundClips))
        c.fail(FileErrorCode::TooLarge,
               FinbookFile::tr("the file holds more than %1 sound clips").arg(kMaxSoundClips));
    SoundClip clip;
    const char *what = QT_TRANSLATE_NOOP("FinbookFile", "the sound clip");
    clip.id = c.u64(what);
    const qint64 start = qint64(c.u64(what));
    if (start < 0 || start > kMaxSoundStart)
        problem(c, FileErrorCode::BadValue,
                FinbookFile::tr("the sound starts at %1, outside 0 to %2")
                    .arg(start)
                    .arg(kMaxSoundStart));
    clip.start = std::clamp<qint64>(start, 0, kMaxSoundStart);
    clip.volume = c.f64(what);
    if (!(clip.volume >= 0.0 && clip.volume <= kMaxSoundVolume)) { // also NaN
        problem(c, FileErrorCode::BadValue,
                FinbookFile::tr("the sound's volume %1 is outside 0 to %2")
                    .arg(clip.volume)
                    .arg(kMaxSoundVolume));
        clip.volume = 1.0;
    }
    const quint8 flags = c.u8(what);
    if (flags & ~kSoundFlagMuted)
        problem(c, FileErrorCode::BadValue,
                FinbookFile::tr("the sound flags 0x%1 are unknown").arg(flags, 0, 16));
    clip.muted = flags & kSoundFlagMuted;
    const quint32 nameBytes = c.u32(what);
    if (nameBytes > quint32(kMaxSoundNameBytes))
        c.fail(FileErrorCode::TooLarge, FinbookFile::tr("the sound's name is %1 bytes long (at "
                                                        "most %2)")
                                            .arg(nameBytes)
                                            .arg(kMaxSoundNameBytes));
    const char *name = c.take(nameBytes, what);
    QStringDecoder utf8(QStringConverter::Utf8, QStringConverter::Flag::ConvertInitialBom |
                                                    QStringConverter::Flag::Stateless);
    clip.name = utf8(QByteArrayView(name, nameBytes));
    if (utf8.hasError())
        problem(c, FileErrorCode::BadValue,
                FinbookFile::tr("the sound's name is not valid UTF-8 text"));
    const quint64 dataBytes = c.u64(what);
    // A clip larger than the bytes left, or than any clip may be, is refused before copying.
    if (dataBytes > quint64(kMaxSoundClipBytes))
        c.fail(FileErrorCode::TooLarge, FinbookFile::tr("the sound is %1 MB long (at most %2 MB)")
                                            .arg(dataBytes >> 20)
                                            .arg(kMaxSoundClipBytes >> 20));
    if (dataBytes == 0)
        problem(c, FileErrorCode::BadValue, FinbookFile::tr("the sound clip holds no sound"));
    const char *data = c.take(std::size_t(dataBytes), what);
    charge(c, qint64(dataBytes) + 2 * qint64(nameBytes) + 64);
    claimId(c, clip.id, FinbookFile::tr("the sound clip"));
    if (m_mode == ParseMode::Check || dataBytes == 0)
        return;
    clip.bytes = QByteArray(data, qsizetype(dataBytes));
    m_doc.sound.push_back(std::move(clip));
}

} // namespace finbook::model::file_format
