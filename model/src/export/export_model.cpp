// What the two 3D model exports (OBJ, glTF) share: the frame's solids, the error when there
// are none, and the result that lists what was written and what was left out.
#include "export_formats.h"
#include "export_text.h"

namespace finbook::model {

Expected<FrameSolids, ExportError> exportedSolids(const ExportContext &context)
{
    const int frameNumber = context.plan.frames.front() + 1;
    auto solids =
        frameSolids(context.frame(0), context.source.settings,
                    [&context](int done, int total) { return !context.cancelled(done, total); });
    if (!solids)
        return unexpected(cancelledError());
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
