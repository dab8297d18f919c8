// The document's value types: frames hold objects (stroke groups), objects hold strokes.
//
// Rest strokes are immutable and shared (std::shared_ptr<const StrokeData>): duplicating a
// frame or an object copies pointers, never points. Every entity carries a stable integer id
// allocated by its Document; commands refer to entities by id only.
#pragma once

#include <finbook/model/skeleton/skeleton_rig.h>

#include <QColor>
#include <QPainterPath>
#include <QPointF>
#include <QSize>
#include <QString>
#include <QTransform>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace finbook::model {

using Id = std::uint64_t;
constexpr Id kNoId = 0;

// One pen sample in canvas pixels (y down). Stored as float: 1e-4 px precision on any
// realistic canvas, and it keeps a stored point at 10 bytes on disk.
struct StrokePoint {
    float x = 0.0f;
    float y = 0.0f;
    float pressure = 1.0f; // 0..1; quantised to 1/65535 by the file format
    friend bool operator==(const StrokePoint &, const StrokePoint &) = default;
};

struct StrokeData {
    std::vector<StrokePoint> points;
    QRgb color = 0xff000000; // ARGB
    float width = 3.0f;      // nominal width in canvas pixels at pressure 1
    friend bool operator==(const StrokeData &, const StrokeData &) = default;
};

using StrokeDataPtr = std::shared_ptr<const StrokeData>;

struct Stroke {
    Id id = kNoId;
    StrokeDataPtr data;
    // Value equality (ids and contents), used by tests and commands' sanity checks.
    friend bool operator==(const Stroke &a, const Stroke &b)
    {
        return a.id == b.id && (a.data == b.data || (a.data && b.data && *a.data == *b.data));
    }
};

// An ARAP pin: where it was put on the rest drawing and where it is dragged to now.
struct Pin {
    Id id = kNoId;
    QPointF rest;
    QPointF target;
    friend bool operator==(const Pin &, const Pin &) = default;
};

// A harmonic cage (Joshi et al. 2007): a simple polygon drawn around the object on its rest
// drawing, and where each corner is dragged to now (same count, same order).
struct CageRig {
    std::vector<QPointF> rest;
    std::vector<QPointF> posed;
    bool empty() const { return rest.empty(); }
    friend bool operator==(const CageRig &, const CageRig &) = default;
};

enum class RigKind { None, Pins, Cage, Skeleton };

// The one deformer an object carries in a frame: pins, a cage, or a skeleton. At most one kind is
// non-empty (Document::setRig enforces it). Its rest definition (pin rest positions, rest
// corners) decides the precompute; its targets (pin targets, posed corners) only re-solve, and
// the pose is a pure function of both.
struct Rig {
    std::vector<Pin> pins;
    CageRig cage;
    SkeletonRig skeleton; // skeleton/skeleton_rig.h

    RigKind kind() const
    {
        if (!pins.empty())
            return RigKind::Pins;
        if (!cage.empty())
            return RigKind::Cage;
        if (!skeleton.empty())
            return RigKind::Skeleton;
        return RigKind::None;
    }
    bool empty() const { return kind() == RigKind::None; }
    // Whether any target differs from its rest position.
    bool isPosed() const;
    // The same rig with every target at its rest position.
    Rig atRest() const;
    // The same rig with the rest definition moved to where the targets are: what stays after
    // the pose has become the drawing.
    Rig rebased() const;
    friend bool operator==(const Rig &, const Rig &) = default;
};

// Points of one deformed object, stroke by stroke (same order and sizes as its rest strokes).
// A picture object's texture mesh as a cut-out pose draws it (picture/picture_cut.h): cut at
// the joints, each piece's triangles with vertices of their own (copied where pieces part), the
// sockets first, then the pieces in drawing order.
struct PictureLayers {
    std::vector<QPointF> uv;               // texture pixels, per vertex
    std::vector<QPointF> vertices;         // posed canvas pixels, per vertex
    std::vector<std::array<int, 3>> faces; // drawn in this order
    bool isEmpty() const { return faces.empty(); }
    friend bool operator==(const PictureLayers &, const PictureLayers &) = default;
};

struct DeformedStrokes {
    std::vector<std::vector<StrokePoint>> strokes;
    // A cut-out skeleton's pose (SkinningMode::CutOut) lies in pieces, each drawn over the ones
    // before it (fill/fill_render.h, paintLayers): per stroke point the piece it moved with
    // (−1 the roots' piece, k ≥ 0 the k-th cut's, deeper cuts later), and each cut piece's
    // outline as posed (non-zero rule). Both empty for every other pose.
    std::vector<std::vector<std::int16_t>> pieceOf;
    std::vector<QPainterPath> pieces;
    // Per cut piece, its socket as posed (deform/skeleton/cut_out.h: the cut's round end, a
    // disk at its joint, painted on the piece above it in the limb's fill) and the piece
    // above it (−1 the roots'). Empty paths where a cut has no round end.
    std::vector<QPainterPath> sockets;
    std::vector<int> socketAbove;
    // The roots' piece's outline as posed, and per piece (the roots', then each cut's) its
    // motion where it moved rigidly: its fills are then the rest fills moved with it, whole
    // however far the pieces around it turned.
    QPainterPath body;
    std::vector<std::optional<QTransform>> motions;
    // A picture object's texture mesh as posed (picture/picture_object.h: one position per
    // vertex of its PictureMesh, canvas pixels). Empty for an object without a picture.
    std::vector<QPointF> pictureVertices;
    // A cut-out pose of a picture object (in memory, as `pieces`): what is drawn instead of the
    // texture mesh through pictureVertices, which hold each vertex in its first piece. Empty for
    // every other pose.
    PictureLayers pictureLayers;
    friend bool operator==(const DeformedStrokes &, const DeformedStrokes &) = default;
};
using DeformedStrokesPtr = std::shared_ptr<const DeformedStrokes>;

// How a fill is shaded from its object's inflated shape (shade/fill_shading.h): not at all, a
// cel ramp of two or three tones (the animator's usual look), or a smooth ramp; with an
// optional rim light on the side away from the light.
enum class ShadeRamp : quint8 { Off = 0, TwoTones = 1, ThreeTones = 2, Smooth = 3 };
constexpr quint8 kLastShadeRamp = 3;

struct FillShading {
    ShadeRamp ramp = ShadeRamp::Off;
    bool rim = false;
    bool shaded() const { return ramp != ShadeRamp::Off; }
    friend bool operator==(const FillShading &, const FillShading &) = default;
};

// A fill: a colour on one region of its object (fill/fill_regions.h), tied to the region by a
// point inside it on the rest drawing and the ids of the strokes that bounded it when it was
// made, not by pixels: when the strokes change, the region that still holds the seed (or, when
// the seed fell out, the one bounded by most of the same strokes) keeps the colour.
//
// One further region of a fill (Fill::more): a point inside it and the strokes bounding it.
struct FillPlace {
    QPointF seed;            // rest canvas pixels
    std::vector<Id> strokes; // sorted, unique
    friend bool operator==(const FillPlace &, const FillPlace &) = default;
};

struct Fill {
    QRgb color = 0xff000000; // ARGB
    QPointF seed;            // rest canvas pixels
    std::vector<Id> strokes; // sorted, unique
    FillShading shading;
    // Further regions that are the same fill, each tied as the first is (fill_resolve.h): Apply
    // Pose makes them where lines that the pose made cross cut one shown region into several
    // (a fork's tines turned through each other), so the animator still has one fill to
    // recolour, not ten. Empty for a fill of one region.
    std::vector<FillPlace> more;
    friend bool operator==(const Fill &, const Fill &) = default;
};
// Calls f(strokes) on the stroke id list of each region of `fill` (its first, then Fill::more),
// for code that renumbers or replaces stroke ids.
template <class F> void forEachFillStrokes(Fill &fill, F &&f)
{
    f(fill.strokes);
    for (FillPlace &place : fill.more)
        f(place.strokes);
}

constexpr double kDefaultMeshDensity = 1.0; // 1 = default edge length; 2 = twice as fine

// Drawing substitution (issue 49): an object that shows one of a set of named drawings, chosen
// per frame (mouths, hands, blinks). `set` is a SwapSet of the document, `drawing` one of its
// drawings; both kNoId for an ordinary object.
struct SwapLink {
    Id set = kNoId;
    Id drawing = kNoId;
    bool linked() const { return set != kNoId; }
    friend bool operator==(const SwapLink &, const SwapLink &) = default;
};

struct ObjectPicture; // picture/picture_object.h

struct StrokeGroup {
    Id id = kNoId;
    QString name;
    bool visible = true;
    bool locked = false;
    double meshDensity = kDefaultMeshDensity;
    std::vector<Stroke> strokes; // rest strokes, drawing order (last on top)
    // Drawn under the strokes, in this order (a later fill on the same region wins).
    std::vector<Fill> fills;
    Rig rig;
    // The pose the rig produced, as last solved. Saved with the file so a reopened document
    // shows (and exports) the deformed drawing without re-solving; cleared by any rest edit.
    DeformedStrokesPtr deformed;
    // The drawing of a set this object shows (document.h, Swap sets). Its strokes, fills and
    // mesh density are then that drawing's, the same (ids included) in every frame showing it;
    // its rig and pose are its own, per frame.
    SwapLink swap;
    // A picture object (issue 51): painted pixels carried by a mesh of their shape, under the
    // object's fills and strokes. Immutable and shared; null for a drawing.
    std::shared_ptr<const ObjectPicture> picture;

    bool isDeformed() const { return !rig.empty() && deformed != nullptr; }
    // Whether there is anything to mesh, rig and deform: strokes or a picture.
    bool hasContent() const { return !strokes.empty() || picture != nullptr; }
};

// A layer's share of a composed shot (scene/shot.h): its objects are the frame's groups up
// to groupEnd (from the previous plane's end), painted at its opacity and seen through the
// camera as a plane at its depth.
struct FramePlane {
    int groupEnd = 0;
    double opacity = 1.0;
    double depth = 0.0;
    Id layer = kNoId; // the layer whose cel this plane shows
    friend bool operator==(const FramePlane &, const FramePlane &) = default;
};

// A drawing: a layer's cel, shown for `hold` ticks.
struct Frame {
    Id id = kNoId;
    int hold = 1; // exposure: how many playback ticks this drawing stays on screen (1..)
    std::vector<StrokeGroup> groups; // back to front
    // Empty for a cel. A shot composed of several layers (scene/shot.h) says here which
    // groups belong to which layer; renderers paint each plane at its opacity and depth.
    std::vector<FramePlane> planes;
};

// Multiplane depth (scene/shot.h): 0 is the page's own plane; deeper planes drift less under
// the camera, planes in front (negative) move more.
constexpr double kMinLayerDepth = -0.9;
constexpr double kMaxLayerDepth = 100.0;

struct LayerProperties {
    QString name;
    bool visible = true;
    bool locked = false;   // every tool leaves the layer alone
    bool onionSkin = true; // its neighbouring cels show in the onion skin when it is current
    double opacity = 1.0;  // [0, 1]
    double depth = 0.0;    // [kMinLayerDepth, kMaxLayerDepth]
    friend bool operator==(const LayerProperties &, const LayerProperties &) = default;
};

// A row of the dope sheet: drawings (cels) one after the other, each for its hold. A cel with
// no objects is an empty stretch.
struct Layer {
    Id id = kNoId;
    LayerProperties properties;
    std::vector<Frame> cels;
};

// One drawing of a swap set: what every object linked to it shows. Its stroke ids are shared
// by those objects (the only ids a document holds more than once, always in different
// frames), so an edit of any of them is an edit of the drawing.
struct SwapDrawing {
    Id id = kNoId;
    QString name;
    std::vector<Stroke> strokes;
    std::vector<Fill> fills;
    double meshDensity = kDefaultMeshDensity;
    // The rig (at rest) a frame switching to this drawing starts with when no other frame
    // shows it: the rig the last frame to leave it had (SetSwapDrawingCommand keeps it).
    Rig rig;
    friend bool operator==(const SwapDrawing &, const SwapDrawing &) = default;
};

// A set of drawings one object swaps between, frame by frame (a mouth chart, a hand's
// positions, eyes open and closed).
struct SwapSet {
    Id id = kNoId;
    QString name;
    std::vector<SwapDrawing> drawings;
    const SwapDrawing *drawing(Id drawingId) const;
    int indexOf(Id drawingId) const; // -1 if it has none
    friend bool operator==(const SwapSet &, const SwapSet &) = default;
};

// Drawings a set may hold, and sets a document may hold (a file claiming more is refused).
constexpr int kMaxSwapDrawings = 1000;
constexpr int kMaxSwapSets = 10000;

struct DocumentSettings {
    QSize canvasSize{1280, 720};
    QRgb background = 0xffffffff;
    int fps = 12; // 1..60
    bool loop = true;
    int playStart = 0; // first frame index of the play range
    int playEnd = -1;  // last frame index, -1 = the last frame
    // Gaps up to this many canvas pixels close the regions that fills use; < 0 = automatic.
    double closeGap = -1.0;
    // The light of shaded fills, fixed in screen space (geometry::lightDirection): degrees
    // counter-clockwise from the right, and above the drawing's plane. Default: upper left.
    double lightAzimuth = 135.0;  // [0, 360)
    double lightElevation = 45.0; // [0, 90]
    friend bool operator==(const DocumentSettings &, const DocumentSettings &) = default;
};

constexpr int kMinFps = 1;
constexpr int kMaxFps = 60;
constexpr int kMaxCanvasSide = 16384;
// A background is exposed once for a whole shot: a hold may cover an hour at 60 fps.
constexpr int kMaxHold = 216000;
constexpr int kMaxLayers = 1000;
// The widest stroke a file may hold: the largest canvas side. Wider says nothing more (it
// covers any canvas), and QPen refuses widths of 32768 and more (it silently draws 1 pixel).
constexpr float kMaxStrokeWidth = 16384.0f;
// The widest gap the "Close gaps" setting offers.
constexpr double kMaxCloseGap = 500.0;
// Fills one object may carry (a file claiming more is refused).
constexpr int kMaxFillsPerObject = 100000;

} // namespace finbook::model
