// Picture objects (issue 51): painted pixels as an object of the drawing, carried by a triangle
// mesh of their shape so that every deformer moves them as it moves strokes.
//
// A picture object is a StrokeGroup whose `picture` is set. Its texture mesh (PictureMesh) is
// made once, when the picture comes in, and saved with it; its vertices are rest points of the
// object like its strokes' points (deform_setup.h restPoints), so pins, cages and skeletons
// carry them and a pose keeps them in DeformedStrokes::pictureVertices. The picture is drawn by
// texture-mapping that mesh (textured_mesh.h): at rest it is its own pixels exactly.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/region.h>
#include <finbook/model/picture/picture_import.h>
#include <finbook/model/types.h>

#include <QByteArray>
#include <QImage>
#include <QPainter>
#include <QRectF>
#include <QTransform>

#include <Eigen/Core>

#include <memory>
#include <optional>

namespace finbook::model {

// A picture's pixels, immutable and shared by every object and frame that shows it. `png` is
// what a .finbook holds of it, once per document however many objects show it; `image` is
// that PNG decoded (Format_ARGB32_Premultiplied, never null).
struct PictureData {
    QImage image;
    QByteArray png;
};
using PictureDataPtr = std::shared_ptr<const PictureData>;

// The texture mesh: `uv` n×2 in the picture's own pixels ((0, 0) its top-left corner), `F`
// m×3 with positive area (object_mesh.h), covering the centre of every pixel that shows.
struct PictureMesh {
    Eigen::MatrixX2d uv;
    Eigen::MatrixX3i F;
};
using PictureMeshPtr = std::shared_ptr<const PictureMesh>;

struct ObjectPicture {
    PictureDataPtr data;
    PictureMeshPtr mesh;
    // Where the picture lies on the rest drawing: picture pixels → canvas px, affine (a move,
    // a turn, a scale; a translation to where its top-left corner lies when it comes in).
    QTransform place;

    // The texture mesh's vertices on the rest drawing (place applied to uv), n×2.
    Eigen::MatrixX2d restVertices() const;
    // The bounding box of the picture's rectangle on the rest drawing.
    QRectF restRect() const;
    friend bool operator==(const ObjectPicture &a, const ObjectPicture &b)
    {
        return a.data == b.data && a.mesh == b.mesh && a.place == b.place;
    }
};

// Vertices aimed for in a picture's texture mesh (the mesher lands at 1.2–3 times that): a
// 1024² picture redraws within a frame of a drag at 1080p (finbook-bench picture).
inline constexpr int kPictureMeshVertices = 2000;

// `image` as a picture: converted to premultiplied ARGB32 and encoded as PNG. Errors: a
// sentence (an empty image, no memory to encode it).
Expected<PictureDataPtr, QString> makePictureData(const QImage &image);

// The texture mesh of `image`: the outline of its pixels that show (alpha ≥ 1; the whole
// rectangle when it is opaque), meshed with about one vertex per 8 × 8 px of it, at least 64
// and at most kPictureMeshVertices (times density²).
// Errors: a sentence (fully transparent, or an outline that cannot be meshed).
Expected<PictureMeshPtr, QString> meshPicture(const QImage &image, double density = 1.0);

// A new object showing `layer`, its top-left corner at `at` (canvas px), named after the
// layer; id kNoId (the document gives ids). Errors: those of makePictureData and meshPicture.
Expected<StrokeGroup, QString> makePictureObject(const PictureLayer &layer, QPointF at);

// The picture's shape on the rest drawing: its texture mesh's outline (canvas px), for the
// skeleton and Fit Cage. Empty when the picture is not valid.
geometry::Region pictureRegion(const ObjectPicture &picture);

// File → Import Picture's work (safe on any thread): the layers of the file at `path`
// (readPictureLayers) as picture objects, bottom layer first, placed as they lie in the file
// with the whole centred on a page of `page` pixels. Errors: a sentence naming the file.
Expected<std::vector<StrokeGroup>, QString> pictureObjectsFromFile(const QString &path,
                                                                   QSizeF page);
// The same from layers already read from `path` (the name its errors give).
Expected<std::vector<StrokeGroup>, QString>
pictureObjectsFromLayers(const std::vector<PictureLayer> &layers, const QString &path, QSizeF page);

// Whether a placement can carry a picture: affine, finite, not flattened (|det| ≥ 1e-6), no
// farther than 1e7 px.
bool validPicturePlace(const QTransform &place);

// The same picture placed by `place` followed by `by` (a move, turn or scale of the object).
std::shared_ptr<const ObjectPicture> movedPicture(const ObjectPicture &picture,
                                                  const QTransform &by);

// Whether the group's picture, if any, is whole: pixels, a mesh whose indices are in range, a
// valid place.
bool pictureIsValid(const ObjectPicture &picture);

// The texture mesh's vertices as the object shows them now: its pose's when it is deformed and
// the pose holds one per vertex, its rest vertices otherwise. Empty without a picture.
Eigen::MatrixX2d shownPictureVertices(const StrokeGroup &group);

// The textured mesh the object draws now: the texture mesh through shownPictureVertices, or a
// cut-out pose's layers (DeformedStrokes::pictureLayers: pieces and sockets). Triangles are drawn
// in the order of F. Empty without a valid picture.
struct ShownPictureMesh {
    Eigen::MatrixX2d uv, V; // texture px and canvas px, per vertex
    Eigen::MatrixX3i F;
};
ShownPictureMesh shownPictureMesh(const StrokeGroup &group);

// The bounding box of the picture as the object shows it now (canvas px); empty without one.
QRectF shownPictureBounds(const StrokeGroup &group);

// Apply Pose for a picture: the picture as the object shows it now, resampled once into a new
// rest picture (bilinear, so it softens a little) with its own texture mesh, placed where it
// shows. The object's picture itself when it is not posed. Errors: those of makePictureData and
// meshPicture (a pose folded to nothing).
Expected<std::shared_ptr<const ObjectPicture>, QString> bakedPicture(const StrokeGroup &group);

// Merge Objects for pictures: the pictures of two objects as they show now, `above`'s over
// `below`'s, as one rest picture covering both (canvas pixels; a picture at rest on whole
// pixels keeps its pixels exactly). When only one of them has a picture, that picture (baked
// when posed). Errors: those of bakedPicture, or neither has a picture.
Expected<std::shared_ptr<const ObjectPicture>, QString> stackedPicture(const StrokeGroup &below,
                                                                       const StrokeGroup &above);

// Whether `pos` (canvas px) lies on the group's picture as it shows now: inside one of its
// texture mesh's triangles as posed (for clicks: a pin, a bone, a selection).
bool pictureShowsAt(const StrokeGroup &group, QPointF pos);

// Whether any object of the frame that `options` shows is a picture.
struct RenderOptions; // render.h
bool frameHasPictures(const Frame &frame, const RenderOptions &options);

// Paints the group's picture as it shows now, with the painter's transform, opacity and
// composition (drawn through a scratch image the size of what the device shows of it).
// `tint`: every pixel in that colour at its own alpha (the onion skin). Nothing for a group
// without a picture.
void paintPicture(QPainter &painter, const StrokeGroup &group,
                  const std::optional<QColor> &tint = std::nullopt);

// The same into `target` (premultiplied ARGB32) through `view` (canvas → target pixels),
// source-over at `opacity`, tinted as above. For rasterizers that draw into their own buffers.
void drawPicture(QImage &target, const QTransform &view, const StrokeGroup &group,
                 qreal opacity = 1.0, const std::optional<QColor> &tint = std::nullopt);

} // namespace finbook::model
