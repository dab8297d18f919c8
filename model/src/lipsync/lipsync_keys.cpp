// Keying a mouth (lipsync/lipsync_keys.h): walks the mouth's layer tick by tick, splitting cels
// with Set Hold and Duplicate Frame and choosing drawings with SetSwapDrawingCommand, all pushed
// inside one macro so each sees the document the one before left.
#include "../command_text.h"

#include <finbook/model/lipsync/lipsync_keys.h>
#include <finbook/model/swap/mouth_chart.h>
#include <finbook/model/swap/swap_commands.h>

namespace finbook::model::lipsync {

std::optional<std::vector<Id>> drawingsForShapes(const SwapSet &set)
{
    std::vector<Id> byShape(kMouthShapeCount, kNoId);
    for (const SwapDrawing &d : set.drawings) {
        const int shape = mouthChartShape(d.name);
        if (shape >= 0 && byShape[std::size_t(shape)] == kNoId)
            byShape[std::size_t(shape)] = d.id;
    }
    for (int shape = 0; shape < 6; ++shape)
        if (byShape[std::size_t(shape)] == kNoId)
            return std::nullopt;
    const auto standIn = [&](MouthShape shape, MouthShape instead) {
        Id &id = byShape[std::size_t(shape)];
        if (id == kNoId)
            id = byShape[std::size_t(instead)];
    };
    standIn(MouthShape::G, MouthShape::B);
    standIn(MouthShape::H, MouthShape::C);
    standIn(MouthShape::X, MouthShape::A);
    return byShape;
}

namespace {
struct CelSpan {
    int index = -1;
    qint64 start = 0;
    qint64 end = 0;
    Id id = kNoId;
};

CelSpan celAt(const Layer &layer, qint64 tick)
{
    qint64 start = 0;
    for (int i = 0; i < int(layer.cels.size()); ++i) {
        const Frame &cel = layer.cels[std::size_t(i)];
        if (tick < start + cel.hold)
            return {i, start, start + cel.hold, cel.id};
        start += cel.hold;
    }
    return {};
}

qint64 layerLength(const Layer &layer)
{
    qint64 ticks = 0;
    for (const Frame &cel : layer.cels)
        ticks += cel.hold;
    return ticks;
}

// Cuts cel `span` at `tick` (start < tick < end): it keeps [start, tick), a copy after it holds
// [tick, end).
void split(Document *doc, const Layer &layer, const CelSpan &span, qint64 tick)
{
    QUndoStack *stack = doc->undoStack();
    stack->push(new SetFrameHoldCommand(doc, span.id, int(tick - span.start)));
    const Id layerId = layer.id;
    const Frame copy = layer.cels[std::size_t(span.index)];
    auto *duplicate = new DuplicateFrameCommand(doc, copy, layerId, span.index + 1);
    stack->push(duplicate);
    stack->push(new SetFrameHoldCommand(doc, duplicate->frameId(), int(span.end - tick)));
}
} // namespace

LipSyncResult keyMouth(Document *doc, Id mouthId, qint64 startTick,
                       const std::vector<MouthShape> &shapes, const QString &text)
{
    LipSyncResult result;
    const StrokeGroup *mouth = doc->group(mouthId);
    const SwapSet *set = mouth ? doc->swapSet(mouth->swap.set) : nullptr;
    if (!set) {
        result.error = Command::tr("The object is not swappable: make a mouth chart first "
                                   "(Object > New Mouth Chart).");
        return result;
    }
    const auto drawings = drawingsForShapes(*set);
    if (!drawings) {
        result.error = Command::tr("The set \"%1\" has no drawings named A to F (the mouth "
                                   "shapes lip sync keys): make a mouth chart, or name its "
                                   "drawings by their shapes.")
                           .arg(set->name);
        return result;
    }
    if (shapes.empty() || startTick < 0) {
        result.error = Command::tr("There is nothing to key.");
        return result;
    }
    const Id setId = set->id;
    const Id layerId = doc->layerAt(doc->locateGroup(mouthId).layer).id;
    const qint64 end = startTick + qint64(shapes.size());
    QUndoStack *stack = doc->undoStack();
    stack->beginMacro(text);
    // The speech runs past the layer's last cel: that cel is held until it ends.
    if (const Layer *layer = doc->layer(layerId); layerLength(*layer) < end && !layer->cels.empty())
        stack->push(new SetFrameHoldCommand(
            doc, layer->cels.back().id,
            int(std::min<qint64>(layer->cels.back().hold + end - layerLength(*layer), kMaxHold))));
    qint64 tick = startTick;
    while (tick < end) {
        const MouthShape shape = shapes[std::size_t(tick - startTick)];
        qint64 runEnd = tick + 1;
        while (runEnd < end && shapes[std::size_t(runEnd - startTick)] == shape)
            ++runEnd;
        CelSpan span = celAt(*doc->layer(layerId), tick);
        if (span.index < 0)
            break; // past the longest hold a cel can have
        if (span.start < tick) {
            split(doc, *doc->layer(layerId), span, tick);
            span = celAt(*doc->layer(layerId), tick);
        }
        const qint64 pieceEnd = std::min(runEnd, span.end);
        if (pieceEnd < span.end) {
            split(doc, *doc->layer(layerId), span, pieceEnd);
            span = celAt(*doc->layer(layerId), tick);
        }
        const Frame *cel = doc->frame(span.id);
        Id shown = kNoId;
        for (const StrokeGroup &g : cel->groups)
            if (g.swap.set == setId)
                shown = g.id;
        const int ticks = int(pieceEnd - tick);
        if (shown == kNoId) {
            result.withoutMouth += ticks;
        } else {
            stack->push(
                new SetSwapDrawingCommand(doc, shown, {setId, (*drawings)[std::size_t(shape)]}));
            result.keyed += ticks;
        }
        tick = pieceEnd;
    }
    stack->endMacro();
    return result;
}

} // namespace finbook::model::lipsync
