// Drawing substitution in the real main window (issue 49): Object > New Mouth Chart makes a
// mouth that swaps between nine drawings; [ and ] step through them on the current frame, also
// after the mouse has touched a panel; the objects panel's picker and the timeline's frame menu
// pick one; each choice is one undo step; and drawing on a mouth in one frame draws on it in
// every frame showing that mouth.
#include "tst_window_support.h"

#include <finbook/model/commands.h>
#include <finbook/model/swap/mouth_chart.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/swap/swap_actions.h>
#include <finbook/ui/window/editor_state.h>
#include <finbook/ui/window/main_window.h>

#include <QComboBox>
#include <QMenu>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;

class TestSwapUi : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { m_settings = std::make_unique<IsolatedSettings>(); }
    void init();
    void cleanup() { m_window.reset(); }

    void aMouthChartSwapsByKeys();
    void thePickerAndTheFrameMenuSwap();
    void drawingOnAMouthDrawsItInEveryFrameShowingIt();

private:
    model::Document *doc() const { return m_window->document(); }
    ui::EditorState *state() const { return m_window->editorState(); }
    QAction *action(const char *name) const
    {
        return m_window->findChild<QAction *>(QString::fromLatin1(name));
    }
    const model::StrokeGroup *mouth(int frame) const
    {
        for (const model::StrokeGroup &g : doc()->frameAt(frame).groups)
            if (g.swap.linked())
                return &g;
        return nullptr;
    }
    QString shown(int frame) const
    {
        const model::StrokeGroup *g = mouth(frame);
        const model::SwapDrawing *d = g ? doc()->swapDrawing(g->swap) : nullptr;
        return d ? d->name : QString();
    }
    bool canvasHasFocus() const
    {
        return QTest::qWaitFor([this] { return QApplication::focusWidget() == m_window->canvas(); },
                               2000);
    }

    std::unique_ptr<IsolatedSettings> m_settings;
    std::unique_ptr<ui::MainWindow> m_window;
};

void TestSwapUi::init()
{
    m_window = std::make_unique<ui::MainWindow>();
    resetDocument(*doc(), 3, 1);
    addStroke(*doc(), doc()->frameAt(0).groups[0].id, line({50, 50}, {200, 120}));
    doc()->undoStack()->clear();
    QVERIFY(showActive(*m_window));
    m_window->canvas()->setFocus();
    QVERIFY(canvasHasFocus());
}

void TestSwapUi::aMouthChartSwapsByKeys()
{
    action("swap.mouthChart")->trigger();
    QCOMPARE(doc()->undoStack()->count(), 1); // one step
    // On a layer of its own, made current, one cel for the whole shot.
    QCOMPARE(doc()->layerCount(), 2);
    QCOMPARE(doc()->currentLayer().properties.name, QStringLiteral("Mouth"));
    QCOMPARE(doc()->frameCount(), 1);
    QCOMPARE(doc()->frameAt(0).hold, 3);
    QVERIFY(mouth(0));
    QCOMPARE(mouth(0)->id, state()->currentGroupId());
    // Made with the drawn object current, the mouth sits on it, two thirds down its box (the
    // line from (50, 50) to (200, 120)).
    QRectF box;
    for (const model::Stroke &s : mouth(0)->strokes)
        for (const model::StrokePoint &p : s.data->points)
            box |= QRectF(double(p.x), double(p.y), 0.001, 0.001);
    QVERIFY2(std::abs(box.center().x() - 125.0) < 2.0,
             qPrintable(QString::number(box.center().x())));
    QVERIFY2(std::abs(box.center().y() - (50.0 + 0.68 * 70.0)) < 6.0,
             qPrintable(QString::number(box.center().y())));
    QVERIFY(box.width() < 60.0);
    const model::SwapSet *set = doc()->swapSet(mouth(0)->swap.set);
    QVERIFY(set);
    QCOMPARE(set->drawings.size(), std::size_t(9));
    for (int shape = 0; shape < 9; ++shape) {
        QCOMPARE(model::mouthChartShape(set->drawings[std::size_t(shape)].name), shape);
        QVERIFY(!set->drawings[std::size_t(shape)].strokes.empty());
    }
    QCOMPARE(shown(0), model::mouthChartName(8)); // at rest
    // ] steps to the next drawing (wrapping to A), [ back.
    QTest::keyClick(m_window->canvas(), Qt::Key_BracketRight);
    QCOMPARE(shown(0), model::mouthChartName(0));
    QTest::keyClick(m_window->canvas(), Qt::Key_BracketRight);
    QCOMPARE(shown(0), model::mouthChartName(1));
    QTest::keyClick(m_window->canvas(), Qt::Key_BracketLeft);
    QCOMPARE(shown(0), model::mouthChartName(0));
    QCOMPARE(doc()->undoStack()->count(), 4);
    doc()->undoStack()->undo();
    QCOMPARE(shown(0), model::mouthChartName(1));
    // After a click on the picker, the keys still reach the window.
    auto *combo = m_window->findChild<QComboBox *>(QStringLiteral("swapPicker.combo"));
    QVERIFY(combo && combo->isVisible());
    QTest::mouseClick(combo, Qt::LeftButton);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Escape); // closes its list
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_BracketRight);
    QCOMPARE(shown(0), model::mouthChartName(2));
    // Undoing everything takes the mouth away.
    while (doc()->undoStack()->canUndo())
        doc()->undoStack()->undo();
    QVERIFY(!mouth(0));
    QVERIFY(doc()->swapSets().empty());
}

void TestSwapUi::thePickerAndTheFrameMenuSwap()
{
    action("swap.mouthChart")->trigger();
    // Frame 2 shows the same mouth (a duplicate of frame 1).
    action("frame.duplicate")->trigger();
    QTRY_COMPARE(state()->currentFrameIndex(), 1);
    QCOMPARE(shown(1), shown(0));
    auto *combo = m_window->findChild<QComboBox *>(QStringLiteral("swapPicker.combo"));
    QVERIFY(combo);
    QCOMPARE(combo->count(), 9);
    QCOMPARE(combo->currentText(), shown(1));
    combo->activated(3); // as a pick in its list does
    combo->setCurrentIndex(3);
    QCOMPARE(shown(1), model::mouthChartName(3));
    QCOMPARE(shown(0), model::mouthChartName(8)); // frame 1 keeps its own choice
    QCOMPARE(combo->currentText(), model::mouthChartName(3));
    // The frame menu's Show Drawing lists the set, the shown one checked.
    auto *swaps = m_window->findChild<ui::SwapActions *>();
    QVERIFY(swaps);
    QMenu *menu = swaps->drawingMenu();
    emit menu->aboutToShow();
    QCOMPARE(menu->actions().size(), 9);
    QVERIFY(menu->actions()[3]->isChecked());
    menu->actions()[5]->trigger();
    QCOMPARE(shown(1), model::mouthChartName(5));
    doc()->undoStack()->undo();
    QCOMPARE(shown(1), model::mouthChartName(3));
}

void TestSwapUi::drawingOnAMouthDrawsItInEveryFrameShowingIt()
{
    action("swap.mouthChart")->trigger();
    action("frame.duplicate")->trigger();
    action("frame.duplicate")->trigger();
    QTRY_COMPARE(state()->currentFrameIndex(), 2);
    // Frame 2 shows another drawing; frames 1 and 3 the rest mouth.
    state()->setCurrentFrameIndex(1);
    QTest::keyClick(m_window->canvas(), Qt::Key_BracketRight);
    QCOMPARE(shown(1), model::mouthChartName(0));
    state()->setCurrentFrameIndex(2);
    const std::size_t before = mouth(0)->strokes.size();
    // Draw on the mouth in frame 3 with the pen.
    m_window->canvas()->setCurrentTool(QStringLiteral("tool.pen"));
    state()->setCurrentGroupId(mouth(2)->id);
    dragCanvas(m_window->canvas(), QPointF(300, 300), QPointF(380, 320));
    QCOMPARE(mouth(2)->strokes.size(), before + 1);
    QCOMPARE(mouth(0)->strokes, mouth(2)->strokes); // frame 1 shows the same drawing
    QVERIFY(mouth(1)->strokes != mouth(2)->strokes);
    // Saved and opened again, the frames still share it.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("mouth.finbook"));
    QVERIFY(m_window->saveFile(path));
    QVERIFY(m_window->openFile(path));
    QCOMPARE(mouth(0)->strokes, mouth(2)->strokes);
    QCOMPARE(shown(1), model::mouthChartName(0));
}

QTEST_MAIN(TestSwapUi)
#include "tst_swap_ui.moc"
