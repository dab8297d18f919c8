// The Cage tool (C): harmonic cages (Joshi et al. 2007). On an object without a cage, click
// points around it and close the polygon on its first point or with Return (Esc cancels,
// Backspace takes back the last point). On a caged object, drag a corner — or rubber-band
// several, Ctrl-click to add or remove one — and drag them together; Shift keeps the drag
// horizontal or vertical. Each drag is one undo step. In Edit Shape mode the same gestures
// change the rest cage instead; Alt-click on an edge (or Insert with the mouse over it) adds a
// corner there, and right-click or Ctrl-click on a corner deletes it.
#pragma once

#include <finbook/model/deform_controller.h>
#include <finbook/ui/canvas/canvas_tool.h>

#include <set>

namespace finbook::ui {

class CageTool : public CanvasTool {
    Q_OBJECT
public:
    explicit CageTool(model::DeformController *controller, QObject *parent = nullptr);

    QString id() const override { return QStringLiteral("tool.cage"); }
    QString name() const override { return tr("Cage"); }
    QString description() const override
    {
        return tr("draw a cage around the drawing, then drag its corners to bend it");
    }
    QIcon icon() const override;
    QKeySequence defaultShortcut() const override { return QKeySequence(Qt::Key_C); }

    void activate() override;
    void deactivate() override;
    void press(const ToolEvent &event) override;
    void move(const ToolEvent &event) override;
    void release(const ToolEvent &event) override;
    void hover(const ToolEvent &event) override;
    void secondaryClick(const ToolEvent &event) override;
    bool keyPress(QKeyEvent *event) override;
    bool claimsKey(const QKeyEvent &event) const override;
    void paintOverlay(QPainter &painter, const QTransform &canvasToWidget) override;

    // Edit Shape: gestures change the rest cage rather than pose it.
    bool editingShape() const { return m_editShape; }
    void setEditingShape(bool on);
    // The polygon being placed (canvas px), empty when none.
    const std::vector<QPointF> &pendingCage() const { return m_pending; }
    // Closes the pending polygon into a cage on the current object (Return does this).
    bool closePendingCage();
    const std::set<int> &selectedCorners() const { return m_selected; }

signals:
    void editingShapeChanged(bool on);

private:
    const model::StrokeGroup *cagedObject() const;
    const std::vector<QPointF> &shownCorners(const model::StrokeGroup &g) const;
    int cornerAt(const model::StrokeGroup &g, QPointF widgetPos) const;
    int edgeAt(const model::StrokeGroup &g, QPointF pos) const;
    void pressOnCage(const model::StrokeGroup &g, const ToolEvent &event);
    void dragCorners(const ToolEvent &event);
    void finishShapeDrag();
    void deleteCorner(const model::StrokeGroup &g, int corner);
    void insertCorner(const model::StrokeGroup &g, int edge, QPointF pos);
    void cancelPending();

    model::DeformController *m_controller;
    bool m_editShape = false;
    std::vector<QPointF> m_pending;
    QPointF m_hoverPos;
    std::set<int> m_selected;
    model::Id m_selectionOf = model::kNoId; // the object whose cage m_selected indexes
    bool m_watching = false;
    // Drag state: where it started, the corners it moves and their positions then.
    bool m_dragging = false;
    bool m_rubberBand = false;
    QPointF m_pressPos;
    QPointF m_dragPos;
    std::vector<QPointF> m_startCorners;
    std::vector<QPointF> m_shapePreview; // rest corners shown during an Edit Shape drag
    int m_dragSerial = 0;
};

} // namespace finbook::ui
