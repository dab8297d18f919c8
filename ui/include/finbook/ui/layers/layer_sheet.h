// The dope sheet: one row per layer (the front one on top), each cel a block as long as its
// exposure showing its drawing, under a ruler of ticks, with the playhead across every row. A
// header column shows each layer's name, an eye (click: show or hide) and a lock (click: lock
// or unlock).
//
// Mouse, as in Krita's timeline and OpenToonz's Xsheet:
//  - the ruler, or a row past its last cel: the playhead goes there (drag to scrub);
//  - a cel: picks it (Ctrl: adds or drops it, Shift: every cel from the last picked one to it,
//    across rows), makes its layer current and puts the playhead there; dragging picked cels
//    moves them to the boundary between cels nearest where they land, in the row they land on
//    (a marker shows it), Alt- or Ctrl-dragging copies them (window managers that move windows
//    on Alt-drag leave Ctrl); one undo step;
//  - the right end of a cel: drags its exposure (one undo step when released);
//  - a layer's name: dragged up or down, reorders the layer; double-click: Layer Properties;
//  - right-click: the Layer menu, and on a cel showing a swappable object (a mouth chart's)
//    the drawings it may show; Ctrl+wheel: zoom in time.
// A cel showing a swappable object is labelled with its drawing's name (as an exposure sheet
// shows "A", "B", "X"), others with their number.
// The Edit menu cuts, copies, pastes and deletes picked cels (cel_editing.h).
#pragma once

#include <finbook/model/types.h>

#include <QWidget>

#include <functional>
#include <optional>

class QMenu;

namespace finbook::ui {

class EditorState;
class LayerActions;
class ThumbnailCache;

class LayerSheet : public QWidget {
    Q_OBJECT
public:
    LayerSheet(EditorState *state, LayerActions *actions, QWidget *parent = nullptr);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
    // Adds to the right-click menu of a cel (the cel's id) what the window offers for it.
    void setCelMenu(std::function<void(QMenu *, model::Id cel)> addItems)
    {
        m_celMenu = std::move(addItems);
    }

    // Geometry, for tests: the row of layer `index` (top to bottom under the ruler: the last
    // layer first) and the x of a tick.
    int rowOfLayer(int layerIndex) const;
    QRect rowRect(int layerIndex) const;
    int xOfTick(qint64 tick) const;
    static constexpr int kHeaderWidth = 150;
    static constexpr int kRulerHeight = 18;
    static constexpr int kRowHeight = 30;

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;

private:
    int layerAtY(int y) const;        // layer index, −1 outside the rows
    int nearestLayerAtY(int y) const; // the row's layer, or the nearest one outside the rows
    qint64 tickAtX(int x) const;
    // The cel of layer `layerIndex` whose right end is within a few pixels of x, or −1.
    int celEndNear(int layerIndex, int x) const;
    // The cel of layer `layerIndex` under x, or −1.
    int celUnder(int layerIndex, int x) const;
    void pressCel(int layerIndex, int cel, Qt::KeyboardModifiers modifiers);
    bool isPicked(model::Id cel) const;
    void relayout();
    void fitThumbnails(); // to the row height and the page's proportions
    void paintRuler(QPainter &painter) const;
    void paintRow(QPainter &painter, int layerIndex) const;
    void paintCelDrop(QPainter &painter) const;

    EditorState *m_state;
    LayerActions *m_actions;
    ThumbnailCache *m_thumbnails;
    int m_tickWidth = 12; // pixels per tick
    enum class Drag { None, Scrub, Exposure, CelsPending, Cels, LayerPending, Layer };
    Drag m_drag = Drag::None;
    QPoint m_pressAt;
    model::Id m_dragFrame = model::kNoId; // the cel whose exposure is dragged, or pressed
    qint64 m_dragStart = 0;               // its first tick
    int m_dragHold = 1;                   // the exposure shown while dragging
    model::Id m_anchor = model::kNoId;    // the cel a Shift-click picks from
    int m_pressLayer = -1;                // the row a drag of cels or of a layer started on
    qint64 m_pressTick = 0;
    int m_dropRows = 0;           // cels dragged this many rows up (negative: down)
    qint64 m_dropTicks = 0;       // and this many ticks later
    bool m_dropCopy = false;      // Alt or Ctrl held: copies
    bool m_dropOnRelease = false; // a Ctrl-click on a picked cel: dropped unless it drags
    int m_layerDrop = -1;         // a dragged layer goes to this index
    std::function<void(QMenu *, model::Id)> m_celMenu;
};

} // namespace finbook::ui
