#include "../deformation_text.h"

#include <finbook/deform/nearest_vertex.h>
#include <finbook/model/pins/pin_setup.h>

namespace finbook::model {

Expected<std::shared_ptr<const PinSetup>, QString>
buildPinSetup(const MeshedObject &meshed, const std::vector<Pin> &pins,
              const deform::ArapOptions &options, const std::function<bool()> &cancelled)
{
    auto setup = std::make_shared<PinSetup>();
    const Eigen::MatrixX2d &V = meshed.mesh.V;
    setup->pinVertex.resize(Eigen::Index(pins.size()));
    for (std::size_t i = 0; i < pins.size(); ++i)
        setup->pinVertex(Eigen::Index(i)) =
            deform::nearestVertex(V, Eigen::Vector2d(pins[i].rest.x(), pins[i].rest.y()));
    auto arap = deform::arapPrecompute(V, meshed.mesh.F, setup->pinVertex, options, cancelled);
    if (!arap)
        return unexpected(Deformation::tr("The pins cannot be solved on this drawing: %1")
                              .arg(QString::fromStdString(arap.error().message)));
    setup->arap = *arap;
    return std::shared_ptr<const PinSetup>(std::move(setup));
}

Expected<Eigen::MatrixX2d, QString> solvePins(const MeshedObject &meshed, const PinSetup &setup,
                                              const std::vector<Pin> &pins, PoseStage stage,
                                              const std::function<bool()> &cancelled,
                                              const Eigen::MatrixX2d *dragStart)
{
    // A pin drags its vertex by the pin's own displacement, so a pin that did not land
    // exactly on a vertex still moves the drawing under it by what the user dragged.
    Eigen::MatrixX2d bc(Eigen::Index(pins.size()), 2);
    for (std::size_t i = 0; i < pins.size(); ++i) {
        const QPointF delta = pins[i].target - pins[i].rest;
        const Eigen::Index row = Eigen::Index(i);
        bc.row(row) =
            meshed.mesh.V.row(setup.pinVertex(row)) + Eigen::RowVector2d(delta.x(), delta.y());
    }
    Eigen::MatrixX2d U;
    auto solved = stage == PoseStage::Preview ? deform::arapSolve(*setup.arap, bc, U)
                  : stage == PoseStage::Drag && dragStart
                      ? deform::arapSolveFrom(*setup.arap, bc, *dragStart, U)
                      : deform::arapSolve(*setup.arap, bc, U,
                                          stage == PoseStage::Drag ? deform::ArapStage::Drag
                                                                   : deform::ArapStage::Final,
                                          cancelled);
    if (!solved)
        return unexpected(Deformation::tr("The pins could not be solved: %1")
                              .arg(QString::fromStdString(solved.error().message)));
    return U;
}

} // namespace finbook::model
