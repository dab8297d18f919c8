// The undoable edits of a document's layers: add, duplicate, remove, reorder, properties
// (name, visibility, lock, onion skin, opacity, depth), and time inserted or deleted on
// layers. Which layer is current is editing state (Document::setCurrentLayer), not a command.
#pragma once

#include <finbook/model/commands.h>

#include <memory>
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

// `ticks` more ticks on each of `layerIds` at `tick`: the cel on screen there is held longer,
// so everything after it on those layers starts later (other layers do not move). Null when
// no listed layer has a cel at `tick`.
std::unique_ptr<QUndoCommand> insertTimeCommand(Document *doc, const std::vector<Id> &layerIds,
                                                qint64 tick, int ticks);
// `ticks` fewer ticks on each of `layerIds` from `tick` on: the cels there are held shorter
// (each keeps at least one tick) and a cel wholly inside the stretch is deleted, so
// everything after moves earlier. Null when nothing would change.
std::unique_ptr<QUndoCommand> deleteTimeCommand(Document *doc, const std::vector<Id> &layerIds,
                                                qint64 tick, int ticks);

} // namespace finbook::model
