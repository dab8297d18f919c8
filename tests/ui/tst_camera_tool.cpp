// The Camera tool and Camera View (issue 46): a drag moves the camera's frame, Shift+drag
// zooms it, Ctrl+drag turns it, each one undo step that sets the key at the current frame's
// first tick; the context menu sets the easing; Delete removes the key; Camera View looks
// through the camera (the shot's middle is the camera's centre) and follows playback's tick.
#include "tst_tools_support.h"
#include "tst_window_support.h"

#include <finbook/model/camera/camera_commands.h>
#include <finbook/ui/camera/tool_camera.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/timeline/thumbnail_cache.h>
#include <finbook/ui/window/editor_state.h>

#include <QMenu>
#include <QTest>

using namespace finbook;
using namespace finbook::test;

namespace {

// The action named `name` anywhere in `menu` (submenus included).
QAction *findAction(QMenu &menu, const QString &name)
{
    for (QAction *a : menu.findChildren<QAction *>())
        if (a->objectName() == name)
            return a;
    return nullptr;
}

} // namespace

class TestCameraTool : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { m_settings = std::make_unique<IsolatedSettings>(); }

    void dragsMoveZoomAndTurnTheKeyOfThisFrame()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        model::Document *doc = window.document();
        ui::CanvasWidget *canvas = window.canvas();
        QVERIFY(window.action(QStringLiteral("tool.camera")));
        QCOMPARE(window.action(QStringLiteral("tool.camera"))->shortcut(), QKeySequence(Qt::Key_A));
        canvas->setCurrentTool(QStringLiteral("tool.camera"));
        const QSizeF page(doc->settings().canvasSize);
        const QPointF c(page.width() / 2, page.height() / 2);
        const int steps = doc->undoStack()->count();

        // Over the page the frame follows the pointer: one key at tick 0, one step.
        dragCanvas(canvas, c, c + QPointF(40, -20));
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QCOMPARE(doc->camera().keys.size(), std::size_t(1));
        const model::CameraKey moved = doc->camera().keys.front();
        QCOMPARE(moved.tick, qint64(0));
        QVERIFY(QLineF(moved.center, c + QPointF(40, -20)).length() < 0.5);
        QCOMPARE(moved.zoom, 1.0);

        // Shift+drag away from the centre to twice the distance: the frame twice as big, the
        // camera zoomed out to a half.
        const QPointF m = moved.center;
        dragCanvas(canvas, m + QPointF(50, 0), m + QPointF(100, 0), 4.0, Qt::ShiftModifier);
        QCOMPARE(doc->undoStack()->count(), steps + 2);
        QVERIFY(std::abs(doc->camera().keys.front().zoom - 0.5) < 0.01);
        // Ctrl+drag a quarter turn clockwise on screen: the frame turns with the pointer, the
        // camera by −90° (counter-clockwise is positive).
        dragCanvas(canvas, m + QPointF(60, 0), m + QPointF(0, 60), 4.0, Qt::ControlModifier);
        QCOMPARE(doc->undoStack()->count(), steps + 3);
        QVERIFY2(std::abs(doc->camera().keys.front().rotation + 90.0) < 1.0,
                 qPrintable(QString::number(doc->camera().keys.front().rotation)));

        // On a later frame the key goes at that frame's first tick (frames before it held).
        doc->undoStack()->push(new model::InsertFrameCommand(doc, 1));
        doc->undoStack()->push(new model::SetFrameHoldCommand(doc, doc->frameAt(0).id, 3));
        window.canvas()->state()->setCurrentFrameIndex(1);
        QCOMPARE(window.canvas()->state()->currentTick(), qint64(3));
        dragCanvas(canvas, m, m + QPointF(-30, 0));
        QCOMPARE(doc->camera().keys.size(), std::size_t(2));
        QCOMPARE(doc->camera().keys.back().tick, qint64(3));

        // Undo takes back exactly, one drag at a time.
        doc->undoStack()->undo();
        QCOMPARE(doc->camera().keys.size(), std::size_t(1));
        doc->undoStack()->setIndex(steps);
        QVERIFY(doc->camera().isEmpty());
    }

    void menuSetsTheEasingAndDeleteRemovesTheKey()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        model::Document *doc = window.document();
        ui::CanvasWidget *canvas = window.canvas();
        canvas->setCurrentTool(QStringLiteral("tool.camera"));
        auto *tool = qobject_cast<ui::CameraTool *>(canvas->currentTool());
        QVERIFY(tool);
        const QPointF c = QPointF(doc->settings().canvasSize.width(), 100) / 2;
        dragCanvas(canvas, c, c + QPointF(10, 0));
        QCOMPARE(doc->camera().keys.size(), std::size_t(1));
        const auto choose = [&](const QString &name) {
            tool->setMenuExec([name](QMenu &menu, QPoint) { return findAction(menu, name); });
            QTest::mouseClick(canvas, Qt::RightButton, {}, canvas->mapFromCanvas(c).toPoint());
        };
        choose(QStringLiteral("camera.easing.%1").arg(int(model::CameraEasing::EaseIn)));
        QCOMPARE(doc->camera().keys.front().easing, model::CameraEasing::EaseIn);
        choose(QStringLiteral("camera.easing.%1").arg(int(model::CameraEasing::Hold)));
        QCOMPARE(doc->camera().keys.front().easing, model::CameraEasing::Hold);
        // Delete, as an animator presses it, with the canvas focused.
        canvas->setFocus();
        QTest::keyClick(canvas, Qt::Key_Delete);
        QVERIFY(doc->camera().isEmpty());
        doc->undoStack()->undo();
        QCOMPARE(doc->camera().keys.size(), std::size_t(1));
        // Reset Camera: the key at rest (the page's centre, zoom 1, unturned), easing kept.
        choose(QStringLiteral("camera.reset"));
        const QSizeF page(doc->settings().canvasSize);
        QCOMPARE(doc->camera().keys.front().center, QPointF(page.width() / 2, page.height() / 2));
        QCOMPARE(doc->camera().keys.front().zoom, 1.0);
        QCOMPARE(doc->camera().keys.front().easing, model::CameraEasing::Hold);
    }

    void cameraViewLooksThroughTheCamera()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        model::Document *doc = window.document();
        ui::CanvasWidget *canvas = window.canvas();
        ui::EditorState *state = window.canvas()->state();
        doc->undoStack()->push(new model::SetFrameHoldCommand(doc, doc->frameAt(0).id, 10));
        model::CameraKey a, b;
        a.tick = 0;
        a.center = QPointF(300, 200);
        a.zoom = 2.0;
        b = a;
        b.tick = 8;
        b.center = QPointF(700, 200);
        b.rotation = 30.0;
        doc->undoStack()->push(model::setCameraKeyCommand(doc, a).release());
        doc->undoStack()->push(model::setCameraKeyCommand(doc, b).release());
        QAction *view = window.action(QStringLiteral("view.cameraView"));
        QVERIFY(view && view->isCheckable());
        const QPointF middleOfPage = canvas->mapFromCanvas(
            QPointF(doc->settings().canvasSize.width(), doc->settings().canvasSize.height()) / 2);
        const qreal zoom = canvas->zoom();
        view->trigger();
        QVERIFY(state->cameraView());
        // The shot's middle (where the page's middle was) shows the camera's centre, and a
        // page px is two widget px as many as before: the tools' grab radii follow (zoom()).
        QVERIFY(QLineF(canvas->mapToCanvas(middleOfPage), a.center).length() < 1e-6);
        QVERIFY(std::abs(QLineF(canvas->mapFromCanvas(a.center),
                                canvas->mapFromCanvas(a.center + QPointF(10, 0)))
                             .length() -
                         20 * zoom) < 1e-6);
        QVERIFY(std::abs(canvas->zoom() - 2 * zoom) < 1e-9);
        // Playback moves on within the hold: the view follows the tick, halfway at tick 4.
        state->setPlaybackTick(4);
        QCOMPARE(state->currentTick(), qint64(4));
        QVERIFY(QLineF(canvas->mapToCanvas(middleOfPage), QPointF(500, 200)).length() < 1e-6);
        state->setPlaybackTick(-1);
        QCOMPARE(state->currentTick(), qint64(0));
        // The canvas still paints (through QPainter, turned) and the tools get page points.
        canvas->repaint();
        view->trigger();
        QVERIFY(!state->cameraView());
        QVERIFY(QLineF(canvas->mapFromCanvas(QPointF(doc->settings().canvasSize.width(),
                                                     doc->settings().canvasSize.height()) /
                                             2),
                       middleOfPage)
                    .length() < 1e-6);
        // Playback shows the shot even outside Camera View: what the audience will see.
        state->setPlaying(true);
        state->setPlaybackTick(8);
        QVERIFY(canvas->looksThroughCamera());
        QVERIFY(QLineF(canvas->mapToCanvas(middleOfPage), b.center).length() < 1e-6);
        state->setPlaybackTick(-1);
        state->setPlaying(false);
        QVERIFY(!canvas->looksThroughCamera());
        QVERIFY(
            QLineF(canvas->mapToCanvas(middleOfPage), QPointF(doc->settings().canvasSize.width(),
                                                              doc->settings().canvasSize.height()) /
                                                          2)
                .length() < 1e-6);
    }

    // The onion skin shows in Camera View too: the frame before, tinted, through the camera.
    void onionSkinShowsInCameraView()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        model::Document *doc = window.document();
        ui::CanvasWidget *canvas = window.canvas();
        ui::EditorState *state = canvas->state();
        const QSizeF page(doc->settings().canvasSize);
        const QPointF c(page.width() / 2, page.height() / 2);
        doc->undoStack()->push(new model::AddStrokeCommand(
            doc, doc->frameAt(0).groups.at(0).id, line(c - QPointF(60, 0), c + QPointF(60, 0))));
        doc->undoStack()->push(new model::InsertFrameCommand(doc, 1));
        state->setCurrentFrameIndex(1);
        model::CameraKey key;
        key.center = c;
        key.zoom = 1.5;
        key.rotation = 20.0;
        doc->undoStack()->push(model::setCameraKeyCommand(doc, key).release());
        ui::OnionSkin onion = state->onionSkin();
        onion.enabled = true;
        state->setOnionSkin(onion);
        state->setCameraView(true);
        const QImage shot = canvas->grab().toImage();
        // The line of frame 1, turned with the camera, in the "before" tint (reddish).
        int tinted = 0;
        for (int x = -40; x <= 40; x += 4) {
            const QPoint at = canvas->mapFromCanvas(c + QPointF(x, 0)).toPoint();
            const QColor colour = shot.pixelColor(at);
            tinted += colour.red() > colour.blue() + 30 && colour.red() > colour.green() + 30;
        }
        QVERIFY2(tinted >= 15, qPrintable(QString::number(tinted)));
    }

    // Timeline thumbnails show the shot: a camera key moves the dot in them, and they are
    // drawn again when the camera changes.
    void thumbnailsShowTheShot()
    {
        model::Document doc;
        model::DocumentSettings settings;
        settings.canvasSize = QSize(200, 100);
        doc.reset(std::vector<model::Frame>{}, settings, 1);
        doc.undoStack()->push(new model::InsertFrameCommand(&doc, 0));
        const model::Id frame = doc.frameAt(0).id;
        doc.undoStack()->push(new model::AddStrokeCommand(&doc, doc.frameAt(0).groups.at(0).id,
                                                          line({149.5, 50}, {150.5, 50}, 2)));
        ui::ThumbnailCache cache(&doc);
        cache.setThumbnailSize(QSize(200, 100));
        const auto dotX = [&] {
            cache.thumbnail(frame);
            cache.renderPending();
            const QImage image = cache.thumbnail(frame).toImage();
            double sum = 0, n = 0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x)
                    if (qGray(image.pixel(x, y)) < 160) {
                        sum += x + 0.5;
                        n += 1;
                    }
            return n > 0 ? sum / n : -1.0;
        };
        QVERIFY(std::abs(dotX() - 150.0) < 1.5);
        model::CameraKey key;
        key.center = QPointF(150, 50);
        key.zoom = 2.0;
        doc.undoStack()->push(model::setCameraKeyCommand(&doc, key).release());
        QVERIFY(!cache.isCurrent(frame));
        QVERIFY(std::abs(dotX() - 100.0) < 1.5);
        doc.undoStack()->undo();
        QVERIFY(std::abs(dotX() - 150.0) < 1.5);
    }

private:
    std::unique_ptr<IsolatedSettings> m_settings;
};

QTEST_MAIN(TestCameraTool)
#include "tst_camera_tool.moc"
