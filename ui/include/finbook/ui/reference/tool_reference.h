// Move Reference: drags the reference layer on the canvas. A plain drag moves it, Shift+drag
// scales it about its centre, Ctrl+drag rotates it about its centre. One drag is one undo
// step; a locked, hidden or absent reference does not move. The drawing tools never see the
// reference; this is the one tool that does.
#pragma once

#include <finbook/model/reference/reference_commands.h>
#include <finbook/ui/canvas/canvas_tool.h>

namespace finbook::ui {

class ReferenceTool : public CanvasTool {
    Q_OBJECT
public:
    explicit ReferenceTool(QObject *parent = nullptr)
        : CanvasTool(parent)
    {}

    QString id() const override { return QStringLiteral("tool.reference"); }
    bool editsLayer() const override { return false; }
    QString name() const override { return tr("Move Reference"); }
    QString description() const override
    {
        return tr("move, scale and turn the reference picture");
    }
    QIcon icon() const override;
    QCursor cursor() const override;

    void press(const ToolEvent &event) override;
    void move(const ToolEvent &event) override;
    void release(const ToolEvent &event) override;
    void hover(const ToolEvent &event) override;
    void deactivate() override;
    void paintOverlay(QPainter &painter, const QTransform &canvasToWidget) override;

private:
    bool movable() const;
    bool grabs(QPointF canvasPos) const; // on the reference's picture
    void finish();

    model::Reference m_start; // as the drag found it
    QPointF m_pressPos;
    model::ReferenceEdit m_edit = model::ReferenceEdit::Place;
    bool m_dragging = false;
    bool m_macroOpen = false;
    bool m_over = false; // the pointer is over a movable reference
};

} // namespace finbook::ui
