// Eyedropper (I): click a line or a fill to take its colour for the pen. It picks what is on top
// at that spot on the page, in any visible layer, as painted: a line over a fill gives the line's
// colour, a fill its own (its flat colour, not a shade of its tones); a click on empty paper leaves
// the pen's colour as it was and says so. The document does not change (nothing to undo).
#pragma once

#include <finbook/ui/canvas/canvas_tool.h>

#include <QColor>

#include <optional>

namespace finbook::model {
struct Frame;
struct DocumentSettings;
} // namespace finbook::model

namespace finbook::ui {

class PenTool;

class EyedropperTool : public CanvasTool {
    Q_OBJECT
public:
    explicit EyedropperTool(PenTool *pen, QObject *parent = nullptr);

    QString id() const override { return QStringLiteral("tool.eyedropper"); }
    bool editsLayer() const override { return false; }
    QString name() const override { return tr("Eyedropper"); }
    QString description() const override
    {
        return tr("take a line's or a fill's colour for the pen");
    }
    QIcon icon() const override;
    QKeySequence defaultShortcut() const override { return QKeySequence(Qt::Key_I); }
    QCursor cursor() const override { return Qt::CrossCursor; }

    void press(const ToolEvent &event) override;

    // The colour painted on top at `pos` (canvas pixels) in `frame`: the topmost line within
    // `tolerance` of it, or fill holding it; nothing on empty paper. `fromLine` says which.
    static std::optional<QColor> colourAt(const model::Frame &frame,
                                          const model::DocumentSettings &settings, QPointF pos,
                                          double tolerance, bool *fromLine = nullptr);

private:
    PenTool *m_pen;
};

} // namespace finbook::ui
