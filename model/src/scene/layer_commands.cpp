// Layer commands (scene/layer_commands.h).
#include "../command_text.h"
#include "../frame_renumber.h"

#include <finbook/model/scene/layer_commands.h>
#include <finbook/model/scene/shot.h>

#include <algorithm>

namespace finbook::model {

AddLayerCommand::AddLayerCommand(Document *doc, int index, const QString &name,
                                 QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_index(std::clamp(index, 0, doc->layerCount()))
{
    setText(Command::tr("New Layer"));
    m_layer.id = doc->allocateId();
    m_layer.properties.name = name;
    Frame cel;
    cel.id = doc->allocateId();
    cel.hold = int(std::clamp<qint64>(shotTicks(doc->layers()), 1, kMaxHold));
    StrokeGroup g;
    g.id = doc->allocateId();
    g.name = Command::tr("Object");
    cel.groups.push_back(std::move(g));
    m_layer.cels.push_back(std::move(cel));
    if (doc->layerCount() >= kMaxLayers)
        setObsolete(true);
}

void AddLayerCommand::redo()
{
    if (!isObsolete())
        m_doc->insertLayer(m_index, m_layer);
}

void AddLayerCommand::undo()
{
    if (!isObsolete())
        m_doc->takeLayer(m_layer.id);
}

DuplicateLayerCommand::DuplicateLayerCommand(Document *doc, Id layerId, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
{
    setText(Command::tr("Duplicate Layer"));
    const Layer *source = doc->layer(layerId);
    if (!source || doc->layerCount() >= kMaxLayers) {
        setObsolete(true);
        return;
    }
    m_index = doc->layerIndex(layerId) + 1;
    m_copy = *source;
    m_copy.id = doc->allocateId();
    m_copy.properties.name = Command::tr("%1 copy").arg(source->properties.name);
    for (Frame &cel : m_copy.cels)
        renumberFrame(cel, doc);
}

void DuplicateLayerCommand::redo()
{
    if (!isObsolete())
        m_doc->insertLayer(m_index, m_copy);
}

void DuplicateLayerCommand::undo()
{
    if (!isObsolete())
        m_copy = m_doc->takeLayer(m_copy.id); // with the poses solved meanwhile
}

RemoveLayerCommand::RemoveLayerCommand(Document *doc, Id layerId, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_layerId(layerId)
{
    setText(Command::tr("Delete Layer"));
    if (!doc->layer(layerId) || doc->layerCount() < 2)
        setObsolete(true);
}

void RemoveLayerCommand::redo()
{
    m_index = m_doc->layerIndex(m_layerId);
    if (isObsolete() || m_index < 0 || m_doc->layerCount() < 2) {
        setObsolete(true);
        return;
    }
    m_layer = m_doc->takeLayer(m_layerId);
}

void RemoveLayerCommand::undo()
{
    if (m_layer)
        m_doc->insertLayer(m_index, std::move(*m_layer));
    m_layer.reset();
}

MoveLayerCommand::MoveLayerCommand(Document *doc, Id layerId, int toIndex, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_layerId(layerId)
    , m_to(toIndex)
{
    setText(Command::tr("Move Layer"));
    m_from = doc->layerIndex(layerId);
    if (m_from < 0 || toIndex < 0 || toIndex >= doc->layerCount() || toIndex == m_from)
        setObsolete(true);
}

void MoveLayerCommand::redo()
{
    if (!isObsolete())
        m_doc->moveLayer(m_layerId, m_to);
}

void MoveLayerCommand::undo()
{
    if (!isObsolete())
        m_doc->moveLayer(m_layerId, m_from);
}

SetLayerPropertiesCommand::SetLayerPropertiesCommand(Document *doc, Id layerId,
                                                     const LayerProperties &properties,
                                                     const QString &text, int mergeKey,
                                                     QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_layerId(layerId)
    , m_new(properties)
    , m_mergeKey(mergeKey)
{
    setText(text);
    if (const Layer *l = doc->layer(layerId))
        m_old = l->properties;
    else
        setObsolete(true);
}

void SetLayerPropertiesCommand::redo()
{
    if (!isObsolete() && m_doc->layer(m_layerId))
        m_doc->setLayerProperties(m_layerId, m_new);
}

void SetLayerPropertiesCommand::undo()
{
    if (!isObsolete() && m_doc->layer(m_layerId))
        m_doc->setLayerProperties(m_layerId, m_old);
}

int SetLayerPropertiesCommand::id() const
{
    return m_mergeKey >= 0 ? int(CommandId::EditLayer) : int(CommandId::None);
}

bool SetLayerPropertiesCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = dynamic_cast<const SetLayerPropertiesCommand *>(other);
    if (!next || next->m_layerId != m_layerId || next->m_mergeKey != m_mergeKey)
        return false;
    m_new = next->m_new;
    setObsolete(m_new == m_old);
    return true;
}

std::unique_ptr<QUndoCommand> insertTimeCommand(Document *doc, const std::vector<Id> &layerIds,
                                                qint64 tick, int ticks)
{
    auto macro = std::make_unique<QUndoCommand>(Command::tr("Insert Time"));
    for (Id id : layerIds) {
        const Layer *l = doc->layer(id);
        const int cel = l ? celAt(l->cels, tick) : -1;
        if (cel < 0)
            continue;
        const Frame &f = l->cels[std::size_t(cel)];
        const int hold = int(std::min<qint64>(qint64(f.hold) + std::max(ticks, 0), kMaxHold));
        if (hold != f.hold)
            new SetFrameHoldCommand(doc, f.id, hold, macro.get());
    }
    return macro->childCount() > 0 ? std::move(macro) : nullptr;
}

std::unique_ptr<QUndoCommand> deleteTimeCommand(Document *doc, const std::vector<Id> &layerIds,
                                                qint64 tick, int ticks)
{
    auto macro = std::make_unique<QUndoCommand>(Command::tr("Delete Time"));
    const qint64 from = std::max<qint64>(tick, 0), to = from + std::max(ticks, 0);
    for (Id id : layerIds) {
        const Layer *l = doc->layer(id);
        if (!l)
            continue;
        std::size_t kept = l->cels.size();
        qint64 start = 0;
        for (const Frame &f : l->cels) {
            const qint64 end = start + std::clamp(f.hold, 1, kMaxHold);
            const qint64 cut = std::min(end, to) - std::max(start, from);
            start = end;
            if (cut <= 0)
                continue;
            if (cut >= f.hold && kept > 1) { // wholly inside: gone (a layer keeps one cel)
                new DeleteFrameCommand(doc, f.id, macro.get());
                --kept;
            } else if (f.hold > 1) {
                new SetFrameHoldCommand(doc, f.id, int(std::max<qint64>(f.hold - cut, 1)),
                                        macro.get());
            }
        }
    }
    return macro->childCount() > 0 ? std::move(macro) : nullptr;
}

} // namespace finbook::model
