// Drawing substitution's edits (issue 49): make an object swappable, pick the drawing a frame
// shows, add, rename and remove drawings, and make a frame's drawing its own again. Each is one
// undo step that undo restores exactly. What a swap set is: types.h SwapSet; how an edit of a
// shown drawing reaches every frame showing it: document.h.
#pragma once

#include <finbook/model/commands.h>

#include <functional>
#include <memory>

namespace finbook::model {

// Turns object `groupId` into the first drawing of a new set, or gives it a whole new set
// (`drawings`, e.g. a mouth chart) and shows `drawings[show]`. Obsolete when the object is
// gone, already linked, or the set would be empty.
class NewSwapSetCommand : public DocumentCommand {
public:
    // The object's own drawing becomes the set's only drawing, named `drawingName`.
    NewSwapSetCommand(Document *doc, Id groupId, const QString &setName, const QString &drawingName,
                      QUndoCommand *parent = nullptr);
    // A set of new drawings (their ids and their strokes' ids are given here).
    NewSwapSetCommand(Document *doc, Id groupId, SwapSet set, int show,
                      QUndoCommand *parent = nullptr);
    Id setId() const { return m_set.id; }
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    SwapSet m_set;
    Id m_show = kNoId;
    std::vector<Stroke> m_oldStrokes;
    std::vector<Fill> m_oldFills;
    double m_oldDensity = kDefaultMeshDensity;
    Rig m_oldRig;
    DeformedStrokesPtr m_oldDeformed;
};

// Makes object `groupId` show drawing `to` of its set (or of any set, linking an ordinary
// object). The object's rig belongs to the drawing it shows: the drawing it leaves keeps it (at
// rest), and it takes the rig `to` kept, or else the one a frame showing `to` has, at rest (a
// pose is a frame's own). Obsolete when nothing would change, the drawing is not there, or
// the frame shows the set on another object.
class SetSwapDrawingCommand : public DocumentCommand {
public:
    SetSwapDrawingCommand(Document *doc, Id groupId, SwapLink to, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    SwapLink m_to;
    SwapLink m_from;
    std::vector<Stroke> m_oldStrokes; // an ordinary object's own drawing
    std::vector<Fill> m_oldFills;
    double m_oldDensity = kDefaultMeshDensity;
    Rig m_oldRig;
    DeformedStrokesPtr m_oldDeformed;
    Rig m_newRig;
    bool m_keepsRig = false; // it leaves a drawing, which keeps its rig
    Rig m_keptBefore;        // what that drawing kept before
};

// The drawing the set's `step`-th neighbour of what object `groupId` shows (wrapping): `[` and
// `]`. Null when the object shows no set or its set has one drawing.
SetSwapDrawingCommand *stepSwapDrawing(Document *doc, Id groupId, int step);

// Adds a drawing to a set, after the one the object shows, and shows it there: empty, or a
// copy (under new ids) of what the object shows now.
class AddSwapDrawingCommand : public DocumentCommand {
public:
    enum class Content { Empty, Copy };
    AddSwapDrawingCommand(Document *doc, Id groupId, const QString &name, Content content,
                          QUndoCommand *parent = nullptr);
    ~AddSwapDrawingCommand() override;
    Id drawingId() const { return m_drawing.id; }
    void redo() override;
    void undo() override;

private:
    Id m_groupId = kNoId;
    Id m_setId = kNoId;
    int m_index = 0;
    SwapDrawing m_drawing;
    std::unique_ptr<SetSwapDrawingCommand> m_show;
};

class RenameSwapDrawingCommand : public DocumentCommand {
public:
    RenameSwapDrawingCommand(Document *doc, SwapLink drawing, const QString &name,
                             QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    SwapLink m_drawing;
    QString m_new;
    QString m_old;
};

// Removes a drawing from its set; every frame that showed it shows the drawing before it (the
// one after, for the first). Obsolete for a set's last drawing.
class RemoveSwapDrawingCommand : public DocumentCommand {
public:
    RemoveSwapDrawingCommand(Document *doc, SwapLink drawing, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    SwapLink m_drawing;
    int m_index = -1;
    std::optional<SwapDrawing> m_taken;
};

// Unlinks object `groupId` from its set: it keeps what it shows as its own drawing, under new
// ids, and edits of it no longer reach the other frames.
class MakeDrawingOwnCommand : public DocumentCommand {
public:
    MakeDrawingOwnCommand(Document *doc, Id groupId, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_groupId;
    SwapLink m_link;
    std::vector<Stroke> m_strokes; // under new ids
    std::vector<Fill> m_fills;
};

// `strokes` and `fills` under new stroke ids (the fills' references follow).
void reIdentify(std::vector<Stroke> &strokes, std::vector<Fill> &fills,
                const std::function<Id()> &newId);

} // namespace finbook::model
