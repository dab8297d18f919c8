// Drawing substitution's commands (swap/swap_commands.h).
#include "../command_text.h"

#include <finbook/model/swap/swap_commands.h>

#include <algorithm>
#include <map>

namespace finbook::model {

void reIdentify(std::vector<Stroke> &strokes, std::vector<Fill> &fills,
                const std::function<Id()> &newId)
{
    std::map<Id, Id> renamed;
    for (Stroke &s : strokes)
        s.id = renamed[s.id] = newId();
    for (Fill &f : fills)
        forEachFillStrokes(f, [&](std::vector<Id> &ids) {
            for (Id &id : ids)
                if (const auto it = renamed.find(id); it != renamed.end())
                    id = it->second;
            std::sort(ids.begin(), ids.end());
        });
}

namespace {
// A rig taken to another frame: new pin ids (ids are unique), at rest, and a skeleton hung from
// an object of that frame where the object it hung from has a namesake there.
Rig rigForFrame(Document &doc, Rig rig, Id frameId)
{
    rig = rig.atRest();
    for (Pin &p : rig.pins)
        p.id = doc.allocateId();
    SkeletonJoin &join = rig.skeleton.join;
    if (join.joined()) {
        const StrokeGroup *parent = doc.group(join.parent);
        const Frame *frame = doc.frame(frameId);
        Id here = kNoId;
        if (parent && frame)
            for (const StrokeGroup &g : frame->groups)
                if (g.name == parent->name && here == kNoId)
                    here = g.id;
        join.parent = here;
        if (here == kNoId)
            join = {};
    }
    return rig;
}

Id frameOf(const Document &doc, Id groupId)
{
    const GroupLocation at = doc.locateGroup(groupId);
    return at.isValid() ? doc.frameAt(at).id : kNoId;
}
} // namespace

// --- NewSwapSetCommand --------------------------------------------------------------------

NewSwapSetCommand::NewSwapSetCommand(Document *doc, Id groupId, const QString &setName,
                                     const QString &drawingName, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
{
    setText(Command::tr("Make Object Swappable"));
    const StrokeGroup *g = doc->group(groupId);
    if (!g || g->swap.linked()) {
        setObsolete(true);
        return;
    }
    m_set.id = doc->allocateId();
    m_set.name = setName;
    // The object's drawing, ids and all: the object goes on showing it.
    // The object keeps its rig: the drawing keeps one only once a frame leaves it.
    m_set.drawings.push_back(
        SwapDrawing{doc->allocateId(), drawingName, g->strokes, g->fills, g->meshDensity, {}});
    m_show = m_set.drawings.front().id;
    m_oldStrokes = g->strokes;
    m_oldFills = g->fills;
    m_oldDensity = g->meshDensity;
    m_oldRig = g->rig;
    m_oldDeformed = g->deformed;
}

NewSwapSetCommand::NewSwapSetCommand(Document *doc, Id groupId, SwapSet set, int show,
                                     QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
    , m_set(std::move(set))
{
    setText(Command::tr("New Swap Set"));
    const StrokeGroup *g = doc->group(groupId);
    if (!g || g->swap.linked() || m_set.drawings.empty() || show < 0 ||
        show >= int(m_set.drawings.size())) {
        setObsolete(true);
        return;
    }
    m_show = m_set.drawings[std::size_t(show)].id;
    m_oldStrokes = g->strokes;
    m_oldFills = g->fills;
    m_oldDensity = g->meshDensity;
    m_oldRig = g->rig;
    m_oldDeformed = g->deformed;
}

void NewSwapSetCommand::redo()
{
    if (isObsolete())
        return;
    m_doc->insertSwapSet(int(m_doc->swapSets().size()), m_set);
    const SwapDrawing *shown = m_set.drawing(m_show);
    if (shown->strokes != m_oldStrokes)
        m_doc->setRig(m_groupId, shown->rig);
    m_doc->setGroupSwap(m_groupId, {m_set.id, m_show});
}

void NewSwapSetCommand::undo()
{
    if (isObsolete())
        return;
    m_doc->setGroupSwap(m_groupId, {});
    m_doc->takeSwapSet(m_set.id);
    m_doc->setStrokes(m_groupId, m_oldStrokes);
    m_doc->setFills(m_groupId, m_oldFills);
    m_doc->setGroupMeshDensity(m_groupId, m_oldDensity);
    m_doc->setRig(m_groupId, m_oldRig);
    m_doc->setDeformed(m_groupId, m_oldDeformed);
}

// --- SetSwapDrawingCommand ----------------------------------------------------------------

SetSwapDrawingCommand::SetSwapDrawingCommand(Document *doc, Id groupId, SwapLink to,
                                             QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
    , m_to(to)
{
    const StrokeGroup *g = doc->group(groupId);
    const SwapDrawing *drawing = doc->swapDrawing(to);
    setText(Command::tr("Show Drawing \"%1\"").arg(drawing ? drawing->name : QString()));
    if (!g || !drawing || g->swap == to) {
        setObsolete(true);
        return;
    }
    const Id frameId = frameOf(*doc, groupId);
    const Frame *frame = doc->frame(frameId);
    for (const StrokeGroup &other : frame->groups)
        if (other.id != groupId && other.swap.linked() && other.swap.set == to.set) {
            setObsolete(true); // a frame shows a set once
            return;
        }
    m_from = g->swap;
    m_oldStrokes = g->strokes;
    m_oldFills = g->fills;
    m_oldDensity = g->meshDensity;
    m_oldRig = g->rig;
    m_oldDeformed = g->deformed;
    if (const SwapDrawing *left = m_from.linked() ? doc->swapDrawing(m_from) : nullptr) {
        m_keepsRig = true;
        m_keptBefore = left->rig;
    }
    // The rig `to` kept, else the one a frame showing it has.
    Rig source = drawing->rig;
    if (source.empty())
        for (Id other : doc->objectsShowing(to))
            if (const StrokeGroup *o = doc->group(other); o && !o->rig.empty()) {
                source = o->rig;
                break;
            }
    m_newRig = rigForFrame(*doc, source, frameId);
}

void SetSwapDrawingCommand::redo()
{
    if (isObsolete())
        return;
    if (m_keepsRig)
        m_doc->setSwapDrawingRig(m_from.set, m_from.drawing, m_oldRig.atRest());
    m_doc->setRig(m_groupId, {});
    m_doc->setGroupSwap(m_groupId, m_to);
    m_doc->setRig(m_groupId, m_newRig);
}

void SetSwapDrawingCommand::undo()
{
    if (isObsolete())
        return;
    m_doc->setRig(m_groupId, {});
    m_doc->setGroupSwap(m_groupId, m_from);
    if (!m_from.linked()) {
        m_doc->setStrokes(m_groupId, m_oldStrokes);
        m_doc->setFills(m_groupId, m_oldFills);
        m_doc->setGroupMeshDensity(m_groupId, m_oldDensity);
    } else if (m_keepsRig) {
        m_doc->setSwapDrawingRig(m_from.set, m_from.drawing, m_keptBefore);
    }
    m_doc->setRig(m_groupId, m_oldRig);
    m_doc->setDeformed(m_groupId, m_oldDeformed);
}

SetSwapDrawingCommand *stepSwapDrawing(Document *doc, Id groupId, int step)
{
    const StrokeGroup *g = doc->group(groupId);
    const SwapSet *set = g ? doc->swapSet(g->swap.set) : nullptr;
    if (!set || set->drawings.size() < 2)
        return nullptr;
    const int n = int(set->drawings.size());
    const int at = set->indexOf(g->swap.drawing);
    const int to = ((at + step) % n + n) % n;
    return new SetSwapDrawingCommand(doc, groupId, {set->id, set->drawings[std::size_t(to)].id});
}

// --- AddSwapDrawingCommand ----------------------------------------------------------------

AddSwapDrawingCommand::AddSwapDrawingCommand(Document *doc, Id groupId, const QString &name,
                                             Content content, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
{
    setText(Command::tr("New Drawing \"%1\"").arg(name));
    const StrokeGroup *g = doc->group(groupId);
    const SwapSet *set = g ? doc->swapSet(g->swap.set) : nullptr;
    if (!set || int(set->drawings.size()) >= kMaxSwapDrawings) {
        setObsolete(true);
        return;
    }
    m_setId = set->id;
    m_index = set->indexOf(g->swap.drawing) + 1;
    m_drawing.id = doc->allocateId();
    m_drawing.name = name;
    m_drawing.meshDensity = g->meshDensity;
    if (content == Content::Copy) {
        m_drawing.strokes = g->strokes;
        m_drawing.fills = g->fills;
        reIdentify(m_drawing.strokes, m_drawing.fills, [doc] { return doc->allocateId(); });
        m_drawing.rig = rigForFrame(*doc, g->rig, frameOf(*doc, groupId));
    }
    m_groupId = groupId;
}

AddSwapDrawingCommand::~AddSwapDrawingCommand() = default;

void AddSwapDrawingCommand::redo()
{
    if (isObsolete())
        return;
    m_doc->insertSwapDrawing(m_setId, m_index, m_drawing);
    // Made once the drawing is there (what it takes from the document is then the same at
    // every redo).
    if (!m_show)
        m_show = std::make_unique<SetSwapDrawingCommand>(m_doc, m_groupId,
                                                         SwapLink{m_setId, m_drawing.id});
    m_show->redo();
}

void AddSwapDrawingCommand::undo()
{
    if (isObsolete())
        return;
    m_show->undo();
    m_doc->takeSwapDrawing(m_setId, m_drawing.id);
}

// --- RenameSwapDrawingCommand -------------------------------------------------------------

RenameSwapDrawingCommand::RenameSwapDrawingCommand(Document *doc, SwapLink drawing,
                                                   const QString &name, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_drawing(drawing)
    , m_new(name)
{
    setText(Command::tr("Rename Drawing"));
    const SwapDrawing *found = doc->swapDrawing(drawing);
    if (!found || found->name == name) {
        setObsolete(true);
        return;
    }
    m_old = found->name;
}

void RenameSwapDrawingCommand::redo()
{
    if (!isObsolete())
        m_doc->setSwapDrawingName(m_drawing.set, m_drawing.drawing, m_new);
}

void RenameSwapDrawingCommand::undo()
{
    if (!isObsolete())
        m_doc->setSwapDrawingName(m_drawing.set, m_drawing.drawing, m_old);
}

// --- RemoveSwapDrawingCommand -------------------------------------------------------------

RemoveSwapDrawingCommand::RemoveSwapDrawingCommand(Document *doc, SwapLink drawing,
                                                   QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_drawing(drawing)
{
    const SwapSet *set = doc->swapSet(drawing.set);
    const SwapDrawing *found = doc->swapDrawing(drawing);
    setText(Command::tr("Delete Drawing \"%1\"").arg(found ? found->name : QString()));
    if (!set || !found || set->drawings.size() < 2) {
        setObsolete(true);
        return;
    }
    m_index = set->indexOf(drawing.drawing);
    const SwapDrawing &instead = set->drawings[std::size_t(m_index > 0 ? m_index - 1 : 1)];
    for (Id shown : doc->objectsShowing(drawing))
        new SetSwapDrawingCommand(doc, shown, {drawing.set, instead.id}, this);
}

void RemoveSwapDrawingCommand::redo()
{
    if (isObsolete())
        return;
    QUndoCommand::redo(); // the frames showing it show another
    m_taken = m_doc->takeSwapDrawing(m_drawing.set, m_drawing.drawing);
}

void RemoveSwapDrawingCommand::undo()
{
    if (isObsolete() || !m_taken)
        return;
    m_doc->insertSwapDrawing(m_drawing.set, m_index, std::move(*m_taken));
    m_taken.reset();
    QUndoCommand::undo();
}

// --- MakeDrawingOwnCommand ----------------------------------------------------------------

MakeDrawingOwnCommand::MakeDrawingOwnCommand(Document *doc, Id groupId, QUndoCommand *parent)
    : DocumentCommand(doc, parent)
    , m_groupId(groupId)
{
    setText(Command::tr("Make Drawing Independent"));
    const StrokeGroup *g = doc->group(groupId);
    if (!g || !g->swap.linked()) {
        setObsolete(true);
        return;
    }
    m_link = g->swap;
    m_strokes = g->strokes;
    m_fills = g->fills;
    reIdentify(m_strokes, m_fills, [doc] { return doc->allocateId(); });
}

void MakeDrawingOwnCommand::redo()
{
    if (isObsolete())
        return;
    const DeformedStrokesPtr pose = m_doc->group(m_groupId)->deformed;
    m_doc->setGroupSwap(m_groupId, {});
    m_doc->setStrokes(m_groupId, m_strokes);
    m_doc->setFills(m_groupId, m_fills);
    m_doc->setDeformed(m_groupId, pose); // the same points: the pose still fits
}

void MakeDrawingOwnCommand::undo()
{
    if (isObsolete())
        return;
    const DeformedStrokesPtr pose = m_doc->group(m_groupId)->deformed;
    m_doc->setGroupSwap(m_groupId, m_link);
    m_doc->setDeformed(m_groupId, pose);
}

} // namespace finbook::model
