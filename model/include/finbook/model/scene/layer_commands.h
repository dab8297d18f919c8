// The undoable edits of a document's layers: add, duplicate, remove, reorder, properties
// (name, visibility, lock, onion skin, opacity, depth), and time inserted or deleted on
// layers. Which layer is current is editing state (Document::setCurrentLayer), not a command.
#pragma once

#include <finbook/model/commands.h>

#include <memory>
#include <optional>
#include <vector>

namespace finbook::model {

// A new layer at `index` (back to front) holding one cel with one empty object, exposed for
// the whole shot (at least one tick), so drawing can start at once and a background drawn on
// it stays for the whole shot.
class AddLayerCommand : public DocumentCommand {
public:
    AddLayerCommand(Document *doc, int index, const QString &name, QUndoCommand *parent = nullptr);
    Id layerId() const { return m_layer.id; }
    void redo() override;
    void undo() override;

private:
    int m_index;
    Layer m_layer;
};

// A copy of a layer above it: every cel, object, stroke and pin under fresh ids (stroke points
// shared), so edits to either never touch the other.
class DuplicateLayerCommand : public DocumentCommand {
public:
    DuplicateLayerCommand(Document *doc, Id layerId, QUndoCommand *parent = nullptr);
    Id layerId() const { return m_copy.id; }
    void redo() override;
    void undo() override;

private:
    int m_index = 0;
    Layer m_copy;
};

// Obsolete for the last layer a document has.
class RemoveLayerCommand : public DocumentCommand {
public:
    RemoveLayerCommand(Document *doc, Id layerId, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_layerId;
    int m_index = -1;
    std::optional<Layer> m_layer;
};

class MoveLayerCommand : public DocumentCommand {
public:
    MoveLayerCommand(Document *doc, Id layerId, int toIndex, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_layerId;
    int m_from = -1;
    int m_to;
};

class SetLayerPropertiesCommand : public DocumentCommand {
public:
    // `mergeKey` ≥ 0: successive commands on the same layer with the same key (one drag of
    // the opacity slider) merge into one undo step.
    SetLayerPropertiesCommand(Document *doc, Id layerId, const LayerProperties &properties,
                              const QString &text, int mergeKey = -1,
                              QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    Id m_layerId;
    LayerProperties m_old, m_new;
    int m_mergeKey;
};

// --- cels, as the dope sheet edits them ------------------------------------------------

// Moves a cel with everything on it to `toIndex` of layer `toLayerId` (its own layer or
// another): what follows it there starts later, what followed it where it was starts earlier.
// The index is where the cel is after the move. Obsolete for an unknown cel or layer.
class MoveCelCommand : public DocumentCommand {
public:
    MoveCelCommand(Document *doc, Id celId, Id toLayerId, int toIndex,
                   QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_cel;
    Id m_fromLayer = kNoId, m_toLayer;
    int m_fromIndex = -1, m_toIndex;
};

// An empty stretch of `hold` ticks at `index` of a layer (a layer whose cels all went keeps
// one, so that it still has a cel).
class InsertEmptyCelCommand : public DocumentCommand {
public:
    InsertEmptyCelCommand(Document *doc, Id layerId, int index, int hold,
                          QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    Id m_layer;
    int m_index;
    Frame m_cel;
};

// Where cels dropped or pasted at `tick` go in a layer: the index of the boundary between cels
// nearest to it (0 = before the first, size = after the last).
int celBoundaryNear(const std::vector<Frame> &cels, qint64 tick);
// The same among the cels that stay once `leaving` (cels being moved away) are gone: the
// boundary's index among those and the tick it is at (what a drag's marker shows).
struct CelBoundary {
    int index = 0;
    qint64 tick = 0;
};
CelBoundary celBoundaryStaying(const std::vector<Frame> &cels, const std::vector<Id> &leaving,
                               qint64 tick);

// A dope sheet's drag of the cels `celIds` (on any layers) by `layerDelta` rows (to the layer
// that many above: +1 is the next one in front) and `tickDelta` ticks. The cels of each layer
// keep their order and go, together, to the boundary nearest the tick where the first of them
// lands, in the layer they land on; with `copy` they stay and copies (fresh ids) go there.
// Cels on locked layers are left alone. Null when nothing would change or a row would land
// outside the layers or on a locked one.
std::unique_ptr<QUndoCommand> rearrangeCelsCommand(Document *doc, const std::vector<Id> &celIds,
                                                   int layerDelta, qint64 tickDelta, bool copy);

// Copies of `rows` of cels (copied earlier): the first row into layer `layerId`, each next row
// into the layer above, at the boundary nearest `tick`. Rows above the front layer, or landing
// on a locked layer, are left out. Null when nothing is pasted.
std::unique_ptr<QUndoCommand> pasteCelsCommand(Document *doc,
                                               const std::vector<std::vector<Frame>> &rows,
                                               Id layerId, qint64 tick);

// Removes cels; what follows each starts earlier. A layer left without a cel keeps an empty
// stretch of one tick. Cels on locked layers stay. Null when nothing is removed.
std::unique_ptr<QUndoCommand> removeCelsCommand(Document *doc, const std::vector<Id> &celIds);

// `ticks` more ticks on each of `layerIds` at `tick`: the cel on screen there is held longer,
// so everything after it on those layers starts later (other layers do not move). Locked
// layers are left alone. Null when no listed layer has a cel at `tick`.
std::unique_ptr<QUndoCommand> insertTimeCommand(Document *doc, const std::vector<Id> &layerIds,
                                                qint64 tick, int ticks);
// `ticks` fewer ticks on each of `layerIds` from `tick` on: the cels there are held shorter
// (each keeps at least one tick) and a cel wholly inside the stretch is deleted, so
// everything after moves earlier. Locked layers are left alone. Null when nothing would change.
std::unique_ptr<QUndoCommand> deleteTimeCommand(Document *doc, const std::vector<Id> &layerIds,
                                                qint64 tick, int ticks);

} // namespace finbook::model
