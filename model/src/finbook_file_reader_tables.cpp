// The shared tables of a .finbook file: stroke data and deformed poses. Their points are
// nearly all of a file, so this is the hot loop of opening one.
#include "finbook_file_reader.h"

namespace finbook::model::file_format {

namespace {
// The index of the first point with a NaN or infinite coordinate, or -1.
qint64 firstNonFinite(const char *in, quint32 n)
{
    for (quint32 i = 0; i < n; ++i, in += kPointBytes)
        if (!isFiniteBits(qFromLittleEndian<quint32>(in)) ||
            !isFiniteBits(qFromLittleEndian<quint32>(in + 4)))
            return i;
    return -1;
}
} // namespace

quint32 Reader::readPoints(Cursor &c, std::vector<StrokePoint> &points, Deferred &deferred,
                           quint32 entry)
{
    const quint32 n = c.count(kPointBytes, QT_TRANSLATE_NOOP("FinbookFile", "a stroke"));
    const char *in =
        c.take(std::size_t(n) * kPointBytes, QT_TRANSLATE_NOOP("FinbookFile", "a stroke"));
    if (const qint64 bad = firstNonFinite(in, n); bad >= 0)
        deferred.note(entry, FinbookFile::tr("point %1 has a non-finite coordinate").arg(bad + 1));
    if (m_mode == ParseMode::Check)
        return n;
    points.resize(n);
    for (StrokePoint &p : points) {
        p.x = std::bit_cast<float>(qFromLittleEndian<quint32>(in));
        p.y = std::bit_cast<float>(qFromLittleEndian<quint32>(in + 4));
        p.pressure = dequantisePressure(qFromLittleEndian<quint16>(in + 8));
        in += kPointBytes;
    }
    return n;
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
            m_badStrokeData.note(
                i, FinbookFile::tr("the width %1 is not a positive number").arg(data->width));
        m_strokeDataSizes.push_back(readPoints(c, data->points, m_badStrokeData, i));
        m_strokeData.push_back(std::move(data));
    }
    m_where.strokeData = 0;
}

void Reader::readPoseTable(Cursor &c)
{
    const quint32 n = c.count(4, QT_TRANSLATE_NOOP("FinbookFile", "the pose table"));
    m_poses.reserve(n);
    m_poseSizes.reserve(n);
    for (quint32 i = 0; i < n; ++i) {
        m_where.pose = int(i + 1);
        auto pose = std::make_shared<DeformedStrokes>();
        pose->strokes.resize(c.count(4, QT_TRANSLATE_NOOP("FinbookFile", "a pose")));
        std::vector<quint32> &sizes = m_poseSizes.emplace_back();
        for (auto &points : pose->strokes)
            sizes.push_back(readPoints(c, points, m_badPose, i));
        m_poses.push_back(std::move(pose));
    }
    m_where.pose = 0;
}

} // namespace finbook::model::file_format
