#include "command_text.h"

#include <finbook/model/commands.h>
#include <finbook/model/fill/fill_ids.h>
#include <finbook/model/skeleton/skeleton_join.h>

#include <QCoreApplication>

#include <algorithm>
#include <climits>
#include <cmath>

namespace finbook::model {

// --- strokes -----------------------------------------------------------------------------

AddStrokeCommand::AddStrokeCommand(Document *doc, Id groupId, StrokeDataPtr data, int index,
                                   QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
    , m_stroke{doc->allocateId(), std::move(data)}
    , m_index(index)
{
    setText(Command::tr("Draw Stroke"));
    const StrokeGroup *g = doc->group(groupId);
    if (!g || !m_stroke.data)
        setObsolete(true);
    else if (m_index < 0 || m_index > int(g->strokes.size()))
        m_index = int(g->strokes.size());
}

void AddStrokeCommand::redo()
{
    if (!isObsolete())
        m_doc->insertStroke(m_groupId, m_index, m_stroke);
}

void AddStrokeCommand::undo()
{
    if (!isObsolete())
        m_doc->takeStroke(m_stroke.id);
}

RemoveStrokeCommand::RemoveStrokeCommand(Document *doc, Id strokeId, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_strokeId(strokeId)
{
    setText(Command::tr("Erase Stroke"));
    if (!doc->locateStroke(strokeId).isValid())
        setObsolete(true);
}

void RemoveStrokeCommand::redo()
{
    const StrokeLocation at = m_doc->locateStroke(m_strokeId);
    if (!at.isValid()) {
        setObsolete(true);
        return;
    }
    m_groupId = m_doc->frameAt(at).groups[std::size_t(at.group)].id;
    m_index = at.stroke;
    m_stroke = m_doc->takeStroke(m_strokeId);
}

void RemoveStrokeCommand::undo()
{
    if (m_groupId != kNoId)
        m_doc->insertStroke(m_groupId, m_index, m_stroke);
}

MoveStrokesCommand::MoveStrokesCommand(Document *doc, std::vector<Id> strokeIds, Id targetGroupId,
                                       QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_strokeIds(std::move(strokeIds))
    , m_targetGroupId(targetGroupId)
{
    setText(Command::tr("Move Strokes to Object"));
    if (!doc->group(targetGroupId) || m_strokeIds.empty())
        setObsolete(true);
}

void MoveStrokesCommand::redo()
{
    m_origins.clear();
    std::vector<Stroke> moved;
    for (Id id : m_strokeIds) {
        const StrokeLocation at = m_doc->locateStroke(id);
        if (!at.isValid())
            continue;
        const Id groupId = m_doc->frameAt(at).groups[std::size_t(at.group)].id;
        m_origins.push_back({id, groupId, at.stroke});
        moved.push_back(m_doc->takeStroke(id));
    }
    for (Stroke &s : moved)
        m_doc->insertStroke(m_targetGroupId, INT_MAX, std::move(s));
}

void MoveStrokesCommand::undo()
{
    // Take them back out of the target, then re-insert in reverse removal order so every
    // original index is valid again when it is used.
    std::vector<Stroke> moved;
    for (const Origin &o : m_origins)
        moved.push_back(m_doc->takeStroke(o.strokeId));
    for (std::size_t i = m_origins.size(); i-- > 0;)
        m_doc->insertStroke(m_origins[i].groupId, m_origins[i].index, std::move(moved[i]));
}

ReplaceStrokeDataCommand::ReplaceStrokeDataCommand(Document *doc, std::vector<Id> strokeIds,
                                                   std::vector<StrokeDataPtr> newData,
                                                   const QString &text, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_strokeIds(std::move(strokeIds))
    , m_new(std::move(newData))
{
    setText(text);
    if (m_strokeIds.size() != m_new.size())
        setObsolete(true);
    for (Id id : m_strokeIds) {
        const StrokeLocation at = doc->locateStroke(id);
        if (!at.isValid()) {
            setObsolete(true);
            return;
        }
        m_old.push_back(
            doc->frameAt(at).groups[std::size_t(at.group)].strokes[std::size_t(at.stroke)].data);
    }
}

void ReplaceStrokeDataCommand::apply(const std::vector<StrokeDataPtr> &data)
{
    if (isObsolete())
        return;
    // Group the replacements per object so each object is rewritten (and re-meshed) once.
    std::vector<Id> groups;
    for (std::size_t i = 0; i < m_strokeIds.size(); ++i) {
        const StrokeLocation at = m_doc->locateStroke(m_strokeIds[i]);
        const Id gid = m_doc->frameAt(at).groups[std::size_t(at.group)].id;
        if (std::find(groups.begin(), groups.end(), gid) == groups.end())
            groups.push_back(gid);
    }
    for (Id gid : groups) {
        std::vector<Stroke> strokes = m_doc->group(gid)->strokes;
        for (Stroke &s : strokes) {
            const auto it = std::find(m_strokeIds.begin(), m_strokeIds.end(), s.id);
            if (it != m_strokeIds.end())
                s.data = data[std::size_t(it - m_strokeIds.begin())];
        }
        m_doc->setStrokes(gid, std::move(strokes));
    }
}

void ReplaceStrokeDataCommand::redo()
{
    apply(m_new);
}
void ReplaceStrokeDataCommand::undo()
{
    apply(m_old);
}

// --- objects -----------------------------------------------------------------------------

AddObjectCommand::AddObjectCommand(Document *doc, Id frameId, int index, const QString &name,
                                   QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_frameId(frameId)
    , m_index(index)
    , m_name(name)
    , m_groupId(doc->allocateId())
{
    setText(Command::tr("New Object"));
    const Frame *f = doc->frame(frameId);
    if (!f)
        setObsolete(true);
    else if (m_index < 0 || m_index > int(f->groups.size()))
        m_index = int(f->groups.size());
}

void AddObjectCommand::redo()
{
    if (isObsolete())
        return;
    StrokeGroup g;
    g.id = m_groupId;
    g.name = m_name;
    m_doc->insertGroup(m_frameId, m_index, std::move(g));
}

void AddObjectCommand::undo()
{
    if (!isObsolete())
        m_doc->takeGroup(m_groupId);
}

RemoveObjectCommand::RemoveObjectCommand(Document *doc, Id groupId, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
{
    setText(Command::tr("Delete Object"));
    if (!doc->group(groupId))
        setObsolete(true);
}

void RemoveObjectCommand::redo()
{
    const GroupLocation at = m_doc->locateGroup(m_groupId);
    if (!at.isValid()) {
        setObsolete(true);
        return;
    }
    m_frameId = m_doc->frameAt(at).id;
    m_index = at.group;
    m_group = m_doc->takeGroup(m_groupId);
}

void RemoveObjectCommand::undo()
{
    if (m_group)
        m_doc->insertGroup(m_frameId, m_index, *m_group);
}

RenameObjectCommand::RenameObjectCommand(Document *doc, Id groupId, const QString &name,
                                         QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
    , m_new(name)
{
    setText(Command::tr("Rename Object"));
    if (const StrokeGroup *g = doc->group(groupId))
        m_old = g->name;
    else
        setObsolete(true);
}

void RenameObjectCommand::redo()
{
    if (!isObsolete())
        m_doc->setGroupName(m_groupId, m_new);
}

void RenameObjectCommand::undo()
{
    if (!isObsolete())
        m_doc->setGroupName(m_groupId, m_old);
}

ReorderObjectCommand::ReorderObjectCommand(Document *doc, Id groupId, int toIndex,
                                           QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
    , m_to(toIndex)
{
    setText(Command::tr("Reorder Object"));
    const GroupLocation at = doc->locateGroup(groupId);
    if (!at.isValid()) {
        setObsolete(true);
        return;
    }
    m_from = at.group;
    const int count = int(doc->frameAt(at).groups.size());
    m_to = std::clamp(m_to, 0, count - 1);
}

void ReorderObjectCommand::redo()
{
    if (!isObsolete())
        m_doc->moveGroup(m_groupId, m_to);
}

void ReorderObjectCommand::undo()
{
    if (!isObsolete())
        m_doc->moveGroup(m_groupId, m_from);
}

SetObjectFlagCommand::SetObjectFlagCommand(Document *doc, Id groupId, ObjectFlag flag, bool value,
                                           QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
    , m_flag(flag)
    , m_new(value)
{
    if (flag == ObjectFlag::Visible)
        setText(value ? Command::tr("Show Object") : Command::tr("Hide Object"));
    else
        setText(value ? Command::tr("Lock Object") : Command::tr("Unlock Object"));
    const StrokeGroup *g = doc->group(groupId);
    if (!g)
        setObsolete(true);
    else
        m_old = flag == ObjectFlag::Visible ? g->visible : g->locked;
}

void SetObjectFlagCommand::apply(bool value)
{
    if (isObsolete())
        return;
    if (m_flag == ObjectFlag::Visible)
        m_doc->setGroupVisible(m_groupId, value);
    else
        m_doc->setGroupLocked(m_groupId, value);
}

void SetObjectFlagCommand::redo()
{
    apply(m_new);
}
void SetObjectFlagCommand::undo()
{
    apply(m_old);
}

// --- frames ------------------------------------------------------------------------------

InsertFrameCommand::InsertFrameCommand(Document *doc, int index, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_layer(doc->currentLayerId())
    , m_index(std::clamp(index, 0, doc->frameCount()))
{
    setText(Command::tr("Insert Frame"));
    m_frame.id = doc->allocateId();
    StrokeGroup g;
    g.id = doc->allocateId();
    g.name = Command::tr("Object");
    m_frame.groups.push_back(std::move(g));
}

void InsertFrameCommand::redo()
{
    if (!isObsolete())
        m_doc->insertFrame(m_layer, m_index, m_frame);
}
void InsertFrameCommand::undo()
{
    if (!isObsolete())
        m_doc->takeFrame(m_layer, m_index);
}

DuplicateFrameCommand::DuplicateFrameCommand(Document *doc, Id sourceFrameId, int index,
                                             QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_sourceId(sourceFrameId)
    , m_index(index)
{
    setText(Command::tr("Duplicate Frame"));
    const Frame *source = doc->frame(sourceFrameId);
    if (!source) {
        setObsolete(true);
        return;
    }
    m_layer = doc->layerOfFrame(sourceFrameId);
    m_index = std::clamp(m_index, 0, int(doc->layer(m_layer)->cels.size()));
    allocateIds(*source);
}

DuplicateFrameCommand::DuplicateFrameCommand(Document *doc, Frame source, Id layerId, int index,
                                             QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_sourceId(source.id)
    , m_source(std::move(source))
    , m_layer(layerId)
    , m_index(index)
{
    setText(Command::tr("Paste Cels"));
    const Layer *layer = doc->layer(layerId);
    if (!layer) {
        setObsolete(true);
        return;
    }
    allocateIds(*m_source); // the index is clamped when the copy goes in
}

void DuplicateFrameCommand::allocateIds(const Frame &source)
{
    m_copyId = m_doc->allocateId();
    for (const StrokeGroup &g : source.groups) {
        m_ids.push_back(m_doc->allocateId());
        for (std::size_t i = 0; i < g.strokes.size() + g.rig.pins.size(); ++i)
            m_ids.push_back(m_doc->allocateId());
    }
}

void DuplicateFrameCommand::redo()
{
    const Frame *source = m_source ? &*m_source : m_doc->frame(m_sourceId);
    if (isObsolete() || !source) {
        setObsolete(true);
        return;
    }
    Frame copy = *source; // strokes share their point data; pose caches are immutable too
    copy.id = m_copyId;
    std::size_t next = 0;
    std::unordered_map<Id, Id> groupIds; // joins between parts follow the copies
    for (StrokeGroup &g : copy.groups) {
        groupIds[g.id] = m_ids.at(next);
        g.id = m_ids.at(next++);
        std::unordered_map<Id, Id> strokeIds;
        for (Stroke &s : g.strokes)
            s.id = strokeIds[s.id] = m_ids.at(next++);
        remapFillStrokeIds(g, strokeIds);
        for (Pin &p : g.rig.pins)
            p.id = m_ids.at(next++);
    }
    remapJoins(copy, groupIds);
    const int size = int(m_doc->layer(m_layer)->cels.size());
    m_doc->insertFrame(m_layer, std::clamp(m_index, 0, size), std::move(copy));
}

void DuplicateFrameCommand::undo()
{
    if (!isObsolete())
        m_doc->takeFrame(m_layer, m_doc->celIndex(m_copyId));
}

DeleteFrameCommand::DeleteFrameCommand(Document *doc, Id frameId, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_frameId(frameId)
{
    setText(Command::tr("Delete Frame"));
    if (!doc->frame(frameId))
        setObsolete(true);
}

void DeleteFrameCommand::redo()
{
    m_layer = m_doc->layerOfFrame(m_frameId);
    m_index = m_doc->celIndex(m_frameId);
    if (m_index < 0) {
        setObsolete(true);
        return;
    }
    m_frame = m_doc->takeFrame(m_layer, m_index);
}

void DeleteFrameCommand::undo()
{
    if (m_frame)
        m_doc->insertFrame(m_layer, m_index, *m_frame);
}

MoveFrameCommand::MoveFrameCommand(Document *doc, int from, int to, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_from(from)
    , m_to(to)
{
    setText(Command::tr("Move Frame"));
    m_layer = doc->currentLayerId();
    const int n = doc->frameCount();
    if (from < 0 || from >= n || to < 0 || to >= n || from == to)
        setObsolete(true);
}

void MoveFrameCommand::redo()
{
    if (!isObsolete())
        m_doc->moveFrame(m_layer, m_from, m_to);
}

void MoveFrameCommand::undo()
{
    if (!isObsolete())
        m_doc->moveFrame(m_layer, m_to, m_from);
}

SetFrameHoldCommand::SetFrameHoldCommand(Document *doc, Id frameId, int hold, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_frameId(frameId)
    , m_new(std::clamp(hold, 1, kMaxHold))
{
    setText(Command::tr("Change Frame Exposure"));
    if (const Frame *f = doc->frame(frameId))
        m_old = f->hold;
    else
        setObsolete(true);
}

void SetFrameHoldCommand::redo()
{
    if (!isObsolete())
        m_doc->setFrameHold(m_frameId, m_new);
}

void SetFrameHoldCommand::undo()
{
    if (!isObsolete())
        m_doc->setFrameHold(m_frameId, m_old);
}

// --- document ----------------------------------------------------------------------------

DocumentSettings sanitizedSettings(DocumentSettings s)
{
    s.fps = std::clamp(s.fps, kMinFps, kMaxFps);
    s.canvasSize = QSize(std::clamp(s.canvasSize.width(), 1, kMaxCanvasSide),
                         std::clamp(s.canvasSize.height(), 1, kMaxCanvasSide));
    s.playStart = std::max(0, s.playStart);
    if (s.playEnd >= 0 && s.playEnd < s.playStart)
        std::swap(s.playStart, s.playEnd);
    s.closeGap = s.closeGap >= 0 ? std::min(s.closeGap, kMaxCloseGap) : -1.0; // NaN: automatic
    s.lightAzimuth = std::isfinite(s.lightAzimuth) ? std::fmod(s.lightAzimuth, 360.0) : 135.0;
    if (s.lightAzimuth < 0.0)
        s.lightAzimuth += 360.0;
    s.lightElevation =
        std::isfinite(s.lightElevation) ? std::clamp(s.lightElevation, 0.0, 90.0) : 45.0;
    return s;
}

ChangeSettingsCommand::ChangeSettingsCommand(Document *doc, const DocumentSettings &settings,
                                             QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_new(sanitizedSettings(settings))
    , m_old(doc->settings())
{
    setText(Command::tr("Change Document Settings"));
    if (m_new == m_old)
        setObsolete(true);
}

void ChangeSettingsCommand::redo()
{
    m_doc->setSettings(m_new);
}
void ChangeSettingsCommand::undo()
{
    m_doc->setSettings(m_old);
}

} // namespace finbook::model
