// SoundRow: the sound row under the timeline's frames. Each frame cell's column shows the
// soundtrack's waveform over that frame's time (a frame held twice shows twice as much sound),
// each clip in its own colour with its name at its start; muted clips are grey, clips still
// decoding are outlined, clips that cannot be decoded are marked.
//
// Mouse: drag a clip sideways to move its start (one command on release, Escape cancels);
// right click for Mute, Volume… and Delete. Click on empty sound picks the frame above.
#pragma once

#include <finbook/model/types.h>

#include <QWidget>

class QAction;

namespace finbook::ui {

class SoundController;
class TimelineView;

class SoundRow : public QWidget {
    Q_OBJECT
public:
    static constexpr int kHeight = 40;

    SoundRow(SoundController *controller, TimelineView *view, QWidget *parent = nullptr);

    // The tick under x (fractional: where inside the frame), clamped to the frames there are.
    double tickAt(int x) const;
    // The x where tick `tick` is drawn; -1 if the frames hold no such tick.
    int xOfTick(double tick) const;
    // The top clip sounding at x, or kNoId.
    model::Id clipAt(int x) const;
    // How many seconds of sound play on past the last frame (0 when none does): the row shows
    // that part hatched after the last frame, with the seconds written on it, since playback
    // and export stop at the last frame.
    double secondsPastEnd() const;
    // The clip being dragged and how many ticks it moved (tests).
    qint64 dragTicks() const { return m_dragTicks; }

    QSize sizeHint() const override { return {400, kHeight}; }
    QSize minimumSizeHint() const override { return {100, kHeight}; }

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;

private:
    struct Cell {
        int left;
        int width;
        qint64 tick;
        int hold;
        int row;
    };
    std::vector<Cell> visibleCells() const;
    void paintClip(QPainter &painter, const std::vector<Cell> &cells, int index);
    void paintPastEnd(QPainter &painter, const std::vector<Cell> &cells);
    double clipEndTick(model::Id clipId) const;

    SoundController *m_controller;
    TimelineView *m_view;
    model::Id m_dragClip = model::kNoId;
    double m_pressTick = 0.0;
    qint64 m_dragTicks = 0;
};

} // namespace finbook::ui
