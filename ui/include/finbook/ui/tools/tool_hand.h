// Hand (H): drags the view. Space-drag and the middle button do the same with any tool.
#pragma once

#include <finbook/ui/canvas/canvas_tool.h>

namespace finbook::ui {

class HandTool : public CanvasTool {
    Q_OBJECT
public:
    explicit HandTool(QObject *parent = nullptr)
        : CanvasTool(parent)
    {}

    QString id() const override { return QStringLiteral("tool.hand"); }
    bool editsLayer() const override { return false; }
    QString name() const override { return tr("Hand"); }
    QString description() const override { return tr("drag the view"); }
    QIcon icon() const override
    {
        return QIcon::fromTheme(QStringLiteral("transform-browse"),
                                QIcon(QStringLiteral(":/icons/tool_hand.svg")));
    }
    QKeySequence defaultShortcut() const override { return QKeySequence(Qt::Key_H); }
    QCursor cursor() const override
    {
        return m_dragging ? Qt::ClosedHandCursor : Qt::OpenHandCursor;
    }

    void press(const ToolEvent &event) override;
    void move(const ToolEvent &event) override;
    void release(const ToolEvent &event) override;
    void deactivate() override { m_dragging = false; }

private:
    QPointF m_last;
    bool m_dragging = false;
};

} // namespace finbook::ui
