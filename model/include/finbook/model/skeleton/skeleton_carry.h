// Hand edits surviving a rebuild (issue 21): when strokes are added to or erased from an object
// with an unposed skeleton, the rebuilt automatic skeleton keeps the old one's hand-moved joints
// and locks where they still fit.
#pragma once

#include <finbook/model/skeleton/skeleton_rig.h>

namespace finbook::model {

// `rebuilt` (from buildSkeletonRig on the new drawing) with the joints of `old` carried over:
// each joint of `rebuilt` whose nearest joint of the same kind in `old` (tip, inner joint or
// junction) is mutually nearest and within 1.5 inscribed radii (the larger of the two) takes
// that old joint's position and lock. So a joint moved by hand by less than that, and every
// lock, stays where the drawing did not change there; a joint the new drawing moved further
// (an arm drawn longer) takes its new place. Sizes, parents and the root of `rebuilt` are
// kept; a result that would not be valid is `rebuilt` unchanged.
SkeletonRig carryHandEdits(const SkeletonRig &old, const SkeletonRig &rebuilt);

} // namespace finbook::model
