// "The same object" across frames (issue 45): an animator shades a character, not a frame, so
// object-wide settings such as fill shading apply to the object wherever it appears.
//
// Objects get fresh ids in every frame (Duplicate Frame, in-betweens, paste), but each copy
// keeps its name, and the object list shows that name in every frame: the name is what an
// animator sees as "the head in frame 1 is the head in frame 5". A frame that holds several
// objects of one name (two "Object"s) pairs them by their order among those of that name
// (back to front), so the second "Object" of frame 1 is the second "Object" of frame 5.
// Renaming an object in one frame makes it another object from then on.
#pragma once

#include <finbook/model/document.h>

#include <optional>
#include <vector>

namespace finbook::model {

// Object `groupId` and its namesakes in the other frames, in frame order (at most one per
// frame; the object itself included). Empty when there is no such object.
std::vector<Id> sameObjectInFrames(const Document &doc, Id groupId);

// The shading of the object's fills in the nearest frame where it has fills (before or after
// `groupId`'s own frame; the object's own fills first): what a first fill of this object in a
// new frame takes. nullopt when it has fills nowhere.
std::optional<FillShading> objectShading(const Document &doc, Id groupId);

} // namespace finbook::model
