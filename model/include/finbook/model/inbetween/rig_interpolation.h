// Interpolating a rig's pose targets between two keys. A pose is a pure function of the rig's
// targets (deform_setup.h), so an in-between is the deformer re-solved at interpolated targets
// rather than a blend of stroke points.
#pragma once

#include <finbook/model/types.h>

#include <vector>

namespace finbook::model {

// How targets travel between keys.
//  - Arc: the targets' best-fitting rigid motion from the first key to the second (2D
//    Procrustes: the rotation along the shorter arc) is followed as a turn about its fixed
//    point, and whatever is not rigid is blended linearly. A hand pin swung about a shoulder
//    pin travels on the circle, so a pinned limb keeps its length.
//  - Straight: every target moves along the straight line between its two positions. A swung
//    limb's pins come closer half way, so the deformer has to squash it.
enum class TargetPath { Arc, Straight };

// Whether two keys' rigs can be interpolated: same kind, same rest definition (pins by rest
// position and order, cage rest corners, skeleton rest joints and parents) and, for a
// skeleton, the same skinning mode. Targets and pin ids may differ; a skeleton's angles may be
// left out in either key (empty = at rest). Empty rigs cannot be interpolated.
bool canInterpolateRigs(const Rig &first, const Rig &second);

// Target positions at t for two sets of the same size (and order). t <= 0 gives `first`
// exactly, t >= 1 gives `second` exactly; NaN t counts as 0. Sizes that differ give `first`.
std::vector<QPointF> interpolateTargets(const std::vector<QPointF> &first,
                                        const std::vector<QPointF> &second, double t,
                                        TargetPath path);

// The rig at t: `first`'s rest definition and pin ids, targets between the keys' (see
// interpolateTargets); a skeleton's joint angles along the shorter arc (one per joint), its
// root offset along the line. t <= 0 (or NaN) gives `first`, t >= 1 `second`'s targets, exactly.
// Needs canInterpolateRigs(first, second); otherwise returns `first`.
Rig interpolateRig(const Rig &first, const Rig &second, double t, TargetPath path);

} // namespace finbook::model
