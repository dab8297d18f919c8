#include "finbook_file_ids.h"

#include <algorithm>

namespace finbook::model {

std::unordered_set<Id> idsIn(const LoadedDocument &doc)
{
    std::unordered_set<Id> used;
    const auto use = [&used](Id id) { used.insert(id); };
    const auto useRig = [&use](const Rig &rig) {
        for (const Pin &p : rig.pins)
            use(p.id);
        use(rig.skeleton.join.parent);
    };
    for (const SwapSet &set : doc.swapSets) {
        use(set.id);
        for (const SwapDrawing &d : set.drawings) {
            use(d.id);
            for (const Stroke &s : d.strokes)
                use(s.id);
            useRig(d.rig);
        }
    }
    for (const Frame &f : doc.frames) {
        use(f.id);
        for (const StrokeGroup &g : f.groups) {
            use(g.id);
            for (const Stroke &s : g.strokes)
                use(s.id);
            useRig(g.rig);
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
