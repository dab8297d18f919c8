// An object's automatic skeleton (issue 9's pipeline) as a rig: shape of the rest strokes
// (object_shape.h: closed regions and the ink), raw straight skeleton, refinement under the panel's
// four sliders.
#include "../deformation_text.h"

#include <finbook/geometry/object_shape.h>
#include <finbook/geometry/skeleton/skeleton_refine.h>
#include <finbook/model/deform_setup.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/skeleton/skeleton_commands.h>

#include <cmath>
#include <limits>

namespace finbook::model {

namespace {

double clampUnit(double v)
{
    return std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0;
}

geometry::RefineOptions refineOptions(const geometry::RawSkeleton &raw, const SkeletonSettings &s,
                                      std::optional<QPointF> rootNear)
{
    const geometry::RefineRanges ranges = geometry::refineRanges(raw);
    geometry::RefineOptions o;
    // 0 keeps the engine's default (the fewest bones that stay inside the shape).
    o.boneTolerance = s.complexity > 0.0 ? (1.0 - s.complexity) * ranges.boneTolerance
                                         : std::numeric_limits<double>::infinity();
    o.mergeDistance = s.merge * ranges.mergeDistance;
    o.pruneLength = s.prune * ranges.pruneLength;
    o.collapseLength = s.collapse * ranges.collapseLength;
    if (rootNear && std::isfinite(rootNear->x()) && std::isfinite(rootNear->y()))
        o.rootNear = Eigen::Vector2d(rootNear->x(), rootNear->y());
    return o;
}

QString sentence(const geometry::GeometryError &e)
{
    return Deformation::tr("No skeleton can be built for this drawing: %1")
        .arg(QString::fromStdString(e.message));
}

} // namespace

Expected<SkeletonRig, QString> buildSkeletonRig(const StrokeGroup &group,
                                                const SkeletonSettings &settings,
                                                std::optional<QPointF> rootNear, double closeGap)
{
    const MeshKey key = MeshKey::of(group, closeGap);
    const auto inputs = strokeInputs(key);
    if (inputs.empty() && !group.picture)
        return unexpected(Deformation::tr("The object has no strokes to build a skeleton in."));
    // A picture object's skeleton is its picture's shape's (strokes drawn on it ride along).
    auto region =
        group.picture
            ? Expected<geometry::Region, geometry::GeometryError>(pictureRegion(*group.picture))
            : geometry::objectShape(inputs, {}, geometry::RegionsOptions{key.closeGap});
    if (!region)
        return unexpected(sentence(region.error()));
    auto raw = geometry::rawSkeleton(*region);
    if (!raw)
        return unexpected(sentence(raw.error()));
    SkeletonRig rig;
    rig.settings = {clampUnit(settings.complexity), clampUnit(settings.merge),
                    clampUnit(settings.prune), clampUnit(settings.collapse)};
    auto skeleton = geometry::refineSkeleton(*raw, refineOptions(*raw, rig.settings, rootNear));
    if (!skeleton)
        return unexpected(sentence(skeleton.error()));
    if (skeleton->jointCount() == 0)
        return unexpected(Deformation::tr("No skeleton can be built for this drawing."));
    for (int j = 0; j < skeleton->jointCount(); ++j) {
        rig.joints.emplace_back(skeleton->joints(j, 0), skeleton->joints(j, 1));
        rig.parent.push_back(skeleton->parent(j));
        rig.radius.push_back(skeleton->radius(j));
    }
    rig.root = skeleton->root;
    rig.limbBase = skeleton->limbBase; // empty or one per joint, some set (refineSkeleton)
    // A new skeleton turns its limbs as cut-out pieces: of the skinnings measured with
    // `finbook-bench limbs` it is the one whose ±60° turns leave ≥ 95 % of the limbs without a
    // fold or a flipped triangle (Rigid: about half), the body where it was. Deform → Skinning
    // switches an object to Rigid or Linear Blend; a rebuild keeps the object's choice.
    rig.mode = SkinningMode::CutOut;
    rig = rig.atRest();
    if (!rig.isValid())
        return unexpected(Deformation::tr("No skeleton can be built for this drawing."));
    return rig;
}

} // namespace finbook::model
