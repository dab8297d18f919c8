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
    if (!solids->objects.empty())
        return std::move(*solids);
    if (solids->candidates == 0)
        return unexpected(exportError(
            ExportErrorCode::BadOptions,
            Export::tr("Frame %1 shows no drawing to make a 3D model of; choose another frame.")
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
