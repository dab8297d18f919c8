// Fresh ids for a frame and everything in it (objects, strokes, pins), for a copy that must
// not share ids with its source (in-betweens, a duplicated layer). Stroke points stay shared;
// fills and skeleton joins follow the new ids.
#pragma once

#include <finbook/model/document.h>
#include <finbook/model/fill/fill_ids.h>
#include <finbook/model/skeleton/skeleton_join.h>

#include <unordered_map>

namespace finbook::model {

inline void renumberFrame(Frame &frame, Document *doc)
{
    frame.id = doc->allocateId();
    std::unordered_map<Id, Id> groupIds;
    for (StrokeGroup &g : frame.groups) {
        const Id old = g.id;
        g.id = doc->allocateId();
        groupIds[old] = g.id;
        std::unordered_map<Id, Id> strokeIds;
        for (Stroke &s : g.strokes)
            s.id = strokeIds[s.id] = doc->allocateId();
        remapFillStrokeIds(g, strokeIds);
        for (Pin &p : g.rig.pins)
            p.id = doc->allocateId();
    }
    remapJoins(frame, groupIds);
}

} // namespace finbook::model
