// Numbers from a tablet: positions and pressures that are NaN, infinite or 1e30 never reach
// the document, the view or the status bar as NaN or as garbage, and never crash the editor.
#include <finbook/model/document.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/window/main_window.h>

#include <QApplication>
#include <QLabel>
#include <QTabletEvent>
#include <QtTest>

#include <limits>

using namespace finbook;

class TestHostileInput : public QObject {
    Q_OBJECT
private slots:
    void tabletNumbersNeverReachTheScreenAsNaN();
};

void TestHostileInput::tabletNumbersNeverReachTheScreenAsNaN()
{
    ui::MainWindow window;
    window.resize(1000, 700);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    ui::CanvasWidget *canvas = window.canvas();
    canvas->setCurrentTool(QStringLiteral("tool.pen"));
    const qreal nan = std::numeric_limits<qreal>::quiet_NaN();
    const qreal inf = std::numeric_limits<qreal>::infinity();
    const auto tablet = [&](QEvent::Type type, QPointF widgetPos, qreal pressure,
                            Qt::MouseButton button, Qt::MouseButtons buttons) {
        QTabletEvent e(type, QPointingDevice::primaryPointingDevice(), widgetPos, widgetPos,
                       pressure, 0, 0, 0, 0, 0, Qt::NoModifier, button, buttons);
        QApplication::sendEvent(canvas, &e);
    };
    const QPointF middle(canvas->width() / 2.0, canvas->height() / 2.0);
    // A stroke whose samples include every kind of bad number.
    tablet(QEvent::TabletPress, middle, nan, Qt::LeftButton, Qt::LeftButton);
    for (const auto &[pos, pressure] :
         std::vector<std::pair<QPointF, qreal>>{{{nan, 10}, 0.5},
                                                {{10, inf}, 0.5},
                                                {middle + QPointF(10, 0), inf},
                                                {middle + QPointF(20, 5), -3},
                                                {{1e30, 1e30}, 0.5},
                                                {middle + QPointF(30, 5), nan},
                                                {{-inf, -inf}, 1}})
        tablet(QEvent::TabletMove, pos, pressure, Qt::NoButton, Qt::LeftButton);
    tablet(QEvent::TabletRelease, middle + QPointF(40, 0), 0.3, Qt::LeftButton, Qt::NoButton);
    // A pan with the middle button through a position that is not a number.
    tablet(QEvent::TabletPress, middle, 1, Qt::MiddleButton, Qt::MiddleButton);
    tablet(QEvent::TabletMove, {nan, nan}, 1, Qt::NoButton, Qt::MiddleButton);
    tablet(QEvent::TabletMove, middle + QPointF(5, 5), 1, Qt::NoButton, Qt::MiddleButton);
    tablet(QEvent::TabletRelease, middle + QPointF(5, 5), 1, Qt::MiddleButton, Qt::NoButton);

    int points = 0;
    for (const model::Frame &f : window.document()->frames())
        for (const model::StrokeGroup &g : f.groups)
            for (const model::Stroke &s : g.strokes)
                for (const model::StrokePoint &p : s.data->points) {
                    QVERIFY(std::isfinite(p.x) && std::isfinite(p.y));
                    QVERIFY(p.pressure >= 0.0f && p.pressure <= 1.0f);
                    ++points;
                }
    QVERIFY(points > 0); // the good samples made a stroke
    const QPointF canvasPoint = canvas->mapToCanvas(middle);
    QVERIFY(std::isfinite(canvasPoint.x()) && std::isfinite(canvasPoint.y()));
    QVERIFY(std::isfinite(canvas->zoom()));
    for (const QLabel *label : window.findChildren<QLabel *>()) {
        QVERIFY2(!label->text().contains(QLatin1String("nan"), Qt::CaseInsensitive) &&
                     !label->text().contains(QLatin1String("inf")) &&
                     !label->text().contains(QLatin1String("922337")),
                 qPrintable(label->text()));
    }
    const QImage shot = canvas->grab().toImage();
    QVERIFY(!shot.isNull());
}

QTEST_MAIN(TestHostileInput)
#include "tst_hostile_input.moc"
