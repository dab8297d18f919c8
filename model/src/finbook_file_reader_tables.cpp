// The shared tables of a .finbook file: stroke data and deformed poses. Their points are
// nearly all of a file, so this is the hot loop of opening one.
#include "finbook_file_reader.h"

namespace finbook::model::file_format {

void Reader::readPoints(Cursor &c, std::vector<StrokePoint> &points, Deferred &deferred,
                        quint32 entry)
{
    const quint32 n = c.count(kPointBytes, QT_TRANSLATE_NOOP("FinbookFile", "a stroke"));
    const char *in =
        c.take(std::size_t(n) * kPointBytes, QT_TRANSLATE_NOOP("FinbookFile", "a stroke"));
    points.resize(n);
    bool finite = true;
    for (StrokePoint &p : points) {
        const quint32 x = qFromLittleEndian<quint32>(in);
        const quint32 y = qFromLittleEndian<quint32>(in + 4);
        finite &= isFiniteBits(x) & isFiniteBits(y);
        p.x = std::bit_cast<float>(x);
        p.y = std::bit_cast<float>(y);
        p.pressure = dequantisePressure(qFromLittleEndian<quint16>(in + 8));
        in += kPointBytes;
    }
    if (finite)
        return;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y)) {
            deferred.note(entry, tr("point %1 has a non-finite coordinate").arg(i + 1));
            return;
        }
    }
}

void Reader::readStrokeTable(Cursor &c)
{
    const quint32 n =
        c.count(kStrokeDataHeaderBytes, QT_TRANSLATE_NOOP("FinbookFile", "the stroke table"));
    m_strokeData.reserve(n);
    for (quint32 i = 0; i < n; ++i) {
        m_where.strokeData = int(i + 1);
        auto data = std::make_shared<StrokeData>();
        data->color = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a stroke colour"));
        data->width = c.f32(QT_TRANSLATE_NOOP("FinbookFile", "a stroke width"));
        if (!(std::isfinite(data->width) && data->width > 0.0f))
            m_badStrokeData.note(i, tr("the width %1 is not a positive number").arg(data->width));
        readPoints(c, data->points, m_badStrokeData, i);
        m_strokeData.push_back(std::move(data));
    }
    m_where.strokeData = 0;
}

void Reader::readPoseTable(Cursor &c)
{
    const quint32 n = c.count(4, QT_TRANSLATE_NOOP("FinbookFile", "the pose table"));
    m_poses.reserve(n);
    for (quint32 i = 0; i < n; ++i) {
        m_where.pose = int(i + 1);
        auto pose = std::make_shared<DeformedStrokes>();
        pose->strokes.resize(c.count(4, QT_TRANSLATE_NOOP("FinbookFile", "a pose")));
        for (auto &points : pose->strokes)
            readPoints(c, points, m_badPose, i);
        m_poses.push_back(std::move(pose));
    }
    m_where.pose = 0;
}

} // namespace finbook::model::file_format
