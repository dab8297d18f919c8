// Fill (F): click inside a region of an object to fill it with the pen's colour, click a filled
// region to recolour it, Shift-click or right-click to remove its fill (each one undo step).
// The region under the cursor is highlighted before the click, and the gap lines that close
// the regions (fill/fill_regions.h) are drawn dashed while the tool is active. The topmost
// visible, unlocked object with a region under the cursor is the one filled.
#pragma once

#include <finbook/model/types.h>
#include <finbook/ui/canvas/canvas_tool.h>

#include <QPainterPath>

namespace finbook::ui {

class PenTool;

class FillTool : public CanvasTool {
    Q_OBJECT
public:
    explicit FillTool(const PenTool *pen, QObject *parent = nullptr);

    QString id() const override { return QStringLiteral("tool.fill"); }
    QString name() const override { return tr("Fill"); }
    QString description() const override { return tr("fill an enclosed region with colour"); }
    QIcon icon() const override;
    QKeySequence defaultShortcut() const override { return QKeySequence(Qt::Key_F); }
    bool picksColourOnCtrlClick() const override { return true; }
    QCursor cursor() const override;

    void activate() override;
    void deactivate() override;
    void press(const ToolEvent &event) override;
    void hover(const ToolEvent &event) override;
    void secondaryClick(const ToolEvent &event) override;
    void paintOverlay(QPainter &painter, const QTransform &canvasToWidget) override;

    // The object and the outline (canvas pixels, as shown) of the region under `pos`.
    struct Target {
        model::Id groupId = model::kNoId;
        QPainterPath outline;
    };
    Target targetAt(const QPointF &pos) const;

signals:
    // A sentence for the status bar ("No closed region here…").
    void messagePosted(const QString &message);

private:
    void fillAt(const QPointF &pos, bool remove);
    void setHover(const QPointF &pos);

    const PenTool *m_pen;
    Target m_hover;
    bool m_hoverShown = false;
};

} // namespace finbook::ui
