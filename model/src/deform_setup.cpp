#include <finbook/deform/nearest_vertex.h>
#include <finbook/model/deform_setup.h>

#include <QCoreApplication>

#include <cmath>

namespace finbook::model {

namespace {
// The translation context of these texts; a class so lupdate files the strings under
// "Deformation" too.
struct Deformation {
    Q_DECLARE_TR_FUNCTIONS(Deformation)
};

std::vector<geometry::StrokeInput> strokeInputs(const MeshKey &key)
{
    std::vector<geometry::StrokeInput> inputs;
    inputs.reserve(key.strokes.size());
    for (const StrokeDataPtr &data : key.strokes) {
        geometry::StrokeInput in;
        in.points.resize(Eigen::Index(data->points.size()), 2);
        for (std::size_t i = 0; i < data->points.size(); ++i)
            in.points.row(Eigen::Index(i)) << data->points[i].x, data->points[i].y;
        in.width = std::isfinite(data->width) ? data->width : 1.0;
        inputs.push_back(std::move(in));
    }
    return inputs;
}

Eigen::MatrixX2d allRestPoints(const MeshKey &key, std::vector<std::size_t> &offsets)
{
    offsets.assign(1, 0);
    for (const StrokeDataPtr &data : key.strokes)
        offsets.push_back(offsets.back() + data->points.size());
    Eigen::MatrixX2d points(Eigen::Index(offsets.back()), 2);
    Eigen::Index row = 0;
    for (const StrokeDataPtr &data : key.strokes)
        for (const StrokePoint &p : data->points)
            points.row(row++) << p.x, p.y;
    return points;
}
} // namespace

MeshKey MeshKey::of(const StrokeGroup &group)
{
    MeshKey key;
    key.density = group.meshDensity;
    key.strokes.reserve(group.strokes.size());
    for (const Stroke &s : group.strokes)
        key.strokes.push_back(s.data);
    return key;
}

bool DeformSetup::matches(const StrokeGroup &group) const
{
    // Pins are compared by where they sit, not by id: a duplicated frame's pins have new ids
    // but the same rest positions, and may share this factorization.
    if (Eigen::Index(group.pins.size()) != pinRest.rows() || !(key == MeshKey::of(group)))
        return false;
    for (std::size_t i = 0; i < group.pins.size(); ++i) {
        const Pin &p = group.pins[i];
        if (p.rest.x() != pinRest(Eigen::Index(i), 0) || p.rest.y() != pinRest(Eigen::Index(i), 1))
            return false;
    }
    return true;
}

Expected<std::shared_ptr<const MeshedObject>, QString> meshObject(const MeshKey &key)
{
    if (key.strokes.empty())
        return unexpected(Deformation::tr("The object has no strokes to deform."));
    geometry::MeshOptions options;
    options.density = key.density;
    auto mesh = geometry::buildObjectMesh(strokeInputs(key), options);
    if (!mesh)
        return unexpected(Deformation::tr("This drawing cannot be meshed for deformation: %1")
                              .arg(QString::fromStdString(mesh.error().message)));
    auto meshed = std::make_shared<MeshedObject>();
    meshed->mesh = std::move(*mesh);
    const Eigen::MatrixX2d points = allRestPoints(key, meshed->strokeOffsets);
    meshed->embedding = geometry::embed(meshed->mesh.V, meshed->mesh.F, points);
    return std::shared_ptr<const MeshedObject>(std::move(meshed));
}

Expected<std::shared_ptr<const DeformSetup>, QString>
buildDeformSetup(const DeformJob &job, const std::function<bool()> &cancelled)
{
    auto setup = std::make_shared<DeformSetup>();
    setup->key = job.key;
    setup->pinRest = job.pinRest;
    setup->extraPasses = job.options.extraPasses;
    setup->meshed = job.meshed;
    if (!setup->meshed) {
        auto meshed = meshObject(job.key);
        if (!meshed)
            return unexpected(meshed.error());
        setup->meshed = *meshed;
    }
    if (cancelled && cancelled())
        return unexpected(Deformation::tr("Cancelled."));
    const Eigen::MatrixX2d &V = setup->meshed->mesh.V;
    setup->pinVertex.resize(job.pinRest.rows());
    for (Eigen::Index i = 0; i < job.pinRest.rows(); ++i)
        setup->pinVertex(i) = deform::nearestVertex(V, job.pinRest.row(i).transpose());
    if (job.pinRest.rows() > 0) {
        auto arap = deform::arapPrecompute(V, setup->meshed->mesh.F, setup->pinVertex, job.options,
                                           cancelled);
        if (!arap)
            return unexpected(Deformation::tr("The pins cannot be solved on this drawing: %1")
                                  .arg(QString::fromStdString(arap.error().message)));
        setup->arap = *arap;
    }
    return std::shared_ptr<const DeformSetup>(std::move(setup));
}

Expected<Pose, QString> solvePose(const DeformSetup &setup, const StrokeGroup &group)
{
    const geometry::ObjectMesh &mesh = setup.meshed->mesh;
    Pose pose;
    if (!setup.arap || Eigen::Index(group.pins.size()) != setup.pinRest.rows()) {
        pose.vertices = mesh.V;
    } else {
        // A pin drags its vertex by the pin's own displacement, so a pin that did not land
        // exactly on a vertex still moves the drawing under it by what the user dragged.
        Eigen::MatrixX2d bc(Eigen::Index(group.pins.size()), 2);
        for (std::size_t i = 0; i < group.pins.size(); ++i) {
            const Pin &p = group.pins[i];
            const QPointF delta = p.target - p.rest;
            const Eigen::Index row = Eigen::Index(i);
            bc.row(row) =
                mesh.V.row(setup.pinVertex(row)) + Eigen::RowVector2d(delta.x(), delta.y());
        }
        auto solved = deform::arapSolve(*setup.arap, bc, pose.vertices);
        if (!solved)
            return unexpected(Deformation::tr("The pins could not be solved: %1")
                                  .arg(QString::fromStdString(solved.error().message)));
    }
    const Eigen::MatrixX2d points =
        geometry::applyEmbedding(setup.meshed->embedding, pose.vertices, mesh.F);
    if (!points.allFinite())
        return unexpected(
            Deformation::tr("The deformation produced invalid points; it was not applied."));
    auto strokes = std::make_shared<DeformedStrokes>();
    strokes->strokes.resize(group.strokes.size());
    const auto &offsets = setup.meshed->strokeOffsets;
    for (std::size_t s = 0; s < group.strokes.size() && s + 1 < offsets.size(); ++s) {
        const auto &rest = group.strokes[s].data->points;
        auto &out = strokes->strokes[s];
        out.resize(rest.size());
        for (std::size_t i = 0; i < rest.size(); ++i) {
            const Eigen::Index row = Eigen::Index(offsets[s] + i);
            out[i] = {float(points(row, 0)), float(points(row, 1)), rest[i].pressure};
        }
    }
    pose.strokes = std::move(strokes);
    return pose;
}

QPointF restPointFor(const DeformSetup &setup, const Eigen::MatrixX2d &U, QPointF shown)
{
    const geometry::ObjectMesh &mesh = setup.meshed->mesh;
    const Eigen::Vector2d p(shown.x(), shown.y());
    double bestDistance = std::numeric_limits<double>::infinity();
    Eigen::Vector3d bestWeights(1, 0, 0);
    Eigen::Index bestFace = -1;
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
        const Eigen::Vector2d a = U.row(mesh.F(f, 0)), b = U.row(mesh.F(f, 1)),
                              c = U.row(mesh.F(f, 2));
        const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
        if (std::abs(area) < 1e-12)
            continue;
        auto cross = [](Eigen::Vector2d u, Eigen::Vector2d v) {
            return u.x() * v.y() - u.y() * v.x();
        };
        Eigen::Vector3d w(cross(b - p, c - p) / area, cross(c - p, a - p) / area, 0.0);
        w.z() = 1.0 - w.x() - w.y();
        // Distance outside the triangle in barycentric terms: 0 inside.
        const double outside = -std::min({w.x(), w.y(), w.z(), 0.0});
        if (outside < bestDistance) {
            bestDistance = outside;
            bestFace = f;
            bestWeights = w.cwiseMax(0.0) / w.cwiseMax(0.0).sum();
            if (outside == 0.0)
                break;
        }
    }
    if (bestFace < 0)
        return shown;
    Eigen::Vector2d rest = Eigen::Vector2d::Zero();
    for (int k = 0; k < 3; ++k)
        rest += bestWeights(k) * mesh.V.row(mesh.F(bestFace, k)).transpose();
    return {rest.x(), rest.y()};
}

} // namespace finbook::model
