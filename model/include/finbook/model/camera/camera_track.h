// The camera: a document-wide track of keys over playback ticks (the animation's own clock,
// holds included, as the sound row counts it). Each key holds where the camera looks (the
// page point at the middle of the shot), how far it zooms in and how it is turned, and how
// the move to the next key eases. The shot is the document's canvas size: zoom 1 at the page's
// centre, unturned, shows the page exactly as a document without a camera does.
//
// Between two keys the centre and the turn move linearly and the zoom geometrically (each
// tick zooms by the same factor, so a zoom in feels even), all along the first key's easing
// of time. Before the first key the camera holds it, after the last key it holds that one.
#pragma once

#include <finbook/model/types.h>

#include <QPointF>
#include <QSizeF>
#include <QTransform>

#include <vector>

namespace finbook::model {

constexpr qint64 kMaxCameraTick = 1'000'000; // as kMaxSoundStart: over 4 hours at 60 fps
constexpr int kMaxCameraKeys = 100000;
constexpr double kMinCameraZoom = 0.05; // the page at a twentieth: a wide establishing shot
constexpr double kMaxCameraZoom = 50.0;
constexpr double kMaxCameraTurn = 36000.0; // degrees either way (a hundred turns)
// How far from the page the camera may look (page px): far enough for any pan across a
// background drawn beyond the page, near enough that nothing loses float precision.
constexpr double kMaxCameraReach = 1.0e6;

enum class CameraEasing : quint8 {
    Linear = 0,
    EaseIn = 1,    // starts slowly: t²
    EaseOut = 2,   // ends slowly: 1 − (1 − t)²
    EaseInOut = 3, // both: 3t² − 2t³
    Hold = 4,      // stays on this key until the next one, then cuts
    Bezier = 5,    // a cubic Bézier from (0, 0) to (1, 1), as CSS's cubic-bezier()
};
constexpr int kCameraEasingCount = 6;

struct CameraKey {
    qint64 tick = 0;
    QPointF center;        // page px at the middle of the shot
    double zoom = 1.0;     // kMinCameraZoom … kMaxCameraZoom; 2 shows half the page's width
    double rotation = 0.0; // degrees the camera is turned counter-clockwise
    CameraEasing easing = CameraEasing::Linear; // of the move from this key to the next
    // The Bézier's two inner control points (x in [0, 1], y within [−1, 2]); used for Bezier.
    QPointF control1{0.25, 0.1}, control2{0.25, 1.0};

    bool operator==(const CameraKey &other) const = default;
};

// Where the camera is at one moment.
struct CameraState {
    QPointF center;
    double zoom = 1.0;
    double rotation = 0.0;
    bool operator==(const CameraState &other) const = default;
};

// Keys in increasing tick order, at most one per tick.
struct CameraTrack {
    std::vector<CameraKey> keys;

    bool isEmpty() const { return keys.empty(); }
    // Whether the shot differs anywhere from the plain page (some key is not at rest).
    bool isUsed(QSizeF page) const;
    // Whether the camera moves between ticks `first` and `last` (inclusive).
    bool movesBetween(double first, double last) const;
    // The key at `tick`, or −1.
    int keyAt(qint64 tick) const;
    bool operator==(const CameraTrack &other) const = default;
};

// The state at rest: the page's centre, zoom 1, unturned.
CameraState restCamera(QSizeF page);

// The eased share of the way (0..1, a Bézier may overshoot a little) at share `t` (0..1) of
// the time between two keys.
double easedTime(const CameraKey &from, double t);

// The camera at `tick` (fractions allowed). An empty track is restCamera(page).
CameraState cameraAt(const CameraTrack &track, double tick, QSizeF page);

// Page px → shot px for a shot of `shot` size (the canvas size) seen through `state`: the
// state's centre goes to the middle of the shot, zoomed and turned about it.
QTransform cameraTransform(const CameraState &state, QSizeF shot);

// The shot's outline on the page (page px): the page's rectangle as the camera frames it, a
// closed polygon of 4 corners + the first again.
QPolygonF cameraFrame(const CameraState &state, QSizeF shot);

// Whether every value is finite and within the limits above, ticks strictly increasing.
bool isValidCameraTrack(const CameraTrack &track);

// `track` with the key at key.tick added or replaced, kept in tick order.
CameraTrack withKey(CameraTrack track, const CameraKey &key);
// `track` without the key at `tick` (unchanged when there is none).
CameraTrack withoutKey(CameraTrack track, qint64 tick);

} // namespace finbook::model
