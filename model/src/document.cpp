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
{}

Document::~Document()
{
    // Commands refer to this document; drop them before the frames go.
    m_undoStack.clear();
}

int Document::frameIndex(Id frameId) const
{
    for (int i = 0; i < frameCount(); ++i)
        if (m_frames[std::size_t(i)].id == frameId)
            return i;
    return -1;
}

const Frame *Document::frame(Id frameId) const
{
    const int index = frameIndex(frameId);
    return index < 0 ? nullptr : &m_frames[std::size_t(index)];
}

GroupLocation Document::locateGroup(Id groupId) const
{
    for (int f = 0; f < frameCount(); ++f) {
        const auto &groups = m_frames[std::size_t(f)].groups;
        for (int g = 0; g < int(groups.size()); ++g)
            if (groups[std::size_t(g)].id == groupId)
                return {f, g};
    }
    return {};
}

const StrokeGroup *Document::group(Id groupId) const
{
    const GroupLocation at = locateGroup(groupId);
    if (!at.isValid())
        return nullptr;
    return &m_frames[std::size_t(at.frame)].groups[std::size_t(at.group)];
}

StrokeLocation Document::locateStroke(Id strokeId) const
{
    for (int f = 0; f < frameCount(); ++f) {
        const auto &groups = m_frames[std::size_t(f)].groups;
        for (int g = 0; g < int(groups.size()); ++g) {
            const auto &strokes = groups[std::size_t(g)].strokes;
            for (int s = 0; s < int(strokes.size()); ++s)
                if (strokes[std::size_t(s)].id == strokeId)
                    return {f, g, s};
        }
    }
    return {};
}

int Document::playFirst() const
{
    if (m_frames.empty())
        return 0;
    return std::clamp(m_settings.playStart, 0, frameCount() - 1);
}

int Document::playLast() const
{
    if (m_frames.empty())
        return 0;
    const int last = m_settings.playEnd < 0 ? frameCount() - 1 : m_settings.playEnd;
    return std::clamp(last, playFirst(), frameCount() - 1);
}

qint64 Document::pointCount() const
{
    qint64 total = 0;
    for (const Frame &f : m_frames)
        for (const StrokeGroup &g : f.groups)
            for (const Stroke &s : g.strokes)
                total += qint64(s.data ? s.data->points.size() : 0);
    return total;
}

void Document::reset(std::vector<Frame> frames, const DocumentSettings &settings, Id nextId)
{
    m_undoStack.clear();
    m_frames = std::move(frames);
    for (Frame &f : m_frames)
        resolveJoins(f);
    m_settings = settings;
    m_camera = {};
    m_nextId = std::max<Id>(nextId, 1);
    m_reference->setReference({});
    m_soundtrack->reset({});
    emit documentReset();
}

void Document::insertFrame(int index, Frame frame)
{
    index = std::clamp(index, 0, frameCount());
    resolveJoins(frame);
    m_frames.insert(m_frames.begin() + index, std::move(frame));
    emit framesInserted(index, 1);
}

Frame Document::takeFrame(int index)
{
    if (index < 0 || index >= frameCount())
        throw std::out_of_range("Document::takeFrame: no such frame");
    Frame taken = std::move(m_frames[std::size_t(index)]);
    m_frames.erase(m_frames.begin() + index);
    emit framesRemoved(index, 1);
    return taken;
}

void Document::moveFrame(int from, int to)
{
    if (from < 0 || from >= frameCount() || to < 0 || to >= frameCount())
        throw std::out_of_range("Document::moveFrame: no such frame");
    if (from == to)
        return;
    Frame moving = std::move(m_frames[std::size_t(from)]);
    m_frames.erase(m_frames.begin() + from);
    m_frames.insert(m_frames.begin() + to, std::move(moving));
    emit frameMoved(from, to);
}

void Document::setFrameHold(Id frameId, int hold)
{
    const int index = frameIndex(frameId);
    if (index < 0)
        throw std::out_of_range("Document::setFrameHold: no such frame");
    m_frames[std::size_t(index)].hold = std::clamp(hold, 1, kMaxHold);
    emit frameChanged(frameId);
}

void Document::insertGroup(Id frameId, int index, StrokeGroup group)
{
    const int f = frameIndex(frameId);
    if (f < 0)
        throw std::out_of_range("Document::insertGroup: no such frame");
    auto &groups = m_frames[std::size_t(f)].groups;
    index = std::clamp(index, 0, int(groups.size()));
    groups.insert(groups.begin() + index, std::move(group));
    const std::vector<Id> joined = resolveJoins(m_frames[std::size_t(f)]);
    emit groupsChanged(frameId);
    emit frameChanged(frameId);
    joinsChanged(joined, kNoId);
}

StrokeGroup Document::takeGroup(Id groupId)
{
    const GroupLocation at = locateGroup(groupId);
    if (!at.isValid())
        throw std::out_of_range("Document::takeGroup: no such object");
    auto &groups = m_frames[std::size_t(at.frame)].groups;
    StrokeGroup taken = std::move(groups[std::size_t(at.group)]);
    groups.erase(groups.begin() + at.group);
    const std::vector<Id> joined = resolveJoins(m_frames[std::size_t(at.frame)]);
    const Id frameId = m_frames[std::size_t(at.frame)].id;
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
    auto &groups = m_frames[std::size_t(at.frame)].groups;
    toIndex = std::clamp(toIndex, 0, int(groups.size()) - 1);
    if (toIndex == at.group)
        return;
    StrokeGroup moving = std::move(groups[std::size_t(at.group)]);
    groups.erase(groups.begin() + at.group);
    groups.insert(groups.begin() + toIndex, std::move(moving));
    const Id frameId = m_frames[std::size_t(at.frame)].id;
    emit groupsChanged(frameId);
    emit frameChanged(frameId);
}

StrokeGroup &Document::mutableGroup(Id groupId)
{
    const GroupLocation at = locateGroup(groupId);
    if (!at.isValid())
        throw std::out_of_range("Document: no such object");
    return m_frames[std::size_t(at.frame)].groups[std::size_t(at.group)];
}

void Document::groupEdited(Id groupId, bool structural)
{
    const GroupLocation at = locateGroup(groupId);
    const Id frameId = m_frames[std::size_t(at.frame)].id;
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
}

void Document::insertStroke(Id groupId, int index, Stroke stroke)
{
    StrokeGroup &g = mutableGroup(groupId);
    index = std::clamp(index, 0, int(g.strokes.size()));
    g.strokes.insert(g.strokes.begin() + index, std::move(stroke));
    g.deformed.reset();
    emit strokesChanged(groupId);
    groupEdited(groupId, false);
}

Stroke Document::takeStroke(Id strokeId)
{
    const StrokeLocation at = locateStroke(strokeId);
    if (!at.isValid())
        throw std::out_of_range("Document::takeStroke: no such stroke");
    StrokeGroup &g = m_frames[std::size_t(at.frame)].groups[std::size_t(at.group)];
    Stroke taken = std::move(g.strokes[std::size_t(at.stroke)]);
    g.strokes.erase(g.strokes.begin() + at.stroke);
    g.deformed.reset();
    emit strokesChanged(g.id);
    groupEdited(g.id, false);
    return taken;
}

void Document::setStrokes(Id groupId, std::vector<Stroke> strokes)
{
    StrokeGroup &g = mutableGroup(groupId);
    g.strokes = std::move(strokes);
    g.deformed.reset();
    emit strokesChanged(groupId);
    groupEdited(groupId, false);
}

void Document::setFills(Id groupId, std::vector<Fill> fills)
{
    mutableGroup(groupId).fills = std::move(fills);
    groupEdited(groupId, false);
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
    const std::vector<Id> joined = resolveJoins(m_frames[std::size_t(locateGroup(groupId).frame)]);
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
