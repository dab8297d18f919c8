#include "command_text.h"

#include <finbook/model/fill/fill_resolve.h>
#include <finbook/model/object_commands.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/render.h>

#include <QCoreApplication>

namespace finbook::model {

namespace {

// Whether `lower`'s lines would be drawn over `upper`'s picture once they are one object.
bool linesUnderPicture(const StrokeGroup &lower, const StrokeGroup &upper)
{
    return !lower.strokes.empty() && upper.picture != nullptr;
}

} // namespace

QString mergeRefusal(const Document &doc, const std::vector<Id> &bottomUp)
{
    for (std::size_t i = 0; i < bottomUp.size(); ++i)
        for (std::size_t j = i + 1; j < bottomUp.size(); ++j) {
            const StrokeGroup *lower = doc.group(bottomUp[i]), *upper = doc.group(bottomUp[j]);
            if (lower && upper && linesUnderPicture(*lower, *upper))
                return Command::tr("“%1” has lines under the picture of “%2”: one object draws "
                                   "its picture under its lines, so merged they would cover "
                                   "it. Put the picture below them first (Object → Send "
                                   "Backward).")
                    .arg(lower->name, upper->name);
        }
    return {};
}

MergeObjectsCommand::MergeObjectsCommand(Document *doc, Id sourceId, Id targetId,
                                         QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_sourceId(sourceId)
    , m_targetId(targetId)
{
    setText(Command::tr("Merge Objects"));
    const GroupLocation source = doc->locateGroup(sourceId);
    const GroupLocation target = doc->locateGroup(targetId);
    if (!source.isValid() || !target.isValid() || source.frame != target.frame ||
        source.layer != target.layer || sourceId == targetId)
        setObsolete(true);
}

void MergeObjectsCommand::redo()
{
    const GroupLocation source = m_doc->locateGroup(m_sourceId);
    const GroupLocation target = m_doc->locateGroup(m_targetId);
    if (isObsolete() || !source.isValid() || !target.isValid() || source.frame != target.frame ||
        source.layer != target.layer) {
        setObsolete(true);
        return;
    }
    const StrokeGroup &targetGroup = *m_doc->group(m_targetId);
    const StrokeGroup &sourceGroup = *m_doc->group(m_sourceId);
    const bool sourceAbove = source.group > target.group;
    if (sourceGroup.picture || targetGroup.picture) {
        const StrokeGroup &lower = sourceAbove ? targetGroup : sourceGroup;
        const StrokeGroup &upper = sourceAbove ? sourceGroup : targetGroup;
        if (linesUnderPicture(lower, upper)) { // merged, the lines would cover the picture
            setObsolete(true);
            return;
        }
        if (!m_mergedPicture) { // once: a redo after an undo puts back the very same picture
            auto picture = stackedPicture(lower, upper);
            if (!picture) { // too large to keep, or no memory: nothing changes
                setObsolete(true);
                return;
            }
            m_mergedPicture = *picture;
        }
        m_targetPicture = targetGroup.picture;
    }
    m_frameId = m_doc->frameAt(source).id;
    m_sourceIndex = source.group;
    m_targetStrokes = targetGroup.strokes;
    m_targetDeformed = targetGroup.deformed;

    // Take the source out first so no stroke id is ever in two objects at once.
    m_source = m_doc->takeGroup(m_sourceId);
    std::vector<Stroke> moved = posedStrokes(*m_source);
    std::vector<Stroke> merged;
    merged.reserve(m_targetStrokes.size() + moved.size());
    const std::vector<Stroke> &below = sourceAbove ? m_targetStrokes : moved;
    const std::vector<Stroke> &above = sourceAbove ? moved : m_targetStrokes;
    merged.insert(merged.end(), below.begin(), below.end());
    merged.insert(merged.end(), above.begin(), above.end());
    m_doc->setStrokes(m_targetId, std::move(merged));
    // The source's fills come along (their seeds moved with a pose that was baked), under the
    // target's when the source was below it.
    if (!m_source->fills.empty()) {
        m_targetFills = m_doc->group(m_targetId)->fills;
        const std::vector<Fill> movedFills =
            fillsAfterBake(*m_source, moved, m_doc->settings().closeGap);
        std::vector<Fill> fills = sourceAbove ? m_targetFills : movedFills;
        const std::vector<Fill> &upper = sourceAbove ? movedFills : m_targetFills;
        fills.insert(fills.end(), upper.begin(), upper.end());
        m_doc->setFills(m_targetId, std::move(fills));
    }
    if (m_mergedPicture)
        m_doc->setPicture(m_targetId, m_mergedPicture);
}

void MergeObjectsCommand::undo()
{
    if (isObsolete() || !m_source)
        return;
    m_doc->setStrokes(m_targetId, m_targetStrokes);
    if (!m_source->fills.empty())
        m_doc->setFills(m_targetId, m_targetFills);
    if (m_mergedPicture)
        m_doc->setPicture(m_targetId, m_targetPicture);
    if (m_targetDeformed)
        m_doc->setDeformed(m_targetId, m_targetDeformed);
    m_doc->insertGroup(m_frameId, m_sourceIndex, *m_source);
}

} // namespace finbook::model
