// Helpers for the editor's widget tests: real mouse and wheel events on a real canvas.
#pragma once

#include <finbook/model/commands.h>
#include <finbook/model/document.h>
#include <finbook/ui/canvas/canvas_widget.h>

#include <QApplication>
#include <QMouseEvent>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QWheelEvent>

#include <memory>
#include <vector>

namespace finbook::test {

// QTest::mouseMove carries no buttons in Qt 6, so drags are sent as QMouseEvents.
inline void sendMouse(QWidget *w, QEvent::Type type, const QPointF &pos, Qt::MouseButton button,
                      Qt::MouseButtons buttons, Qt::KeyboardModifiers mods = Qt::NoModifier)
{
    QMouseEvent event(type, pos, w->mapToGlobal(pos), button, buttons, mods);
    QApplication::sendEvent(w, &event);
}

// Drags the left (or another) button through `widgetPoints`.
inline void drag(QWidget *w, const std::vector<QPointF> &widgetPoints,
                 Qt::MouseButton button = Qt::LeftButton,
                 Qt::KeyboardModifiers mods = Qt::NoModifier)
{
    if (widgetPoints.empty())
        return;
    sendMouse(w, QEvent::MouseButtonPress, widgetPoints.front(), button, button, mods);
    for (std::size_t i = 1; i < widgetPoints.size(); ++i)
        sendMouse(w, QEvent::MouseMove, widgetPoints[i], Qt::NoButton, button, mods);
    sendMouse(w, QEvent::MouseButtonRelease, widgetPoints.back(), button, Qt::NoButton, mods);
}

// A straight drag in canvas coordinates, sampled every `step` canvas pixels.
inline void dragCanvas(ui::CanvasWidget *canvas, QPointF from, QPointF to, qreal step = 4.0,
                       Qt::KeyboardModifiers mods = Qt::NoModifier)
{
    const int n = std::max(1, int(QLineF(from, to).length() / step));
    std::vector<QPointF> points;
    for (int i = 0; i <= n; ++i)
        points.push_back(canvas->mapFromCanvas(from + (to - from) * (qreal(i) / n)));
    drag(canvas, points, Qt::LeftButton, mods);
}

inline void wheel(QWidget *w, const QPointF &pos, int angleY, Qt::KeyboardModifiers mods = {})
{
    QWheelEvent event(pos, w->mapToGlobal(pos), QPoint(), QPoint(0, angleY), Qt::NoButton, mods,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(w, &event);
}

// A stroke along a straight line, `n` points.
inline model::StrokeDataPtr line(QPointF a, QPointF b, int n = 20, QRgb color = 0xff000000)
{
    auto s = std::make_shared<model::StrokeData>();
    for (int i = 0; i < n; ++i) {
        const QPointF p = a + (b - a) * (qreal(i) / (n - 1));
        s->points.push_back({float(p.x()), float(p.y()), 1.0f});
    }
    s->color = color;
    s->width = 3.0f;
    return s;
}

// A 3 px stroke through `corners` in order, 40 points per side.
inline model::StrokeDataPtr polyline(const std::vector<QPointF> &corners)
{
    auto s = std::make_shared<model::StrokeData>();
    for (std::size_t c = 0; c + 1 < corners.size(); ++c)
        for (int i = 0; i < 40; ++i) {
            const QPointF p = corners[c] + (corners[c + 1] - corners[c]) * (i / 40.0);
            s->points.push_back({float(p.x()), float(p.y()), 1.0f});
        }
    if (!corners.empty())
        s->points.push_back({float(corners.back().x()), float(corners.back().y()), 1.0f});
    s->width = 3.0f;
    return s;
}

// `frames` frames of one empty object each, on a 400×300 page; no undo history.
inline void resetDocument(model::Document &doc, int frames, int objectsPerFrame = 1)
{
    std::vector<model::Frame> list;
    model::Id next = 1;
    for (int f = 0; f < frames; ++f) {
        model::Frame frame;
        frame.id = next++;
        for (int g = 0; g < objectsPerFrame; ++g) {
            model::StrokeGroup group;
            group.id = next++;
            group.name = QStringLiteral("Object %1").arg(g + 1);
            frame.groups.push_back(group);
        }
        list.push_back(frame);
    }
    model::DocumentSettings settings;
    settings.canvasSize = QSize(400, 300);
    doc.reset(std::move(list), settings, next);
}

inline model::Id addStroke(model::Document &doc, model::Id groupId, model::StrokeDataPtr data)
{
    auto *cmd = new model::AddStrokeCommand(&doc, groupId, std::move(data));
    const model::Id id = cmd->strokeId();
    doc.undoStack()->push(cmd);
    return id;
}

inline const model::Stroke *findStroke(const model::Document &doc, model::Id id)
{
    const model::StrokeLocation at = doc.locateStroke(id);
    if (!at.isValid())
        return nullptr;
    return &doc.frameAt(at).groups[std::size_t(at.group)].strokes[std::size_t(at.stroke)];
}

// Keeps QSettings of a test run away from the user's real settings.
class IsolatedSettings {
public:
    IsolatedSettings()
    {
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
        QCoreApplication::setOrganizationName(QStringLiteral("FinbookTests"));
        QCoreApplication::setApplicationName(QStringLiteral("FinbookTests"));
    }
    QString path() const { return m_dir.path(); }

private:
    QTemporaryDir m_dir;
};

} // namespace finbook::test
