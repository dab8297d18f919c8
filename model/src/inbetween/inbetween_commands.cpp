#include "../command_text.h"
#include "../frame_renumber.h"

#include <finbook/model/inbetween/inbetween_commands.h>
#include <finbook/model/skeleton/skeleton_join.h>

#include <algorithm>
#include <optional>

namespace finbook::model {

InsertInbetweensCommand::InsertInbetweensCommand(Document *doc, Id firstKey, Id secondKey,
                                                 int count, const InbetweenOptions &options,
                                                 const DrawingFits &fits, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
{
    setText(Command::tr("Generate In-betweens"));
    const std::optional<std::pair<int, int>> keys = keyIndices(firstKey, secondKey, count);
    if (!keys)
        return;
    take(planInbetweens(doc->frameAt(keys->first), doc->frameAt(keys->second),
                        inbetweenTimes(count, options.spacing), options.path, fits));
}

InsertInbetweensCommand::InsertInbetweensCommand(Document *doc, Id firstKey, Id secondKey,
                                                 InbetweenPlan plan, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
{
    setText(Command::tr("Generate In-betweens"));
    if (keyIndices(firstKey, secondKey, int(plan.frames.size())))
        take(std::move(plan));
}

std::optional<std::pair<int, int>> InsertInbetweensCommand::keyIndices(Id firstKey, Id secondKey,
                                                                       int count)
{
    int a = m_doc->frameIndex(firstKey), b = m_doc->frameIndex(secondKey);
    if (a < 0 || b < 0 || a == b || count < 1 || count > kMaxInbetweens) {
        setObsolete(true);
        return std::nullopt;
    }
    if (a > b)
        std::swap(a, b);
    m_layer = m_doc->currentLayerId();
    m_firstKey = m_doc->frameAt(a).id;
    return std::make_pair(a, b);
}

void InsertInbetweensCommand::take(InbetweenPlan plan)
{
    m_plan = std::move(plan);
    for (Frame &f : m_plan.frames)
        renumberFrame(f, m_doc);
}

std::vector<Id> InsertInbetweensCommand::frameIds() const
{
    std::vector<Id> ids;
    for (const Frame &f : m_plan.frames)
        ids.push_back(f.id);
    return ids;
}

void InsertInbetweensCommand::redo()
{
    const int key = m_doc->celIndex(m_firstKey);
    if (isObsolete() || key < 0) {
        setObsolete(true);
        return;
    }
    for (std::size_t i = 0; i < m_plan.frames.size(); ++i)
        m_doc->insertFrame(m_layer, key + 1 + int(i), m_plan.frames[i]);
}

void InsertInbetweensCommand::undo()
{
    if (isObsolete())
        return;
    // Taken back with whatever poses were solved meanwhile, so a redo shows them at once.
    for (auto it = m_plan.frames.rbegin(); it != m_plan.frames.rend(); ++it) {
        const int index = m_doc->celIndex(it->id);
        if (index >= 0)
            *it = m_doc->takeFrame(m_layer, index);
    }
}

} // namespace finbook::model
