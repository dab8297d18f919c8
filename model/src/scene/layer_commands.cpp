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
        const int cel = l && !l->properties.locked ? celAt(l->cels, tick) : -1;
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
        if (!l || l->properties.locked)
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

namespace finbook::model {

MoveCelCommand::MoveCelCommand(Document *doc, Id celId, Id toLayerId, int toIndex,
                               QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_cel(celId)
    , m_toLayer(toLayerId)
    , m_toIndex(toIndex)
{
    setText(Command::tr("Move Cels"));
    if (!doc->frame(celId) || !doc->layer(toLayerId))
        setObsolete(true);
}

void MoveCelCommand::redo()
{
    if (isObsolete())
        return;
    m_fromLayer = m_doc->layerOfFrame(m_cel);
    m_fromIndex = m_doc->celIndex(m_cel);
    Frame cel = m_doc->takeFrame(m_fromLayer, m_fromIndex);
    const int size = int(m_doc->layer(m_toLayer)->cels.size());
    m_doc->insertFrame(m_toLayer, std::clamp(m_toIndex, 0, size), std::move(cel));
}

void MoveCelCommand::undo()
{
    if (isObsolete() || m_fromIndex < 0)
        return;
    Frame cel = m_doc->takeFrame(m_toLayer, m_doc->celIndex(m_cel));
    m_doc->insertFrame(m_fromLayer, m_fromIndex, std::move(cel));
}

InsertEmptyCelCommand::InsertEmptyCelCommand(Document *doc, Id layerId, int index, int hold,
                                             QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_layer(layerId)
    , m_index(index)
{
    setText(Command::tr("Insert Empty Cel"));
    const Layer *layer = doc->layer(layerId);
    if (!layer) {
        setObsolete(true);
        return;
    }
    m_index = std::clamp(index, 0, int(layer->cels.size()));
    m_cel.id = doc->allocateId();
    m_cel.hold = std::clamp(hold, 1, kMaxHold);
}

void InsertEmptyCelCommand::redo()
{
    if (!isObsolete())
        m_doc->insertFrame(m_layer, m_index, m_cel);
}

void InsertEmptyCelCommand::undo()
{
    if (!isObsolete())
        m_doc->takeFrame(m_layer, m_doc->celIndex(m_cel.id));
}

int celBoundaryNear(const std::vector<Frame> &cels, qint64 tick)
{
    return celBoundaryStaying(cels, {}, tick).index;
}

CelBoundary celBoundaryStaying(const std::vector<Frame> &cels, const std::vector<Id> &leaving,
                               qint64 tick)
{
    CelBoundary best;
    qint64 start = 0, bestDistance = std::abs(tick);
    int staying = 0;
    for (const Frame &f : cels) {
        if (std::find(leaving.begin(), leaving.end(), f.id) != leaving.end())
            continue;
        start += std::clamp(f.hold, 1, kMaxHold);
        ++staying;
        if (std::abs(tick - start) < bestDistance) {
            bestDistance = std::abs(tick - start);
            best = {staying, start};
        }
    }
    return best;
}

namespace {
// The chosen cels of one layer, in the layer's order, with the tick the first one starts at.
struct RowOfCels {
    int layerIndex = -1;
    std::vector<Id> cels;
    qint64 firstTick = 0;
};

// `celIds` grouped by layer (back to front), leaving out unknown cels and locked layers.
std::vector<RowOfCels> rowsOf(const Document &doc, const std::vector<Id> &celIds)
{
    std::vector<RowOfCels> rows;
    for (int l = 0; l < doc.layerCount(); ++l) {
        const Layer &layer = doc.layerAt(l);
        if (layer.properties.locked)
            continue;
        RowOfCels row{l, {}, 0};
        for (std::size_t i = 0; i < layer.cels.size(); ++i)
            if (std::find(celIds.begin(), celIds.end(), layer.cels[i].id) != celIds.end()) {
                if (row.cels.empty())
                    row.firstTick = celStart(layer.cels, int(i));
                row.cels.push_back(layer.cels[i].id);
            }
        if (!row.cels.empty())
            rows.push_back(std::move(row));
    }
    return rows;
}

} // namespace

std::unique_ptr<QUndoCommand> rearrangeCelsCommand(Document *doc, const std::vector<Id> &celIds,
                                                   int layerDelta, qint64 tickDelta, bool copy)
{
    const std::vector<RowOfCels> rows = rowsOf(*doc, celIds);
    if (rows.empty())
        return nullptr;
    for (const RowOfCels &row : rows) {
        const int to = row.layerIndex + layerDelta;
        if (to < 0 || to >= doc->layerCount() || doc->layerAt(to).properties.locked)
            return nullptr;
    }
    auto macro =
        std::make_unique<QUndoCommand>(copy ? Command::tr("Copy Cels") : Command::tr("Move Cels"));
    if (copy) {
        for (const RowOfCels &row : rows) {
            const Layer &target = doc->layerAt(row.layerIndex + layerDelta);
            int at = celBoundaryNear(target.cels, row.firstTick + tickDelta);
            for (Id id : row.cels)
                new DuplicateFrameCommand(doc, *doc->frame(id), target.id, at++, macro.get());
        }
        return macro;
    }
    // The order each layer the cels touch ends with, as ids; then moves that make it so, one
    // cel at a time, simulated on `now` so that a cel already in place is not moved.
    std::vector<Id> moving;
    for (const RowOfCels &row : rows)
        moving.insert(moving.end(), row.cels.begin(), row.cels.end());
    std::vector<std::pair<Id, std::vector<Id>>> finalOrder; // layer id, cel ids
    std::vector<std::pair<Id, std::vector<Id>>> now;
    const auto idsOf = [](const Layer &l) {
        std::vector<Id> ids;
        for (const Frame &f : l.cels)
            ids.push_back(f.id);
        return ids;
    };
    for (const Layer &l : doc->layers())
        now.emplace_back(l.id, idsOf(l));
    for (const RowOfCels &row : rows) {
        const Layer &target = doc->layerAt(row.layerIndex + layerDelta);
        const int at = celBoundaryStaying(target.cels, moving, row.firstTick + tickDelta).index;
        std::vector<Id> order;
        for (const Frame &f : target.cels)
            if (std::find(moving.begin(), moving.end(), f.id) == moving.end())
                order.push_back(f.id);
        order.insert(order.begin() + at, row.cels.begin(), row.cels.end());
        finalOrder.emplace_back(target.id, std::move(order));
    }
    // A layer every cel leaves, and none arrives at, keeps an empty tick (inserted first, so
    // that no layer is ever without a cel).
    for (const RowOfCels &row : rows) {
        const Layer &source = doc->layerAt(row.layerIndex);
        const bool target = std::any_of(finalOrder.begin(), finalOrder.end(),
                                        [&](const auto &o) { return o.first == source.id; });
        if (!target && row.cels.size() == source.cels.size())
            new InsertEmptyCelCommand(doc, source.id, 0, 1, macro.get());
    }
    bool changed = false;
    for (const auto &target : finalOrder) {
        const Id layerId = target.first;
        const std::vector<Id> &order = target.second;
        for (std::size_t p = 0; p < order.size(); ++p) {
            auto into = std::find_if(now.begin(), now.end(),
                                     [layerId](const auto &n) { return n.first == layerId; });
            if (p < into->second.size() && into->second[p] == order[p])
                continue;
            for (auto &[id, cels] : now) // simulate the move
                cels.erase(std::remove(cels.begin(), cels.end(), order[p]), cels.end());
            into->second.insert(into->second.begin() + long(std::min(p, into->second.size())),
                                order[p]);
            new MoveCelCommand(doc, order[p], layerId, int(p), macro.get());
            changed = true;
        }
    }
    return changed ? std::move(macro) : nullptr;
}

std::unique_ptr<QUndoCommand> pasteCelsCommand(Document *doc,
                                               const std::vector<std::vector<Frame>> &rows,
                                               Id layerId, qint64 tick)
{
    const int first = doc->layerIndex(layerId);
    if (first < 0)
        return nullptr;
    auto macro = std::make_unique<QUndoCommand>(Command::tr("Paste Cels"));
    for (std::size_t r = 0; r < rows.size() && first + int(r) < doc->layerCount(); ++r) {
        const Layer &target = doc->layerAt(first + int(r));
        if (target.properties.locked)
            continue;
        int at = celBoundaryNear(target.cels, tick);
        for (const Frame &cel : rows[r])
            new DuplicateFrameCommand(doc, cel, target.id, at++, macro.get());
    }
    return macro->childCount() > 0 ? std::move(macro) : nullptr;
}

std::unique_ptr<QUndoCommand> removeCelsCommand(Document *doc, const std::vector<Id> &celIds)
{
    const std::vector<RowOfCels> rows = rowsOf(*doc, celIds);
    if (rows.empty())
        return nullptr;
    auto macro = std::make_unique<QUndoCommand>(Command::tr("Delete Cels"));
    for (const RowOfCels &row : rows) {
        const Layer &layer = doc->layerAt(row.layerIndex);
        if (row.cels.size() == layer.cels.size())
            new InsertEmptyCelCommand(doc, layer.id, 0, 1, macro.get());
        for (Id id : row.cels)
            new DeleteFrameCommand(doc, id, macro.get());
    }
    return macro;
}

} // namespace finbook::model
