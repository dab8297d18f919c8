#include "../deformation_text.h"

#include <finbook/geometry/cage/cage_polygon.h>
#include <finbook/geometry/cage/fit_cage.h>
#include <finbook/geometry/simplicity.h>
#include <finbook/model/cage/cage_setup.h>
#include <finbook/model/picture/picture_object.h>

#include <cmath>

namespace finbook::model {

namespace {
Eigen::MatrixX2d toMatrix(const std::vector<QPointF> &points)
{
    Eigen::MatrixX2d m(Eigen::Index(points.size()), 2);
    for (std::size_t i = 0; i < points.size(); ++i)
        m.row(Eigen::Index(i)) << points[i].x(), points[i].y();
    return m;
}

QString sentence(const std::string &message)
{
    return QString::fromStdString(message);
}

} // namespace

Expected<std::shared_ptr<const CageSetup>, QString>
buildCageSetup(const MeshKey &key, const std::vector<QPointF> &corners,
               const std::function<bool()> &cancelled)
{
    auto coordinates = deform::cagePrecompute(toMatrix(corners), {}, cancelled);
    if (!coordinates)
        return unexpected(Deformation::tr("The cage cannot be used: %1")
                              .arg(sentence(coordinates.error().message)));
    std::vector<std::size_t> offsets;
    auto bound = deform::cageBind(**coordinates, restPoints(key, offsets));
    if (!bound) {
        if (bound.error().code == deform::DeformErrorCode::PointsOutsideCage)
            return unexpected(Deformation::tr("%n stroke point(s) lie outside the cage; "
                                              "move its corners out so it encloses the drawing.",
                                              nullptr, int(bound.error().items.size())));
        return unexpected(Deformation::tr("The drawing cannot be bound to the cage: %1")
                              .arg(sentence(bound.error().message)));
    }
    auto setup = std::make_shared<CageSetup>();
    setup->coordinates = *coordinates;
    setup->binding = std::move(*bound);
    return std::shared_ptr<const CageSetup>(std::move(setup));
}

Expected<CageSolution, QString> solveCage(const CageSetup &setup, const std::vector<QPointF> &posed)
{
    const Eigen::MatrixX2d corners = toMatrix(posed);
    CageSolution solution;
    if (auto error = deform::cageDeform(setup.binding, corners, solution.points))
        return unexpected(
            Deformation::tr("The cage could not be solved: %1").arg(sentence(error->message)));
    auto mesh = deform::cageDeformMesh(*setup.coordinates, corners);
    if (!mesh)
        return unexpected(Deformation::tr("The cage could not be solved: %1")
                              .arg(sentence(mesh.error().message)));
    solution.meshVertices = std::move(*mesh);
    return solution;
}

std::optional<QString> cageProblem(const StrokeGroup &group, const std::vector<QPointF> &corners)
{
    const Eigen::MatrixX2d cage = toMatrix(corners);
    if (auto error = geometry::checkCage(cage))
        return Deformation::tr("This cage cannot be used: %1").arg(sentence(error->message));
    std::vector<std::size_t> offsets;
    if (auto error =
            geometry::checkCageContains(cage, restPoints(MeshKey::of(group, -1.0), offsets)))
        return Deformation::tr("The cage must enclose the whole object: %1")
            .arg(sentence(error->message));
    return std::nullopt;
}

bool cageCrossesItself(const std::vector<QPointF> &corners)
{
    return corners.size() >= 3 && !geometry::isSimple(toMatrix(corners));
}

Expected<std::vector<QPointF>, QString> fitCage(const StrokeGroup &group, int corners,
                                                double closeGap)
{
    geometry::FitCageOptions options;
    options.corners = corners;
    const MeshKey key = MeshKey::of(group, closeGap);
    options.regions.closeGap = key.closeGap;
    std::vector<std::size_t> offsets;
    auto cage = group.picture ? geometry::fitCage(pictureRegion(*group.picture),
                                                  restPoints(key, offsets), options)
                              : geometry::fitCage(strokeInputs(key), options);
    if (!cage)
        return unexpected(
            Deformation::tr("No cage fits this drawing: %1").arg(sentence(cage.error().message)));
    std::vector<QPointF> out;
    for (Eigen::Index i = 0; i < cage->rows(); ++i)
        out.emplace_back((*cage)(i, 0), (*cage)(i, 1));
    return out;
}

} // namespace finbook::model
