// The eraser (E). By default it cuts: rub across a line and the part under the eraser goes,
// the stroke splitting into pieces that keep its colour, width and pressure
// (model/erase/stroke_cut.h). In Whole Strokes mode — or with Shift held when the rub starts —
// it removes every stroke it touches, as the stroke eraser did. The size is the eraser's
// diameter in canvas pixels, shown by the circle that follows the mouse (dashed for whole
// strokes). One rub is one undo step; hidden and locked objects are left alone; a posed object
// has its pose applied first, in the same step, and an object erased to nothing loses its rig.
#pragma once

#include <finbook/model/types.h>
#include <finbook/ui/canvas/canvas_tool.h>

#include <vector>

namespace finbook::ui {

enum class EraserMode { Cut, WholeStrokes };

class EraserTool : public CanvasTool {
    Q_OBJECT
public:
    static constexpr qreal kMinSize = 1.0;
    static constexpr qreal kMaxSize = 400.0;
    static constexpr qreal kDefaultSize = 16.0;

    explicit EraserTool(QObject *parent = nullptr);

    QString id() const override { return QStringLiteral("tool.eraser"); }
    QString name() const override { return tr("Eraser"); }
    QString description() const override { return tr("rub out parts of lines, or whole strokes"); }
    QIcon icon() const override;
    QKeySequence defaultShortcut() const override { return QKeySequence(Qt::Key_E); }

    EraserMode mode() const { return m_mode; }
    void setMode(EraserMode mode);
    qreal size() const { return m_size; } // diameter, canvas px
    void setSize(qreal size);             // clamped to kMinSize..kMaxSize; NaN is ignored

    void deactivate() override;
    void press(const ToolEvent &event) override;
    void move(const ToolEvent &event) override;
    void release(const ToolEvent &event) override;
    void hover(const ToolEvent &event) override;
    bool keyPress(QKeyEvent *event) override;
    bool claimsKey(const QKeyEvent &event) const override;
    void paintOverlay(QPainter &painter, const QTransform &canvasToWidget) override;

signals:
    void modeChanged(finbook::ui::EraserMode mode);
    void sizeChanged(qreal size);

private:
    qreal radius() const;
    void eraseAlong(const QPointF &from, const QPointF &to);
    std::vector<model::Id> touchedStrokes(const QLineF &path) const;
    // Opens the rub's macro at its first hit and applies the poses of the objects it reaches;
    // returns whether a pose was applied (the strokes are then the baked ones, new ids too).
    bool openMacro(const std::vector<model::Id> &strokes);
    void cut(const std::vector<model::Id> &strokes, const QPointF &from, const QPointF &to);
    void finish();
    void moveCursor(const QPointF &pos);

    EraserMode m_mode = EraserMode::Cut;
    qreal m_size = kDefaultSize;
    bool m_erasing = false;
    bool m_wholeStrokes = false; // the mode of the rub in progress
    bool m_macroOpen = false;
    std::vector<model::Id> m_erasedFrom; // objects the open macro erased from
    std::vector<model::Id> m_following;  // those whose skeleton follows (skeleton_follow.h)
    // Those objects as the rub first reached them (poses applied), for the lines it uncovers.
    std::vector<model::StrokeGroup> m_before;
    QPointF m_last;
    QPointF m_cursor;
    bool m_cursorShown = false;
};

} // namespace finbook::ui
