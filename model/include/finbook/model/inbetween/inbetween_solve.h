// The synchronous way to pose planned in-betweens (benchmarks, tests, the dialog's preview):
// one DeformSetup per distinct drawing and rest definition, built once with buildDeformSetup,
// then solvePose per frame. In the app the DeformController does the same on insertion.
#pragma once

#include <finbook/deform/arap.h>
#include <finbook/model/deform_setup.h>

#include <memory>
#include <vector>

namespace finbook::model {

using DeformSetupCache = std::vector<std::shared_ptr<const DeformSetup>>;

// The setup in `cache` that serves `group` with `options`, else one built now (reusing a
// cached mesh of the same drawing) and added to it. Errors: sentences for the user.
Expected<std::shared_ptr<const DeformSetup>, QString>
setupFromCache(const StrokeGroup &group, const deform::ArapOptions &options,
               DeformSetupCache &cache, double closeGap);

// Solves every object of `frames` that has a rig and no pose (deformed == nullptr). `cache`
// (optional) offers setups to reuse — e.g. the keys' — and receives the ones built here.
// Returns how many objects were solved, or the first error (frames solved before it keep
// their poses). `closeGap`: the document's Close gaps (the shape the objects are meshed from).
Expected<int, QString> solveInbetweenPoses(std::vector<Frame> &frames,
                                           const deform::ArapOptions &options = {},
                                           DeformSetupCache *cache = nullptr,
                                           double closeGap = -1.0);

} // namespace finbook::model
