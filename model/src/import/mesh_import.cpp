#include <finbook/geometry/import/off_mesh.h>
#include <finbook/model/import/mesh_import.h>

#include <QCoreApplication>
#include <QFile>

#include <algorithm>

namespace finbook::model {

namespace {
struct MeshImport {
    Q_DECLARE_TR_FUNCTIONS(MeshImport)
};
} // namespace

Expected<std::vector<StrokeDataPtr>, QString> importMeshStrokes(const QString &path, QSize canvas,
                                                                QRgb color, float width)
{
    auto mesh = geometry::readOff(QFile::encodeName(path).toStdString());
    if (!mesh)
        return unexpected(MeshImport::tr("Cannot import \"%1\": %2")
                              .arg(path, QString::fromStdString(mesh.error().message)));
    const std::vector<Eigen::MatrixX2d> rings = geometry::boundaryRings(*mesh);
    if (rings.empty() || mesh->V.rows() == 0)
        return unexpected(
            MeshImport::tr("Cannot import \"%1\": the mesh has no boundary to draw.").arg(path));
    const Eigen::RowVector2d lo = mesh->V.colwise().minCoeff(), hi = mesh->V.colwise().maxCoeff();
    const double extent = std::max(hi.x() - lo.x(), hi.y() - lo.y());
    const double scale =
        extent > 0 ? (2.0 / 3.0) * std::min(canvas.width(), canvas.height()) / extent : 1.0;
    const Eigen::RowVector2d centre = (lo + hi) / 2;
    std::vector<StrokeDataPtr> strokes;
    for (const Eigen::MatrixX2d &ring : rings) {
        auto data = std::make_shared<StrokeData>();
        data->color = color;
        data->width = width;
        for (Eigen::Index i = 0; i <= ring.rows(); ++i) { // closed: back to the first point
            const Eigen::RowVector2d p = ring.row(i % ring.rows()) - centre;
            data->points.push_back({float(canvas.width() / 2.0 + scale * p.x()),
                                    float(canvas.height() / 2.0 - scale * p.y()), 1.0f});
        }
        strokes.push_back(std::move(data));
    }
    return strokes;
}

} // namespace finbook::model
