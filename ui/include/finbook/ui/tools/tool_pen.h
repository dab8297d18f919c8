// Pen (B): draws one stroke per drag into the current object.
#pragma once

#include <finbook/model/types.h>
#include <finbook/ui/canvas/canvas_tool.h>

#include <QColor>

#include <vector>

namespace finbook::ui {

struct PenSettings {
    QColor color = Qt::black;
    double width = 3.0; // canvas pixels at full pressure
    int smoothing = 2;  // passes of a 1-2-1 filter applied on release, 0..10
    friend bool operator==(const PenSettings &, const PenSettings &) = default;
};

class PenTool : public CanvasTool {
    Q_OBJECT
public:
    static constexpr double kMinWidth = 0.5;
    static constexpr double kMaxWidth = 200.0;
    static constexpr int kMaxSmoothing = 10;

    explicit PenTool(QObject *parent = nullptr);

    QString id() const override { return QStringLiteral("tool.pen"); }
    QString name() const override { return tr("Pen"); }
    QIcon icon() const override;
    QKeySequence defaultShortcut() const override { return QKeySequence(Qt::Key_B); }

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
    void addPoint(const ToolEvent &event);
    QRectF lastSegmentRect() const;
    void cancel();

    PenSettings m_settings;
    std::vector<model::StrokePoint> m_points;
    bool m_drawing = false;
};

} // namespace finbook::ui
