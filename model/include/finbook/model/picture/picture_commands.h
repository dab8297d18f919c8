// Bringing picture objects into a frame as one undo step (issue 51).
#pragma once

#include <finbook/model/commands.h>

#include <vector>

namespace finbook::model {

// Inserts `objects` (picture objects made by makePictureObject, ids unset) into frame
// `frameId` at `index` (on top when out of range), bottom layer first, each with a new id.
// Undo takes them out again; redo puts back the very same objects (the pictures are shared,
// never copied).
class ImportPictureCommand : public DocumentCommand {
public:
    ImportPictureCommand(Document *doc, Id frameId, int index, std::vector<StrokeGroup> objects,
                         QUndoCommand *parent = nullptr);
    const std::vector<Id> &objectIds() const { return m_ids; }
    void redo() override;
    void undo() override;

private:
    Id m_frameId;
    int m_index;
    std::vector<StrokeGroup> m_objects;
    std::vector<Id> m_ids;
};

} // namespace finbook::model
