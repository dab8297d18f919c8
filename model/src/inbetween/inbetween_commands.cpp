#include "../command_text.h"
#include "../frame_renumber.h"

#include <finbook/model/inbetween/inbetween_commands.h>
#include <finbook/model/skeleton/skeleton_join.h>

#include <algorithm>

namespace finbook::model {

InsertInbetweensCommand::InsertInbetweensCommand(Document *doc, Id firstKey, Id secondKey,
                                                 int count, const InbetweenOptions &options,
                                                 const DrawingFits &fits, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
{
    setText(Command::tr("Generate In-betweens"));
    int a = doc->frameIndex(firstKey), b = doc->frameIndex(secondKey);
    if (a < 0 || b < 0 || a == b || count < 1 || count > kMaxInbetweens) {
        setObsolete(true);
        return;
    }
    if (a > b)
        std::swap(a, b);
    m_layer = doc->currentLayerId();
    m_firstKey = doc->frameAt(a).id;
    m_plan = planInbetweens(doc->frameAt(a), doc->frameAt(b),
                            inbetweenTimes(count, options.spacing), options.path, fits);
    for (Frame &f : m_plan.frames)
        renumberFrame(f, doc);
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
