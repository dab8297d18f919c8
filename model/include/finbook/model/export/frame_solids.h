// A frame's objects as 3D solids (issue 27's 3D export, RealSkel's own output): each visible
// object's shape as it shows now (posed where it is posed), meshed, inflated and closed
// (geometry/inflate), with the colour it is exported in.
#pragma once

#include <finbook/geometry/inflate/inflated_solid.h>
#include <finbook/model/types.h>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace finbook::model {

struct PictureData; // picture/picture_object.h

struct ObjectSolid {
    Id groupId = kNoId;
    QString name; // the object's name as the user gave it (may be empty or repeated)
    QRgb color = 0xff000000;
    geometry::InflatedSolid solid; // y up, canvas px (inflated_solid.h)
    // A picture object's picture, which its solid's texture coordinates map into (both its
    // faces show it); null for a drawn object.
    std::shared_ptr<const PictureData> picture;
};

// A 3D model holds at most this many vertices, every object's solid together: about 25 MB of
// glTF or 100 MB of OBJ. Making the solids costs time and memory in proportion, so the count
// is kept as they are made and the export refused as soon as it passes (FrameSolids::tooLarge).
constexpr qint64 kMaxModelVertices = 500000;
// An object with a point farther than this from the page (canvas pixels, either axis) is left
// out: meshing works in single precision there to no use (FrameSolids::tooFar).
constexpr double kMaxModelCoordinate = 1e6;

struct FrameSolids {
    std::vector<ObjectSolid> objects; // back to front, as the frame holds them
    int candidates = 0; // visible objects with at least one stroke point, or a picture
    // Of those, the ones that are a dot or a straight line (every point within one pen width
    // of a line), lie too far out, or whose shape could not be meshed or inflated.
    int skipped = 0;
    int tooFar = 0;      // of the skipped, those with a point beyond kMaxModelCoordinate
    qint64 vertices = 0; // in `objects`
    // The solids would pass the vertex limit: making them stopped there (objects incomplete).
    bool tooLarge = false;
};

// The colour an object is exported in: its largest fill's (by the rest area of the regions it
// shows on) when a fill shows, else its first stroke's; opaque black for an empty object.
QRgb objectExportColor(const StrokeGroup &group, double closeGap);

// Called after each object with (objects done, candidates); returning false cancels.
using SolidsProgress = std::function<bool(int done, int total)>;

// A picture object is its picture's shape as it shows (posed where it is posed: its texture
// mesh at rest inflated, every point then carried where the pose takes it), textured with the
// picture; a cut-out pose's pieces are not parted in 3D.
// Every visible object of `frame` with strokes, shaped from its displayed strokes
// (posedStrokes) as meshing sees them (its mesh density, the document's gap closing), meshed
// (geometry::buildObjectMesh), inflated and closed; an object whose every stroke closes a
// region by itself (two or more: a body and an arm drawn over it) gets one closed solid per
// stroke's region instead (geometry/inflate/layers.h), all in its one solid. A dot or a straight
// line (its pen band would only make a bead or a rod), or an object that cannot be meshed or
// inflated, is counted in `skipped`, never an error. Stops with `tooLarge` set once the solids
// pass `maxVertices`. nullopt only when `progress` cancelled. Reads only its arguments: safe on
// a worker thread.
std::optional<FrameSolids> frameSolids(const Frame &frame, const DocumentSettings &settings,
                                       const SolidsProgress &progress = {},
                                       qint64 maxVertices = kMaxModelVertices);

} // namespace finbook::model
