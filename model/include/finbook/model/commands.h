// Every edit a user can make, as a QUndoCommand. Commands hold ids and values, never pointers
// into the document; a command whose target has gone marks itself obsolete instead of
// crashing. redo() does the work (QUndoStack::push calls it); undo() restores exactly.
#pragma once

#include <finbook/model/document.h>

#include <QUndoCommand>

#include <optional>
#include <vector>

namespace finbook::model {

// Merge ids for QUndoCommand::id(); one enum so they never collide.
enum class CommandId : int {
    None = -1,
    PoseRig = 1,
    SetMeshDensity,
    SetSkeletonSettings,
    MoveJoint,
    EditReference,
    SetCloseGap,
    EditCamera,
    EditLayer,
};

class DocumentCommand : public QUndoCommand {
public:
    explicit DocumentCommand(Document *document, QUndoCommand *parent = nullptr)
        : QUndoCommand(parent)
        , m_doc(document)
    {}

protected:
    Document *m_doc;
};

// --- strokes -----------------------------------------------------------------------------

class AddStrokeCommand : public DocumentCommand {
public:
    // Inserts a new stroke at `index` (-1 = on top) of object `groupId`.
    AddStrokeCommand(Document *doc, Id groupId, StrokeDataPtr data, int index = -1,
                     QUndoCommand *parent = nullptr);
    Id strokeId() const { return m_stroke.id; }
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    Stroke m_stroke;
    int m_index;
};

class RemoveStrokeCommand : public DocumentCommand {
public:
    RemoveStrokeCommand(Document *doc, Id strokeId, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_strokeId;
    Id m_groupId = kNoId;
    int m_index = -1;
    Stroke m_stroke;
};

// Moves strokes (in their current drawing order) to the top of another object.
class MoveStrokesCommand : public DocumentCommand {
public:
    MoveStrokesCommand(Document *doc, std::vector<Id> strokeIds, Id targetGroupId,
                       QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    struct Origin {
        Id strokeId;
        Id groupId;
        int index;
    };
    std::vector<Id> m_strokeIds;
    Id m_targetGroupId;
    std::vector<Origin> m_origins; // filled by redo, in removal order
};

// Replaces the data of strokes (transforms, smoothing); ids stay.
class ReplaceStrokeDataCommand : public DocumentCommand {
public:
    ReplaceStrokeDataCommand(Document *doc, std::vector<Id> strokeIds,
                             std::vector<StrokeDataPtr> newData, const QString &text,
                             QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    void apply(const std::vector<StrokeDataPtr> &data);
    std::vector<Id> m_strokeIds;
    std::vector<StrokeDataPtr> m_new;
    std::vector<StrokeDataPtr> m_old;
};

// --- objects -----------------------------------------------------------------------------

class AddObjectCommand : public DocumentCommand {
public:
    AddObjectCommand(Document *doc, Id frameId, int index, const QString &name,
                     QUndoCommand *parent = nullptr);
    Id groupId() const { return m_groupId; }
    void redo() override;
    void undo() override;

private:
    Id m_frameId;
    int m_index;
    QString m_name;
    Id m_groupId;
};

class RemoveObjectCommand : public DocumentCommand {
public:
    RemoveObjectCommand(Document *doc, Id groupId, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    Id m_frameId = kNoId;
    int m_index = -1;
    std::optional<StrokeGroup> m_group;
};

class RenameObjectCommand : public DocumentCommand {
public:
    RenameObjectCommand(Document *doc, Id groupId, const QString &name,
                        QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    QString m_new;
    QString m_old;
};

// Changes the z-order of an object within its frame (0 = back).
class ReorderObjectCommand : public DocumentCommand {
public:
    ReorderObjectCommand(Document *doc, Id groupId, int toIndex, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    int m_to;
    int m_from = -1;
};

enum class ObjectFlag { Visible, Locked };

class SetObjectFlagCommand : public DocumentCommand {
public:
    SetObjectFlagCommand(Document *doc, Id groupId, ObjectFlag flag, bool value,
                         QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    void apply(bool value);
    Id m_groupId;
    ObjectFlag m_flag;
    bool m_new;
    bool m_old = false;
};

// --- frames ------------------------------------------------------------------------------

// Inserts an empty frame holding one empty object into the current layer, so drawing can
// start at once.
class InsertFrameCommand : public DocumentCommand {
public:
    InsertFrameCommand(Document *doc, int index, QUndoCommand *parent = nullptr);
    Id frameId() const { return m_frame.id; }
    void redo() override;
    void undo() override;

private:
    Id m_layer;
    int m_index;
    Frame m_frame;
};

// Copies a frame with everything its objects carry (pins, pose, flags) under fresh ids, into
// the same layer at `index`; strokes' points are shared, so the copy costs no point memory.
// Edits to either frame afterwards never touch the other.
class DuplicateFrameCommand : public DocumentCommand {
public:
    DuplicateFrameCommand(Document *doc, Id sourceFrameId, int index,
                          QUndoCommand *parent = nullptr);
    // A copy of `source` (a cel copied earlier, which need not be in the document any more)
    // into layer `layerId` at `index`: pasted or Alt-dragged cels.
    DuplicateFrameCommand(Document *doc, Frame source, Id layerId, int index,
                          QUndoCommand *parent = nullptr);
    Id frameId() const { return m_copyId; }
    void redo() override;
    void undo() override;

private:
    void allocateIds(const Frame &source);
    Id m_sourceId;
    std::optional<Frame> m_source; // the copied cel, when it was given
    Id m_layer = kNoId;
    int m_index;
    Id m_copyId = kNoId;
    std::vector<Id> m_ids; // ids for the copy, allocated once so redo is repeatable
};

class DeleteFrameCommand : public DocumentCommand {
public:
    DeleteFrameCommand(Document *doc, Id frameId, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_frameId;
    Id m_layer = kNoId;
    int m_index = -1;
    std::optional<Frame> m_frame;
};

// Moves a cel of the current layer.
class MoveFrameCommand : public DocumentCommand {
public:
    MoveFrameCommand(Document *doc, int from, int to, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_layer;
    int m_from;
    int m_to;
};

class SetFrameHoldCommand : public DocumentCommand {
public:
    SetFrameHoldCommand(Document *doc, Id frameId, int hold, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_frameId;
    int m_new;
    int m_old = 1;
};

// --- document ----------------------------------------------------------------------------

class ChangeSettingsCommand : public DocumentCommand {
public:
    ChangeSettingsCommand(Document *doc, const DocumentSettings &settings,
                          QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    DocumentSettings m_new;
    DocumentSettings m_old;
};

// Clamps settings to what the editor supports (fps 1..60, canvas 1..16384, range order).
DocumentSettings sanitizedSettings(DocumentSettings settings);

} // namespace finbook::model
