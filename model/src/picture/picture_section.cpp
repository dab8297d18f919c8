// Writing and reading picture objects: the "PICT" section and the "PICO" object chunk
// (picture_section.h). Reading trusts nothing: counts are bounded by the bytes left, the
// pixels are charged against the file's memory budget and the pictures' own limit before they
// are decoded, the PNG must decode to the size it claims, and a texture mesh must index its own
// vertices with triangles of positive area. Recovering, a picture that does not read is left
// out (its objects keep their strokes) with a note.
#include "picture_section.h"

#include "../finbook_file_reader.h"
#include "picture_decode.h"

#include <QBuffer>
#include <QImageReader>

#include <cmath>
#include <unordered_map>

namespace finbook::model::file_format {

void PictureTable::add(const StrokeGroup &group)
{
    if (!hasPictureChunk(group))
        return;
    const ObjectPicture &p = *group.picture;
    if (m_index.try_emplace(Key(p.data.get(), p.mesh.get()), quint32(m_entries.size())).second)
        m_entries.push_back(&p);
}

quint32 PictureTable::indexOf(const ObjectPicture &picture) const
{
    return m_index.at(Key(picture.data.get(), picture.mesh.get()));
}

qsizetype PictureTable::expectedBytes() const
{
    qsizetype bytes = 4;
    for (const ObjectPicture *p : m_entries)
        bytes += qsizetype(kPictureFixedBytes) + p->data->png.size() +
                 qsizetype(p->mesh->uv.rows() * kPictureVertexBytes +
                           p->mesh->F.rows() * kPictureTriangleBytes);
    return bytes;
}

void PictureTable::write(ByteWriter &w) const
{
    w.u32(quint32(m_entries.size()));
    for (const ObjectPicture *p : m_entries) {
        w.u32(quint32(p->data->image.width()));
        w.u32(quint32(p->data->image.height()));
        w.u64(quint64(p->data->png.size()));
        w.raw(p->data->png.constData(), std::size_t(p->data->png.size()));
        const PictureMesh &m = *p->mesh;
        w.u32(quint32(m.uv.rows()));
        for (Eigen::Index i = 0; i < m.uv.rows(); ++i) {
            w.f64(m.uv(i, 0));
            w.f64(m.uv(i, 1));
        }
        w.u32(quint32(m.F.rows()));
        for (Eigen::Index f = 0; f < m.F.rows(); ++f)
            for (int k = 0; k < 3; ++k)
                w.u32(quint32(m.F(f, k)));
    }
}

bool hasPictureChunk(const StrokeGroup &group)
{
    return group.picture && pictureIsValid(*group.picture) && !group.picture->data->png.isEmpty();
}

void writePictureChunk(ByteWriter &w, const StrokeGroup &group, const PictureTable &table,
                       bool posed)
{
    const ObjectPicture &p = *group.picture;
    w.u32(table.indexOf(p));
    for (const double v :
         {p.place.m11(), p.place.m12(), p.place.m21(), p.place.m22(), p.place.dx(), p.place.dy()})
        w.f64(v);
    const std::size_t n = std::size_t(p.mesh->uv.rows());
    const bool withPose = posed && group.deformed && group.deformed->pictureVertices.size() == n;
    w.u32(withPose ? quint32(n) : 0);
    if (withPose)
        for (const QPointF &v : group.deformed->pictureVertices) {
            w.f64(v.x());
            w.f64(v.y());
        }
}

namespace {

// Far enough for any canvas, near enough that no sum of them overflows.
constexpr double kMaxPicturePlace = 1e7;
// The decoded pixels of all of a document's pictures (PNG packs a flat picture a hundredfold,
// so the file's own memory budget, which follows its size, cannot bound them).
constexpr qint64 kMaxDocumentPictureBytes = 4 * kMaxPictureDecodedBytes;

bool sane(double v)
{
    return std::isfinite(v) && std::abs(v) <= kMaxPicturePlace;
}

} // namespace

void Reader::readPictureSection(Cursor &c)
{
    m_where = Where();
    m_where.section = FinbookFile::tr("the pictures");
    const char *what = QT_TRANSLATE_NOOP("FinbookFile", "the pictures");
    const quint32 n = count(c, kPictureFixedBytes, what);
    // A document may hold several imports' worth of pixels; still a bound, whatever it claims.
    qint64 budget = kMaxDocumentPictureBytes;
    for (quint32 i = 0; i < n; ++i) {
        PictureEntry entry;
        try {
            const quint32 width = c.u32(what), height = c.u32(what);
            const quint64 pngBytes = c.u64(what);
            if (pngBytes > c.remaining())
                c.fail(FileErrorCode::Truncated,
                       FinbookFile::tr("picture %1 is cut off").arg(i + 1));
            const char *png = c.take(std::size_t(pngBytes), what);
            const quint32 vertices = c.count(kPictureVertexBytes, what);
            if (vertices < 3 || vertices > kMaxPictureMeshVertices)
                c.fail(
                    FileErrorCode::BadValue,
                    FinbookFile::tr("picture %1's mesh has %2 vertices").arg(i + 1).arg(vertices));
            charge(c, qint64(vertices) * 16);
            auto mesh = std::make_shared<PictureMesh>();
            mesh->uv.resize(vertices, 2);
            for (quint32 v = 0; v < vertices; ++v) {
                const double u = c.f64(what), t = c.f64(what);
                if (!std::isfinite(u) || !std::isfinite(t) || u < -1.0 || t < -1.0 ||
                    u > double(width) + 1.0 || t > double(height) + 1.0)
                    c.fail(FileErrorCode::BadValue,
                           FinbookFile::tr("picture %1's mesh has a vertex outside the picture")
                               .arg(i + 1));
                mesh->uv.row(v) << u, t;
            }
            const quint32 triangles = c.count(kPictureTriangleBytes, what);
            if (triangles == 0)
                c.fail(FileErrorCode::BadValue,
                       FinbookFile::tr("picture %1's mesh has no triangles").arg(i + 1));
            charge(c, qint64(triangles) * 12);
            mesh->F.resize(triangles, 3);
            for (quint32 f = 0; f < triangles; ++f) {
                for (int k = 0; k < 3; ++k) {
                    const quint32 index = c.u32(what);
                    if (index >= vertices)
                        c.fail(FileErrorCode::BadValue,
                               FinbookFile::tr("picture %1's mesh names a vertex it does not have")
                                   .arg(i + 1));
                    mesh->F(f, k) = int(index);
                }
                const Eigen::RowVector2d a = mesh->uv.row(mesh->F(f, 0)),
                                         b = mesh->uv.row(mesh->F(f, 1)),
                                         d = mesh->uv.row(mesh->F(f, 2));
                if (!((b - a).x() * (d - a).y() - (b - a).y() * (d - a).x() > 0.0))
                    c.fail(FileErrorCode::BadValue,
                           FinbookFile::tr("picture %1's mesh has a triangle turned over or "
                                           "without area")
                               .arg(i + 1));
            }
            // The pixels: within the pictures' own limits and the file's budget before any is
            // decoded; the PNG must be the size the entry says.
            const QSize claimed(int(std::min<quint32>(width, 1u << 30)),
                                int(std::min<quint32>(height, 1u << 30)));
            const QString tooLarge = picture_detail::sizeRefusal(claimed, budget);
            if (width == 0 || height == 0 || !tooLarge.isEmpty())
                c.fail(FileErrorCode::TooLarge, FinbookFile::tr("picture %1 is %2 × %3 pixels: %4")
                                                    .arg(i + 1)
                                                    .arg(width)
                                                    .arg(height)
                                                    .arg(tooLarge));
            auto data = std::make_shared<PictureData>();
            data->png = QByteArray(png, qsizetype(pngBytes));
            if (m_mode == ParseMode::Check) {
                // Saving checks its own output: the PNG it just wrote, of pixels it had, need
                // not be decoded again; its header must still say the size the entry says.
                QBuffer buffer(&data->png);
                QImageReader header(&buffer, "png");
                if (header.size() != QSize(int(width), int(height)))
                    c.fail(FileErrorCode::BadValue,
                           FinbookFile::tr("picture %1 does not decode: %2")
                               .arg(i + 1)
                               .arg(header.errorString()));
                entry.data = std::move(data);
                entry.mesh = std::move(mesh);
                m_pictureTable.push_back(std::move(entry));
                continue;
            }
            auto image = picture_detail::decodePicture(data->png, &budget, false);
            if (!image)
                c.fail(FileErrorCode::Damaged, FinbookFile::tr("picture %1 does not decode: %2")
                                                   .arg(i + 1)
                                                   .arg(image.error()));
            if (image->width() != int(width) || image->height() != int(height))
                c.fail(FileErrorCode::BadValue,
                       FinbookFile::tr("picture %1 is %2 × %3 pixels, not the %4 × %5 it claims")
                           .arg(i + 1)
                           .arg(image->width())
                           .arg(image->height())
                           .arg(width)
                           .arg(height));
            data->image = std::move(*image);
            entry.data = std::move(data);
            entry.mesh = std::move(mesh);
        } catch (const ReadFailure &failure) {
            if (!recovering())
                throw;
            m_problems << FinbookFile::tr("%1; the objects showing it are left without it")
                              .arg(failure.what);
            // What follows this entry cannot be found again: the rest are left out too.
            m_pictureTable.resize(n);
            return;
        }
        m_pictureTable.push_back(std::move(entry));
    }
}

void Reader::readPictureChunk(Cursor &c, StrokeGroup &g)
{
    const char *what = QT_TRANSLATE_NOOP("FinbookFile", "the object's picture");
    PendingPicture pending;
    pending.index = c.u32(what);
    double m[6];
    for (double &v : m)
        v = c.f64(what);
    const QTransform place(m[0], m[1], m[2], m[3], m[4], m[5]);
    if (!validPicturePlace(place))
        c.fail(FileErrorCode::BadValue, FinbookFile::tr("the picture's place is out of range"));
    const quint32 posed = c.count(kPictureVertexBytes, what);
    charge(c, qint64(posed) * qint64(sizeof(QPointF)));
    pending.posed.reserve(posed);
    for (quint32 i = 0; i < posed; ++i) {
        const double px = c.f64(what), py = c.f64(what);
        if (!sane(px) || !sane(py))
            c.fail(FileErrorCode::BadValue,
                   FinbookFile::tr("the picture's pose has a point out of range"));
        pending.posed.emplace_back(px, py);
    }
    auto picture = std::make_shared<ObjectPicture>();
    picture->place = place;
    pending.picture = picture;
    g.picture = std::move(picture);
    m_pendingPictures.push_back(std::move(pending));
}

void Reader::resolvePictures(Cursor &c)
{
    if (m_pendingPictures.empty())
        return;
    m_where = Where();
    m_where.section = FinbookFile::tr("the pictures");
    std::unordered_map<const ObjectPicture *, const PendingPicture *> pending;
    for (const PendingPicture &p : m_pendingPictures) {
        if (p.index < m_pictureTable.size() && m_pictureTable[p.index].data) {
            p.picture->data = m_pictureTable[p.index].data;
            p.picture->mesh = m_pictureTable[p.index].mesh;
        } else {
            problem(c, FileErrorCode::BadValue,
                    FinbookFile::tr("an object shows picture %1, which the file does not hold")
                        .arg(p.index + 1));
        }
        pending.emplace(p.picture.get(), &p);
    }
    // Objects sharing a pose share its copy with the picture's vertices too, so that the file
    // saves again as it was.
    std::map<const DeformedStrokes *,
             std::vector<std::pair<const std::vector<QPointF> *, DeformedStrokesPtr>>>
        copies;
    const auto resolve = [&](StrokeGroup &g) {
        if (!g.picture)
            return;
        const auto it = pending.find(g.picture.get());
        if (it == pending.end())
            return;
        const PendingPicture &p = *it->second;
        if (!p.picture->data) { // recovering: the picture is gone, the object stays
            g.picture = nullptr;
            return;
        }
        if (p.posed.empty())
            return;
        if (!g.deformed || p.posed.size() != std::size_t(p.picture->mesh->uv.rows())) {
            problem(c, FileErrorCode::BadValue,
                    FinbookFile::tr("a picture's pose does not fit its mesh; it is shown at rest"));
            return;
        }
        for (const auto &[vertices, copy] : copies[g.deformed.get()])
            if (*vertices == p.posed) {
                g.deformed = copy;
                return;
            }
        auto withPicture = std::make_shared<DeformedStrokes>(*g.deformed);
        withPicture->pictureVertices = p.posed;
        copies[g.deformed.get()].emplace_back(&p.posed, withPicture);
        g.deformed = std::move(withPicture);
    };
    for (Frame &f : m_doc.frames)
        for (StrokeGroup &g : f.groups)
            resolve(g);
    std::vector<PendingPicture>().swap(m_pendingPictures);
}

} // namespace finbook::model::file_format
