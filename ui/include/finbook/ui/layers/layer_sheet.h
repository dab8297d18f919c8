// The dope sheet: one row per layer (the front one on top), each cel a block as long as its
// exposure, with the playhead across every row. A header column shows each layer's name, an eye
// (click: show or hide) and a lock (click: lock or unlock).
//
// Click a row: its layer becomes current and the playhead goes to the tick clicked; drag to
// scrub. Drag the right end of a cel: its exposure changes (one undo step when released).
// Double-click a name: Layer Properties. Right-click: the Layer menu. Ctrl+wheel: zoom in time.
#pragma once

#include <finbook/model/types.h>

#include <QWidget>

#include <optional>

namespace finbook::ui {

class EditorState;
class LayerActions;

class LayerSheet : public QWidget {
    Q_OBJECT
public:
    LayerSheet(EditorState *state, LayerActions *actions, QWidget *parent = nullptr);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

    // Geometry, for tests: the row of layer `index` (top to bottom: the last layer first) and
    // the x of a tick.
    int rowOfLayer(int layerIndex) const;
    QRect rowRect(int layerIndex) const;
    int xOfTick(qint64 tick) const;
    static constexpr int kHeaderWidth = 150;
    static constexpr int kRowHeight = 22;

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;

private:
    int layerAtY(int y) const; // layer index, −1 outside the rows
    qint64 tickAtX(int x) const;
    // The cel of layer `layerIndex` whose right end is within a few pixels of x, or −1.
    int celEndNear(int layerIndex, int x) const;
    void relayout();
    void paintRow(QPainter &painter, int layerIndex) const;

    EditorState *m_state;
    LayerActions *m_actions;
    int m_tickWidth = 12; // pixels per tick
    enum class Drag { None, Scrub, Exposure };
    Drag m_drag = Drag::None;
    model::Id m_dragFrame = model::kNoId; // the cel whose exposure is dragged
    qint64 m_dragStart = 0;               // its first tick
    int m_dragHold = 1;                   // the exposure shown while dragging
};

} // namespace finbook::ui
