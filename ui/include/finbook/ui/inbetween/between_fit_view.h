// The fit of Between Drawings, shown and corrected in the in-between dialog: the second key's
// lines in grey, the first key's lines where the fit put them, each part (the bone of its
// automatic skeleton nearest it) in its own colour, and the correspondence pins.
//
// Drag from a line of the first drawing to where that point belongs on the second to put a
// pin; drag a pin's dot to move it; right-click it to take it away. While a pin is dragged the
// view says so with pinsDragged (the dialog refits live); when it is let go, or taken away,
// pinsChanged gives the pins before and after (one undo step in the dialog).
#pragma once

#include <finbook/model/inbetween/between_drawings.h>

#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

namespace finbook::ui {

class BetweenFitView : public QWidget {
    Q_OBJECT
public:
    explicit BetweenFitView(QWidget *parent = nullptr);

    void setFit(std::shared_ptr<const model::DrawingFit> fit);
    const std::shared_ptr<const model::DrawingFit> &fit() const { return m_fit; }
    // The pins shown: the fit's, or those being dragged until the fit catches up.
    const std::vector<model::BetweenPin> &pins() const { return m_pins; }
    void setPins(std::vector<model::BetweenPin> pins);

    // Canvas ↔ widget coordinates of the current view (tests drive the mouse with them).
    QPointF toWidget(QPointF canvas) const;
    QPointF toCanvas(QPointF widget) const;
    // Where the fit put point `k` of stroke `s` of the first drawing (canvas px).
    QPointF fittedPoint(std::size_t s, std::size_t k) const;

    QSize sizeHint() const override { return {360, 260}; }

signals:
    void pinsDragged(const std::vector<model::BetweenPin> &pins);
    void pinsChanged(const std::vector<model::BetweenPin> &before,
                     const std::vector<model::BetweenPin> &after);

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;

private:
    QTransform view() const;
    // The first drawing's stroke point nearest `widget` within the pick radius: its rest place.
    std::optional<QPointF> pickLine(QPointF widget) const;
    int pickPin(QPointF widget) const; // −1 if none

    std::shared_ptr<const model::DrawingFit> m_fit;
    std::vector<model::BetweenPin> m_pins;
    std::vector<model::BetweenPin> m_before; // at the start of a drag
    int m_dragged = -1;
    // Made once per fit, not per paint or mouse move: the first drawing's points as fitted
    // (stroke after stroke, the rows of its mesh embedding), and the box of both drawings.
    Eigen::MatrixX2d m_fitted;
    QRectF m_bounds;
    // Per first-drawing stroke point: its part (nearest bone), −1 none. A refit keeps the
    // drawing and its skeleton: made again only for another drawing.
    std::vector<int> m_part;
    std::shared_ptr<const model::MeshedObject> m_partsOf;
};

} // namespace finbook::ui
