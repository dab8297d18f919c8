// Document's swap sets (document.h, types.h SwapSet): the drawings objects swap between frame by
// frame, and the one rule that makes them one drawing wherever they are shown: an edit of a
// linked object's strokes, fills or mesh density is made, the same, on its drawing and on every
// other object showing it. Each is a plain copy of shared pointers, so a drawing shown in a
// hundred frames costs its points once.
#include <finbook/model/document.h>

#include <algorithm>
#include <stdexcept>

namespace finbook::model {

const SwapDrawing *SwapSet::drawing(Id drawingId) const
{
    const int at = indexOf(drawingId);
    return at < 0 ? nullptr : &drawings[std::size_t(at)];
}

int SwapSet::indexOf(Id drawingId) const
{
    for (int i = 0; i < int(drawings.size()); ++i)
        if (drawings[std::size_t(i)].id == drawingId)
            return i;
    return -1;
}

const SwapSet *Document::swapSet(Id setId) const
{
    for (const SwapSet &s : m_swapSets)
        if (s.id == setId)
            return &s;
    return nullptr;
}

SwapSet &Document::mutableSwapSet(Id setId)
{
    for (SwapSet &s : m_swapSets)
        if (s.id == setId)
            return s;
    throw std::out_of_range("Document: no such swap set");
}

const SwapDrawing *Document::swapDrawing(const SwapLink &link) const
{
    const SwapSet *set = swapSet(link.set);
    return set ? set->drawing(link.drawing) : nullptr;
}

std::vector<Id> Document::objectsShowing(const SwapLink &link) const
{
    std::vector<Id> out;
    if (!link.linked())
        return out;
    for (const Layer &l : m_layers)
        for (const Frame &f : l.cels)
            for (const StrokeGroup &g : f.groups)
                if (g.swap == link)
                    out.push_back(g.id);
    return out;
}

std::vector<Id> Document::objectsOfSet(Id setId) const
{
    std::vector<Id> out;
    for (const Layer &l : m_layers)
        for (const Frame &f : l.cels)
            for (const StrokeGroup &g : f.groups)
                if (g.swap.linked() && g.swap.set == setId)
                    out.push_back(g.id);
    return out;
}

namespace {
// Makes `g` show `drawing`; whether its strokes changed.
bool showDrawing(StrokeGroup &g, const SwapDrawing &drawing)
{
    const bool strokes = g.strokes != drawing.strokes || g.meshDensity != drawing.meshDensity;
    g.strokes = drawing.strokes;
    g.fills = drawing.fills;
    g.meshDensity = drawing.meshDensity;
    if (strokes)
        g.deformed.reset();
    return strokes;
}
} // namespace

void Document::linkInserted(Frame &frame)
{
    std::vector<Id> setsHere;
    for (StrokeGroup &g : frame.groups) {
        if (!g.swap.linked())
            continue;
        const SwapDrawing *drawing = swapDrawing(g.swap);
        // One object per frame shows a set: two would hold the same strokes in one frame.
        if (!drawing || std::find(setsHere.begin(), setsHere.end(), g.swap.set) != setsHere.end()) {
            g.swap = {};
            continue;
        }
        setsHere.push_back(g.swap.set);
        showDrawing(g, *drawing);
    }
}

void Document::shareDrawing(Id groupId)
{
    if (m_swapSets.empty()) // no object is linked: not even a lookup per edit
        return;
    const StrokeGroup *edited = group(groupId);
    if (!edited || !edited->swap.linked())
        return;
    const SwapLink link = edited->swap;
    SwapSet *set = nullptr;
    for (SwapSet &s : m_swapSets)
        if (s.id == link.set)
            set = &s;
    const int at = set ? set->indexOf(link.drawing) : -1;
    if (at < 0)
        return;
    SwapDrawing &drawing = set->drawings[std::size_t(at)];
    drawing.strokes = edited->strokes;
    drawing.fills = edited->fills;
    drawing.meshDensity = edited->meshDensity;
    for (Id other : objectsShowing(link)) {
        if (other == groupId)
            continue;
        if (showDrawing(mutableGroup(other), drawing))
            emit strokesChanged(other);
        groupEdited(other, false);
    }
}

void Document::insertSwapSet(int index, SwapSet set)
{
    if (set.id == kNoId || swapSet(set.id))
        throw std::invalid_argument("Document::insertSwapSet: the set needs a new id");
    index = std::clamp(index, 0, int(m_swapSets.size()));
    m_swapSets.insert(m_swapSets.begin() + index, std::move(set));
    emit swapSetsChanged();
}

SwapSet Document::takeSwapSet(Id setId)
{
    const auto it = std::find_if(m_swapSets.begin(), m_swapSets.end(),
                                 [&](const SwapSet &s) { return s.id == setId; });
    if (it == m_swapSets.end())
        throw std::out_of_range("Document::takeSwapSet: no such set");
    for (Id id : objectsOfSet(setId)) {
        mutableGroup(id).swap = {};
        groupEdited(id, true);
    }
    SwapSet taken = std::move(*it);
    m_swapSets.erase(it);
    emit swapSetsChanged();
    return taken;
}

void Document::insertSwapDrawing(Id setId, int index, SwapDrawing drawing)
{
    SwapSet &set = mutableSwapSet(setId);
    if (drawing.id == kNoId || set.indexOf(drawing.id) >= 0)
        throw std::invalid_argument("Document::insertSwapDrawing: the drawing needs a new id");
    index = std::clamp(index, 0, int(set.drawings.size()));
    set.drawings.insert(set.drawings.begin() + index, std::move(drawing));
    emit swapSetsChanged();
}

SwapDrawing Document::takeSwapDrawing(Id setId, Id drawingId)
{
    SwapSet &set = mutableSwapSet(setId);
    const int at = set.indexOf(drawingId);
    if (at < 0)
        throw std::out_of_range("Document::takeSwapDrawing: no such drawing");
    for (Id id : objectsShowing({setId, drawingId})) {
        mutableGroup(id).swap = {};
        groupEdited(id, true);
    }
    SwapDrawing taken = std::move(set.drawings[std::size_t(at)]);
    set.drawings.erase(set.drawings.begin() + at);
    emit swapSetsChanged();
    return taken;
}

void Document::setSwapDrawingName(Id setId, Id drawingId, const QString &name)
{
    SwapSet &set = mutableSwapSet(setId);
    const int at = set.indexOf(drawingId);
    if (at < 0)
        throw std::out_of_range("Document::setSwapDrawingName: no such drawing");
    set.drawings[std::size_t(at)].name = name;
    emit swapSetsChanged();
    for (Id id : objectsShowing({setId, drawingId}))
        groupEdited(id, true);
}

void Document::setSwapSetName(Id setId, const QString &name)
{
    mutableSwapSet(setId).name = name;
    emit swapSetsChanged();
}

void Document::setSwapDrawingRig(Id setId, Id drawingId, Rig rig)
{
    SwapSet &set = mutableSwapSet(setId);
    const int at = set.indexOf(drawingId);
    if (at < 0)
        throw std::out_of_range("Document::setSwapDrawingRig: no such drawing");
    set.drawings[std::size_t(at)].rig = std::move(rig);
}

void Document::setGroupSwap(Id groupId, SwapLink link)
{
    StrokeGroup &g = mutableGroup(groupId);
    const GroupLocation at = locateGroup(groupId);
    const SwapDrawing *drawing = swapDrawing(link);
    bool taken = false;
    for (const StrokeGroup &other : frameAt(at).groups)
        taken = taken || (other.id != groupId && link.linked() && other.swap.set == link.set);
    if (!drawing || taken)
        link = {};
    g.swap = link;
    const bool strokes = drawing && link.linked() && showDrawing(g, *drawing);
    if (strokes)
        emit strokesChanged(groupId);
    groupEdited(groupId, true);
}

} // namespace finbook::model
