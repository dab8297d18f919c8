#include <finbook/model/camera/camera_track.h>
#include <finbook/model/inbetween/spacing.h>

#include <QPolygonF>

#include <algorithm>
#include <cmath>

namespace finbook::model {

namespace {

CameraState stateOf(const CameraKey &key)
{
    return {key.center, key.zoom, key.rotation};
}

// A cubic Bézier coordinate at parameter s, from 0 through a and b to 1.
double bezier(double a, double b, double s)
{
    const double r = 1.0 - s;
    return 3.0 * r * r * s * a + 3.0 * r * s * s * b + s * s * s;
}

double bezierSlope(double a, double b, double s)
{
    const double r = 1.0 - s;
    return 3.0 * r * r * a + 6.0 * r * s * (b - a) + 3.0 * s * s * (1.0 - b);
}

// y at the x = t of the Bézier through control points c1 and c2 (x within [0, 1], so x grows
// with s): Newton's method from t, bisection where the slope is flat.
double bezierEase(QPointF c1, QPointF c2, double t)
{
    double s = t;
    for (int i = 0; i < 8; ++i) {
        const double error = bezier(c1.x(), c2.x(), s) - t;
        if (std::abs(error) < 1e-9)
            return bezier(c1.y(), c2.y(), s);
        const double slope = bezierSlope(c1.x(), c2.x(), s);
        if (std::abs(slope) < 1e-6)
            break;
        s = std::clamp(s - error / slope, 0.0, 1.0);
    }
    double lo = 0.0, hi = 1.0;
    s = t;
    for (int i = 0; i < 60; ++i) {
        if (bezier(c1.x(), c2.x(), s) < t)
            lo = s;
        else
            hi = s;
        s = 0.5 * (lo + hi);
    }
    return bezier(c1.y(), c2.y(), s);
}

bool finiteIn(double v, double lo, double hi)
{
    return std::isfinite(v) && v >= lo && v <= hi;
}

} // namespace

bool CameraTrack::isUsed(QSizeF page) const
{
    const CameraState rest = restCamera(page);
    return std::any_of(keys.begin(), keys.end(),
                       [&](const CameraKey &k) { return stateOf(k) != rest; });
}

bool CameraTrack::movesBetween(double first, double last) const
{
    for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
        const CameraKey &a = keys[i], &b = keys[i + 1];
        if (double(b.tick) <= first || double(a.tick) >= last || stateOf(a) == stateOf(b))
            continue;
        // A hold changes only at the next key.
        if (a.easing != CameraEasing::Hold || double(b.tick) <= last)
            return true;
    }
    return false;
}

int CameraTrack::keyAt(qint64 tick) const
{
    const auto it = std::lower_bound(keys.begin(), keys.end(), tick,
                                     [](const CameraKey &k, qint64 t) { return k.tick < t; });
    return it != keys.end() && it->tick == tick ? int(it - keys.begin()) : -1;
}

CameraState restCamera(QSizeF page)
{
    return {QPointF(page.width() / 2.0, page.height() / 2.0), 1.0, 0.0};
}

double easedTime(const CameraKey &from, double t)
{
    t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
    // The curves in-betweens are spaced by (inbetween/spacing.h): one formula for each.
    switch (from.easing) {
    case CameraEasing::Linear:
        return spacedTime(t, {SpacingKind::Linear});
    case CameraEasing::EaseIn:
        return spacedTime(t, {SpacingKind::EaseIn});
    case CameraEasing::EaseOut:
        return spacedTime(t, {SpacingKind::EaseOut});
    case CameraEasing::EaseInOut:
        return spacedTime(t, {SpacingKind::EaseInOut});
    case CameraEasing::Hold:
        return t < 1.0 ? 0.0 : 1.0;
    case CameraEasing::Bezier:
        return bezierEase(from.control1, from.control2, t);
    }
    return t;
}

CameraState cameraAt(const CameraTrack &track, double tick, QSizeF page)
{
    const std::vector<CameraKey> &keys = track.keys;
    if (keys.empty())
        return restCamera(page);
    if (!(tick > double(keys.front().tick)))
        return stateOf(keys.front());
    if (tick >= double(keys.back().tick))
        return stateOf(keys.back());
    const auto next = std::upper_bound(keys.begin(), keys.end(), tick,
                                       [](double t, const CameraKey &k) { return t < k.tick; });
    const CameraKey &b = *next, &a = *(next - 1);
    const double u = easedTime(a, (tick - double(a.tick)) / double(b.tick - a.tick));
    CameraState out;
    out.center = a.center + (b.center - a.center) * u;
    out.zoom = a.zoom * std::pow(b.zoom / a.zoom, u);
    out.rotation = a.rotation + (b.rotation - a.rotation) * u;
    return out;
}

QTransform cameraTransform(const CameraState &state, QSizeF shot)
{
    QTransform t;
    t.translate(shot.width() / 2.0, shot.height() / 2.0);
    t.scale(state.zoom, state.zoom);
    t.rotate(state.rotation); // the camera turns counter-clockwise, the picture clockwise
    t.translate(-state.center.x(), -state.center.y());
    return t;
}

QPolygonF cameraFrame(const CameraState &state, QSizeF shot)
{
    const QTransform toPage = cameraTransform(state, shot).inverted();
    QPolygonF out;
    for (QPointF corner : {QPointF(0, 0), QPointF(shot.width(), 0),
                           QPointF(shot.width(), shot.height()), QPointF(0, shot.height())})
        out << toPage.map(corner);
    out << out.front();
    return out;
}

bool isValidCameraTrack(const CameraTrack &track)
{
    if (track.keys.size() > std::size_t(kMaxCameraKeys))
        return false;
    for (std::size_t i = 0; i < track.keys.size(); ++i) {
        const CameraKey &k = track.keys[i];
        if (k.tick < 0 || k.tick > kMaxCameraTick || (i > 0 && k.tick <= track.keys[i - 1].tick) ||
            !finiteIn(k.center.x(), -kMaxCameraReach, kMaxCameraReach) ||
            !finiteIn(k.center.y(), -kMaxCameraReach, kMaxCameraReach) ||
            !finiteIn(k.zoom, kMinCameraZoom, kMaxCameraZoom) ||
            !finiteIn(k.rotation, -kMaxCameraTurn, kMaxCameraTurn) ||
            int(k.easing) >= kCameraEasingCount || !finiteIn(k.control1.x(), 0.0, 1.0) ||
            !finiteIn(k.control2.x(), 0.0, 1.0) || !finiteIn(k.control1.y(), -1.0, 2.0) ||
            !finiteIn(k.control2.y(), -1.0, 2.0))
            return false;
    }
    return true;
}

CameraTrack withKey(CameraTrack track, const CameraKey &key)
{
    auto it = std::lower_bound(track.keys.begin(), track.keys.end(), key.tick,
                               [](const CameraKey &k, qint64 t) { return k.tick < t; });
    if (it != track.keys.end() && it->tick == key.tick)
        *it = key;
    else
        track.keys.insert(it, key);
    return track;
}

CameraTrack withoutKey(CameraTrack track, qint64 tick)
{
    std::erase_if(track.keys, [tick](const CameraKey &k) { return k.tick == tick; });
    return track;
}

} // namespace finbook::model
