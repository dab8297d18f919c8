#include "finbook_file_ids.h"

#include <algorithm>

namespace finbook::model {

std::unordered_set<Id> idsIn(const LoadedDocument &doc)
{
    std::unordered_set<Id> used;
    const auto use = [&used](Id id) { used.insert(id); };
    // A swap drawing and an object alike: its id, its strokes', its pins' and its join's.
    const auto useDrawing = [&use](const auto &drawing) {
        use(drawing.id);
        for (const Stroke &s : drawing.strokes)
            use(s.id);
        for (const Pin &p : drawing.rig.pins)
            use(p.id);
        use(drawing.rig.skeleton.join.parent);
    };
    for (const SwapSet &set : doc.swapSets) {
        use(set.id);
        for (const SwapDrawing &d : set.drawings)
            useDrawing(d);
    }
    for (const Frame &f : doc.frames) {
        use(f.id);
        for (const StrokeGroup &g : f.groups) {
            useDrawing(g);
            for (const Fill &fill : g.fills) {
                std::for_each(fill.strokes.begin(), fill.strokes.end(), use);
                for (const FillPlace &place : fill.more)
                    std::for_each(place.strokes.begin(), place.strokes.end(), use);
            }
            use(g.swap.set);
            use(g.swap.drawing);
        }
    }
    for (const SoundClip &clip : doc.sound)
        use(clip.id);
    for (const LoadedLayer &l : doc.layers)
        use(l.id);
    used.erase(kNoId);
    return used;
}

Id lowestFreeId(std::unordered_set<Id> &used, Id &below)
{
    do
        ++below;
    while (used.count(below) > 0);
    used.insert(below);
    return below;
}

} // namespace finbook::model
