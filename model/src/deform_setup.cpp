// The part of every deformer that is the same for all kinds: the content key, meshing, the
// job → setup dispatch, turning solved points into strokes, and mapping clicks back to rest.
#include "deformation_text.h"
#include "picture/picture_cut.h"

#include <finbook/model/cage/cage_setup.h>
#include <finbook/model/deform_setup.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/pins/pin_setup.h>
#include <finbook/model/rig/rig_commands.h>
#include <finbook/model/skeleton/skeleton_setup.h>
#include <finbook/model/stroke_input.h>

#include <algorithm>
#include <cmath>

namespace finbook::model {

std::vector<geometry::StrokeInput> strokeInputs(const MeshKey &key)
{
    std::vector<geometry::StrokeInput> inputs;
    inputs.reserve(key.strokes.size());
    for (const StrokeDataPtr &data : key.strokes) {
        if (!data || data->points.empty()) // nothing to outline
            continue;
        inputs.push_back(strokeInput(data->points, data->width));
    }
    return inputs;
}

Eigen::MatrixX2d restPoints(const MeshKey &key, std::vector<std::size_t> &offsets)
{
    offsets.assign(1, 0);
    for (const StrokeDataPtr &data : key.strokes)
        offsets.push_back(offsets.back() + data->points.size());
    const Eigen::MatrixX2d picture = key.picture ? key.picture->restVertices() : Eigen::MatrixX2d();
    Eigen::MatrixX2d points(Eigen::Index(offsets.back()) + picture.rows(), 2);
    Eigen::Index row = 0;
    for (const StrokeDataPtr &data : key.strokes)
        for (const StrokePoint &p : data->points)
            points.row(row++) << p.x, p.y;
    if (picture.rows() > 0)
        points.bottomRows(picture.rows()) = picture;
    return points;
}

bool operator==(const MeshKey &a, const MeshKey &b)
{
    const bool samePicture =
        a.picture == b.picture || (a.picture && b.picture && *a.picture == *b.picture);
    return samePicture && a.strokes == b.strokes && a.density == b.density &&
           a.closeGap == b.closeGap;
}

MeshKey MeshKey::of(const StrokeGroup &group, double closeGap)
{
    MeshKey key;
    key.density = group.meshDensity;
    key.closeGap = std::isfinite(closeGap) && closeGap >= 0.0 ? closeGap : -1.0;
    key.strokes.reserve(group.strokes.size());
    for (const Stroke &s : group.strokes)
        key.strokes.push_back(s.data);
    key.picture = group.picture;
    return key;
}

const Eigen::MatrixX2d &DeformSetup::meshVertices() const
{
    return cage                        ? cage->meshVertices()
           : skeleton && skeleton->cut ? skeleton->cut->V
                                       : meshed->mesh.V;
}

const Eigen::MatrixX3i &DeformSetup::meshTriangles() const
{
    return cage                        ? cage->meshTriangles()
           : skeleton && skeleton->cut ? skeleton->cut->F
                                       : meshed->mesh.F;
}

bool DeformSetup::matches(const StrokeGroup &group, double closeGap) const
{
    // Pins are compared by where they sit, not by id: a duplicated frame's pins have new ids
    // but the same rest positions, and may share this factorization.
    return sameRestDefinition(rest, group.rig) && key == MeshKey::of(group, closeGap);
}

namespace {

// A picture object's mesh: its texture mesh as it is at the usual density (the picture's
// vertices then sit on the mesh's own), its outline meshed anew at another. Strokes drawn on a
// picture object ride on the picture's mesh (embedded in the nearest triangle where they leave
// it).
Expected<geometry::ObjectMesh, geometry::GeometryError> pictureObjectMesh(const ObjectPicture &p,
                                                                          double density)
{
    if (!pictureIsValid(p))
        return unexpected(geometry::GeometryError{geometry::GeometryErrorCode::DegenerateRegion,
                                                  "The picture has no mesh."});
    auto mesh = geometry::objectMeshFrom(p.restVertices(), p.mesh->F);
    if (!mesh || density == kDefaultMeshDensity)
        return mesh;
    geometry::MeshOptions options;
    options.targetVertices =
        std::clamp(int(geometry::regionArea(mesh->region) / 64.0), 64, kPictureMeshVertices);
    options.density = density;
    options.repair.cornerRadius = 0.0;
    options.repair.simplifyTolerance = 0.1;
    return geometry::buildObjectMesh(mesh->region, options);
}

// Whether `meshed` is the picture's texture mesh itself (the usual density), so that a cut of
// it is a cut of the picture.
bool meshIsPictures(const MeshedObject &meshed, const ObjectPicture &picture)
{
    const geometry::ObjectMesh &mesh = meshed.mesh;
    return pictureIsValid(picture) && mesh.V.rows() == picture.mesh->uv.rows() &&
           mesh.F.rows() == picture.mesh->F.rows() &&
           (mesh.F.array() == picture.mesh->F.array()).all();
}

} // namespace

Expected<std::shared_ptr<const MeshedObject>, QString> meshObject(const MeshKey &key)
{
    if (key.strokes.empty() && !key.picture)
        return unexpected(Deformation::tr("The object has no strokes to deform."));
    geometry::MeshOptions options;
    options.density = key.density;
    options.regions.closeGap = key.closeGap;
    auto mesh = key.picture ? pictureObjectMesh(*key.picture, key.density)
                            : geometry::buildObjectMesh(strokeInputs(key), options);
    if (!mesh)
        return unexpected(Deformation::tr("This drawing cannot be meshed for deformation: %1")
                              .arg(QString::fromStdString(mesh.error().message)));
    auto meshed = std::make_shared<MeshedObject>();
    meshed->mesh = std::move(*mesh);
    const Eigen::MatrixX2d points = restPoints(key, meshed->strokeOffsets);
    meshed->embedding = geometry::embed(meshed->mesh.V, meshed->mesh.F, points);
    return std::shared_ptr<const MeshedObject>(std::move(meshed));
}

Expected<std::shared_ptr<const DeformSetup>, QString>
buildDeformSetup(const DeformJob &job, const std::function<bool()> &cancelled)
{
    auto setup = std::make_shared<DeformSetup>();
    setup->key = job.key;
    setup->rest = job.rig.atRest();
    setup->options = job.options;
    if (job.rig.kind() == RigKind::Cage) {
        // The cage carries its own interior mesh; the object's mesh is not needed.
        auto cage = buildCageSetup(job.key, job.rig.cage.rest, cancelled);
        if (!cage)
            return unexpected(cage.error());
        setup->cage = *cage;
        return std::shared_ptr<const DeformSetup>(std::move(setup));
    }
    setup->meshed = job.meshed;
    if (!setup->meshed) {
        auto meshed = meshObject(job.key);
        if (!meshed)
            return unexpected(meshed.error());
        setup->meshed = *meshed;
    }
    if (cancelled && cancelled())
        return unexpected(Deformation::tr("Cancelled."));
    if (job.rig.kind() == RigKind::Pins) {
        auto pins = buildPinSetup(*setup->meshed, job.rig.pins, job.options, cancelled);
        if (!pins)
            return unexpected(pins.error());
        setup->pins = *pins;
    }
    if (job.rig.kind() == RigKind::Skeleton) {
        auto skeleton =
            buildSkeletonSetup(*setup->meshed, job.rig.skeleton, job.options, cancelled);
        if (!skeleton)
            return unexpected(skeleton.error());
        setup->skeleton = *skeleton;
    }
    return std::shared_ptr<const DeformSetup>(std::move(setup));
}

DeformedStrokesPtr strokesFromPoints(const StrokeGroup &group, const Eigen::MatrixX2d &points)
{
    auto strokes = std::make_shared<DeformedStrokes>();
    strokes->strokes.resize(group.strokes.size());
    Eigen::Index row = 0;
    for (std::size_t s = 0; s < group.strokes.size(); ++s) {
        const auto &rest = group.strokes[s].data->points;
        auto &out = strokes->strokes[s];
        out.resize(rest.size());
        for (std::size_t i = 0; i < rest.size() && row < points.rows(); ++i, ++row)
            out[i] = {float(points(row, 0)), float(points(row, 1)), rest[i].pressure};
    }
    if (group.picture && group.picture->mesh &&
        points.rows() - row == group.picture->mesh->uv.rows()) {
        strokes->pictureVertices.reserve(std::size_t(points.rows() - row));
        for (; row < points.rows(); ++row)
            strokes->pictureVertices.emplace_back(points(row, 0), points(row, 1));
    }
    return strokes;
}

bool sameSolverOptions(const deform::ArapOptions &a, const deform::ArapOptions &b)
{
    return a.method == b.method && a.extraPasses == b.extraPasses;
}

Expected<Pose, QString> solvePose(const DeformSetup &setup, const StrokeGroup &group,
                                  PoseStage stage, const std::function<bool()> &cancelled,
                                  const Eigen::MatrixX2d *dragStart)
{
    Pose pose;
    Eigen::MatrixX2d points;
    if (setup.cage) {
        if (group.rig.cage.posed.size() != setup.rest.cage.rest.size())
            return unexpected(Deformation::tr("The cage changed while it was being prepared."));
        auto solved = solveCage(*setup.cage, group.rig.cage.posed);
        if (!solved)
            return unexpected(solved.error());
        pose.vertices = std::move(solved->meshVertices);
        points = std::move(solved->points);
    } else {
        if (!setup.meshed)
            return unexpected(Deformation::tr("The object has no mesh to deform."));
        if (setup.pins && group.rig.pins.size() == setup.rest.pins.size()) {
            auto solved =
                solvePins(*setup.meshed, *setup.pins, group.rig.pins, stage, cancelled, dragStart);
            if (!solved)
                return unexpected(solved.error());
            pose.vertices = std::move(*solved);
        } else if (setup.skeleton && group.rig.kind() == RigKind::Skeleton &&
                   setup.rest.skeleton.sameRest(group.rig.skeleton)) {
            auto solved = solveSkeleton(*setup.meshed, *setup.skeleton, group.rig.skeleton);
            if (!solved)
                return unexpected(solved.error());
            pose.vertices = std::move(*solved);
        } else {
            pose.vertices = setup.meshVertices();
        }
        // A cut-out skeleton's mesh has the object mesh's triangles in the same order, so the
        // strokes' embedding holds for it too.
        points =
            geometry::applyEmbedding(setup.meshed->embedding, pose.vertices, setup.meshTriangles());
    }
    if (!points.allFinite() || !pose.vertices.allFinite())
        return unexpected(
            Deformation::tr("The deformation produced invalid points; it was not applied."));
    pose.strokes = strokesFromPoints(group, points);
    if (setup.skeleton && setup.skeleton->cut && setup.meshed) {
        auto layered = std::make_shared<DeformedStrokes>(*pose.strokes);
        addCutOutPieces(*setup.skeleton, *setup.meshed, pose.vertices, group.rig.skeleton,
                        *layered);
        if (group.picture && meshIsPictures(*setup.meshed, *group.picture))
            if (auto posed = posedSkinningSkeleton(setup.skeleton->skeleton, group.rig.skeleton))
                layered->pictureLayers =
                    cutOutPictureLayers(*group.picture, *setup.skeleton->cut, pose.vertices,
                                        setup.skeleton->skeleton, *posed);
        pose.strokes = std::move(layered);
    }
    return pose;
}

QPointF restPointFor(const DeformSetup &setup, const Eigen::MatrixX2d &U, QPointF shown)
{
    const Eigen::MatrixX2d &V = setup.meshVertices();
    const Eigen::MatrixX3i &F = setup.meshTriangles();
    const Eigen::Vector2d p(shown.x(), shown.y());
    double bestDistance = std::numeric_limits<double>::infinity();
    Eigen::Vector3d bestWeights(1, 0, 0);
    Eigen::Index bestFace = -1;
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
        const Eigen::Vector2d a = U.row(F(f, 0)), b = U.row(F(f, 1)), c = U.row(F(f, 2));
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
        rest += bestWeights(k) * V.row(F(bestFace, k)).transpose();
    return {rest.x(), rest.y()};
}

} // namespace finbook::model
