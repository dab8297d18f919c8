// Move Reference on the canvas: a drag moves the reference, Shift+drag scales it, Ctrl+drag
// rotates it, each drag one undo step; a locked reference stays put, a click adds no step.
#include "../model/reference_support.h"
#include "tst_tools_support.h"
#include "tst_window_support.h"

#include <finbook/model/reference/reference_commands.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/reference/reference_panel.h>

#include <QTest>

using namespace finbook;
using namespace finbook::test;

class TestReferenceTool : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { m_settings = std::make_unique<IsolatedSettings>(); }

    void dragsMoveScaleAndRotateInOneStepEach()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        model::Document *doc = window.document();
        QVERIFY(!ui::importReference(*doc, writeTwoColourPng(m_dir.path())));
        ui::CanvasWidget *canvas = window.canvas();
        canvas->setCurrentTool(QStringLiteral("tool.reference"));
        QVERIFY(window.action(QStringLiteral("tool.reference")));
        const model::Reference start = doc->referenceLayer().reference();
        const QPointF c = start.center;
        const int steps = doc->undoStack()->count();

        dragCanvas(canvas, c, c + QPointF(30, 20));
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        const model::Reference moved = doc->referenceLayer().reference();
        QVERIFY(QLineF(moved.center, c + QPointF(30, 20)).length() < 0.5);
        QCOMPARE(moved.scale, start.scale);

        const QPointF m = moved.center;
        dragCanvas(canvas, m + QPointF(40, 0), m + QPointF(80, 0), 4.0, Qt::ShiftModifier);
        QCOMPARE(doc->undoStack()->count(), steps + 2);
        QVERIFY(std::abs(doc->referenceLayer().reference().scale / start.scale - 2.0) < 0.02);
        QCOMPARE(doc->referenceLayer().reference().center, m);

        dragCanvas(canvas, m + QPointF(40, 0), m + QPointF(0, 40), 4.0, Qt::ControlModifier);
        QCOMPARE(doc->undoStack()->count(), steps + 3);
        QVERIFY(std::abs(doc->referenceLayer().reference().rotation - 90.0) < 1.0);

        // A click moves nothing and leaves no step; the frame's drawing is untouched.
        dragCanvas(canvas, m, m);
        QCOMPARE(doc->undoStack()->count(), steps + 3);
        QVERIFY(doc->frameAt(0).groups.empty() || doc->frameAt(0).groups.front().strokes.empty());

        doc->undoStack()->undo();
        doc->undoStack()->undo();
        QCOMPARE(doc->referenceLayer().reference(), moved);
        doc->undoStack()->undo();
        QCOMPARE(doc->referenceLayer().reference(), start);
    }

    void lockedOrOutsideDoesNotMove()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        model::Document *doc = window.document();
        QVERIFY(!ui::importReference(*doc, writeTwoColourPng(m_dir.path())));
        model::Reference small = doc->referenceLayer().reference();
        small.scale = 0.5; // 40×30 canvas pixels around the centre
        doc->undoStack()->push(
            model::editReferenceCommand(doc, small, model::ReferenceEdit::Scale).release());
        ui::CanvasWidget *canvas = window.canvas();
        canvas->setCurrentTool(QStringLiteral("tool.reference"));
        const int steps = doc->undoStack()->count();
        // Off the picture: nothing is grabbed.
        dragCanvas(canvas, small.center + QPointF(60, 0), small.center + QPointF(90, 10));
        QCOMPARE(doc->referenceLayer().reference(), small);
        model::Reference locked = small;
        locked.locked = true;
        doc->undoStack()->push(
            model::editReferenceCommand(doc, locked, model::ReferenceEdit::Locked).release());
        dragCanvas(canvas, small.center, small.center + QPointF(30, 20));
        QCOMPARE(doc->referenceLayer().reference(), locked);
        QCOMPARE(doc->undoStack()->count(), steps + 1);
    }

private:
    std::unique_ptr<IsolatedSettings> m_settings;
    QTemporaryDir m_dir;
};

QTEST_MAIN(TestReferenceTool)
#include "tst_reference_tool.moc"
