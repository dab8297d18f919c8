#include "command_text.h"

#include <finbook/model/document.h>
#include <finbook/model/reference/reference_layer.h>
#include <finbook/model/skeleton/skeleton_join.h>
#include <finbook/model/sound/soundtrack.h>

#include <algorithm>
#include <stdexcept>

namespace finbook::model {

Document::Document(QObject *parent)
    : QObject(parent)
    , m_soundtrack(std::make_unique<Soundtrack>())
    , m_reference(new ReferenceLayer(this))
{
    m_palette = defaultPalette();
    Layer first;
    first.id = allocateId();
    first.properties.name = Command::tr("Layer 1");
    m_layers.push_back(std::move(first));
}

Document::~Document()
{
    // Commands refer to this document; drop them before the frames go.
    m_undoStack.clear();
}

int Document::layerIndex(Id layerId) const
{
    for (int i = 0; i < layerCount(); ++i)
        if (m_layers[std::size_t(i)].id == layerId)
            return i;
    return -1;
}

const Layer *Document::layer(Id layerId) const
{
    const int index = layerIndex(layerId);
    return index < 0 ? nullptr : &m_layers[std::size_t(index)];
}

Layer &Document::mutableLayer(Id layerId)
{
    const int index = layerIndex(layerId);
    if (index < 0)
        throw std::out_of_range("Document: no such layer");
    return m_layers[std::size_t(index)];
}

Id Document::layerOfFrame(Id frameId) const
{
    for (const Layer &l : m_layers)
        for (const Frame &f : l.cels)
            if (f.id == frameId)
                return l.id;
    return kNoId;
}

int Document::frameIndex(Id frameId) const
{
    const std::vector<Frame> &cels = frames();
    for (int i = 0; i < int(cels.size()); ++i)
        if (cels[std::size_t(i)].id == frameId)
            return i;
    return -1;
}

int Document::celIndex(Id frameId) const
{
    for (const Layer &l : m_layers)
        for (std::size_t i = 0; i < l.cels.size(); ++i)
            if (l.cels[i].id == frameId)
                return int(i);
    return -1;
}

const Frame *Document::frame(Id frameId) const
{
    for (const Layer &l : m_layers)
        for (const Frame &f : l.cels)
            if (f.id == frameId)
                return &f;
    return nullptr;
}

Frame *Document::findFrame(Id frameId)
{
    for (Layer &l : m_layers)
        for (Frame &f : l.cels)
            if (f.id == frameId)
                return &f;
    return nullptr;
}

const Frame &Document::frameAt(const GroupLocation &at) const
{
    return m_layers.at(std::size_t(at.layer)).cels.at(std::size_t(at.frame));
}

const Frame &Document::frameAt(const StrokeLocation &at) const
{
    return m_layers.at(std::size_t(at.layer)).cels.at(std::size_t(at.frame));
}

Frame &Document::mutableFrame(const GroupLocation &at)
{
    return m_layers.at(std::size_t(at.layer)).cels.at(std::size_t(at.frame));
}

GroupLocation Document::locateGroup(Id groupId) const
{
    // The current layer first: nearly every edit is there.
    for (int k = 0; k < layerCount(); ++k) {
        const int l = k == 0 ? m_current : (k <= m_current ? k - 1 : k);
        const auto &cels = m_layers[std::size_t(l)].cels;
        for (int f = 0; f < int(cels.size()); ++f) {
            const auto &groups = cels[std::size_t(f)].groups;
            for (int g = 0; g < int(groups.size()); ++g)
                if (groups[std::size_t(g)].id == groupId)
                    return {f, g, l};
        }
    }
    return {};
}

const StrokeGroup *Document::group(Id groupId) const
{
    const GroupLocation at = locateGroup(groupId);
    if (!at.isValid())
        return nullptr;
    return &frameAt(at).groups[std::size_t(at.group)];
}

namespace {
// Where stroke `strokeId` is in cel `f` of layer `l` (invalid when it is not there).
StrokeLocation strokeInCel(const Frame &cel, int f, int l, Id strokeId)
{
    const auto &groups = cel.groups;
    for (int g = 0; g < int(groups.size()); ++g) {
        const auto &strokes = groups[std::size_t(g)].strokes;
        for (int s = 0; s < int(strokes.size()); ++s)
            if (strokes[std::size_t(s)].id == strokeId)
                return {f, g, s, l};
    }
    return {};
}
} // namespace

StrokeLocation Document::locateStroke(Id strokeId) const
{
    // The frame being edited first: a drawing shown in several frames (a swap set's) has its
    // stroke ids in each of them. Then the current layer's, where nearly every edit is.
    if (m_focusFrame != kNoId)
        for (int l = 0; l < layerCount(); ++l) {
            const auto &cels = m_layers[std::size_t(l)].cels;
            for (int f = 0; f < int(cels.size()); ++f)
                if (cels[std::size_t(f)].id == m_focusFrame)
                    if (const StrokeLocation at = strokeInCel(cels[std::size_t(f)], f, l, strokeId);
                        at.isValid())
                        return at;
        }
    for (int k = 0; k < layerCount(); ++k) {
        const int l = k == 0 ? m_current : (k <= m_current ? k - 1 : k);
        const auto &cels = m_layers[std::size_t(l)].cels;
        for (int f = 0; f < int(cels.size()); ++f)
            if (const StrokeLocation at = strokeInCel(cels[std::size_t(f)], f, l, strokeId);
                at.isValid())
                return at;
    }
    return {};
}

int Document::playFirst() const
{
    if (frames().empty())
        return 0;
    return std::clamp(m_settings.playStart, 0, frameCount() - 1);
}

int Document::playLast() const
{
    if (frames().empty())
        return 0;
    const int last = m_settings.playEnd < 0 ? frameCount() - 1 : m_settings.playEnd;
    return std::clamp(last, playFirst(), frameCount() - 1);
}

qint64 Document::pointCount() const
{
    qint64 total = 0;
    for (const Layer &l : m_layers)
        for (const Frame &f : l.cels)
            for (const StrokeGroup &g : f.groups)
                for (const Stroke &s : g.strokes)
                    total += qint64(s.data ? s.data->points.size() : 0);
    return total;
}

namespace {
Id largestId(const std::vector<Frame> &frames)
{
    Id largest = kNoId;
    for (const Frame &f : frames) {
        largest = std::max(largest, f.id);
        for (const StrokeGroup &g : f.groups) {
            largest = std::max(largest, g.id);
            for (const Stroke &s : g.strokes)
                largest = std::max(largest, s.id);
            for (const Pin &p : g.rig.pins)
                largest = std::max(largest, p.id);
        }
    }
    return largest;
}
} // namespace

void Document::reset(std::vector<Frame> frames, const DocumentSettings &settings, Id nextId)
{
    // The layer's id must not clash with the frames' even when `nextId` is too low (the writer
    // and the loader repair a low counter the same way).
    Layer only;
    only.id = std::max<Id>({nextId, 1, largestId(frames) + 1});
    only.properties.name = Command::tr("Layer 1");
    only.cels = std::move(frames);
    std::vector<Layer> layers;
    layers.push_back(std::move(only));
    const Id after = layers.front().id + 1;
    reset(std::move(layers), settings, after);
}

void Document::setPalette(Palette palette)
{
    palette = sanitizedPalette(std::move(palette));
    if (palette == m_palette)
        return;
    m_palette = std::move(palette);
    emit paletteChanged();
}

void Document::reset(std::vector<Layer> layers, const DocumentSettings &settings, Id nextId,
                     std::vector<SwapSet> swapSets)
{
    if (layers.empty())
        throw std::invalid_argument("Document::reset: a document has at least one layer");
    m_undoStack.clear();
    m_layers = std::move(layers);
    // Opened on the layer with the most drawings (the topmost of equals): the animated one,
    // where a background exposed once is the first layer.
    m_current = 0;
    for (int i = 1; i < layerCount(); ++i)
        if (m_layers[std::size_t(i)].cels.size() >= m_layers[std::size_t(m_current)].cels.size())
            m_current = i;
    m_swapSets = std::move(swapSets);
    m_focusFrame = kNoId;
    for (Layer &l : m_layers)
        for (Frame &f : l.cels) {
            linkInserted(f);
            resolveJoins(f);
        }
    m_settings = settings;
    m_camera = {};
    m_palette = defaultPalette();
    m_nextId = std::max<Id>(nextId, 1);
    m_reference->setReference({});
    m_soundtrack->reset({});
    emit documentReset();
}

void Document::insertFrame(Id layerId, int index, Frame frame)
{
    std::vector<Frame> &cels = mutableLayer(layerId).cels;
    index = std::clamp(index, 0, int(cels.size()));
    linkInserted(frame);
    resolveJoins(frame);
    cels.insert(cels.begin() + index, std::move(frame));
    if (layerId == currentLayerId())
        emit framesInserted(index, 1);
    emit celsChanged(layerId);
}

Frame Document::takeFrame(Id layerId, int index)
{
    std::vector<Frame> &cels = mutableLayer(layerId).cels;
    if (index < 0 || index >= int(cels.size()))
        throw std::out_of_range("Document::takeFrame: no such frame");
    Frame taken = std::move(cels[std::size_t(index)]);
    cels.erase(cels.begin() + index);
    if (layerId == currentLayerId())
        emit framesRemoved(index, 1);
    emit celsChanged(layerId);
    return taken;
}

void Document::moveFrame(Id layerId, int from, int to)
{
    std::vector<Frame> &cels = mutableLayer(layerId).cels;
    const int count = int(cels.size());
    if (from < 0 || from >= count || to < 0 || to >= count)
        throw std::out_of_range("Document::moveFrame: no such frame");
    if (from == to)
        return;
    Frame moving = std::move(cels[std::size_t(from)]);
    cels.erase(cels.begin() + from);
    cels.insert(cels.begin() + to, std::move(moving));
    if (layerId == currentLayerId())
        emit frameMoved(from, to);
    emit celsChanged(layerId);
}

void Document::setFrameHold(Id frameId, int hold)
{
    const Id layerId = layerOfFrame(frameId);
    if (layerId == kNoId)
        throw std::out_of_range("Document::setFrameHold: no such frame");
    findFrame(frameId)->hold = std::clamp(hold, 1, kMaxHold);
    emit frameChanged(frameId);
    emit celsChanged(layerId);
}

void Document::insertGroup(Id frameId, int index, StrokeGroup group)
{
    Frame *found = findFrame(frameId);
    if (!found)
        throw std::out_of_range("Document::insertGroup: no such frame");
    Frame &target = *found;
    auto &groups = target.groups;
    index = std::clamp(index, 0, int(groups.size()));
    if (group.swap.linked()) {
        // It shows its drawing, unless the frame already shows that set (linkInserted).
        Frame single;
        for (const StrokeGroup &g : groups)
            if (g.swap.set == group.swap.set)
                group.swap = {};
        single.groups.push_back(std::move(group));
        linkInserted(single);
        group = std::move(single.groups.front());
    }
    groups.insert(groups.begin() + index, std::move(group));
    const std::vector<Id> joined = resolveJoins(target);
    emit groupsChanged(frameId);
    emit frameChanged(frameId);
    joinsChanged(joined, kNoId);
}

StrokeGroup Document::takeGroup(Id groupId)
{
    const GroupLocation at = locateGroup(groupId);
    if (!at.isValid())
        throw std::out_of_range("Document::takeGroup: no such object");
    Frame &from = mutableFrame(at);
    auto &groups = from.groups;
    StrokeGroup taken = std::move(groups[std::size_t(at.group)]);
    groups.erase(groups.begin() + at.group);
    const std::vector<Id> joined = resolveJoins(from);
    const Id frameId = from.id;
    emit groupsChanged(frameId);
    emit frameChanged(frameId);
    joinsChanged(joined, kNoId);
    return taken;
}

void Document::moveGroup(Id groupId, int toIndex)
{
    const GroupLocation at = locateGroup(groupId);
    if (!at.isValid())
        throw std::out_of_range("Document::moveGroup: no such object");
    auto &groups = mutableFrame(at).groups;
    toIndex = std::clamp(toIndex, 0, int(groups.size()) - 1);
    if (toIndex == at.group)
        return;
    StrokeGroup moving = std::move(groups[std::size_t(at.group)]);
    groups.erase(groups.begin() + at.group);
    groups.insert(groups.begin() + toIndex, std::move(moving));
    const Id frameId = frameAt(at).id;
    emit groupsChanged(frameId);
    emit frameChanged(frameId);
}

StrokeGroup &Document::mutableGroup(Id groupId)
{
    const GroupLocation at = locateGroup(groupId);
    if (!at.isValid())
        throw std::out_of_range("Document: no such object");
    return mutableFrame(at).groups[std::size_t(at.group)];
}

void Document::groupEdited(Id groupId, bool structural)
{
    const Id frameId = frameAt(locateGroup(groupId)).id;
    if (structural)
        emit groupsChanged(frameId);
    emit frameChanged(frameId);
}

void Document::setGroupName(Id groupId, const QString &name)
{
    mutableGroup(groupId).name = name;
    groupEdited(groupId, true);
}

void Document::setGroupVisible(Id groupId, bool visible)
{
    mutableGroup(groupId).visible = visible;
    groupEdited(groupId, true);
}

void Document::setGroupLocked(Id groupId, bool locked)
{
    mutableGroup(groupId).locked = locked;
    groupEdited(groupId, true);
}

void Document::setGroupMeshDensity(Id groupId, double density)
{
    mutableGroup(groupId).meshDensity = density;
    groupEdited(groupId, true);
    emit strokesChanged(groupId); // the mesh depends on it like on the strokes
    shareDrawing(groupId);
}

void Document::insertStroke(Id groupId, int index, Stroke stroke)
{
    StrokeGroup &g = mutableGroup(groupId);
    index = std::clamp(index, 0, int(g.strokes.size()));
    g.strokes.insert(g.strokes.begin() + index, std::move(stroke));
    g.deformed.reset();
    emit strokesChanged(groupId);
    groupEdited(groupId, false);
    shareDrawing(groupId);
}

Stroke Document::takeStroke(Id strokeId)
{
    const StrokeLocation at = locateStroke(strokeId);
    if (!at.isValid())
        throw std::out_of_range("Document::takeStroke: no such stroke");
    StrokeGroup &g = mutableFrame({at.frame, at.group, at.layer}).groups[std::size_t(at.group)];
    Stroke taken = std::move(g.strokes[std::size_t(at.stroke)]);
    g.strokes.erase(g.strokes.begin() + at.stroke);
    g.deformed.reset();
    const Id groupId = g.id;
    emit strokesChanged(groupId);
    groupEdited(groupId, false);
    shareDrawing(groupId);
    return taken;
}

void Document::setStrokes(Id groupId, std::vector<Stroke> strokes)
{
    StrokeGroup &g = mutableGroup(groupId);
    g.strokes = std::move(strokes);
    g.deformed.reset();
    emit strokesChanged(groupId);
    groupEdited(groupId, false);
    shareDrawing(groupId);
}

void Document::setPicture(Id groupId, std::shared_ptr<const ObjectPicture> picture)
{
    StrokeGroup &g = mutableGroup(groupId);
    g.picture = std::move(picture);
    g.deformed.reset();
    emit strokesChanged(groupId);
    groupEdited(groupId, false);
}

void Document::setFills(Id groupId, std::vector<Fill> fills)
{
    mutableGroup(groupId).fills = std::move(fills);
    groupEdited(groupId, false);
    shareDrawing(groupId);
}

void Document::setRig(Id groupId, Rig rig)
{
    StrokeGroup &g = mutableGroup(groupId);
    if (rig.kind() == RigKind::Pins)
        rig.cage = {};
    if (rig.cage.posed.size() != rig.cage.rest.size())
        rig.cage.posed = rig.cage.rest;
    if (rig.kind() != RigKind::Skeleton)
        rig.skeleton = {};
    g.rig = std::move(rig);
    if (g.rig.empty())
        g.deformed.reset();
    // The parts hanging from this object follow its new pose (and this one its parent).
    const std::vector<Id> joined = resolveJoins(mutableFrame(locateGroup(groupId)));
    emit constraintsChanged(groupId);
    groupEdited(groupId, false);
    joinsChanged(joined, groupId);
}

void Document::joinsChanged(const std::vector<Id> &groupIds, Id already)
{
    for (Id id : groupIds)
        if (id != already && group(id)) {
            emit constraintsChanged(id);
            groupEdited(id, false);
        }
}

void Document::setDeformed(Id groupId, DeformedStrokesPtr deformed)
{
    mutableGroup(groupId).deformed = std::move(deformed);
    emit deformedChanged(groupId);
    groupEdited(groupId, false);
}

void Document::setSettings(const DocumentSettings &settings)
{
    m_settings = settings;
    emit settingsChanged();
}

void Document::setCamera(CameraTrack camera)
{
    if (camera == m_camera)
        return;
    m_camera = std::move(camera);
    emit cameraChanged();
}

} // namespace finbook::model
