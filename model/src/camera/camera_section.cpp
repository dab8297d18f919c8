// Reading the "CAMR" section: the camera's keys (layout in finbook_file_format.h). The count
// is checked against the section's bytes before anything is allocated. Opening anyway, a key
// that is out of range or out of order is left out and the others kept.
#include "../finbook_file_reader.h"

#include <cmath>

namespace finbook::model::file_format {

void Reader::readCameraSection(Cursor &body)
{
    m_where = Where();
    m_where.section = FinbookFile::tr("the camera");
    try {
        const char *what = QT_TRANSLATE_NOOP("FinbookFile", "the camera");
        const quint32 n = count(body, kCameraKeyBytes, what);
        if (n > quint32(kMaxCameraKeys))
            body.fail(
                FileErrorCode::TooLarge,
                FinbookFile::tr("the camera has %1 keys (at most %2)").arg(n).arg(kMaxCameraKeys));
        charge(body, qint64(n) * qint64(sizeof(CameraKey)));
        CameraTrack track;
        track.keys.reserve(n);
        for (quint32 i = 0; i < n; ++i) {
            CameraKey k;
            k.tick = qint64(body.u64(what));
            const double cx = body.f64(what), cy = body.f64(what);
            k.center = QPointF(cx, cy);
            k.zoom = body.f64(what);
            k.rotation = body.f64(what);
            const quint8 easing = body.u8(what);
            k.easing = CameraEasing(easing);
            const double c1x = body.f64(what), c1y = body.f64(what);
            const double c2x = body.f64(what), c2y = body.f64(what);
            k.control1 = QPointF(c1x, c1y);
            k.control2 = QPointF(c2x, c2y);
            CameraTrack alone{{k}};
            if (easing >= kCameraEasingCount || !isValidCameraTrack(alone)) {
                problem(body, FileErrorCode::BadValue,
                        FinbookFile::tr("camera key %1 holds a value out of range; it is left out")
                            .arg(i + 1));
                continue;
            }
            if (!track.keys.empty() && k.tick <= track.keys.back().tick) {
                problem(body, FileErrorCode::BadValue,
                        FinbookFile::tr("camera key %1 is not after the key before it; it is "
                                        "left out")
                            .arg(i + 1));
                continue;
            }
            track.keys.push_back(k);
        }
        body.expectEnd(what);
        if (m_mode != ParseMode::Check)
            m_doc.camera = std::move(track);
    } catch (const ReadFailure &failure) {
        if (!recovering())
            throw;
        m_problems << FinbookFile::tr("%1; the camera is left out").arg(failure.what);
    }
}

} // namespace finbook::model::file_format
