// What the two 3D model exports (OBJ, glTF) share: the frame's solids, the error when there
// are none, and the result that lists what was written and what was left out.
#include "export_formats.h"
#include "export_text.h"

#include <finbook/model/scene/shot.h>

#include <algorithm>
#include <cmath>

namespace finbook::model {

namespace {
// The solids as the camera sees them: each object's plane (its layer's depth) through its own
// camera (planeCamera), so x and y are the shot's pixels (y up) and heights scale with the
// zoom. The camera is a similarity (move, turn, zoom): shapes keep their proportions.
void seeThroughCamera(FrameSolids &solids, const Frame &frame, const CameraState &camera,
                      QSizeF page)
{
    for (ObjectSolid &object : solids.objects) {
        double depth = 0.0;
        int begin = 0;
        const auto group =
            std::find_if(frame.groups.begin(), frame.groups.end(),
                         [&](const StrokeGroup &g) { return g.id == object.groupId; });
        const int index = int(group - frame.groups.begin());
        for (const FramePlane &plane : frame.planes) {
            if (index >= begin && index < plane.groupEnd) {
                depth = plane.depth;
                break;
            }
            begin = plane.groupEnd;
        }
        const QTransform t = cameraTransform(planeCamera(camera, depth, page), page);
        const double scale = std::sqrt(std::abs(t.determinant()));
        if (!(scale > 0.0) || !std::isfinite(scale))
            continue;
        geometry::InflatedSolid &solid = object.solid;
        for (Eigen::Index i = 0; i < solid.V.rows(); ++i) {
            const QPointF p = t.map(QPointF(solid.V(i, 0), -solid.V(i, 1)));
            solid.V.row(i) << p.x(), -p.y(), solid.V(i, 2) * scale;
        }
        // Normals turn with the camera (the y flips cancel); the zoom does not change them.
        for (Eigen::Index i = 0; i < solid.N.rows(); ++i) {
            const double x = solid.N(i, 0), y = -solid.N(i, 1);
            const double nx = (t.m11() * x + t.m21() * y) / scale;
            const double ny = (t.m12() * x + t.m22() * y) / scale;
            solid.N.row(i) << nx, -ny, solid.N(i, 2);
        }
    }
}
} // namespace

Expected<FrameSolids, ExportError> exportedSolids(const ExportContext &context)
{
    const int frameNumber = context.plan.frames.front() + 1;
    auto solids =
        frameSolids(context.frame(0), context.source.settings,
                    [&context](int done, int total) { return !context.cancelled(done, total); });
    if (!solids)
        return unexpected(cancelledError());
    if (const CameraState *camera = context.camera(0))
        seeThroughCamera(*solids, context.frame(0), *camera,
                         QSizeF(context.source.settings.canvasSize));
    if (solids->tooLarge)
        return unexpected(exportError(
            ExportErrorCode::TooLarge,
            Export::tr("The 3D model of frame %1 would have more than %L2 vertices, the most a 3D "
                       "export writes (about 25 MB of glTF). Nothing was exported; lower the "
                       "mesh density of its objects (Deform → Mesh Density) or hide some of "
                       "them.")
                .arg(frameNumber)
                .arg(kMaxModelVertices)));
    if (!solids->objects.empty())
        return std::move(*solids);
    if (solids->candidates == 0)
        return unexpected(exportError(
            ExportErrorCode::BadOptions,
            Export::tr("Frame %1 shows no drawing to make a 3D model of; choose another frame.")
                .arg(frameNumber)));
    if (solids->tooFar == solids->skipped)
        return unexpected(exportError(
            ExportErrorCode::BadOptions,
            Export::tr("No object of frame %1 can be made 3D: their points lie more than %L2 "
                       "pixels from the page, too far out to mesh. Nothing was exported; move "
                       "the drawing back onto the page or choose another frame.")
                .arg(frameNumber)
                .arg(kMaxModelCoordinate, 0, 'f', 0)));
    if (solids->tooFar > 0)
        return unexpected(
            exportError(ExportErrorCode::BadOptions,
                        Export::tr("No object of frame %1 can be made 3D: each is a dot or a "
                                   "straight line, with no area to inflate, or lies too far "
                                   "from the page to mesh. Nothing was exported; draw a shape "
                                   "or choose another frame.")
                            .arg(frameNumber)));
    return unexpected(
        exportError(ExportErrorCode::BadOptions,
                    Export::tr("No object of frame %1 can be made 3D: each is a dot or a straight "
                               "line, with no area to inflate. Nothing was exported; draw a "
                               "shape or choose another frame.")
                        .arg(frameNumber)));
}

QString skippedSolidsNote(const ExportContext &context, const FrameSolids &solids)
{
    if (solids.skipped == 0)
        return {};
    if (solids.tooFar > 0)
        return Export::tr("%n object(s) of frame %1 could not be made 3D (a dot or a straight "
                          "line has no area to inflate; a drawing far off the page cannot be "
                          "meshed) and were left out.",
                          nullptr, solids.skipped)
            .arg(context.plan.frames.front() + 1);
    return Export::tr("%n object(s) of frame %1 could not be made 3D (a dot or a straight line "
                      "has no area to inflate) and were left out.",
                      nullptr, solids.skipped)
        .arg(context.plan.frames.front() + 1);
}

ExportResult modelResult(const ExportContext &context, const QStringList &files,
                         const FrameSolids &solids)
{
    ExportResult result;
    result.files = files;
    result.fileCount = files.size();
    result.images = 1;
    result.ticks = context.plan.ticks;
    result.size = context.plan.size;
    result.note = skippedSolidsNote(context, solids);
    return result;
}

} // namespace finbook::model
