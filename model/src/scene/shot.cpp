// Composing layers over time (scene/shot.h).
#include <finbook/model/scene/shot.h>

#include <algorithm>
#include <cmath>

namespace finbook::model {

namespace {
qint64 holdOf(const Frame &frame)
{
    return std::clamp(frame.hold, 1, kMaxHold);
}
} // namespace

qint64 celTicks(const std::vector<Frame> &cels)
{
    qint64 ticks = 0;
    for (const Frame &f : cels)
        ticks += holdOf(f);
    return ticks;
}

qint64 celStart(const std::vector<Frame> &cels, int index)
{
    qint64 tick = 0;
    const int end = std::clamp(index, 0, int(cels.size()));
    for (int i = 0; i < end; ++i)
        tick += holdOf(cels[std::size_t(i)]);
    return tick;
}

int celAt(const std::vector<Frame> &cels, qint64 tick)
{
    if (tick < 0)
        return -1;
    qint64 start = 0;
    for (std::size_t i = 0; i < cels.size(); ++i) {
        start += holdOf(cels[i]);
        if (tick < start)
            return int(i);
    }
    return -1;
}

qint64 shotTicks(const std::vector<Layer> &layers)
{
    qint64 ticks = 0;
    for (const Layer &l : layers)
        ticks = std::max(ticks, celTicks(l.cels));
    return ticks;
}

bool ShotFilter::admits(const Layer &layer) const
{
    if (!hiddenToo && !layer.properties.visible)
        return false;
    return onlyLayers.empty() ||
           std::find(onlyLayers.begin(), onlyLayers.end(), layer.id) != onlyLayers.end();
}

namespace {
void addPlane(Frame &shot, const Layer &layer, const Frame &cel)
{
    if (shot.id == kNoId)
        shot.id = cel.id;
    shot.groups.insert(shot.groups.end(), cel.groups.begin(), cel.groups.end());
    shot.planes.push_back(
        {int(shot.groups.size()), layer.properties.opacity, layer.properties.depth, layer.id});
}
} // namespace

Frame composeShot(const std::vector<Layer> &layers, qint64 tick, const ShotFilter &filter)
{
    Frame shot;
    for (const Layer &l : layers) {
        if (!filter.admits(l))
            continue;
        const int cel = celAt(l.cels, tick);
        if (cel >= 0)
            addPlane(shot, l, l.cels[std::size_t(cel)]);
    }
    return shot;
}

std::vector<Frame> composeShots(const std::vector<Layer> &layers, const ShotFilter &filter)
{
    // Walk every admitted layer's cels together: each stretch ends where the next cel of any
    // layer begins (or a layer ends).
    struct Cursor {
        const Layer *layer;
        std::size_t cel = 0;
        qint64 end = 0; // the tick the current cel ends at
    };
    std::vector<Cursor> cursors;
    for (const Layer &l : layers)
        if (filter.admits(l) && !l.cels.empty())
            cursors.push_back({&l, 0, holdOf(l.cels.front())});
    std::vector<Frame> shots;
    qint64 tick = 0;
    while (true) {
        Frame shot;
        qint64 next = -1;
        for (const Cursor &c : cursors) {
            if (c.cel >= c.layer->cels.size())
                continue;
            addPlane(shot, *c.layer, c.layer->cels[c.cel]);
            next = next < 0 ? c.end : std::min(next, c.end);
        }
        if (next < 0)
            break;
        shot.hold = int(std::min<qint64>(next - tick, kMaxHold));
        shots.push_back(std::move(shot));
        tick = next;
        for (Cursor &c : cursors)
            if (c.cel < c.layer->cels.size() && c.end == tick && ++c.cel < c.layer->cels.size())
                c.end += holdOf(c.layer->cels[c.cel]);
    }
    return shots;
}

CameraState planeCamera(const CameraState &camera, double depth, QSizeF page)
{
    if (depth == 0.0 || !std::isfinite(depth))
        return camera;
    const double f = 1.0 / (1.0 + std::clamp(depth, kMinLayerDepth, kMaxLayerDepth));
    const CameraState rest = restCamera(page);
    CameraState plane = camera;
    plane.center = rest.center + (camera.center - rest.center) * f;
    // A plane close in front of the lens may zoom far; kept finite and invertible.
    plane.zoom = std::clamp(rest.zoom * std::pow(camera.zoom / rest.zoom, f), 1e-4, 1e4);
    return plane;
}

} // namespace finbook::model
