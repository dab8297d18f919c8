// What the editor is looking at and working on, shared by the canvas, timeline, objects
// panel, playback and main window. Not document state: nothing here is saved or undone.
#pragma once

#include <finbook/model/document.h>

#include <QObject>

#include <vector>

namespace finbook::ui {

struct OnionSkin {
    bool enabled = false;
    int before = 1;      // 0..5 frames
    int after = 1;       // 0..5 frames
    qreal opacity = 0.4; // of the nearest neighbour; falls off with distance
    QColor beforeTint{220, 40, 40};
    QColor afterTint{40, 90, 220};
    friend bool operator==(const OnionSkin &, const OnionSkin &) = default;
};

class EditorState : public QObject {
    Q_OBJECT
public:
    explicit EditorState(model::Document *document, QObject *parent = nullptr);

    model::Document *document() const { return m_doc; }

    int currentFrameIndex() const { return m_frameIndex; }
    model::Id currentFrameId() const;
    const model::Frame *currentFrame() const;
    // The object new strokes go into. Falls back to the top object of the current frame.
    model::Id currentGroupId() const;
    const model::StrokeGroup *currentGroup() const;

    // Selected strokes (lasso), all in the current frame. Cleared when the frame changes.
    const std::vector<model::Id> &selectedStrokes() const { return m_selection; }
    // Picture objects whose picture is selected (a click on it, or a lasso around it), in the
    // current frame; moved, turned, scaled and deleted with the strokes. Setting the strokes
    // alone clears them; both cleared when the frame changes.
    const std::vector<model::Id> &selectedPictures() const { return m_pictureSelection; }
    bool hasSelection() const { return !m_selection.empty() || !m_pictureSelection.empty(); }

    // Frames picked together in the timeline (Ctrl/Shift-click), as indices in document order;
    // just the current frame when no other is picked. A current frame outside the picked
    // ones clears them.
    std::vector<int> selectedFrames() const;
    // Cels picked in the dope sheet, on any layers. Picking cels drops the picked strokes and
    // picking strokes drops the cels, so the Edit menu works on whichever was picked last.
    const std::vector<model::Id> &selectedCels() const { return m_celSelection; }
    const OnionSkin &onionSkin() const { return m_onion; }
    bool isPlaying() const { return m_playing; }
    bool showMesh() const { return m_showMesh; }
    // View → Show Skeleton; while on, skeletons follow the drawing (skeleton_follow.h).
    bool showSkeleton() const { return m_showSkeleton; }
    // The playback tick on screen (the animation's clock from its first frame, holds
    // included): while playing, the tick playback has reached (the camera moves during a
    // hold); otherwise the playhead, a tick within the current layer's current cel (its first
    // unless the playhead was put later, or kept there when another layer became current).
    // Every layer shows its cel at this tick.
    qint64 currentTick() const;
    // View → Camera View: the canvas shows the shot the camera frames at currentTick().
    bool cameraView() const { return m_cameraView; }
    // View → Dim Other Layers: layers other than the current one at half strength.
    bool dimOtherLayers() const { return m_dimOthers; }

public slots:
    void setCurrentFrameIndex(int index);
    void setCurrentGroupId(model::Id groupId);
    void setSelectedStrokes(std::vector<model::Id> strokeIds);
    void setSelection(std::vector<model::Id> strokeIds, std::vector<model::Id> pictureObjectIds);
    void setSelectedFrames(std::vector<model::Id> frameIds);
    void setSelectedCels(std::vector<model::Id> celIds);
    void setOnionSkin(const OnionSkin &onion);
    void setPlaying(bool playing);
    void setShowMesh(bool show);
    void setShowSkeleton(bool show);
    // Playback reports the tick it shows; −1 when it stops (currentTick() follows the frame).
    void setPlaybackTick(qint64 tick);
    void setCameraView(bool on);
    void setDimOtherLayers(bool on);
    // Puts the playhead at `tick` (the dope sheet): the current layer's cel there becomes the
    // current frame (its last cel past its end).
    void setCurrentTick(qint64 tick);
    void nextFrame();
    void previousFrame();

signals:
    void currentFrameChanged(int index);
    void currentGroupChanged(model::Id groupId);
    void selectionChanged();
    void frameSelectionChanged();
    void celSelectionChanged();
    void onionSkinChanged();
    void playingChanged(bool playing);
    void showMeshChanged(bool show);
    // currentTick() changed (a new frame, or playback moved on within a hold).
    void tickChanged(qint64 tick);
    void cameraViewChanged(bool on);
    void dimOtherLayersChanged(bool on);

private:
    void clampToDocument();
    // The playhead into the current cel, if it is not there (the cel's first tick).
    void keepTickInCel();
    // The current layer changed: the current frame becomes its cel at the playhead.
    void followLayer();

    model::Document *m_doc;
    int m_frameIndex = 0;
    model::Id m_groupId = model::kNoId;
    std::vector<model::Id> m_selection;
    std::vector<model::Id> m_pictureSelection;
    std::vector<model::Id> m_frameSelection;
    std::vector<model::Id> m_celSelection;
    OnionSkin m_onion;
    bool m_playing = false;
    bool m_showMesh = false;
    bool m_showSkeleton = false;
    bool m_cameraView = false;
    bool m_dimOthers = false;
    qint64 m_playbackTick = -1;
    qint64 m_tick = 0; // the playhead when not playing
};

} // namespace finbook::ui
