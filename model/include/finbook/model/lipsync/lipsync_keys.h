// Keying a mouth from lip sync (issue 49): one mouth shape per tick becomes, on the mouth's
// layer, the drawing of its swap set each tick shows. Cels are split where the mouth changes
// inside them (each piece a copy of the cel: what else it holds looks the same) and the layer's
// last cel is held longer when the speech runs past it. One undo step; keying the same range
// again replaces what it showed.
#pragma once

#include <finbook/model/document.h>
#include <finbook/model/lipsync/mouth_shape.h>

#include <optional>
#include <vector>

namespace finbook::model::lipsync {

// The drawing of `set` each shape shows: the drawing named by the shape's letter (a mouth
// chart's "A (M B P)", or just "A"), else the one its stand-in is named by (G → B, H → C,
// X → A, as Rhubarb stands in for its extended shapes), else none. Null when the set has no
// drawing for A, B, C, D, E or F.
std::optional<std::vector<Id>> drawingsForShapes(const SwapSet &set);

struct LipSyncResult {
    QString error;        // empty when keyed
    int keyed = 0;        // ticks whose mouth was set
    int withoutMouth = 0; // ticks whose cel holds no object of the set (left as they were)
};

// Pushes, as one undo step named `text`, the keys of `shapes` (one per tick from `startTick`)
// onto the swap set object `mouthId` shows, on its layer. Fails (nothing pushed) when the object
// shows no set, its set lacks the shapes, or there is nothing to key.
LipSyncResult keyMouth(Document *doc, Id mouthId, qint64 startTick,
                       const std::vector<MouthShape> &shapes, const QString &text);

} // namespace finbook::model::lipsync
