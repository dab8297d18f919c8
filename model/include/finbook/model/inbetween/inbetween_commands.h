// Inserting planned in-betweens into the document as one undo step.
#pragma once

#include <finbook/model/commands.h>
#include <finbook/model/inbetween/inbetween_plan.h>

#include <optional>
#include <utility>

namespace finbook::model {

// Plans `count` (1..kMaxInbetweens) in-betweens between two key frames (given in either
// order: the earlier one in the document is the first key) and inserts them right after the
// first key, under new ids for frames, objects, strokes and pins (stroke points are shared with
// the keys). Their poses are solved by whoever follows the document (the DeformController);
// undo takes exactly these frames out again. Obsolete when a key is missing, the keys are the
// same frame, or count is out of range.
class InsertInbetweensCommand : public DocumentCommand {
public:
    static constexpr int kMaxInbetweens = 60;

    // `fits`: Between Drawings' fits of the keys' objects drawn differently (fitKeyDrawings on
    // the earlier key, then the later one); without them such objects switch over half way.
    InsertInbetweensCommand(Document *doc, Id firstKey, Id secondKey, int count,
                            const InbetweenOptions &options, const DrawingFits &fits = {},
                            QUndoCommand *parent = nullptr);
    // The same with the in-betweens already planned (planInbetweens of the earlier key, then
    // the later one: the dialog plans them off the GUI thread when drawings are carried).
    InsertInbetweensCommand(Document *doc, Id firstKey, Id secondKey, InbetweenPlan plan,
                            QUndoCommand *parent = nullptr);
    const InbetweenPlan &plan() const { return m_plan; }
    // Ids of the inserted frames, in order.
    std::vector<Id> frameIds() const;
    void redo() override;
    void undo() override;

private:
    // The keys' indices, earlier first (obsolete and nullopt when they or count are not valid).
    std::optional<std::pair<int, int>> keyIndices(Id firstKey, Id secondKey, int count);
    void take(InbetweenPlan plan); // the frames under new ids

    Id m_firstKey = kNoId;
    Id m_layer = kNoId;   // the keys' layer (the current one when the command was made)
    InbetweenPlan m_plan; // frames carry their new ids; undo stores them back with their poses
};

} // namespace finbook::model
