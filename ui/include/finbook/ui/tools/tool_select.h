// Select (V): lasso strokes, then move (drag inside the box), rotate (handle above the box,
// Shift snaps to 15°) or scale (corner handles, Shift keeps the aspect ratio). Each drag is
// one ReplaceStrokeDataCommand. A click picks the stroke under the cursor; Shift adds to the
// selection; Escape clears it. Only visible, unlocked objects of the current frame take part.
#pragma once

#include <finbook/model/types.h>
#include <finbook/ui/canvas/canvas_tool.h>

#include <QPolygonF>

#include <vector>

namespace finbook::ui {

class SelectTool : public CanvasTool {
    Q_OBJECT
public:
    // A stroke is lassoed when at least this share of its points lies inside the lasso.
    static constexpr qreal kLassoShare = 0.5;
    static constexpr qreal kHandleSize = 8.0;     // screen pixels
    static constexpr qreal kRotateOffset = 24.0;  // screen pixels above the box
    static constexpr qreal kClickTolerance = 4.0; // screen pixels

    explicit SelectTool(QObject *parent = nullptr);

    QString id() const override { return QStringLiteral("tool.select"); }
    QString name() const override { return tr("Select"); }
    QString description() const override
    {
        return tr("lasso lines, then move, turn or scale them");
    }
    QIcon icon() const override;
    QKeySequence defaultShortcut() const override { return QKeySequence(Qt::Key_V); }
    QCursor cursor() const override { return Qt::ArrowCursor; }

    void deactivate() override;
    void press(const ToolEvent &event) override;
    void move(const ToolEvent &event) override;
    void release(const ToolEvent &event) override;
    void hover(const ToolEvent &event) override;
    bool keyPress(QKeyEvent *event) override;
    void paintOverlay(QPainter &painter, const QTransform &canvasToWidget) override;

    // Bounds of the selected strokes as displayed (canvas coordinates), null if none.
    QRectF selectionBounds() const;

private:
    enum class Mode { Idle, Lasso, Move, Rotate, Scale };
    enum class Handle { None, Inside, Rotate, TopLeft, TopRight, BottomRight, BottomLeft };

    Handle handleAt(const QPointF &widgetPos) const;
    // The selection's box on screen: its corners (top left, top right, bottom right, bottom
    // left of the box in the drawing, turned and mirrored with the view) and the rotate
    // handle, beyond the middle of its top side. Empty without a selection.
    struct BoxHandles {
        QPolygonF corners;
        QPointF rotate;
    };
    BoxHandles boxHandles() const;
    QTransform dragTransform(const ToolEvent &event) const;
    void finishLasso(const ToolEvent &event);
    void commitTransform();
    void cancelDrag();
    QCursor cursorFor(Handle handle) const;

    Mode m_mode = Mode::Idle;
    QPolygonF m_lasso;      // canvas coordinates
    QPointF m_start;        // canvas position where the drag began
    QRectF m_startBounds;   // selection bounds when the drag began
    QPointF m_anchor;       // fixed corner while scaling
    QPointF m_grabbed;      // dragged corner while scaling
    QTransform m_transform; // live transform of the drag
    std::vector<model::Id> m_dragged;
    std::vector<model::Id> m_draggedPictures; // picture objects moving with the strokes
};

} // namespace finbook::ui
