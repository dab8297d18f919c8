// The Shading dock in the real main window: choosing a ramp shades the current object's fills
// (one undo step, shown on the canvas), the light's direction is one undo step, and the panel
// follows undo.
#include "tst_window_support.h"

#include <finbook/model/shade/fill_shading.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/shade/light_handle.h>
#include <finbook/ui/window/main_window.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QSpinBox>
#include <QTest>

using namespace finbook;
using namespace finbook::model;

namespace {
constexpr QRgb kFill = 0xffe0a040;

// One object: a filled square outline from (200, 150) to (400, 350).
Id filledSquare(Document &doc)
{
    auto data = std::make_shared<StrokeData>();
    data->width = 4.0f;
    const QPolygonF corners{QPointF(200, 150), QPointF(400, 150), QPointF(400, 350),
                            QPointF(200, 350), QPointF(200, 150)};
    for (qsizetype i = 0; i + 1 < corners.size(); ++i)
        for (int k = 0; k < 40; ++k) {
            const QPointF p = corners[i] + (corners[i + 1] - corners[i]) * (k / 40.0);
            data->points.push_back({float(p.x()), float(p.y()), 1.0f});
        }
    data->points.push_back({200.0f, 150.0f, 1.0f});
    Frame f;
    f.id = doc.allocateId();
    StrokeGroup g;
    g.id = doc.allocateId();
    g.strokes.push_back({doc.allocateId(), data});
    g.fills.push_back({kFill, QPointF(300, 250), {g.strokes[0].id}, {}, {}});
    f.groups.push_back(g);
    DocumentSettings s;
    s.canvasSize = QSize(800, 600);
    doc.reset({f}, s, doc.nextId());
    return g.id;
}
} // namespace

class TestShadingPanel : public QObject {
    Q_OBJECT
private slots:
    void rampShadesTheCurrentObjectsFills();
    void askingForThePanelBringsItToTheFront();
};

void TestShadingPanel::rampShadesTheCurrentObjectsFills()
{
    ui::MainWindow window;
    QVERIFY(test::showActive(window));
    Document *doc = window.document();
    const Id g = filledSquare(*doc);
    auto *dock = window.findChild<QDockWidget *>(QStringLiteral("shadingDock"));
    QVERIFY(dock);
    QVERIFY(!dock->isVisible()); // until asked for, from View → Panels
    dock->toggleViewAction()->trigger();
    QTRY_VERIFY(dock->widget()->isVisible());
    auto *ramp = window.findChild<QComboBox *>(QStringLiteral("shade.ramp"));
    auto *rim = window.findChild<QCheckBox *>(QStringLiteral("shade.rim"));
    auto *azimuth = window.findChild<QSpinBox *>(QStringLiteral("shade.azimuth"));
    QVERIFY(ramp && rim && azimuth);
    QVERIFY(ramp->isEnabled());
    QCOMPARE(ramp->currentIndex(), 0); // flat
    // Two steps down the list with the keyboard: cel, three tones.
    ramp->setFocus();
    QTest::keyClick(ramp, Qt::Key_Down);
    QTest::keyClick(ramp, Qt::Key_Down);
    QCOMPARE(doc->group(g)->fills[0].shading.ramp, ShadeRamp::ThreeTones);
    QCOMPARE(doc->undoStack()->count(), 2);
    QTest::mouseClick(rim, Qt::LeftButton, {}, QPoint(8, rim->height() / 2)); // its box
    QVERIFY(doc->group(g)->fills[0].shading.rim);
    // The canvas shows the shadow along the side away from the light (upper left by default).
    auto *canvas = window.findChild<ui::CanvasWidget *>();
    QVERIFY(canvas);
    const auto shownAt = [canvas](QPointF p) {
        const QImage image = canvas->grab().toImage();
        return image.pixel(canvas->mapFromCanvas(p).toPoint() * image.devicePixelRatio()) |
               0xff000000u;
    };
    QCOMPARE(shownAt(QPointF(300, 340)), shadowTone(kFill));
    QCOMPARE(shownAt(QPointF(300, 250)), kFill);
    // The light from the lower right instead: the shadow moves to the other side.
    azimuth->setValue(315);
    QCOMPARE(doc->settings().lightAzimuth, 315.0);
    QCOMPARE(shownAt(QPointF(300, 160)), shadowTone(kFill));
    QCOMPARE(shownAt(QPointF(300, 340)), kFill);
    // Undo brings the light back, then the rim, then flat fills; the panel follows.
    doc->undoStack()->undo();
    QCOMPARE(azimuth->value(), 135);
    doc->undoStack()->undo();
    QVERIFY(!rim->isChecked());
    doc->undoStack()->undo();
    doc->undoStack()->undo();
    QCOMPARE(ramp->currentIndex(), 0);
    QVERIFY(!doc->group(g)->fills[0].shading.shaded());
    QCOMPARE(shownAt(QPointF(300, 340)), kFill);
}

void TestShadingPanel::askingForThePanelBringsItToTheFront()
{
    // The Shading panel shares the Skeleton panel's place as a tab. Asking for it (View →
    // Panels → Shading) must show it in front, with the light's sun on the canvas, not leave
    // it behind the Skeleton tab where nothing says it opened.
    ui::MainWindow window;
    QVERIFY(test::showActive(window));
    filledSquare(*window.document());
    auto *skeleton = window.findChild<QDockWidget *>(QStringLiteral("skeletonDock"));
    auto *shading = window.findChild<QDockWidget *>(QStringLiteral("shadingDock"));
    auto *sun = window.findChild<ui::LightHandle *>(QStringLiteral("lightHandle"));
    QVERIFY(skeleton && shading && sun);
    QVERIFY(window.tabifiedDockWidgets(skeleton).contains(shading));
    // A tab behind another stays "visible" but is moved out of the window: what shows is what
    // has some of its area on screen.
    const auto inFront = [](QDockWidget *dock) {
        return dock->isVisible() && !dock->widget()->visibleRegion().isEmpty();
    };
    QTRY_VERIFY(inFront(skeleton));
    QVERIFY(!sun->shown());
    shading->toggleViewAction()->trigger();
    QTRY_VERIFY(inFront(shading));
    QVERIFY(!inFront(skeleton)); // the Skeleton tab is behind it now
    QTRY_VERIFY(sun->shown());
    // Back to the Skeleton tab: the sun goes; asked for again, the panel comes to the front.
    skeleton->raise();
    QTRY_VERIFY(inFront(skeleton));
    QTRY_VERIFY(!sun->shown());
    shading->toggleViewAction()->trigger(); // closes it (it was open, behind)
    QVERIFY(shading->isHidden());
    shading->toggleViewAction()->trigger();
    QTRY_VERIFY(inFront(shading));
    QTRY_VERIFY(sun->shown());
}

QTEST_MAIN(TestShadingPanel)
#include "tst_shading_panel.moc"
