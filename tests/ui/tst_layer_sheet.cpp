// Layers in the real window (issue 46): the dope sheet's rows make a layer current and move the
// playhead, a cel's end dragged changes its exposure in one undo step, the eye and the padlock
// show, hide, lock and unlock, a locked layer refuses the pen, the Layer menu's keys work after
// the mouse has touched the timeline, and the canvas draws the other layers at the playhead.
#include "tst_tools_support.h"
#include "tst_window_support.h"

#include <finbook/model/finbook_file.h>
#include <finbook/model/scene/layer_commands.h>
#include <finbook/model/scene/shot.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/layers/layer_sheet.h>
#include <finbook/ui/window/editor_state.h>

#include <QTest>

using namespace finbook;
using namespace finbook::test;

namespace {

// Two layers: a background of one cel held 6 ticks with a stroke, and the window's own frames
// (3 cels of one tick) in front.
void twoLayers(ui::MainWindow &window)
{
    model::Document *doc = window.document();
    resetDocument(*doc, 3);
    auto *add = new model::AddLayerCommand(doc, 0, QStringLiteral("Background"));
    doc->undoStack()->push(add);
    const model::Layer &bg = doc->layerAt(0);
    doc->undoStack()->push(new model::SetFrameHoldCommand(doc, bg.cels[0].id, 6));
    addStroke(*doc, bg.cels[0].groups[0].id, line(QPointF(20, 20), QPointF(300, 300), 40));
    doc->undoStack()->clear();
}

QPoint cellPoint(const ui::LayerSheet *sheet, int layerIndex, qint64 tick)
{
    const QRect row = sheet->rowRect(layerIndex);
    return {sheet->xOfTick(tick) + 6, row.center().y()}; // the middle of the tick
}

} // namespace

class TestLayerSheet : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { m_settings = std::make_unique<IsolatedSettings>(); }

    void rowsPickTheLayerAndThePlayhead()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        twoLayers(window);
        model::Document *doc = window.document();
        auto *sheet = window.findChild<ui::LayerSheet *>(QStringLiteral("layerSheet"));
        QVERIFY(sheet);
        QCOMPARE(doc->currentLayerIndex(), 1);
        // The background's row at tick 4: its layer current, the playhead there, its one cel.
        QTest::mouseClick(sheet, Qt::LeftButton, {}, cellPoint(sheet, 0, 4));
        QCOMPARE(doc->currentLayerIndex(), 0);
        QCOMPARE(window.editorState()->currentTick(), qint64(4));
        QCOMPARE(window.editorState()->currentFrameIndex(), 0);
        // The front layer at tick 2: its third cel.
        QTest::mouseClick(sheet, Qt::LeftButton, {}, cellPoint(sheet, 1, 2));
        QCOMPARE(doc->currentLayerIndex(), 1);
        QCOMPARE(window.editorState()->currentFrameIndex(), 2);
        // Keys after the mouse touched the timeline: PgDown picks the layer below.
        typeKey(Qt::Key_PageDown);
        QCOMPARE(doc->currentLayerIndex(), 0);
        typeKey(Qt::Key_PageUp);
        QCOMPARE(doc->currentLayerIndex(), 1);
        QCOMPARE(window.editorState()->currentTick(), qint64(2)); // the playhead stayed
    }

    void draggingACelsEndChangesItsExposure()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        twoLayers(window);
        model::Document *doc = window.document();
        auto *sheet = window.findChild<ui::LayerSheet *>(QStringLiteral("layerSheet"));
        const int steps = doc->undoStack()->count();
        // The front layer's first cel ends at tick 1: drag its end to tick 4 (held 4 ticks).
        const int y = sheet->rowRect(1).center().y();
        drag(sheet, {QPointF(sheet->xOfTick(1), y), QPointF(sheet->xOfTick(2), y),
                     QPointF(sheet->xOfTick(4), y)});
        QCOMPARE(doc->layerAt(1).cels[0].hold, 4);
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QCOMPARE(model::celStart(doc->layerAt(1).cels, 1), qint64(4));
        QCOMPARE(doc->layerAt(0).cels[0].hold, 6); // the other layer keeps its timing
        doc->undoStack()->undo();
        QCOMPARE(doc->layerAt(1).cels[0].hold, 1);
    }

    void lockedLayerRefusesThePen()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        twoLayers(window);
        model::Document *doc = window.document();
        auto *sheet = window.findChild<ui::LayerSheet *>(QStringLiteral("layerSheet"));
        // The padlock of the front layer (the second glyph of its header).
        QTest::mouseClick(sheet, Qt::LeftButton, {}, QPoint(27, sheet->rowRect(1).center().y()));
        QVERIFY(doc->layerAt(1).properties.locked);
        QCOMPARE(doc->undoStack()->text(doc->undoStack()->count() - 1),
                 QStringLiteral("Lock Layer"));
        ui::CanvasWidget *canvas = window.canvas();
        canvas->setCurrentTool(QStringLiteral("tool.pen"));
        const int steps = doc->undoStack()->count();
        dragCanvas(canvas, QPointF(100, 100), QPointF(200, 150));
        QCOMPARE(doc->undoStack()->count(), steps); // nothing drawn
        // The eye hides the background; unlocking lets the pen draw again.
        QTest::mouseClick(sheet, Qt::LeftButton, {}, QPoint(10, sheet->rowRect(0).center().y()));
        QVERIFY(!doc->layerAt(0).properties.visible);
        QVERIFY(window.action(QStringLiteral("layer.locked")));
        window.action(QStringLiteral("layer.locked"))->trigger();
        QVERIFY(!doc->layerAt(1).properties.locked);
        dragCanvas(canvas, QPointF(100, 100), QPointF(200, 150));
        QCOMPARE(doc->undoStack()->count(), steps + 3); // hide, unlock, then the stroke
        QCOMPARE(doc->layerAt(1).cels[0].groups[0].strokes.size(), std::size_t(1));
    }

    void draggedCelsMoveAndAltDragCopies()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        twoLayers(window);
        model::Document *doc = window.document();
        auto *sheet = window.findChild<ui::LayerSheet *>(QStringLiteral("layerSheet"));
        const std::vector<model::Id> front{doc->layerAt(1).cels[0].id, doc->layerAt(1).cels[1].id,
                                           doc->layerAt(1).cels[2].id};
        const QByteArray before = model::serializeFinbook(*doc);
        const int steps = doc->undoStack()->count();
        // The front layer's first cel dragged three ticks on: after the other two.
        drag(sheet, {cellPoint(sheet, 1, 0), cellPoint(sheet, 1, 1), cellPoint(sheet, 1, 3)});
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QCOMPARE(doc->layerAt(1).cels[2].id, front[0]);
        QCOMPARE(doc->layerAt(1).cels[0].id, front[1]);
        QCOMPARE(window.editorState()->selectedCels(), std::vector<model::Id>{front[0]});
        // Alt-dragged down a row onto the background's end: a copy there, the cel stays.
        drag(sheet, {cellPoint(sheet, 1, 2), cellPoint(sheet, 1, 3), cellPoint(sheet, 0, 6)},
             Qt::LeftButton, Qt::AltModifier);
        QCOMPARE(doc->undoStack()->count(), steps + 2);
        QCOMPARE(doc->layerAt(0).cels.size(), std::size_t(2));
        QCOMPARE(doc->layerAt(1).cels.size(), std::size_t(3));
        QVERIFY(doc->layerAt(0).cels[1].id != front[0]);
        QCOMPARE(doc->layerAt(0).cels[1].groups.size(), doc->frame(front[0])->groups.size());
        doc->undoStack()->undo();
        doc->undoStack()->undo();
        QCOMPARE(model::serializeFinbook(*doc), before);
        // Ctrl-drag copies too (window managers that move windows on Alt-drag leave Ctrl).
        drag(sheet, {cellPoint(sheet, 1, 0), cellPoint(sheet, 1, 1), cellPoint(sheet, 1, 3)},
             Qt::LeftButton, Qt::ControlModifier);
        QCOMPARE(doc->layerAt(1).cels.size(), std::size_t(4));
        QCOMPARE(doc->layerAt(1).cels[0].id, front[0]);
        doc->undoStack()->undo();
        QCOMPARE(model::serializeFinbook(*doc), before);
        // A locked layer's cels stay where they are.
        window.action(QStringLiteral("layer.locked"))->trigger();
        const int locked = doc->undoStack()->count();
        drag(sheet, {cellPoint(sheet, 1, 0), cellPoint(sheet, 1, 1), cellPoint(sheet, 1, 3)});
        QCOMPARE(doc->undoStack()->count(), locked);
    }

    void pickedCelsAreCutCopiedPastedAndDeleted()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        twoLayers(window);
        model::Document *doc = window.document();
        ui::EditorState *state = window.editorState();
        auto *sheet = window.findChild<ui::LayerSheet *>(QStringLiteral("layerSheet"));
        const QByteArray before = model::serializeFinbook(*doc);
        // Ctrl-click picks the first and the third cel of the front layer.
        QTest::mouseClick(sheet, Qt::LeftButton, {}, cellPoint(sheet, 1, 0));
        QTest::mouseClick(sheet, Qt::LeftButton, Qt::ControlModifier, cellPoint(sheet, 1, 2));
        QCOMPARE(state->selectedCels().size(), std::size_t(2));
        // Ctrl-click on a picked cel drops it; again, picks it.
        QTest::mouseClick(sheet, Qt::LeftButton, Qt::ControlModifier, cellPoint(sheet, 1, 2));
        QCOMPARE(state->selectedCels().size(), std::size_t(1));
        QTest::mouseClick(sheet, Qt::LeftButton, Qt::ControlModifier, cellPoint(sheet, 1, 2));
        QCOMPARE(state->selectedCels().size(), std::size_t(2));
        QVERIFY(window.action(QStringLiteral("edit.copy"))->isEnabled());
        // Copy, then paste at the end of the layer: five cels, the copies after the three.
        typeKey(Qt::Key_C, Qt::ControlModifier);
        QTest::mouseClick(sheet, Qt::LeftButton, {}, QPoint(sheet->xOfTick(3) + 2, 5)); // ruler
        QCOMPARE(state->currentTick(), qint64(3));
        typeKey(Qt::Key_V, Qt::ControlModifier);
        QCOMPARE(doc->layerAt(1).cels.size(), std::size_t(5));
        QCOMPARE(doc->layerAt(1).cels[3].groups[0].strokes.size(),
                 doc->layerAt(1).cels[0].groups[0].strokes.size());
        // The picked cels deleted with the Delete key (the keyboard is the canvas's).
        typeKey(Qt::Key_Delete);
        QCOMPARE(doc->layerAt(1).cels.size(), std::size_t(3));
        QVERIFY(state->selectedCels().empty());
        // Shift-click picks a block across rows: from the background's cel to the front's
        // third, every cel in between (4).
        QTest::mouseClick(sheet, Qt::LeftButton, {}, cellPoint(sheet, 0, 0));
        QTest::mouseClick(sheet, Qt::LeftButton, Qt::ShiftModifier, cellPoint(sheet, 1, 1));
        QCOMPARE(state->selectedCels().size(), std::size_t(4));
        // Cut: the background keeps an empty tick, the front layer too.
        typeKey(Qt::Key_X, Qt::ControlModifier);
        QCOMPARE(doc->layerAt(0).cels.size(), std::size_t(1));
        QVERIFY(doc->layerAt(0).cels[0].groups.empty());
        QCOMPARE(doc->layerAt(1).cels.size(), std::size_t(1));
        // Picking strokes afterwards drops the picked cels: Delete is the strokes' again.
        QTest::mouseClick(sheet, Qt::LeftButton, {}, cellPoint(sheet, 1, 0));
        QCOMPARE(state->selectedCels().size(), std::size_t(1));
        state->setSelectedStrokes({doc->layerAt(1).cels[0].id}); // any id: it is the rule
        QVERIFY(state->selectedCels().empty());
        state->setSelectedStrokes({});
        while (doc->undoStack()->canUndo())
            doc->undoStack()->undo();
        QCOMPARE(model::serializeFinbook(*doc), before);
    }

    void timeIsInsertedOnThePickedCelsLayers()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        twoLayers(window);
        model::Document *doc = window.document();
        auto *sheet = window.findChild<ui::LayerSheet *>(QStringLiteral("layerSheet"));
        // The front layer's cels 1 and 2 (ticks 1-2) picked: two ticks go in at tick 1 on the
        // front layer only; the background keeps its six.
        QTest::mouseClick(sheet, Qt::LeftButton, {}, cellPoint(sheet, 1, 1));
        QTest::mouseClick(sheet, Qt::LeftButton, Qt::ShiftModifier, cellPoint(sheet, 1, 2));
        QCOMPARE(window.editorState()->selectedCels().size(), std::size_t(2));
        window.action(QStringLiteral("layer.insertTime"))->trigger();
        QCOMPARE(doc->layerAt(1).cels[1].hold, 3);
        QCOMPARE(model::celTicks(doc->layerAt(1).cels), qint64(5));
        QCOMPARE(model::celTicks(doc->layerAt(0).cels), qint64(6));
        // Delete Time takes the stretch the picked cels now span (ticks 1-4): both go.
        window.action(QStringLiteral("layer.deleteTime"))->trigger();
        QCOMPARE(doc->layerAt(1).cels.size(), std::size_t(1));
        QCOMPARE(model::celTicks(doc->layerAt(1).cels), qint64(1));
        QCOMPARE(model::celTicks(doc->layerAt(0).cels), qint64(6));
        // Nothing picked: one tick at the playhead, on the current layer.
        QVERIFY(window.editorState()->selectedCels().empty());
        window.editorState()->setCurrentTick(0);
        window.action(QStringLiteral("layer.insertTime"))->trigger();
        QCOMPARE(doc->layerAt(1).cels[0].hold, 2);
    }

    void layersAreReorderedByDraggingTheirName()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        twoLayers(window);
        model::Document *doc = window.document();
        auto *sheet = window.findChild<ui::LayerSheet *>(QStringLiteral("layerSheet"));
        const model::Id background = doc->layerAt(0).id;
        const int x = 90;
        drag(sheet, {QPointF(x, sheet->rowRect(0).center().y()),
                     QPointF(x, sheet->rowRect(0).center().y() - 12),
                     QPointF(x, sheet->rowRect(1).center().y())});
        QCOMPARE(doc->layerAt(1).id, background);
        QCOMPARE(doc->undoStack()->text(doc->undoStack()->count() - 1),
                 QStringLiteral("Move Layer"));
        doc->undoStack()->undo();
        QCOMPARE(doc->layerAt(0).id, background);
    }

    void clickingAnotherLayersDrawingMakesItCurrent()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        twoLayers(window);
        model::Document *doc = window.document();
        ui::CanvasWidget *canvas = window.canvas();
        canvas->setCurrentTool(QStringLiteral("tool.select"));
        QCOMPARE(doc->currentLayerIndex(), 1);
        const model::Id stroke = doc->layerAt(0).cels[0].groups[0].strokes[0].id;
        // A click on the background's line (the front layer has nothing there).
        const QPoint on = canvas->mapFromCanvas(QPointF(160, 160)).toPoint();
        QTest::mouseClick(canvas, Qt::LeftButton, {}, on);
        QCOMPARE(doc->currentLayerIndex(), 0);
        QCOMPARE(window.editorState()->selectedStrokes(), std::vector<model::Id>{stroke});
        // A click on nothing picks nothing and leaves the layer current.
        QTest::mouseClick(canvas, Qt::LeftButton, {},
                          canvas->mapFromCanvas(QPointF(350, 40)).toPoint());
        QCOMPARE(doc->currentLayerIndex(), 0);
        QVERIFY(window.editorState()->selectedStrokes().empty());
        // A locked layer's drawing is not picked that way.
        window.action(QStringLiteral("layer.locked"))->trigger();
        window.action(QStringLiteral("layer.above"))->trigger();
        QTest::mouseClick(canvas, Qt::LeftButton, {}, on);
        QCOMPARE(doc->currentLayerIndex(), 1);
    }

    void otherLayersDrawUnderTheCurrentOne()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        twoLayers(window);
        ui::CanvasWidget *canvas = window.canvas();
        // The background's stroke crosses the page's (160, 160): dark on the canvas, though
        // the current layer has nothing there.
        const QPoint at = canvas->mapFromCanvas(QPointF(160, 160)).toPoint();
        const auto dark = [&] { return qGray(canvas->grab().toImage().pixel(at)) < 128; };
        QVERIFY(dark());
        window.action(QStringLiteral("layer.below"))->trigger();
        window.action(QStringLiteral("layer.visible"))->trigger(); // hide the background
        QCOMPARE(window.document()->currentLayerIndex(), 0);
        QVERIFY(!window.document()->layerAt(0).properties.visible);
        QVERIFY(!dark());
        window.document()->undoStack()->undo();
        QVERIFY(dark());
        // Past the background's six ticks it shows nothing (seen from the front layer: the
        // current layer's last drawing stays on show for editing past its end).
        window.action(QStringLiteral("layer.above"))->trigger();
        window.editorState()->setCurrentTick(5);
        QVERIFY(dark());
        window.editorState()->setCurrentTick(7);
        QVERIFY(!dark());
    }

private:
    std::unique_ptr<IsolatedSettings> m_settings;
};

QTEST_MAIN(TestLayerSheet)
#include "tst_layer_sheet.moc"
