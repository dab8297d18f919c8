// The shared tables of a .finbook file: stroke data and deformed poses. Their points are
// nearly all of a file, so this is the hot loop of opening one.
#include "finbook_file_reader.h"

namespace finbook::model::file_format {

namespace {
// What one shared table entry costs besides its points: the make_shared block (control block
// and object, rounded up by malloc) and the table's pointer to it.
constexpr qint64 kSharedEntryBytes = 96;

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
    const quint32 n = count(c, kPointBytes, QT_TRANSLATE_NOOP("FinbookFile", "a stroke"));
    const char *in =
        c.take(std::size_t(n) * kPointBytes, QT_TRANSLATE_NOOP("FinbookFile", "a stroke"));
    const qint64 bad = firstNonFinite(in, n);
    const bool dropBad = bad >= 0 && recovering();
    if (bad >= 0 && !recovering())
        deferred.note(entry, FinbookFile::tr("point %1 has a non-finite coordinate").arg(bad + 1));
    if (m_mode == ParseMode::Check)
        return n;
    charge(c, qint64(n) * qint64(sizeof(StrokePoint)));
    points.resize(n);
    StrokePoint *out = points.data();
    for (quint32 i = 0; i < n; ++i, in += kPointBytes) {
        const quint32 x = qFromLittleEndian<quint32>(in), y = qFromLittleEndian<quint32>(in + 4);
        if (dropBad && (!isFiniteBits(x) || !isFiniteBits(y)))
            continue; // recovering: a point that is not a number is left out
        *out++ = {std::bit_cast<float>(x), std::bit_cast<float>(y),
                  dequantisePressure(qFromLittleEndian<quint16>(in + 8))};
    }
    if (dropBad) {
        points.resize(std::size_t(out - points.data()));
        problem(c, FileErrorCode::BadValue,
                FinbookFile::tr("%n point(s) with a non-finite coordinate are left out", nullptr,
                                int(n - points.size())));
    }
    return quint32(points.size());
}

void Reader::readStrokeTable(Cursor &c)
{
    const quint32 n =
        count(c, kStrokeDataHeaderBytes, QT_TRANSLATE_NOOP("FinbookFile", "the stroke table"));
    charge(c, qint64(n) * (kSharedEntryBytes + 4));
    m_strokeData.reserve(n);
    m_strokeDataSizes.reserve(n);
    for (quint32 i = 0; i < n; ++i) {
        m_where.strokeData = int(i + 1);
        readStrokeEntry(c, i);
    }
    m_where.strokeData = 0;
}

void Reader::readStrokeEntry(Cursor &c, quint32 index)
{
    auto data = std::make_shared<StrokeData>();
    data->color = c.u32(QT_TRANSLATE_NOOP("FinbookFile", "a stroke colour"));
    data->width = c.f32(QT_TRANSLATE_NOOP("FinbookFile", "a stroke width"));
    if (!(data->width > 0.0f && data->width <= kMaxStrokeWidth)) { // also NaN
        const QString what = FinbookFile::tr("the width %1 is not a number above 0 and up to %2")
                                 .arg(data->width)
                                 .arg(kMaxStrokeWidth);
        if (recovering()) {
            problem(c, FileErrorCode::BadValue, what);
            data->width = StrokeData().width;
        } else {
            m_badStrokeData.note(index, what);
        }
    }
    m_strokeDataSizes.push_back(readPoints(c, data->points, m_badStrokeData, index));
    m_strokeData.push_back(std::move(data));
}

void Reader::readPoseTable(Cursor &c)
{
    const quint32 n = count(c, 4, QT_TRANSLATE_NOOP("FinbookFile", "the pose table"));
    charge(c, qint64(n) * (kSharedEntryBytes + qint64(sizeof(std::vector<quint32>))));
    m_poses.reserve(n);
    m_poseSizes.reserve(n);
    for (quint32 i = 0; i < n; ++i) {
        m_where.pose = int(i + 1);
        auto pose = std::make_shared<DeformedStrokes>();
        const quint32 strokes = count(c, 4, QT_TRANSLATE_NOOP("FinbookFile", "a pose"));
        charge(c, qint64(strokes) * qint64(sizeof(std::vector<StrokePoint>) + 4));
        pose->strokes.resize(strokes);
        std::vector<quint32> &sizes = m_poseSizes.emplace_back();
        sizes.reserve(strokes);
        for (auto &points : pose->strokes)
            sizes.push_back(readPoints(c, points, m_badPose, i));
        m_poses.push_back(std::move(pose));
    }
    m_where.pose = 0;
}

} // namespace finbook::model::file_format
