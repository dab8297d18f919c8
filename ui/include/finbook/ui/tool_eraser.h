// Stroke eraser (E): removes every whole stroke the cursor touches during one drag, as one
// undo step. Hidden and locked objects are left alone.
#pragma once

#include <finbook/model/types.h>
#include <finbook/ui/canvas_tool.h>

#include <vector>

namespace finbook::ui {

class StrokeEraserTool : public CanvasTool {
    Q_OBJECT
public:
    static constexpr qreal kRadius = 6.0; // screen pixels around the cursor

    explicit StrokeEraserTool(QObject *parent = nullptr);

    QString id() const override { return QStringLiteral("tool.eraser"); }
    QString name() const override { return tr("Stroke Eraser"); }
    QIcon icon() const override;
    QKeySequence defaultShortcut() const override { return QKeySequence(Qt::Key_E); }

    void deactivate() override;
    void press(const ToolEvent &event) override;
    void move(const ToolEvent &event) override;
    void release(const ToolEvent &event) override;
    void hover(const ToolEvent &event) override;
    void paintOverlay(QPainter &painter, const QTransform &canvasToWidget) override;

private:
    void eraseAlong(const QPointF &from, const QPointF &to);
    void finish();
    void moveCursor(const QPointF &pos);

    bool m_erasing = false;
    bool m_macroOpen = false;
    std::vector<model::Id> m_erasedFrom; // objects the open macro erased from
    std::vector<model::Id> m_following;  // those whose skeleton follows (skeleton_follow.h)
    QPointF m_last;
    QPointF m_cursor;
    bool m_cursorShown = false;
};

} // namespace finbook::ui
