// TimelineWidget: the frame strip with its header, ready to dock at the bottom of the window.
//
// Header, left to right: play/pause and loop buttons (the PlaybackController's actions), the
// frame counter, and the onion-skin controls (toggle, frames before and after, 0–5) bound
// two-way to EditorState::onionSkin. Below it the TimelineView (see timeline_view.h): click
// to pick a frame, drag in the number band to scrub, drag a thumbnail to reorder, right click
// for the frame actions. Thumbnails render lazily, only for frames on screen.
#pragma once

#include <QWidget>

class QLabel;
class QSpinBox;
class QToolButton;

namespace finbook::model {
class FrameListModel;
}

namespace finbook::ui {

class EditorState;
class FrameActions;
class PlaybackController;
class ThumbnailCache;
class TimelineView;

class TimelineWidget : public QWidget {
    Q_OBJECT
public:
    // `playback` may be null: the play and loop buttons are then left out.
    TimelineWidget(EditorState *state, FrameActions *frameActions, PlaybackController *playback,
                   QWidget *parent = nullptr);

    TimelineView *view() const { return m_view; }
    model::FrameListModel *frameModel() const { return m_model; }
    ThumbnailCache *thumbnails() const { return m_thumbnails; }
    QToolButton *onionToggle() const { return m_onion; }
    QSpinBox *onionBefore() const { return m_before; }
    QSpinBox *onionAfter() const { return m_after; }
    // Adds a row under the frame strip (the sound row), reparented to this widget.
    void addBelowFrames(QWidget *row);
    // Rows shown between the header and the frames (the dope sheet's layers).
    void addAboveFrames(QWidget *rows);

    // The header, the frame strip at its least readable height and every row under it: the
    // dock asks for that much, so rows added under the frames never cover the thumbnails.
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

private:
    QWidget *createHeader(PlaybackController *playback);
    void showOnionSkin();
    void editOnionSkin();
    void showCounter();

    EditorState *m_state;
    model::FrameListModel *m_model;
    ThumbnailCache *m_thumbnails;
    TimelineView *m_view;
    QToolButton *m_onion = nullptr;
    QSpinBox *m_before = nullptr;
    QSpinBox *m_after = nullptr;
    QLabel *m_counter = nullptr;
};

} // namespace finbook::ui
