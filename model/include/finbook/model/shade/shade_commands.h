// The shading edits (issue 27), each one undo step that restores exactly: how an object's
// fills are shaded, and where the document's light comes from.
#pragma once

#include <finbook/model/commands.h>

#include <memory>

namespace finbook::model {

// Shades every fill of object `groupId` as `shading` (ramp Off: flat again), in every frame
// where the object appears (shade/same_object.h: its namesakes), as one undo step. Null when
// the object is gone, has no fill, or every fill of it in every frame is already shaded so.
std::unique_ptr<QUndoCommand> shadeFillsCommand(Document *doc, Id groupId,
                                                const FillShading &shading);

// Moves the document's light (degrees; sanitizedSettings wraps the azimuth into [0, 360) and
// clamps the elevation to [0, 90], non-finite values give the default). Null when unchanged.
std::unique_ptr<QUndoCommand> setLightCommand(Document *doc, double azimuth, double elevation);

} // namespace finbook::model
