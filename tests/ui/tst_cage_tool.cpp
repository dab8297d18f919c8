// The Cage tool and Fit Cage driven by real mouse and key events on the real canvas.
#include <finbook/model/cage/cage_commands.h>
#include <finbook/model/cage/cage_setup.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/pins/pin_commands.h>
#include <finbook/ui/cage/cage_actions.h>
#include <finbook/ui/cage/tool_cage.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/rig/deform_actions.h>
#include <finbook/ui/window/editor_state.h>

#include <QAbstractButton>
#include <QMessageBox>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>

#include <cmath>

using namespace finbook;
using namespace finbook::model;
using namespace finbook::ui;

namespace {

StrokeDataPtr bar(float y)
{
    auto data = std::make_shared<StrokeData>();
    for (int i = 0; i <= 100; ++i)
        data->points.push_back(
            {200.0f + 4.0f * float(i), y + 3.0f * std::sin(float(i) * 0.3f), 1.0f});
    data->width = 6.0f;
    return data;
}

struct Fixture {
    Document doc;
    EditorState state{&doc};
    DeformActions actions{&state};
    CanvasWidget canvas{&state};
    CageTool *tool = nullptr;
    CageActions *cage = nullptr;
    Id group = kNoId;

    Fixture()
    {
        Frame f;
        f.id = doc.allocateId();
        StrokeGroup g;
        g.id = doc.allocateId();
        g.name = QStringLiteral("arm");
        g.strokes.push_back({doc.allocateId(), bar(300)});
        g.strokes.push_back({doc.allocateId(), bar(306)});
        f.groups.push_back(g);
        group = g.id;
        DocumentSettings s;
        s.canvasSize = QSize(800, 600);
        doc.reset({f}, s, doc.nextId());
        state.setCurrentGroupId(group);
        tool = static_cast<CageTool *>(
            canvas.addTool(std::make_unique<CageTool>(actions.controller())));
        cage = new CageActions(&state, actions.controller(), tool, &canvas);
        canvas.setCurrentTool(tool->id());
        canvas.resize(800, 600);
        canvas.show();
        canvas.fitToView();
    }

    QPoint at(QPointF canvasPos) const { return canvas.mapFromCanvas(canvasPos).toPoint(); }
    const StrokeGroup &object() const { return *doc.group(group); }
    void click(QPointF p) { QTest::mouseClick(&canvas, Qt::LeftButton, {}, at(p)); }

    void drag(QPointF from, QPointF to, Qt::KeyboardModifiers mods = Qt::NoModifier)
    {
        QTest::mousePress(&canvas, Qt::LeftButton, mods, at(from));
        for (int i = 1; i <= 10; ++i) {
            const QPointF p = from + (to - from) * (i / 10.0);
            QMouseEvent move(QEvent::MouseMove, at(p), canvas.mapToGlobal(at(p)), Qt::NoButton,
                             Qt::LeftButton, mods);
            QApplication::sendEvent(&canvas, &move);
        }
        QTest::mouseRelease(&canvas, Qt::LeftButton, mods, at(to));
    }

    bool waitReady()
    {
        return QTest::qWaitFor(
            [this] {
                return actions.controller()->setup(group) &&
                       !actions.controller()->isWaiting(group) && object().isDeformed();
            },
            10000);
    }
};

// Mouse positions go through whole widget pixels: canvas positions agree to a pixel.
bool near(QPointF a, QPointF b)
{
    return QLineF(a, b).length() < 1.0;
}

// Answers the next "discard the pose?" question.
void answerNextPrompt(QMessageBox::StandardButton button)
{
    QTimer::singleShot(0, [button] {
        for (QWidget *w : QApplication::topLevelWidgets())
            if (auto *box = qobject_cast<QMessageBox *>(w);
                box && box->objectName() == QStringLiteral("discardPosePrompt"))
                box->button(button)->click();
    });
}

} // namespace

class TestCageTool : public QObject {
    Q_OBJECT
private slots:
    void clicksAndReturnPlaceACage();
    void escapeCancelsAndTooSmallIsRefused();
    void dragCornerIsOneUndoStep();
    void rubberBandMovesSeveralCorners();
    void editShapeMovesTheRestCage();
    void fitCageWrapsTheObject();
    void replacingPosedPinsAsksFirst();
    void removingAPosedRigSaysRemoving();
    void aNewCageStartsWithNothingSelected();
};

void TestCageTool::clicksAndReturnPlaceACage()
{
    Fixture fx;
    for (QPointF p : {QPointF(180, 270), QPointF(620, 270), QPointF(620, 340)})
        fx.click(p);
    QCOMPARE(fx.tool->pendingCage().size(), std::size_t(3));
    fx.click({180, 340});
    QTest::keyClick(&fx.canvas, Qt::Key_Return);
    QCOMPARE(fx.object().rig.kind(), RigKind::Cage);
    QCOMPARE(fx.object().rig.cage.rest.size(), std::size_t(4));
    QVERIFY(fx.tool->pendingCage().empty());
    QCOMPARE(fx.doc.undoStack()->count(), 1);
    QVERIFY(fx.waitReady());
    // Closing on the first point works too (after undoing the first cage).
    fx.doc.undoStack()->undo();
    for (QPointF p : {QPointF(180, 270), QPointF(620, 270), QPointF(620, 340), QPointF(180, 340),
                      QPointF(180, 270)})
        fx.click(p);
    QCOMPARE(fx.object().rig.cage.rest.size(), std::size_t(4));
}

void TestCageTool::escapeCancelsAndTooSmallIsRefused()
{
    Fixture fx;
    fx.click({180, 270});
    fx.click({620, 270});
    QTest::keyClick(&fx.canvas, Qt::Key_Escape);
    QVERIFY(fx.tool->pendingCage().empty());
    // A cage that leaves the right half of the drawing out is refused; nothing changes.
    for (QPointF p : {QPointF(180, 270), QPointF(400, 270), QPointF(400, 340), QPointF(180, 340)})
        fx.click(p);
    QTest::keyClick(&fx.canvas, Qt::Key_Return);
    QVERIFY(fx.object().rig.empty());
    QCOMPARE(fx.doc.undoStack()->count(), 0);
}

void TestCageTool::dragCornerIsOneUndoStep()
{
    Fixture fx;
    for (QPointF p : {QPointF(180, 270), QPointF(620, 270), QPointF(620, 340), QPointF(180, 340)})
        fx.click(p);
    QTest::keyClick(&fx.canvas, Qt::Key_Return);
    QVERIFY(fx.waitReady());
    const QByteArray placed = serializeFinbook(fx.doc);
    fx.drag({620, 270}, {680, 220});
    fx.drag({620, 340}, {680, 290});
    QCOMPARE(fx.doc.undoStack()->count(), 3);
    QVERIFY(near(fx.object().rig.cage.posed[1], QPointF(680, 220)));
    QTRY_VERIFY(fx.object().isDeformed());
    // The right end moved up and right with its corners; the left end stayed.
    const auto &pose = fx.object().deformed->strokes[0];
    const auto &rest = fx.object().strokes[0].data->points;
    QVERIFY(pose.back().x > rest.back().x + 30);
    QVERIFY(std::abs(pose.front().y - rest.front().y) < 10);
    fx.doc.undoStack()->undo();
    fx.doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(fx.doc), placed);
}

void TestCageTool::rubberBandMovesSeveralCorners()
{
    Fixture fx;
    for (QPointF p : {QPointF(180, 270), QPointF(620, 270), QPointF(620, 340), QPointF(180, 340)})
        fx.click(p);
    QTest::keyClick(&fx.canvas, Qt::Key_Return);
    fx.drag({600, 200}, {700, 400}); // a box around the two right corners
    QCOMPARE(fx.tool->selectedCorners(), (std::set<int>{1, 2}));
    fx.drag({620, 270}, {650, 285}, Qt::ShiftModifier); // Shift: horizontal only
    QVERIFY(near(fx.object().rig.cage.posed[1], QPointF(650, 270)));
    QVERIFY(near(fx.object().rig.cage.posed[2], QPointF(650, 340)));
    QCOMPARE(fx.object().rig.cage.posed[1].y(), fx.object().rig.cage.rest[1].y());
    QCOMPARE(fx.object().rig.cage.posed[0], fx.object().rig.cage.rest[0]);
}

void TestCageTool::editShapeMovesTheRestCage()
{
    Fixture fx;
    for (QPointF p : {QPointF(180, 270), QPointF(620, 270), QPointF(620, 340), QPointF(180, 340)})
        fx.click(p);
    QTest::keyClick(&fx.canvas, Qt::Key_Return);
    fx.cage->editShapeAction()->trigger();
    QVERIFY(fx.tool->editingShape());
    fx.drag({180, 340}, {160, 380});
    QVERIFY(near(fx.object().rig.cage.rest[3], QPointF(160, 380)));
    QCOMPARE(fx.object().rig.cage.posed[3], fx.object().rig.cage.rest[3]);
    QVERIFY(!fx.object().rig.isPosed());
    // Alt-click on an edge inserts a corner there; right-click deletes it again.
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, Qt::AltModifier, fx.at({400, 270}));
    QCOMPARE(fx.object().rig.cage.rest.size(), std::size_t(5));
    QVERIFY(near(fx.object().rig.cage.rest[1], QPointF(400, 270)));
    QTest::mouseClick(&fx.canvas, Qt::RightButton, {}, fx.at({400, 270}));
    QCOMPARE(fx.object().rig.cage.rest.size(), std::size_t(4));
    // Deleting a corner that would leave part of the drawing outside is refused.
    QTest::mouseClick(&fx.canvas, Qt::RightButton, {}, fx.at({620, 340}));
    QCOMPARE(fx.object().rig.cage.rest.size(), std::size_t(4));
}

void TestCageTool::fitCageWrapsTheObject()
{
    Fixture fx;
    fx.cage->setFitCorners(10);
    fx.cage->fitAction()->trigger();
    QCOMPARE(fx.object().rig.kind(), RigKind::Cage);
    const std::size_t corners = fx.object().rig.cage.rest.size();
    QVERIFY2(corners >= 3 && corners <= 14, qPrintable(QString::number(corners)));
    QVERIFY(!cageProblem(fx.object(), fx.object().rig.cage.rest));
    QVERIFY(fx.waitReady());
}

void TestCageTool::replacingPosedPinsAsksFirst()
{
    Fixture fx;
    auto *stack = fx.doc.undoStack();
    stack->push(new AddPinCommand(&fx.doc, fx.group, {200, 300}, {200, 300}));
    stack->push(new AddPinCommand(&fx.doc, fx.group, {600, 300}, {600, 300}));
    const Id tip = fx.object().rig.pins[1].id;
    stack->push(new MovePinCommand(&fx.doc, fx.group, tip, {580, 360}, 1));
    QVERIFY(fx.object().rig.isPosed());
    answerNextPrompt(QMessageBox::Cancel);
    fx.cage->fitAction()->trigger();
    QCOMPARE(fx.object().rig.kind(), RigKind::Pins); // kept
    answerNextPrompt(QMessageBox::Discard);
    fx.cage->fitAction()->trigger();
    QCOMPARE(fx.object().rig.kind(), RigKind::Cage);
    stack->undo();
    QCOMPARE(fx.object().rig.kind(), RigKind::Pins);
    QCOMPARE(fx.object().rig.pins[1].target, QPointF(580, 360));
}

// Issue 45: Remove Rig on a posed object asked about replacing its rig.
void TestCageTool::removingAPosedRigSaysRemoving()
{
    Fixture fx;
    auto *stack = fx.doc.undoStack();
    stack->push(new AddPinCommand(&fx.doc, fx.group, {200, 300}, {200, 300}));
    stack->push(new AddPinCommand(&fx.doc, fx.group, {600, 300}, {600, 300}));
    stack->push(new MovePinCommand(&fx.doc, fx.group, fx.object().rig.pins[1].id, {580, 360}, 1));
    QString question;
    QTimer::singleShot(0, [&question] {
        for (QWidget *w : QApplication::topLevelWidgets())
            if (auto *box = qobject_cast<QMessageBox *>(w);
                box && box->objectName() == QStringLiteral("discardPosePrompt")) {
                question = box->text();
                box->button(QMessageBox::Discard)->click();
            }
    });
    fx.actions.removePinsAction()->trigger();
    QVERIFY2(question.contains(QStringLiteral("Removing its rig")), qPrintable(question));
    QVERIFY(!question.contains(QStringLiteral("Replacing")));
    QCOMPARE(fx.object().rig.kind(), RigKind::None);
    stack->undo();
    QCOMPARE(fx.object().rig.kind(), RigKind::Pins);
}

// Issue 22, bug 3: after Remove Rig a new cage came up with the old cage's corners selected,
// and dragging one moved them all.
void TestCageTool::aNewCageStartsWithNothingSelected()
{
    Fixture fx;
    const std::vector<QPointF> corners{{180, 270}, {400, 250}, {620, 270}, {620, 340}, {180, 340}};
    for (QPointF p : corners)
        fx.click(p);
    QTest::keyClick(&fx.canvas, Qt::Key_Return);
    fx.drag({160, 200}, {700, 400}); // a box around every corner
    QCOMPARE(fx.tool->selectedCorners().size(), std::size_t(5));
    fx.doc.undoStack()->push(new RemoveRigCommand(&fx.doc, fx.group));
    QVERIFY(fx.object().rig.empty());
    for (QPointF p : corners)
        fx.click(p);
    QTest::keyClick(&fx.canvas, Qt::Key_Return);
    QCOMPARE(fx.object().rig.cage.rest.size(), std::size_t(5));
    QVERIFY(fx.tool->selectedCorners().empty());
    fx.drag({620, 270}, {650, 250});
    const CageRig &cage = fx.object().rig.cage;
    QVERIFY(near(cage.posed[2], QPointF(650, 250)));
    for (std::size_t i : {0, 1, 3, 4})
        QCOMPARE(cage.posed[i], cage.rest[i]);
}

QTEST_MAIN(TestCageTool)
#include "tst_cage_tool.moc"
