// Pen (B): draws one stroke per drag into the current object, through the stabiliser when it is
// set (the ink trails the pen on a lazy string, tools/stabiliser.h).
#pragma once

#include <finbook/model/types.h>
#include <finbook/ui/canvas/canvas_tool.h>
#include <finbook/ui/tools/stabiliser.h>

#include <QColor>

#include <optional>
#include <vector>

namespace finbook::ui {

struct PenSettings {
    QColor color = Qt::black;
    double width = 3.0; // canvas pixels at full pressure
    int smoothing = 2;  // passes of a 1-2-1 filter applied on release, 0..10
    // The stabiliser while drawing, 0 (off) ..10: a lazy string 4 screen pixels long per step
    // (tools/stabiliser.h).
    int stabiliser = 0;
    // Whether a tablet's pressure sets the line's width; off, a tablet draws as a mouse does,
    // at full width.
    bool pressure = true;
    friend bool operator==(const PenSettings &, const PenSettings &) = default;
};

class PenTool : public CanvasTool {
    Q_OBJECT
public:
    static constexpr double kMinWidth = 0.5;
    static constexpr double kMaxWidth = 200.0;
    static constexpr int kMaxSmoothing = 10;
    static constexpr int kMaxStabiliser = 10;

    explicit PenTool(QObject *parent = nullptr);

    QString id() const override { return QStringLiteral("tool.pen"); }
    QString name() const override { return tr("Pen"); }
    QString description() const override
    {
        return tr("draw lines; the pen's pressure sets their width");
    }
    QIcon icon() const override;
    QKeySequence defaultShortcut() const override { return QKeySequence(Qt::Key_B); }
    bool picksColourOnCtrlClick() const override { return true; }

    const PenSettings &settings() const { return m_settings; }
    void setSettings(const PenSettings &settings);

    void deactivate() override;
    void press(const ToolEvent &event) override;
    void move(const ToolEvent &event) override;
    void release(const ToolEvent &event) override;
    bool keyPress(QKeyEvent *event) override;
    void paintOverlay(QPainter &painter, const QTransform &canvasToWidget) override;

    // The stroke as it will be committed: smoothed, finite, no repeated points.
    static std::vector<model::StrokePoint> finishedPoints(std::vector<model::StrokePoint> points,
                                                          int smoothing);

signals:
    void settingsChanged(const finbook::ui::PenSettings &settings);

private:
    // The event as a stroke sample, or nothing for non-finite input.
    std::optional<model::StrokePoint> sampleOf(const ToolEvent &event) const;
    // Appends unless it is within minStep() of the last sample.
    void append(const model::StrokePoint &point);
    float minStep() const; // half a screen pixel, in canvas pixels
    QRectF lastSegmentRect() const;
    QRectF stringRect() const;
    void cancel();

    PenSettings m_settings;
    std::vector<model::StrokePoint> m_points;
    LazyString m_string;           // the stabiliser of the stroke being drawn
    model::StrokePoint m_cursor{}; // where the pen is (the ink trails it when stabilised)
    bool m_drawing = false;
};

} // namespace finbook::ui
