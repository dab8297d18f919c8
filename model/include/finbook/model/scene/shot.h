// A shot: layers over time, composed into what the audience sees at one tick.
//
// Each layer's cels follow each other from tick 0, each for its hold; past its last cel a layer
// shows nothing. The shot lasts as long as its longest layer. Composing takes, at a tick, the
// cel each visible layer shows and lays them back to front into one Frame whose `planes` say
// which objects came from which layer (its opacity and depth); the renderers (render.h) paint
// each plane through its own camera (planeCamera) at its opacity.
//
// Multiplane depth uses the classic 2D parallax factor f = 1 / (1 + depth): a plane's camera
// has moved f times as far from rest as the camera has, and zoomed f times as much (in log
// scale: zoom^f); turns are the same for every plane. Depth 0 (the page) follows the camera
// exactly, a deeper plane drifts (f < 1: depth 1 moves half as far), a plane in front
// (depth < 0) rushes past (depth −0.5 moves twice as far). This is the pinhole camera over
// parallel planes to first order, with every plane drawn at the size it shows at rest.
#pragma once

#include <finbook/model/camera/camera_track.h>
#include <finbook/model/types.h>

#include <vector>

namespace finbook::model {

// Ticks the cels last, holds included.
qint64 celTicks(const std::vector<Frame> &cels);
// The first tick of cel `index` (index == size: the end).
qint64 celStart(const std::vector<Frame> &cels, int index);
// The cel on screen at `tick`, or −1 before 0 and past the last cel.
int celAt(const std::vector<Frame> &cels, qint64 tick);
// The longest layer's ticks.
qint64 shotTicks(const std::vector<Layer> &layers);

struct ShotFilter {
    bool hiddenToo = false;     // also layers that are not visible
    std::vector<Id> onlyLayers; // empty: every layer
    bool admits(const Layer &layer) const;
};

// What the audience sees at `tick`: the cels the admitted layers show, back to front, in one
// frame with a plane per layer that shows something (the frame's id is the first of them).
Frame composeShot(const std::vector<Layer> &layers, qint64 tick, const ShotFilter &filter = {});

// The whole shot as a sequence of composed frames, one per stretch in which no admitted layer
// changes its cel; holds are the stretches' ticks. Empty when no admitted layer has a cel.
std::vector<Frame> composeShots(const std::vector<Layer> &layers, const ShotFilter &filter = {});

// The camera a plane at `depth` is seen through, when the shot's camera is `camera` (see above).
CameraState planeCamera(const CameraState &camera, double depth, QSizeF page);

} // namespace finbook::model
