// Internal: the ids a loaded document holds, for new ids once they reach kMaxId (a damaged file,
// or one whose ids were used up, may hold the largest id there is).
#pragma once

#include <finbook/model/finbook_file.h>

#include <unordered_set>

namespace finbook::model {

// Every id `doc` holds or refers to: its frames', objects', strokes', pins', layers', sound
// clips', swap sets' and drawings', and the strokes its fills, the parts its joins and the
// drawings its swap links name.
std::unordered_set<Id> idsIn(const LoadedDocument &doc);

// The lowest id above `below` that `used` does not hold; `used` takes it and `below` moves to
// it, so the next call gives the next one.
Id lowestFreeId(std::unordered_set<Id> &used, Id &below);

} // namespace finbook::model
