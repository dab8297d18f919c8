// Keeping fills tied to their strokes when a copy of an object gets new ids.
#pragma once

#include <finbook/model/types.h>

#include <algorithm>
#include <unordered_map>

namespace finbook::model {

// After the strokes of `group` were renumbered (old id → new id in `ids`, as Duplicate Frame and
// in-betweens do), its fills name the same strokes by their new ids. An id the map does not
// know (a stroke erased since the fill was made) is dropped: no stroke of the copy has it.
inline void remapFillStrokeIds(StrokeGroup &group, const std::unordered_map<Id, Id> &ids)
{
    for (Fill &fill : group.fills)
        forEachFillStrokes(fill, [&](std::vector<Id> &strokes) {
            std::vector<Id> mapped;
            for (Id id : strokes)
                if (auto it = ids.find(id); it != ids.end())
                    mapped.push_back(it->second);
            std::sort(mapped.begin(), mapped.end());
            strokes = std::move(mapped);
        });
}

} // namespace finbook::model
