// Keys and focus in the whole main window, driven as a person would: clicks on the real
// controls, keys sent to whatever has the keyboard. Return confirms a field and never starts
// playback; Escape cancels; after touching a toolbar or panel control the single-key tool
// shortcuts work again without clicking the canvas.
#include "tst_window_support.h"

#include <finbook/model/object_list_model.h>
#include <finbook/ui/canvas/canvas_tool.h>
#include <finbook/ui/panels/objects_panel.h>
#include <finbook/ui/timeline/playback_controller.h>
#include <finbook/ui/timeline/timeline_view.h>
#include <finbook/ui/tools/tool_pen.h>
#include <finbook/ui/window/editor_state.h>
#include <finbook/ui/window/main_window.h>

#include <QAbstractItemModel>
#include <QDoubleSpinBox>
#include <QListView>
#include <QSpinBox>
#include <QUndoView>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;

class TestKeysFocus : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { m_settings = std::make_unique<IsolatedSettings>(); }
    void init();
    void cleanup() { m_window.reset(); }

    void returnConfirmsFieldsAndNeverPlays_data();
    void returnConfirmsFieldsAndNeverPlays();
    void escapeCancelsAFieldEdit();
    void renameCommitsOnReturnAndCancelsOnEscape();
    void toolKeysWorkAfterTouchingControls();
    void typingStaysInTheFieldUntilConfirmed();
    void aToolInAGestureGetsItsKeysFirst();
    void viewTurnsByKeysAndByTheRotationField();

private:
    QString tool() const { return m_window->canvas()->currentTool()->id(); }
    bool playing() const { return m_window->editorState()->isPlaying(); }
    template <typename T> T *child(const char *name) const
    {
        return m_window->findChild<T *>(QString::fromLatin1(name));
    }
    // Waits for the canvas to get the keyboard back (the window hands it over queued).
    bool canvasHasFocus() const
    {
        return QTest::qWaitFor([this] { return QApplication::focusWidget() == m_window->canvas(); },
                               2000);
    }
    int undoCount() const { return m_window->document()->undoStack()->count(); }

    std::unique_ptr<IsolatedSettings> m_settings;
    std::unique_ptr<ui::MainWindow> m_window;
};

void TestKeysFocus::init()
{
    m_window = std::make_unique<ui::MainWindow>();
    model::Document *doc = m_window->document();
    resetDocument(*doc, 3, 2);
    for (const model::StrokeGroup &g : doc->frameAt(0).groups)
        addStroke(*doc, g.id, line({50, 50}, {200, 120}));
    doc->undoStack()->clear();
    QVERIFY(showActive(*m_window));
    m_window->canvas()->setCurrentTool(QStringLiteral("tool.pen"));
    m_window->canvas()->setFocus();
    QVERIFY(canvasHasFocus());
}

void TestKeysFocus::returnConfirmsFieldsAndNeverPlays_data()
{
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<double>("value");
    QTest::addColumn<int>("key");
    QTest::newRow("brush width") << "penWidth"
                                 << "4" << 4.0 << int(Qt::Key_Return);
    QTest::newRow("smoothing") << "penSmoothing"
                               << "5" << 5.0 << int(Qt::Key_Return);
    QTest::newRow("mesh density") << "deform.meshDensity"
                                  << "2" << 2.0 << int(Qt::Key_Return);
    QTest::newRow("onion before") << "timeline.onionBefore"
                                  << "3" << 3.0 << int(Qt::Key_Return);
    QTest::newRow("onion after, keypad Enter") << "timeline.onionAfter"
                                               << "2" << 2.0 << int(Qt::Key_Enter);
}

void TestKeysFocus::returnConfirmsFieldsAndNeverPlays()
{
    QFETCH(QString, field);
    QFETCH(QString, typed);
    QFETCH(double, value);
    QFETCH(int, key);
    auto *spin = m_window->findChild<QAbstractSpinBox *>(field);
    QVERIFY(spin);
    if (field == QLatin1String("deform.meshDensity")) // among the pins' options
        m_window->canvas()->setCurrentTool(QStringLiteral("tool.pin"));
    QVERIFY(spin->isVisible());
    clickIntoText(spin);
    QCOMPARE(QApplication::focusWidget(), spin);
    typeText(typed);
    typeKey(Qt::Key(key));
    QVERIFY2(!playing(), "Return in a field started playback");
    QCOMPARE(spin->property("value").toDouble(), value);
    // Confirmed means applied: the editor state or the document follows the field.
    if (field == QLatin1String("penWidth"))
        QCOMPARE(m_window->penTool()->settings().width, value);
    else if (field == QLatin1String("timeline.onionBefore"))
        QCOMPARE(m_window->editorState()->onionSkin().before, int(value));
    else if (field == QLatin1String("deform.meshDensity"))
        QCOMPARE(m_window->editorState()->currentGroup()->meshDensity, value);
    QVERIFY(canvasHasFocus());
    typeKey(Qt::Key_E);
    QCOMPARE(tool(), QStringLiteral("tool.eraser"));
    QVERIFY(!playing());
    // On the canvas Return still plays.
    typeKey(Qt::Key_Return);
    QVERIFY(playing());
    typeKey(Qt::Key_Return);
    QVERIFY(!playing());
}

void TestKeysFocus::escapeCancelsAFieldEdit()
{
    auto *width = child<QDoubleSpinBox>("penWidth");
    const double before = m_window->penTool()->settings().width;
    clickIntoText(width);
    typeText(QStringLiteral("12"));
    QCOMPARE(m_window->penTool()->settings().width, 12.0); // live while typing
    typeKey(Qt::Key_Escape);
    QCOMPARE(m_window->penTool()->settings().width, before);
    QCOMPARE(width->value(), before);
    QVERIFY(canvasHasFocus());
    QVERIFY(!playing());
    typeKey(Qt::Key_V);
    QCOMPARE(tool(), QStringLiteral("tool.select"));
}

void TestKeysFocus::renameCommitsOnReturnAndCancelsOnEscape()
{
    auto *panel = m_window->findChild<ui::ObjectsPanel *>();
    QListView *view = panel->view();
    const model::Id id = m_window->document()->frameAt(0).groups[0].id; // bottom row
    const int row = panel->objectModel()->rowCount() - 1;
    const QPoint at = view->visualRect(panel->objectModel()->index(row, 0)).center() -
                      QPoint(view->visualRect(panel->objectModel()->index(row, 0)).width() / 4, 0);
    const auto openEditor = [&] {
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, at);
        QTest::mouseDClick(view->viewport(), Qt::LeftButton, {}, at);
        auto *editor = view->findChild<QLineEdit *>();
        return editor && QTest::qWaitFor([editor] { return editor->hasFocus(); }, 2000) ? editor
                                                                                        : nullptr;
    };
    QLineEdit *editor = openEditor();
    QVERIFY(editor);
    typeKey(Qt::Key_A, Qt::ControlModifier);
    typeText(QStringLiteral("Arm"));
    typeKey(Qt::Key_Return);
    QVERIFY2(!playing(), "Return in the rename editor started playback");
    QTRY_COMPARE(m_window->document()->group(id)->name, QStringLiteral("Arm"));
    QCOMPARE(undoCount(), 1);
    QVERIFY(canvasHasFocus());
    typeKey(Qt::Key_H);
    QCOMPARE(tool(), QStringLiteral("tool.hand"));

    editor = openEditor();
    QVERIFY(editor);
    typeKey(Qt::Key_A, Qt::ControlModifier);
    typeText(QStringLiteral("Leg"));
    typeKey(Qt::Key_Escape);
    QVERIFY(canvasHasFocus());
    QCOMPARE(m_window->document()->group(id)->name, QStringLiteral("Arm"));
    QCOMPARE(undoCount(), 1);
    typeKey(Qt::Key_B);
    QCOMPARE(tool(), QStringLiteral("tool.pen"));
}

void TestKeysFocus::toolKeysWorkAfterTouchingControls()
{
    // The brush width's arrows.
    auto *width = child<QDoubleSpinBox>("penWidth");
    const double before = width->value();
    clickSpinArrow(width);
    QCOMPARE(width->value(), before + width->singleStep());
    QVERIFY(canvasHasFocus());
    typeKey(Qt::Key_E);
    QCOMPARE(tool(), QStringLiteral("tool.eraser"));

    // The onion-skin count in the timeline, then the mesh density on the Deform toolbar.
    const int onionBefore = m_window->editorState()->onionSkin().before;
    clickSpinArrow(child<QSpinBox>("timeline.onionBefore"));
    QCOMPARE(m_window->editorState()->onionSkin().before, onionBefore + 1);
    QVERIFY(canvasHasFocus());
    typeKey(Qt::Key_P); // the mesh density is among the pins' options
    QCOMPARE(tool(), QStringLiteral("tool.pin"));
    clickSpinArrow(child<QDoubleSpinBox>("deform.meshDensity"));
    QVERIFY(canvasHasFocus());
    typeKey(Qt::Key_H);
    QCOMPARE(tool(), QStringLiteral("tool.hand"));

    // A row of the objects list.
    auto *panel = m_window->findChild<ui::ObjectsPanel *>();
    const QRect row = panel->view()->visualRect(panel->objectModel()->index(1, 0));
    QTest::mouseClick(panel->view()->viewport(), Qt::LeftButton, {},
                      QPoint(row.left() + 20, row.center().y()));
    QCOMPARE(m_window->editorState()->currentGroupId(),
             m_window->document()->frameAt(0).groups[0].id);
    QVERIFY(canvasHasFocus());
    typeKey(Qt::Key_P);
    QCOMPARE(tool(), QStringLiteral("tool.pin"));

    // A frame in the timeline; then the frame keys step from there.
    auto *timeline = m_window->findChild<ui::TimelineView *>();
    QTest::mouseClick(timeline->viewport(), Qt::LeftButton, {},
                      timeline->thumbnailRect(1).center());
    QCOMPARE(m_window->editorState()->currentFrameIndex(), 1);
    QVERIFY(canvasHasFocus());
    typeKey(Qt::Key_B);
    QCOMPARE(tool(), QStringLiteral("tool.pen"));
    typeKey(Qt::Key_Period);
    QCOMPARE(m_window->editorState()->currentFrameIndex(), 2);
    typeKey(Qt::Key_Comma);
    QCOMPARE(m_window->editorState()->currentFrameIndex(), 1);

    // A line of the undo history.
    dragCanvas(m_window->canvas(), {60, 60}, {160, 90});
    auto *history = m_window->findChild<QUndoView *>();
    QTest::mouseClick(history->viewport(), Qt::LeftButton, {},
                      history->visualRect(history->model()->index(0, 0)).center());
    QCOMPARE(m_window->document()->undoStack()->index(),
             0); // the mesh density and the stroke undone
    QVERIFY(canvasHasFocus());
    const bool onion = m_window->editorState()->onionSkin().enabled;
    typeKey(Qt::Key_O);
    QCOMPARE(m_window->editorState()->onionSkin().enabled, !onion);
}

void TestKeysFocus::typingStaysInTheFieldUntilConfirmed()
{
    m_window->action(QStringLiteral("edit.selectAll"))->trigger();
    const std::size_t selected = m_window->editorState()->selectedStrokes().size();
    QCOMPARE(selected, std::size_t(2));
    auto *width = child<QDoubleSpinBox>("penWidth");
    clickIntoText(width);
    // '.' is part of the number, a letter is refused by the field, Backspace edits the text:
    // none of them reaches the window's shortcuts (next frame, eraser, delete strokes).
    typeText(QStringLiteral("2.5"));
    QCOMPARE(width->cleanText(), QStringLiteral("2.5")); // not reformatted while typing
    typeKey(Qt::Key_E);
    typeKey(Qt::Key_Backspace);
    typeText(QStringLiteral("5"));
    QCOMPARE(QApplication::focusWidget(), width);
    QCOMPARE(m_window->editorState()->currentFrameIndex(), 0);
    QCOMPARE(tool(), QStringLiteral("tool.select"));
    QCOMPARE(m_window->editorState()->selectedStrokes().size(), selected);
    int strokes = 0;
    for (const model::StrokeGroup &g : m_window->document()->frameAt(0).groups)
        strokes += int(g.strokes.size());
    QCOMPARE(strokes, 2);
    typeKey(Qt::Key_Return);
    QCOMPARE(m_window->penTool()->settings().width, 2.5);
    QVERIFY(canvasHasFocus());
    typeKey(Qt::Key_Backspace); // on the canvas Backspace deletes the selection
    QVERIFY(m_window->editorState()->selectedStrokes().empty());
}

// Issue 22, bug 1: Return while placing a cage closed the cage only on the keypad; the main
// Return started playback (Play's window-wide shortcut fires before the tool). A tool in the
// middle of a gesture gets Return, Escape, Backspace and Delete first.
void TestKeysFocus::aToolInAGestureGetsItsKeysFirst()
{
    ui::CanvasWidget *canvas = m_window->canvas();
    const model::Id object = m_window->document()->frameAt(0).groups[0].id;
    m_window->editorState()->setCurrentGroupId(object);
    typeKey(Qt::Key_C);
    QCOMPARE(tool(), QStringLiteral("tool.cage"));
    const auto click = [canvas](QPointF p) {
        QTest::mouseClick(canvas, Qt::LeftButton, {}, canvas->mapFromCanvas(p).toPoint());
    };
    // Both objects' lines run from (50, 50) to (200, 120): a cage around them, with a stray
    // corner that Backspace and Delete take back.
    for (QPointF p : {QPointF(30, 30), QPointF(220, 30), QPointF(220, 140), QPointF(30, 140),
                      QPointF(10, 200), QPointF(10, 210)})
        click(p);
    QVERIFY(canvasHasFocus());
    typeKey(Qt::Key_Backspace);
    typeKey(Qt::Key_Delete);
    QCOMPARE(m_window->document()->frameAt(0).groups[1].strokes.size(), std::size_t(1));
    typeKey(Qt::Key_Return);
    QVERIFY2(!playing(), "Return while placing a cage started playback");
    const model::StrokeGroup *g = m_window->document()->group(object);
    QCOMPARE(g->rig.kind(), model::RigKind::Cage);
    QCOMPARE(g->rig.cage.rest.size(), std::size_t(4));
    // With no gesture under way Return is Play again.
    typeKey(Qt::Key_Return);
    QVERIFY(playing());
    typeKey(Qt::Key_Return);
    QVERIFY(!playing());
    // Escape cancels a cage being placed (around the other object), Return then plays.
    m_window->editorState()->setCurrentGroupId(m_window->document()->frameAt(0).groups[1].id);
    click({30, 30});
    click({220, 30});
    typeKey(Qt::Key_Escape);
    QVERIFY(!playing());
    typeKey(Qt::Key_Return);
    QVERIFY(playing());
}

// 4 and 6 turn the view by 15°, 5 resets it, Shift+M mirrors it, from the canvas and after a
// click on a panel; the status bar's Rotation field shows the turn and takes a typed one.
void TestKeysFocus::viewTurnsByKeysAndByTheRotationField()
{
    ui::CanvasWidget *canvas = m_window->canvas();
    auto *field = child<QDoubleSpinBox>("viewRotation");
    QVERIFY(field);
    typeKey(Qt::Key_6);
    typeKey(Qt::Key_6);
    QCOMPARE(canvas->rotation(), 30.0);
    QCOMPARE(field->value(), 30.0);
    typeKey(Qt::Key_4);
    QCOMPARE(canvas->rotation(), 15.0);
    typeKey(Qt::Key_M, Qt::ShiftModifier);
    QVERIFY(canvas->isMirrored());
    QCOMPARE(canvas->rotation(), -15.0);
    QCOMPARE(field->value(), -15.0);
    // After the mouse has touched a panel, the keys still reach the canvas's view.
    clickSpinArrow(child<QSpinBox>("timeline.onionBefore"));
    QVERIFY(canvasHasFocus());
    typeKey(Qt::Key_5);
    QCOMPARE(canvas->rotation(), 0.0);
    typeKey(Qt::Key_M, Qt::ShiftModifier);
    QVERIFY(!canvas->isMirrored());
    // A typed turn; Return hands the keyboard back to the canvas.
    clickIntoText(field);
    typeText(QStringLiteral("-100"));
    typeKey(Qt::Key_Return);
    QCOMPARE(canvas->rotation(), -100.0);
    QVERIFY(canvasHasFocus());
    typeKey(Qt::Key_4);
    QCOMPARE(canvas->rotation(), -115.0);
    QCOMPARE(undoCount(), 0); // the view is not the document
}

QTEST_MAIN(TestKeysFocus)
#include "tst_keys_focus.moc"
