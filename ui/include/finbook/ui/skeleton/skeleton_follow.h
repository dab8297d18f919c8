// "It appears as you draw" (issue 9): while View → Show Skeleton is on, an object whose
// skeleton is unposed gets it rebuilt, with its own settings, after each stroke edit (add,
// erase, delete, cut). The rebuild goes into the stroke edit's undo macro, so one undo takes
// back the strokes and the skeleton together and redo gives exactly the same bones (a
// rebuild pushed after the macro would be a second step, and a merge across command types
// is not something QUndoStack does).
//
// A rebuild starts from the drawing, so hand joint edits and locks of that object are
// replaced (undo brings them back); with Show Skeleton off nothing follows.
#pragma once

#include <finbook/model/types.h>

#include <vector>

namespace finbook::ui {

class EditorState;

// Of `groupIds`, the objects whose skeleton follows the drawing now: Show Skeleton is on and
// the skeleton is unposed. Ask before the edit (which may apply a pose and so unpose it).
std::vector<model::Id> skeletonsFollowing(const EditorState &state,
                                          const std::vector<model::Id> &groupIds);

// Pushes (into the open macro) a rebuild of the skeleton of each of `groupIds` (from
// skeletonsFollowing) that still has an unposed skeleton, when state.showSkeleton(). The root stays
// near the old root, the skinning mode is kept. An object left without strokes loses its skeleton;
// a drawing the builder cannot skeletonise keeps the old one.
void followDrawing(EditorState &state, const std::vector<model::Id> &groupIds);

} // namespace finbook::ui
