#include <finbook/model/scene/shot.h>
#include <finbook/ui/window/editor_state.h>

#include <algorithm>

namespace finbook::ui {

EditorState::EditorState(model::Document *document, QObject *parent)
    : QObject(parent)
    , m_doc(document)
{
    // Keep the current frame on the same drawing when frames move around it, and valid
    // when frames go away.
    connect(m_doc, &model::Document::documentReset, this, [this] {
        m_groupId = model::kNoId;
        m_frameIndex = -1;
        m_tick = 0;
        setCurrentFrameIndex(0);
    });
    connect(m_doc, &model::Document::currentLayerChanged, this, &EditorState::followLayer);
    connect(m_doc, &model::Document::framesInserted, this, [this](int first, int count) {
        if (first <= m_frameIndex && m_frameIndex >= 0)
            m_frameIndex += count;
        clampToDocument();
        emit currentFrameChanged(m_frameIndex);
    });
    connect(m_doc, &model::Document::framesRemoved, this, [this](int first, int count) {
        if (m_frameIndex >= first + count)
            m_frameIndex -= count;
        clampToDocument();
        emit currentFrameChanged(m_frameIndex);
    });
    connect(m_doc, &model::Document::frameMoved, this, [this](int from, int to) {
        if (m_frameIndex == from)
            m_frameIndex = to;
        else if (from < m_frameIndex && to >= m_frameIndex)
            --m_frameIndex;
        else if (from > m_frameIndex && to <= m_frameIndex)
            ++m_frameIndex;
        emit currentFrameChanged(m_frameIndex);
    });
    // A selection never outlives its strokes (erased, undone, moved to another frame).
    connect(m_doc, &model::Document::frameChanged, this, [this] {
        std::vector<model::Id> kept, keptPictures;
        for (model::Id id : m_selection) {
            const model::StrokeLocation at = m_doc->locateStroke(id);
            if (at.isValid() && at.layer == m_doc->currentLayerIndex() && at.frame == m_frameIndex)
                kept.push_back(id);
        }
        for (model::Id id : m_pictureSelection) {
            const model::GroupLocation at = m_doc->locateGroup(id);
            if (at.isValid() && at.layer == m_doc->currentLayerIndex() &&
                at.frame == m_frameIndex && m_doc->group(id)->picture)
                keptPictures.push_back(id);
        }
        if (kept != m_selection || keptPictures != m_pictureSelection)
            setSelection(std::move(kept), std::move(keptPictures));
    });
    connect(this, &EditorState::currentFrameChanged, this, [this] {
        if (hasSelection())
            setSelectedStrokes({});
        const model::Id current = currentFrameId();
        if (!m_frameSelection.empty() && std::find(m_frameSelection.begin(), m_frameSelection.end(),
                                                   current) == m_frameSelection.end())
            setSelectedFrames({});
    });
    connect(this, &EditorState::currentFrameChanged, this, [this] {
        const qint64 before = m_tick;
        keepTickInCel();
        if (m_playbackTick < 0 && before != m_tick)
            emit tickChanged(currentTick());
    });
    connect(m_doc, &model::Document::framesRemoved, this, &EditorState::frameSelectionChanged);
    connect(m_doc, &model::Document::documentReset, this, [this] {
        setSelectedFrames({});
        setSelectedCels({});
    });
    // After the handlers above have settled the current frame.
    const auto focus = [this] { m_doc->setFocusFrame(currentFrameId()); };
    connect(m_doc, &model::Document::framesInserted, this, focus);
    connect(m_doc, &model::Document::framesRemoved, this, focus);
    connect(m_doc, &model::Document::currentLayerChanged, this, focus);
    connect(m_doc, &model::Document::documentReset, this, focus);
    clampToDocument();
}

qint64 EditorState::currentTick() const
{
    if (m_playbackTick >= 0)
        return m_playbackTick;
    return m_tick;
}

void EditorState::keepTickInCel()
{
    const std::vector<model::Frame> &cels = m_doc->frames();
    if (m_frameIndex < 0 || m_frameIndex >= int(cels.size()))
        return;
    const int at = model::celAt(cels, m_tick);
    // Past the layer's end the playhead may stay (other layers go on): the last cel is current.
    if (at == m_frameIndex || (at < 0 && m_tick > 0 && m_frameIndex == int(cels.size()) - 1))
        return;
    m_tick = model::celStart(cels, m_frameIndex);
}

void EditorState::followLayer()
{
    m_selection.clear();
    m_pictureSelection.clear();
    const std::vector<model::Frame> &cels = m_doc->frames();
    int index = model::celAt(cels, m_tick);
    if (index < 0)
        index = int(cels.size()) - 1;
    m_frameIndex = -1; // announce the frame even at the same index: it is another layer's
    setCurrentFrameIndex(std::max(index, 0));
    emit selectionChanged();
}

void EditorState::setCurrentTick(qint64 tick)
{
    tick = std::max<qint64>(tick, 0);
    if (tick == m_tick)
        return;
    m_tick = tick;
    const std::vector<model::Frame> &cels = m_doc->frames();
    int index = model::celAt(cels, tick);
    if (index < 0)
        index = int(cels.size()) - 1;
    if (index != m_frameIndex && index >= 0)
        setCurrentFrameIndex(index); // keeps m_tick: it is in that cel (or past the last)
    if (m_playbackTick < 0)
        emit tickChanged(m_tick);
}

void EditorState::setPlaybackTick(qint64 tick)
{
    tick = std::max<qint64>(tick, -1);
    if (tick == m_playbackTick)
        return;
    m_playbackTick = tick;
    emit tickChanged(currentTick());
}

void EditorState::setDimOtherLayers(bool on)
{
    if (on == m_dimOthers)
        return;
    m_dimOthers = on;
    emit dimOtherLayersChanged(on);
}

void EditorState::setCameraView(bool on)
{
    if (on == m_cameraView)
        return;
    m_cameraView = on;
    emit cameraViewChanged(on);
}

std::vector<int> EditorState::selectedFrames() const
{
    std::vector<int> rows;
    for (model::Id id : m_frameSelection)
        if (const int row = m_doc->frameIndex(id); row >= 0)
            rows.push_back(row);
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    if (rows.empty() && currentFrame())
        rows.push_back(m_frameIndex);
    return rows;
}

void EditorState::setSelectedFrames(std::vector<model::Id> frameIds)
{
    if (frameIds == m_frameSelection)
        return;
    m_frameSelection = std::move(frameIds);
    emit frameSelectionChanged();
}

model::Id EditorState::currentFrameId() const
{
    const model::Frame *f = currentFrame();
    return f ? f->id : model::kNoId;
}

const model::Frame *EditorState::currentFrame() const
{
    if (m_frameIndex < 0 || m_frameIndex >= m_doc->frameCount())
        return nullptr;
    return &m_doc->frameAt(m_frameIndex);
}

model::Id EditorState::currentGroupId() const
{
    const model::Frame *f = currentFrame();
    if (!f || f->groups.empty())
        return model::kNoId;
    for (const model::StrokeGroup &g : f->groups)
        if (g.id == m_groupId)
            return g.id;
    return f->groups.back().id;
}

const model::StrokeGroup *EditorState::currentGroup() const
{
    const model::Id id = currentGroupId();
    return id == model::kNoId ? nullptr : m_doc->group(id);
}

void EditorState::setCurrentFrameIndex(int index)
{
    index = std::clamp(index, 0, std::max(0, m_doc->frameCount() - 1));
    if (index == m_frameIndex)
        return;
    // Carry the object choice to the same z-position in the new frame, so drawing continues
    // on "the arm" after a duplicate or a frame step.
    const model::Frame *before = currentFrame();
    int slot = -1;
    if (before)
        for (int i = 0; i < int(before->groups.size()); ++i)
            if (before->groups[std::size_t(i)].id == currentGroupId())
                slot = i;
    m_frameIndex = index;
    // Strokes of a drawing shown in several frames are looked up here first (document.h).
    m_doc->setFocusFrame(currentFrameId());
    if (const model::Frame *after = currentFrame();
        after && slot >= 0 && slot < int(after->groups.size()))
        m_groupId = after->groups[std::size_t(slot)].id;
    emit currentFrameChanged(m_frameIndex);
    emit currentGroupChanged(currentGroupId());
}

void EditorState::setCurrentGroupId(model::Id groupId)
{
    model::GroupLocation at = m_doc->locateGroup(groupId);
    if (!at.isValid())
        return;
    // An object of another layer makes its layer current.
    if (at.layer != m_doc->currentLayerIndex()) {
        m_doc->setCurrentLayer(m_doc->layerAt(at.layer).id);
        at = m_doc->locateGroup(groupId);
    }
    if (at.frame != m_frameIndex)
        setCurrentFrameIndex(at.frame);
    if (m_groupId == groupId)
        return;
    m_groupId = groupId;
    emit currentGroupChanged(groupId);
}

void EditorState::setSelectedStrokes(std::vector<model::Id> strokeIds)
{
    setSelection(std::move(strokeIds), {});
}

void EditorState::setSelection(std::vector<model::Id> strokeIds,
                               std::vector<model::Id> pictureObjectIds)
{
    if (strokeIds == m_selection && pictureObjectIds == m_pictureSelection)
        return;
    m_selection = std::move(strokeIds);
    m_pictureSelection = std::move(pictureObjectIds);
    if (hasSelection())
        setSelectedCels({});
    emit selectionChanged();
}

void EditorState::setSelectedCels(std::vector<model::Id> celIds)
{
    if (celIds == m_celSelection)
        return;
    m_celSelection = std::move(celIds);
    if (!m_celSelection.empty())
        setSelectedStrokes({});
    emit celSelectionChanged();
}

void EditorState::setOnionSkin(const OnionSkin &onion)
{
    OnionSkin o = onion;
    o.before = std::clamp(o.before, 0, 5);
    o.after = std::clamp(o.after, 0, 5);
    o.opacity = std::clamp(o.opacity, 0.0, 1.0);
    if (o == m_onion)
        return;
    m_onion = o;
    emit onionSkinChanged();
}

void EditorState::setPlaying(bool playing)
{
    if (playing == m_playing)
        return;
    m_playing = playing;
    emit playingChanged(playing);
}

void EditorState::setShowMesh(bool show)
{
    if (show == m_showMesh)
        return;
    m_showMesh = show;
    emit showMeshChanged(show);
}

void EditorState::setShowSkeleton(bool show)
{
    m_showSkeleton = show;
}

void EditorState::nextFrame()
{
    setCurrentFrameIndex(m_frameIndex + 1);
}
void EditorState::previousFrame()
{
    setCurrentFrameIndex(m_frameIndex - 1);
}

void EditorState::clampToDocument()
{
    const int last = std::max(0, m_doc->frameCount() - 1);
    m_frameIndex = std::clamp(m_frameIndex, 0, last);
}

} // namespace finbook::ui
