// TimelineView: the horizontal strip of frame cells inside the TimelineWidget.
//
// Each cell has a number band on top and the thumbnail below. Mouse:
//  - press or drag in the number band (or past the last frame) scrubs: the current frame
//    follows the pointer;
//  - press on a thumbnail makes that frame current; dragging it past a neighbour shows an
//    insertion marker and the release pushes one MoveFrameCommand (Escape cancels);
//  - Ctrl-click picks frames together (toggles one), Shift-click picks the range from the
//    current frame (e.g. two keys for Frame → Generate In-betweens…);
//  - right click makes the frame current and opens the frame menu.
// Reordering is an internal drag rather than QDrag: it needs no nested event loop, works the
// same on every platform plugin and is what the GUI tests drive.
#pragma once

#include <finbook/model/frame_list_model.h>

#include <QListView>

#include <vector>

namespace finbook::ui {

class EditorState;
class ThumbnailCache;

class TimelineView : public QListView {
    Q_OBJECT
public:
    static constexpr int kBandHeight = 16;
    static constexpr int kPadding = 3;
    // A cell is never lower than this: its number band and a thumbnail of 40 px.
    static constexpr int kMinimumCellHeight = kBandHeight + 2 * kPadding + 40;

    TimelineView(EditorState *state, model::FrameListModel *model, ThumbnailCache *thumbnails,
                 QWidget *parent = nullptr);

    EditorState *editorState() const { return m_state; }
    model::FrameListModel *frameModel() const { return m_model; }
    ThumbnailCache *thumbnails() const { return m_thumbnails; }

    QSize cellSize() const { return m_cell; }
    // Viewport rectangles of a frame's number band and thumbnail (empty if off the strip).
    QRect bandRect(int row) const;
    QRect thumbnailRect(int row) const;
    // Rows whose cells intersect the viewport now.
    std::vector<int> visibleRows() const;
    // Whether a press at `pos` (viewport) scrubs: on a frame's number band or beside the
    // frames; on a thumbnail it picks the frame and a drag reorders.
    bool onNumberBand(const QPoint &pos) const;
    // While reordering: the insertion slot (0..rowCount) the marker shows; -1 otherwise.
    int dropSlot() const { return m_mode == Mode::Reorder ? m_dropSlot : -1; }
    // Actions shown by the right-click menu (the frame actions, typically).
    void setMenuActions(QList<QAction *> actions) { m_menuActions = std::move(actions); }

protected:
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    bool viewportEvent(QEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    enum class Mode { None, Scrub, Press, Reorder };
    // Ctrl-click toggles a frame in the picked set, Shift-click picks the range from the
    // current frame; returns false for a plain click.
    bool pickFrame(int row, Qt::KeyboardModifiers modifiers);
    int rowAtX(int x) const;
    int slotAtX(int x) const;
    void updateCellSize();
    void followCurrentFrame(int row);
    void autoScroll(int x);
    bool isFrameVisible(model::Id frameId) const;

    EditorState *m_state;
    model::FrameListModel *m_model;
    ThumbnailCache *m_thumbnails;
    QSize m_cell{60, 60};
    Mode m_mode = Mode::None;
    int m_pressRow = -1;
    QPoint m_pressPos;
    int m_dropSlot = -1;
    int m_shownCurrent = -1;
    QList<QAction *> m_menuActions;
};

} // namespace finbook::ui
