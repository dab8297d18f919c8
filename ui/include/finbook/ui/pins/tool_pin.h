// The Pin tool (P): ARAP pins on objects. Click an object to pin it (and keep dragging to
// move the new pin), drag a pin to bend the drawing as rigidly as possible, Ctrl-click or
// right-click a pin to remove it. Each drag is one undo step.
#pragma once

#include <finbook/model/deform_controller.h>
#include <finbook/ui/canvas/canvas_tool.h>

#include <utility>

namespace finbook::ui {

class PinTool : public CanvasTool {
    Q_OBJECT
public:
    explicit PinTool(model::DeformController *controller, QObject *parent = nullptr);

    QString id() const override { return QStringLiteral("tool.pin"); }
    QString name() const override { return tr("Pin"); }
    QString description() const override
    {
        return tr("pin points and drag them: the drawing bends as rigidly as it can");
    }
    QIcon icon() const override;
    QKeySequence defaultShortcut() const override { return QKeySequence(Qt::Key_P); }
    QCursor cursor() const override { return Qt::CrossCursor; }

    void activate() override;
    void deactivate() override;
    void press(const ToolEvent &event) override;
    void move(const ToolEvent &event) override;
    void release(const ToolEvent &event) override;
    void hover(const ToolEvent &event) override;
    void secondaryClick(const ToolEvent &event) override;
    void paintOverlay(QPainter &painter, const QTransform &canvasToWidget) override;

    struct PinRef {
        model::Id groupId = model::kNoId;
        model::Id pinId = model::kNoId;
        bool isValid() const { return pinId != model::kNoId; }
    };
    // The pin drawn under a widget position (screen tolerance), current object first.
    PinRef pinAt(const ToolEvent &event) const;
    // The object a click at `pos` pins: the current object when hit, else the topmost.
    model::Id objectAt(const ToolEvent &event) const;
    // Screen pixels the pointer must travel before a press on a pin becomes a drag.
    static constexpr qreal kDragThreshold = 3.0;

private:
    bool objectHit(const model::StrokeGroup &group, const ToolEvent &event) const;
    void removePin(const PinRef &pin);
    void startDrag(const PinRef &pin);
    // Rest position and target of a pin added where `shown` is clicked.
    std::pair<QPointF, QPointF> newPin(model::Id groupId, QPointF shown) const;

    model::DeformController *m_controller;
    PinRef m_drag;
    PinRef m_hover;
    QPointF m_pressPos;
    QPointF m_pressWidgetPos;
    bool m_dragStarted = false;
    int m_dragSerial = 0;
};

} // namespace finbook::ui
