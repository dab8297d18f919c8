// The light handle on the canvas (issue 27): shown while the Shading panel is, dragging the
// sun moves the document's light (direction from its angle, height from its distance to the
// centre) in one undo step, Escape during a drag puts the light back, and presses away from
// the sun reach the current tool.
#include "tst_tools_support.h"
#include "tst_window_support.h"

#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/shade/light_handle.h>
#include <finbook/ui/window/main_window.h>

#include <QDockWidget>
#include <QTest>

using namespace finbook;
using namespace finbook::model;

class TestLightHandle : public QObject {
    Q_OBJECT
private slots:
    void dragMovesTheLightInOneStep();
    void escapeCancelsTheDrag();
    void hiddenWithThePanel();
};

namespace {
struct Setup {
    ui::MainWindow window;
    ui::CanvasWidget *canvas = nullptr;
    ui::LightHandle *handle = nullptr;
    QDockWidget *dock = nullptr;
};

bool open(Setup &s)
{
    if (!test::showActive(s.window))
        return false;
    s.canvas = s.window.canvas();
    s.handle = s.canvas->findChild<ui::LightHandle *>(QStringLiteral("lightHandle"));
    s.dock = s.window.findChild<QDockWidget *>(QStringLiteral("shadingDock"));
    if (!s.handle || !s.dock)
        return false;
    // Asked for, the panel comes to the front of the Skeleton panel's place, and the sun shows.
    s.dock->toggleViewAction()->trigger();
    return QTest::qWaitFor([&] { return s.handle->shown(); });
}
} // namespace

void TestLightHandle::dragMovesTheLightInOneStep()
{
    Setup s;
    QVERIFY(open(s));
    Document *doc = s.window.document();
    const DocumentSettings before = doc->settings();
    const int steps = doc->undoStack()->count();
    // Drag the sun to halfway out, straight left of the centre: from the left, 60° high.
    const QPointF target = s.handle->centre() + QPointF(-0.5 * s.handle->radius(), 0.0);
    std::vector<QPointF> path;
    for (int i = 0; i <= 10; ++i)
        path.push_back(s.handle->sunPos() + (target - s.handle->sunPos()) * (i / 10.0));
    test::drag(s.canvas, path);
    QCOMPARE(doc->settings().lightAzimuth, 180.0);
    QCOMPARE(doc->settings().lightElevation, 60.0);
    QCOMPARE(doc->undoStack()->count(), steps + 1);
    QVERIFY((s.handle->sunPos() - target).manhattanLength() < 2.0);
    QCOMPARE(doc->undoStack()->undoText(), QStringLiteral("Move Light"));
    // No stroke was drawn: the drag was the handle's.
    QVERIFY(doc->frameAt(0).groups.empty() || doc->frameAt(0).groups[0].strokes.empty());
    doc->undoStack()->undo();
    QCOMPARE(doc->settings().lightAzimuth, before.lightAzimuth);
    QCOMPARE(doc->settings().lightElevation, before.lightElevation);
}

void TestLightHandle::escapeCancelsTheDrag()
{
    Setup s;
    QVERIFY(open(s));
    Document *doc = s.window.document();
    const DocumentSettings before = doc->settings();
    const int steps = doc->undoStack()->count();
    const QPointF from = s.handle->sunPos();
    const QPointF to = s.handle->centre() + QPointF(0.0, 0.8 * s.handle->radius());
    test::sendMouse(s.canvas, QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    test::sendMouse(s.canvas, QEvent::MouseMove, (from + to) / 2, Qt::NoButton, Qt::LeftButton);
    test::sendMouse(s.canvas, QEvent::MouseMove, to, Qt::NoButton, Qt::LeftButton);
    QCOMPARE(doc->settings().lightAzimuth, 270.0); // from below, while dragging
    QTest::keyClick(s.canvas, Qt::Key_Escape);
    QCOMPARE(doc->settings().lightAzimuth, before.lightAzimuth);
    QCOMPARE(doc->settings().lightElevation, before.lightElevation);
    test::sendMouse(s.canvas, QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
    QCOMPARE(doc->undoStack()->count(), steps); // nothing to undo, nothing to redo
    QVERIFY(!doc->undoStack()->canRedo());
    QCOMPARE(doc->settings().lightAzimuth, before.lightAzimuth);
}

void TestLightHandle::hiddenWithThePanel()
{
    Setup s;
    QVERIFY(open(s));
    Document *doc = s.window.document();
    s.dock->toggleViewAction()->trigger();
    QTRY_VERIFY(!s.handle->shown());
    const double azimuth = doc->settings().lightAzimuth;
    const QPointF from = s.handle->sunPos();
    test::drag(s.canvas, {from, from + QPointF(-40, 10), from + QPointF(-80, 20)});
    QCOMPARE(doc->settings().lightAzimuth, azimuth); // the pen drew instead
}

QTEST_MAIN(TestLightHandle)
#include "tst_light_handle.moc"
