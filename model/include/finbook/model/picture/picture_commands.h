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

// Gives object `groupId` the picture `picture` (null: the object keeps no picture) as one undo
// step named `text`: a move, turn or scale of a picture object (movedPicture), or taking its
// picture away. The object's pose is dropped as by any rest edit (apply it first to keep it);
// undo puts back the picture and the pose as they were. Obsolete when the object is not there.
class SetPictureCommand : public DocumentCommand {
public:
    SetPictureCommand(Document *doc, Id groupId, std::shared_ptr<const ObjectPicture> picture,
                      const QString &text, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    std::shared_ptr<const ObjectPicture> m_old;
    std::shared_ptr<const ObjectPicture> m_new;
    DeformedStrokesPtr m_oldDeformed;
};

} // namespace finbook::model
