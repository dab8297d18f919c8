// Document: layers → cels (frames) → objects → strokes, canvas settings, the camera and the
// one undo stack.
//
// The UI changes a document only by pushing commands (commands.h) onto undoStack(). The
// low-level mutators below exist for those commands and for the file loader; each one emits a
// past-tense signal so views, thumbnails and caches can follow.
//
// A document has at least one layer, and one of them is current: the one the timeline shows
// and the tools draw on. frames(), frameAt(), frameCount() and frameIndex() read the current
// layer's cels, so code about "the frames" means the current layer's; the frame signals
// (framesInserted, framesRemoved, frameMoved) speak of the current layer only, and
// celsChanged(layer) of any layer. Ids are unique across layers: frame(), group(),
// locateGroup() and every mutator taking an id reach any layer. The current layer is editing
// state, not undo state (like the current frame); it is not saved.
#pragma once

#include <finbook/model/camera/camera_track.h>
#include <finbook/model/palette/palette.h>
#include <finbook/model/types.h>

#include <QObject>
#include <QUndoStack>

#include <memory>
#include <vector>

namespace finbook::model {

class ReferenceLayer;
class Soundtrack; // sound/soundtrack.h

// Where an object is: its layer's index, its cel's index in that layer, its own index.
struct GroupLocation {
    int frame = -1;
    int group = -1;
    int layer = -1;
    bool isValid() const { return frame >= 0 && group >= 0 && layer >= 0; }
};

struct StrokeLocation {
    int frame = -1;
    int group = -1;
    int stroke = -1;
    int layer = -1;
    bool isValid() const { return frame >= 0 && group >= 0 && stroke >= 0 && layer >= 0; }
};

class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(QObject *parent = nullptr);
    ~Document() override;

    QUndoStack *undoStack() { return &m_undoStack; }
    const QUndoStack *undoStack() const { return &m_undoStack; }
    // The picture or video under every frame (reference/reference_layer.h). reset() empties it.
    ReferenceLayer &referenceLayer() { return *m_reference; }
    const ReferenceLayer &referenceLayer() const { return *m_reference; }
    // The sound clips (sound/soundtrack.h); reset() empties it, the loader fills it after.
    Soundtrack &soundtrack() { return *m_soundtrack; }
    const Soundtrack &soundtrack() const { return *m_soundtrack; }

    // --- reading
    const DocumentSettings &settings() const { return m_settings; }
    // The camera's keys (camera/camera_track.h); reset() empties it, the loader fills it after.
    const CameraTrack &camera() const { return m_camera; }
    // Back to front; never empty.
    const std::vector<Layer> &layers() const { return m_layers; }
    int layerCount() const { return int(m_layers.size()); }
    const Layer &layerAt(int index) const { return m_layers.at(std::size_t(index)); }
    int layerIndex(Id layerId) const; // -1 if there is none
    const Layer *layer(Id layerId) const;
    Id currentLayerId() const { return m_layers[std::size_t(m_current)].id; }
    int currentLayerIndex() const { return m_current; }
    const Layer &currentLayer() const { return m_layers[std::size_t(m_current)]; }
    // The layer holding the frame, or kNoId.
    Id layerOfFrame(Id frameId) const;

    // The current layer's cels.
    const std::vector<Frame> &frames() const { return currentLayer().cels; }
    int frameCount() const { return int(currentLayer().cels.size()); }
    const Frame &frameAt(int index) const { return currentLayer().cels.at(std::size_t(index)); }
    // The cel an object or a stroke is in, whatever layer (the location must be valid).
    const Frame &frameAt(const GroupLocation &at) const;
    const Frame &frameAt(const StrokeLocation &at) const;
    int frameIndex(Id frameId) const;     // in the current layer; -1 if it is not there
    int celIndex(Id frameId) const;       // in its own layer; -1 if there is none
    const Frame *frame(Id frameId) const; // any layer
    GroupLocation locateGroup(Id groupId) const;
    const StrokeGroup *group(Id groupId) const;
    StrokeLocation locateStroke(Id strokeId) const;
    // First and last frame index (of the current layer) that playback covers, clamped to the
    // frames there are.
    int playFirst() const;
    int playLast() const;
    // Swap sets (types.h SwapSet): the drawings objects swap between, frame by frame.
    const std::vector<SwapSet> &swapSets() const { return m_swapSets; }
    const SwapSet *swapSet(Id setId) const;
    // The drawing a link names, or null.
    const SwapDrawing *swapDrawing(const SwapLink &link) const;
    // Every object showing drawing `link` (any frame, any layer), in document order.
    std::vector<Id> objectsShowing(const SwapLink &link) const;
    // Every object linked to set `setId`, whatever drawing it shows.
    std::vector<Id> objectsOfSet(Id setId) const;
    // Editing state (not undone, not saved): the frame the tools work in. Stroke lookups look
    // there first, so a stroke of a drawing shown in several frames is found where it is
    // being edited.
    void setFocusFrame(Id frameId) { m_focusFrame = frameId; }

    // Total number of stroke points stored in rest strokes (deformed caches not counted).
    qint64 pointCount() const;

    // --- ids: stable, never reused within a document; saved with the file.
    Id allocateId() { return m_nextId++; }
    Id nextId() const { return m_nextId; }

    // --- low-level mutators (commands and loader only)
    // One layer holding `frames` (an older file, a new document): the layer takes the id
    // `nextId` (or one above the frames' largest id, if that is more), the counter the next.
    void reset(std::vector<Frame> frames, const DocumentSettings &settings, Id nextId);
    // `layers` must not be empty. The one with the most cels (the topmost of equals) becomes
    // current. Objects linked to `swapSets` are made to show their drawings.
    void reset(std::vector<Layer> layers, const DocumentSettings &settings, Id nextId,
               std::vector<SwapSet> swapSets = {});
    void insertFrame(Id layerId, int index, Frame frame);
    Frame takeFrame(Id layerId, int index);
    void moveFrame(Id layerId, int from, int to);
    void setFrameHold(Id frameId, int hold);

    void insertLayer(int index, Layer layer);
    Layer takeLayer(Id layerId); // not the last one
    void moveLayer(Id layerId, int toIndex);
    void setLayerProperties(Id layerId, const LayerProperties &properties);
    // Editing state (not undone, not saved): which layer the timeline and the tools work on.
    void setCurrentLayer(Id layerId);

    void insertGroup(Id frameId, int index, StrokeGroup group);
    StrokeGroup takeGroup(Id groupId);
    void moveGroup(Id groupId, int toIndex);
    void setGroupName(Id groupId, const QString &name);
    void setGroupVisible(Id groupId, bool visible);
    void setGroupLocked(Id groupId, bool locked);
    void setGroupMeshDensity(Id groupId, double density);

    void insertStroke(Id groupId, int index, Stroke stroke);
    Stroke takeStroke(Id strokeId);
    // Replaces all rest strokes of an object (transform, bake). Drops the deformed cache.
    void setStrokes(Id groupId, std::vector<Stroke> strokes);
    // Replaces an object's fills (fill/fill_commands.h).
    void setFills(Id groupId, std::vector<Fill> fills);
    // Replaces a picture object's picture (its rest: Apply Pose, a move). Drops the deformed
    // cache, as a rest edit does.
    void setPicture(Id groupId, std::shared_ptr<const ObjectPicture> picture);

    // Replaces an object's rig (pins or cage, rest definition and targets). A rig with more
    // than one kind keeps only its first (pins, then cage). An empty rig drops the pose.
    // Skeleton joins in the frame are resolved again (skeleton/skeleton_join.h): this
    // object's anchor is recomputed from its parent, and the parts hanging from it get
    // constraintsChanged too. Frames and objects inserted or removed resolve them as well.
    void setRig(Id groupId, Rig rig);
    // Stores a solved pose. Not undo state: a cache that any rest or pin edit invalidates.
    void setDeformed(Id groupId, DeformedStrokesPtr deformed);

    // Swap sets. Inserting a set or drawing whose id is taken, or a drawing into a set that is
    // not there, throws. Objects linked to a set or drawing that is taken away keep what they
    // show and lose the link.
    void insertSwapSet(int index, SwapSet set);
    SwapSet takeSwapSet(Id setId);
    void insertSwapDrawing(Id setId, int index, SwapDrawing drawing);
    SwapDrawing takeSwapDrawing(Id setId, Id drawingId);
    void setSwapDrawingName(Id setId, Id drawingId, const QString &name);
    void setSwapSetName(Id setId, const QString &name);
    void setSwapDrawingRig(Id setId, Id drawingId, Rig rig);
    // Links an object to a drawing (its strokes, fills and mesh density become the drawing's;
    // its rig and pose stay) or, with an empty link, unlinks it (it keeps what it shows as its
    // own drawing). A link to a drawing that is not there, or to a set another object of the
    // same frame shows, unlinks.
    void setGroupSwap(Id groupId, SwapLink link);

    void setSettings(const DocumentSettings &settings);
    // The swatches the animator picks colours from (palette/palette.h): a new document's is
    // defaultPalette(); reset() restores that, the loader sets the file's.
    const Palette &palette() const { return m_palette; }
    void setPalette(Palette palette);
    // Replaces the camera's keys (camera/camera_commands.h); `camera` must be valid
    // (isValidCameraTrack).
    void setCamera(CameraTrack camera);

signals:
    void documentReset();
    // Cels of the current layer inserted, removed or moved.
    void framesInserted(int first, int count);
    void framesRemoved(int first, int count);
    void frameMoved(int from, int to);
    // A layer's cels were inserted, removed, moved or held longer or shorter (any layer).
    void celsChanged(Id layerId);
    // Layers inserted, removed, reordered or with new properties.
    void layersChanged();
    // Another layer became current (its cels are now "the frames").
    void currentLayerChanged();
    // Anything drawn in the frame changed (hold, objects, strokes, pins, pose).
    void frameChanged(Id frameId);
    // Objects of a frame were inserted, removed, reordered or had properties changed.
    void groupsChanged(Id frameId);
    void strokesChanged(Id groupId);
    void constraintsChanged(Id groupId);
    void deformedChanged(Id groupId);
    void settingsChanged();
    void cameraChanged();
    void paletteChanged();
    // Swap sets or their drawings inserted, removed or renamed (not their content: an edit of a
    // drawing's strokes is strokesChanged of every object showing it).
    void swapSetsChanged();

private:
    StrokeGroup &mutableGroup(Id groupId);
    void groupEdited(Id groupId, bool structural);
    // Objects whose join anchor changed (skeleton/skeleton_join.h): their constraints changed
    // too; `already` has been announced.
    void joinsChanged(const std::vector<Id> &groupIds, Id already);

    // After an edit of object `groupId`'s strokes, fills or mesh density: the same on its
    // drawing and on every other object showing it.
    void shareDrawing(Id groupId);
    // An inserted frame's or object's links made to show their drawings (or dropped).
    void linkInserted(Frame &frame);
    SwapSet &mutableSwapSet(Id setId);

    Layer &mutableLayer(Id layerId);
    Frame &mutableFrame(const GroupLocation &at);
    Frame *findFrame(Id frameId);

    std::vector<Layer> m_layers;
    int m_current = 0;
    DocumentSettings m_settings;
    CameraTrack m_camera;
    Palette m_palette;
    std::vector<SwapSet> m_swapSets;
    Id m_focusFrame = kNoId;
    Id m_nextId = 1;
    std::unique_ptr<Soundtrack> m_soundtrack;
    QUndoStack m_undoStack;
    ReferenceLayer *m_reference; // a child QObject
};

} // namespace finbook::model
