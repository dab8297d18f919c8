// Object edits built from more than one low-level mutation.
#pragma once

#include <finbook/model/commands.h>

#include <optional>
#include <vector>

namespace finbook::model {

// Moves every stroke of object `sourceId` into object `targetId` (both in one frame) and
// removes the source, as one undo step. The drawing looks the same afterwards: the source's
// strokes go on top of the target's when the source was above it, underneath otherwise, and a
// posed (deformed) source is baked into its strokes. Stroke ids are kept. The target keeps its
// pins; its solved pose is dropped (its rest drawing changed) and restored by undo, which puts
// back both objects exactly as they were. The source's fills join the target's. Pictures
// (picture/picture_object.h) become the target's one picture, stacked as they were
// (stackedPicture). Merging objects whose look that cannot keep (mergeRefusal) does nothing.
class MergeObjectsCommand : public DocumentCommand {
public:
    MergeObjectsCommand(Document *doc, Id sourceId, Id targetId, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_sourceId;
    Id m_targetId;
    Id m_frameId = kNoId;
    int m_sourceIndex = -1;
    std::optional<StrokeGroup> m_source;
    std::vector<Stroke> m_targetStrokes;
    std::vector<Fill> m_targetFills;
    DeformedStrokesPtr m_targetDeformed;
    std::shared_ptr<const ObjectPicture> m_targetPicture, m_mergedPicture;
};

// Why objects `bottomUp` (ids of one frame, lowest first) cannot be merged into one without
// changing what they show, or an empty string when they can. An object draws its picture
// under its lines, so the lines of an object may not lie under another's picture.
QString mergeRefusal(const Document &doc, const std::vector<Id> &bottomUp);

} // namespace finbook::model
