// Picture objects: their data, texture mesh and drawing (picture_object.h).
#include "picture_decode.h"

#include <finbook/geometry/object_mesh.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/picture/picture_shape.h>
#include <finbook/model/picture/textured_mesh.h>
#include <finbook/model/render.h>

#include <QBuffer>
#include <QImageWriter>

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace finbook::model {

using picture_detail::pictureTr;

Eigen::MatrixX2d ObjectPicture::restVertices() const
{
    if (!mesh)
        return {};
    const Eigen::MatrixX2d &uv = mesh->uv;
    Eigen::MatrixX2d V(uv.rows(), 2);
    for (Eigen::Index i = 0; i < uv.rows(); ++i) {
        const QPointF p = place.map(QPointF(uv(i, 0), uv(i, 1)));
        V.row(i) << p.x(), p.y();
    }
    return V;
}

QRectF ObjectPicture::restRect() const
{
    if (!data)
        return {};
    return place.mapRect(QRectF(QPointF(0, 0), QSizeF(data->image.size())));
}

Expected<PictureDataPtr, QString> makePictureData(const QImage &image)
{
    if (image.isNull() || image.width() <= 0 || image.height() <= 0)
        return unexpected(pictureTr(QT_TRANSLATE_NOOP("PictureImport", "The picture is empty.")));
    auto data = std::make_shared<PictureData>();
    data->image = image.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    if (data->image.isNull())
        return unexpected(pictureTr(
            QT_TRANSLATE_NOOP("PictureImport", "There is not enough memory for the picture.")));
    QBuffer buffer(&data->png);
    buffer.open(QIODevice::WriteOnly);
    QImageWriter writer(&buffer, "png");
    if (!writer.write(data->image) || data->png.isEmpty())
        return unexpected(
            pictureTr(QT_TRANSLATE_NOOP("PictureImport",
                                        "The picture could not be encoded to be saved: %1"))
                .arg(writer.errorString()));
    return PictureDataPtr(std::move(data));
}

Expected<PictureMeshPtr, QString> meshPicture(const QImage &image, double density)
{
    // The mesh must hold the centre of every pixel that shows (textured_mesh.h): the outline at
    // alpha ≥ 1, simplified by less than the half pixel between such a centre and the outline.
    geometry::AlphaOutlineOptions outline;
    outline.threshold = 1;
    outline.simplify = 0.3; // with the mesher's own 0.1 below: 0.4 < 0.5
    outline.minArea = 0.0;
    const auto shape = pictureShape(image, outline);
    if (!shape)
        return unexpected(pictureTr(QT_TRANSLATE_NOOP("PictureImport",
                                                      "The picture's outline cannot be traced: %1"))
                              .arg(QString::fromStdString(shape.error().message)));
    if (shape->empty())
        return unexpected(pictureTr(QT_TRANSLATE_NOOP(
            "PictureImport", "The picture is fully transparent: nothing of it shows.")));
    geometry::MeshOptions options;
    // About one vertex per 8 × 8 px of picture, at most kPictureMeshVertices: a small picture
    // needs no finer mesh to bend smoothly, and costs less to solve, draw and save.
    options.targetVertices =
        std::clamp(int(geometry::regionArea(*shape) / 64.0), 64, kPictureMeshVertices);
    options.density = std::isfinite(density) && density > 0.0 ? std::min(density, 100.0) : 1.0;
    options.repair.cornerRadius = 0.0; // rounding corners would cut visible pixels off
    options.repair.simplifyTolerance = 0.1;
    auto mesh = geometry::buildObjectMesh(*shape, options);
    if (!mesh)
        return unexpected(pictureTr(QT_TRANSLATE_NOOP("PictureImport",
                                                      "The picture's outline cannot be meshed: %1"))
                              .arg(QString::fromStdString(mesh.error().message)));
    auto out = std::make_shared<PictureMesh>();
    out->F = drawingOrder(mesh->V, mesh->F);
    out->uv = std::move(mesh->V);
    return PictureMeshPtr(std::move(out));
}

namespace {

// `image` as a picture with its texture mesh, its top-left corner at `at`.
Expected<std::shared_ptr<const ObjectPicture>, QString> newPicture(const QImage &image, QPointF at)
{
    auto data = makePictureData(image);
    if (!data)
        return unexpected(data.error());
    auto mesh = meshPicture((*data)->image);
    if (!mesh)
        return unexpected(mesh.error());
    auto picture = std::make_shared<ObjectPicture>();
    picture->data = std::move(*data);
    picture->mesh = std::move(*mesh);
    picture->place = QTransform::fromTranslate(at.x(), at.y());
    return std::shared_ptr<const ObjectPicture>(std::move(picture));
}

} // namespace

Expected<StrokeGroup, QString> makePictureObject(const PictureLayer &layer, QPointF at)
{
    auto picture = newPicture(layer.image, at);
    if (!picture)
        return unexpected(picture.error());
    StrokeGroup group;
    group.name = layer.name;
    group.picture = std::move(*picture);
    return group;
}

Expected<std::vector<StrokeGroup>, QString> pictureObjectsFromFile(const QString &path, QSizeF page)
{
    auto layers = readPictureLayers(path);
    if (!layers)
        return unexpected(layers.error());
    return pictureObjectsFromLayers(*layers, path, page);
}

Expected<std::vector<StrokeGroup>, QString>
pictureObjectsFromLayers(const std::vector<PictureLayer> &layers, const QString &path, QSizeF page)
{
    QRect bounds;
    for (const PictureLayer &layer : layers)
        bounds |= QRect(layer.offset, layer.image.size());
    const QPointF shift =
        QPointF(page.width() / 2.0, page.height() / 2.0) - QRectF(bounds).center();
    // Whole pixels: a picture at rest lands on the page's pixel grid, sharp.
    const QPointF at(std::round(shift.x()), std::round(shift.y()));
    std::vector<StrokeGroup> objects;
    for (const PictureLayer &layer : layers) {
        auto object = makePictureObject(layer, at + QPointF(layer.offset));
        if (!object)
            return unexpected(picture_detail::importRefusal(path, object.error()));
        objects.push_back(std::move(*object));
    }
    return objects;
}

bool validPicturePlace(const QTransform &place)
{
    constexpr double kFar = 1e7;
    const double values[] = {place.m11(), place.m12(), place.m21(),
                             place.m22(), place.dx(),  place.dy()};
    for (double v : values)
        if (!std::isfinite(v) || std::abs(v) > kFar)
            return false;
    return place.isAffine() && std::abs(place.determinant()) >= 1e-6;
}

std::shared_ptr<const ObjectPicture> movedPicture(const ObjectPicture &picture,
                                                  const QTransform &by)
{
    auto moved = std::make_shared<ObjectPicture>(picture);
    moved->place = picture.place * by;
    return moved;
}

bool pictureIsValid(const ObjectPicture &picture)
{
    if (!picture.data || picture.data->image.isNull() || !picture.mesh)
        return false;
    const PictureMesh &m = *picture.mesh;
    return m.F.rows() > 0 && m.uv.rows() >= 3 && m.uv.allFinite() && m.F.minCoeff() >= 0 &&
           m.F.maxCoeff() < m.uv.rows() && validPicturePlace(picture.place);
}

geometry::Region pictureRegion(const ObjectPicture &picture)
{
    if (!pictureIsValid(picture))
        return {};
    auto mesh = geometry::objectMeshFrom(picture.restVertices(), picture.mesh->F);
    return mesh ? std::move(mesh->region) : geometry::Region{};
}

Eigen::MatrixX2d shownPictureVertices(const StrokeGroup &group)
{
    if (!group.picture || !group.picture->mesh)
        return {};
    const Eigen::Index n = group.picture->mesh->uv.rows();
    if (group.isDeformed() && group.deformed->pictureVertices.size() == std::size_t(n)) {
        Eigen::MatrixX2d V(n, 2);
        for (Eigen::Index i = 0; i < n; ++i)
            V.row(i) << group.deformed->pictureVertices[std::size_t(i)].x(),
                group.deformed->pictureVertices[std::size_t(i)].y();
        return V;
    }
    return group.picture->restVertices();
}

ShownPictureMesh shownPictureMesh(const StrokeGroup &group)
{
    ShownPictureMesh shown;
    if (!group.picture || !pictureIsValid(*group.picture))
        return shown;
    const PictureLayers *layers = group.isDeformed() ? &group.deformed->pictureLayers : nullptr;
    if (!layers || layers->isEmpty() || layers->uv.size() != layers->vertices.size()) {
        shown.uv = group.picture->mesh->uv;
        shown.V = shownPictureVertices(group);
        shown.F = group.picture->mesh->F;
        return shown;
    }
    const auto n = Eigen::Index(layers->vertices.size());
    shown.uv.resize(n, 2);
    shown.V.resize(n, 2);
    for (Eigen::Index i = 0; i < n; ++i) {
        shown.uv.row(i) << layers->uv[std::size_t(i)].x(), layers->uv[std::size_t(i)].y();
        shown.V.row(i) << layers->vertices[std::size_t(i)].x(),
            layers->vertices[std::size_t(i)].y();
    }
    shown.F.resize(Eigen::Index(layers->faces.size()), 3);
    for (Eigen::Index f = 0; f < shown.F.rows(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int v = layers->faces[std::size_t(f)][std::size_t(k)];
            if (v < 0 || v >= n)
                return {}; // not drawn rather than drawn wrong
            shown.F(f, k) = v;
        }
    return shown;
}

namespace {

// The bounding box of the vertices (canvas px); empty without any or with a non-finite one.
QRectF boundsOf(const Eigen::MatrixX2d &V)
{
    if (V.rows() == 0 || !V.allFinite())
        return {};
    const Eigen::RowVector2d lo = V.colwise().minCoeff(), hi = V.colwise().maxCoeff();
    return QRectF(QPointF(lo.x(), lo.y()), QPointF(hi.x(), hi.y()));
}

} // namespace

QRectF shownPictureBounds(const StrokeGroup &group)
{
    return boundsOf(shownPictureMesh(group).V);
}

namespace {

// The pictures of `groups` as they show now, drawn in that order (source-over) into one new
// rest picture over `shown` (canvas px, whole pixels), placed where they show.
Expected<std::shared_ptr<const ObjectPicture>, QString>
drawnPicture(std::initializer_list<const StrokeGroup *> groups, const QRectF &shown)
{
    const QPoint topLeft(int(std::floor(shown.left())), int(std::floor(shown.top())));
    const QPoint bottomRight(int(std::ceil(shown.right())), int(std::ceil(shown.bottom())));
    const QSize size(bottomRight.x() - topLeft.x(), bottomRight.y() - topLeft.y());
    if (!shown.isValid() || size.width() <= 0 || size.height() <= 0 ||
        size.width() > kMaxPictureSide || size.height() > kMaxPictureSide)
        return unexpected(
            pictureTr(QT_TRANSLATE_NOOP("PictureImport",
                                        "The posed picture is too large to keep (at most %1 pixels "
                                        "wide and high)."))
                .arg(kMaxPictureSide));
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    if (image.isNull())
        return unexpected(pictureTr(
            QT_TRANSLATE_NOOP("PictureImport", "There is not enough memory for the picture.")));
    image.fill(Qt::transparent);
    for (const StrokeGroup *group : groups)
        drawPicture(image, QTransform::fromTranslate(-topLeft.x(), -topLeft.y()), *group);
    return newPicture(image, QPointF(topLeft));
}

} // namespace

Expected<std::shared_ptr<const ObjectPicture>, QString> bakedPicture(const StrokeGroup &group)
{
    if (!group.picture || !pictureIsValid(*group.picture))
        return unexpected(
            pictureTr(QT_TRANSLATE_NOOP("PictureImport", "The object has no picture.")));
    if (!group.isDeformed() ||
        group.deformed->pictureVertices.size() != std::size_t(group.picture->mesh->uv.rows()))
        return group.picture;
    return drawnPicture({&group}, shownPictureBounds(group));
}

Expected<std::shared_ptr<const ObjectPicture>, QString> stackedPicture(const StrokeGroup &below,
                                                                       const StrokeGroup &above)
{
    const bool hasBelow = below.picture && pictureIsValid(*below.picture);
    const bool hasAbove = above.picture && pictureIsValid(*above.picture);
    if (!hasBelow || !hasAbove) // the one picture there is, the very same when not posed
        return bakedPicture(hasBelow ? below : above);
    return drawnPicture({&below, &above},
                        shownPictureBounds(below).united(shownPictureBounds(above)));
}

bool pictureShowsAt(const StrokeGroup &group, QPointF pos)
{
    const ShownPictureMesh mesh = shownPictureMesh(group); // empty without a valid picture
    if (!boundsOf(mesh.V).contains(pos))
        return false;
    const Eigen::MatrixX2d &V = mesh.V;
    const Eigen::MatrixX3i &F = mesh.F;
    const auto cross = [](double ax, double ay, double bx, double by) { return ax * by - ay * bx; };
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
        const double ax = V(F(f, 0), 0), ay = V(F(f, 0), 1), bx = V(F(f, 1), 0), by = V(F(f, 1), 1),
                     cx = V(F(f, 2), 0), cy = V(F(f, 2), 1);
        const double d1 = cross(bx - ax, by - ay, pos.x() - ax, pos.y() - ay);
        const double d2 = cross(cx - bx, cy - by, pos.x() - bx, pos.y() - by);
        const double d3 = cross(ax - cx, ay - cy, pos.x() - cx, pos.y() - cy);
        // Inside whichever way the posed triangle winds (a fold shows both layers).
        if ((d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0))
            return true;
    }
    return false;
}

bool frameHasPictures(const Frame &frame, const RenderOptions &options)
{
    return std::any_of(frame.groups.begin(), frame.groups.end(), [&](const StrokeGroup &g) {
        return g.picture && (g.visible || options.showHidden);
    });
}

namespace {

// Every pixel of `image` (premultiplied) in `tint` at its own alpha.
void tintPixels(QImage &image, const QColor &tint)
{
    const QRgb colour = tint.rgba();
    for (int y = 0; y < image.height(); ++y) {
        auto *line = reinterpret_cast<QRgb *>(image.scanLine(y));
        for (int x = 0; x < image.width(); ++x) {
            const int a = qAlpha(line[x]) * qAlpha(colour) / 255;
            line[x] = qPremultiply(qRgba(qRed(colour), qGreen(colour), qBlue(colour), a));
        }
    }
}

// The device pixels of `bounds` under `view`, inside [0, size).
QRect shownOn(const QRectF &bounds, const QTransform &view, QSize size)
{
    const QRectF mapped = view.mapRect(bounds);
    if (!std::isfinite(mapped.left()) || !std::isfinite(mapped.top()) ||
        !std::isfinite(mapped.right()) || !std::isfinite(mapped.bottom()))
        return {};
    const QRectF clipped = mapped.adjusted(-1, -1, 1, 1) & QRectF(QPointF(0, 0), QSizeF(size));
    return clipped.toAlignedRect() & QRect(QPoint(0, 0), size);
}

} // namespace

namespace {

// The group's picture as it shows through `view`, drawn alone into a transparent scratch image
// over the part of a `size` device it covers (`box`, device pixels), tinted when asked. Null
// when nothing of it is on the device.
QImage scratchPicture(const StrokeGroup &group, const QTransform &view, QSize size,
                      const std::optional<QColor> &tint, QRect &box)
{
    const ShownPictureMesh mesh = shownPictureMesh(group);
    box = shownOn(boundsOf(mesh.V), view, size);
    if (box.isEmpty())
        return {};
    QImage scratch(box.size(), QImage::Format_ARGB32_Premultiplied);
    if (scratch.isNull())
        return {};
    scratch.fill(Qt::transparent);
    drawTexturedMesh(scratch, view * QTransform::fromTranslate(-box.left(), -box.top()),
                     group.picture->data->image, mesh.uv, mesh.V, mesh.F);
    if (tint)
        tintPixels(scratch, *tint);
    return scratch;
}

} // namespace

void drawPicture(QImage &target, const QTransform &view, const StrokeGroup &group, qreal opacity,
                 const std::optional<QColor> &tint)
{
    if (!group.picture || !pictureIsValid(*group.picture) || target.isNull() || !(opacity > 0))
        return;
    if (!tint) { // straight into the target: no scratch copy
        const ShownPictureMesh mesh = shownPictureMesh(group);
        drawTexturedMesh(target, view, group.picture->data->image, mesh.uv, mesh.V, mesh.F,
                         std::min(opacity, 1.0));
        return;
    }
    QRect box;
    const QImage scratch = scratchPicture(group, view, target.size(), tint, box);
    if (scratch.isNull())
        return;
    QPainter painter(&target);
    painter.setOpacity(std::min(opacity, 1.0));
    painter.drawImage(box.topLeft(), scratch);
}

void paintPicture(QPainter &painter, const StrokeGroup &group, const std::optional<QColor> &tint)
{
    if (!group.picture || !pictureIsValid(*group.picture) || !painter.device())
        return;
    // Device pixels (a high-density picture's included): the scratch image is drawn at the
    // device's own resolution, then laid on it unscaled. From the painter's own coordinates,
    // not deviceTransform(): a widget painted into its window's backing store has the widget's
    // offset there too, which the painter adds again when the image is drawn.
    const qreal dpr = std::max(1.0, painter.device()->devicePixelRatioF());
    const QTransform view = painter.combinedTransform() * QTransform::fromScale(dpr, dpr);
    const QSize deviceSize(int(std::ceil(painter.device()->width() * dpr)),
                           int(std::ceil(painter.device()->height() * dpr)));
    QRect box;
    QImage scratch = scratchPicture(group, view, deviceSize, tint, box);
    if (scratch.isNull())
        return;
    scratch.setDevicePixelRatio(dpr);
    painter.save();
    painter.resetTransform();
    painter.drawImage(QPointF(box.topLeft()) / dpr, scratch);
    painter.restore();
}

} // namespace finbook::model
