// The pins' half of a DeformSetup: which mesh vertex each pin drives and the ARAP precompute
// (Igarashi et al. 2005) for that set of vertices.
#pragma once

#include <finbook/model/deform_setup.h>

namespace finbook::model {

struct PinSetup {
    Eigen::VectorXi pinVertex; // per pin: the mesh vertex it drives
    std::shared_ptr<const deform::ArapPrecompute> arap;
};

// Snaps each pin's rest position to the nearest vertex of `meshed` and factorizes.
Expected<std::shared_ptr<const PinSetup>, QString>
buildPinSetup(const MeshedObject &meshed, const std::vector<Pin> &pins,
              const deform::ArapOptions &options, const std::function<bool()> &cancelled);

// Deformed mesh vertices (n×2) for the pins' targets. `pins` must match the setup's rest
// definition (same count and order). A Drag pose continues from `dragStart` when given (see
// solvePose).
Expected<Eigen::MatrixX2d, QString> solvePins(const MeshedObject &meshed, const PinSetup &setup,
                                              const std::vector<Pin> &pins, PoseStage stage,
                                              const std::function<bool()> &cancelled = {},
                                              const Eigen::MatrixX2d *dragStart = nullptr);

} // namespace finbook::model
