// The objects panel and its actions edit the current frame's objects through commands:
// create, rename (double-click), reorder, hide, lock, merge and move strokes, each undone to
// exactly the frame it started from. Driven through the real widgets where a user would click.
#include <finbook/model/commands.h>
#include <finbook/model/object_list_model.h>
#include <finbook/model/picture/picture_commands.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/ui/panels/object_actions.h>
#include <finbook/ui/panels/objects_panel.h>
#include <finbook/ui/window/editor_state.h>

#include <QDir>
#include <QLineEdit>
#include <QListView>
#include <QMenu>
#include <QMimeData>
#include <QSignalSpy>
#include <QTest>
#include <QToolButton>

#include <memory>

using namespace finbook;
using model::Document;
using model::Id;

namespace {

model::StrokeDataPtr line(float x, float y)
{
    auto data = std::make_shared<model::StrokeData>();
    data->points = {{x, y, 1.0f}, {x + 30, y + 10, 0.5f}, {x + 60, y, 0.8f}};
    return data;
}

// Deep equality of a frame's objects: ids, names, flags, strokes (ids and points), order.
bool sameFrame(const model::Frame &a, const model::Frame &b)
{
    if (a.id != b.id || a.hold != b.hold || a.groups.size() != b.groups.size())
        return false;
    for (std::size_t i = 0; i < a.groups.size(); ++i) {
        const model::StrokeGroup &x = a.groups[i];
        const model::StrokeGroup &y = b.groups[i];
        if (x.id != y.id || x.name != y.name || x.visible != y.visible || x.locked != y.locked ||
            x.strokes != y.strokes || x.rig.pins != y.rig.pins)
            return false;
    }
    return true;
}

struct Fixture {
    Document doc;
    std::unique_ptr<ui::EditorState> state;
    std::unique_ptr<ui::ObjectActions> actions;
    std::unique_ptr<ui::ObjectsPanel> panel;
    std::vector<Id> groups;  // bottom to top, in frame 0
    std::vector<Id> strokes; // two per object

    // Frame 0 holds objects "A" (bottom), "B", "C" (top) with two strokes each; frame 1 one.
    Fixture()
    {
        QUndoStack *stack = doc.undoStack();
        stack->push(new model::InsertFrameCommand(&doc, 0));
        stack->push(new model::InsertFrameCommand(&doc, 1));
        const Id frame = doc.frameAt(0).id;
        groups.push_back(doc.frameAt(0).groups[0].id);
        stack->push(new model::RenameObjectCommand(&doc, groups[0], QStringLiteral("A")));
        for (const char *name : {"B", "C"}) {
            auto *add = new model::AddObjectCommand(&doc, frame, -1, QString::fromLatin1(name));
            stack->push(add);
            groups.push_back(add->groupId());
        }
        for (std::size_t g = 0; g < groups.size(); ++g)
            for (int s = 0; s < 2; ++s) {
                auto *add = new model::AddStrokeCommand(&doc, groups[g],
                                                        line(float(g * 100), float(s * 50)));
                stack->push(add);
                strokes.push_back(add->strokeId());
            }
        stack->clear();
        state = std::make_unique<ui::EditorState>(&doc);
        actions = std::make_unique<ui::ObjectActions>(state.get());
        panel = std::make_unique<ui::ObjectsPanel>(state.get(), actions.get());
        panel->resize(280, 300);
        panel->show();
        QVERIFY(QTest::qWaitForWindowExposed(panel.get()));
    }
    QListView *view() const { return panel->view(); }
    QWidget *viewport() const { return panel->view()->viewport(); }
    QPoint rowCenter(int row) const
    {
        const QRect r = view()->visualRect(panel->objectModel()->index(row));
        return QPoint(r.left() + 30, r.center().y());
    }
    void undoAll()
    {
        while (doc.undoStack()->canUndo())
            doc.undoStack()->undo();
    }
};

} // namespace

class TestObjects : public QObject {
    Q_OBJECT
private slots:
    void listsTheCurrentFrameTopFirst();
    void currentObjectIsTwoWay();
    void createAboveCurrentAndUndo();
    void renameByDoubleClick();
    void hideAndLockByClickingToggles();
    void reorderWithActionsAndDrop();
    void mergeDownKeepsOrderAndUndoesExactly();
    void mergeSelectedIsOneUndoStep();
    void mergeRefusedWhereLinesWouldCoverAPicture();
    void moveSelectedStrokesToAnotherObject();
    void deleteKeepsOneObject();
    void grabScreenshot();
};

void TestObjects::listsTheCurrentFrameTopFirst()
{
    Fixture f;
    model::ObjectListModel *m = f.panel->objectModel();
    QCOMPARE(m->rowCount(), 3);
    QCOMPARE(m->index(0).data().toString(), QStringLiteral("C"));
    QCOMPARE(m->index(2).data().toString(), QStringLiteral("A"));
    f.state->setCurrentFrameIndex(1);
    QCOMPARE(m->rowCount(), 1);
    QCOMPARE(m->frameId(), f.doc.frameAt(1).id);
    f.state->setCurrentFrameIndex(0);
    QCOMPARE(m->rowCount(), 3);
}

void TestObjects::currentObjectIsTwoWay()
{
    Fixture f;
    QCOMPARE(f.state->currentGroupId(), f.groups[2]); // the top one by default
    QCOMPARE(f.view()->currentIndex().row(), 0);
    QTest::mouseClick(f.viewport(), Qt::LeftButton, {}, f.rowCenter(2));
    QCOMPARE(f.state->currentGroupId(), f.groups[0]);
    f.state->setCurrentGroupId(f.groups[1]);
    QCOMPARE(f.view()->currentIndex().row(), 1);
    QCOMPARE(f.view()->selectionModel()->selectedRows().size(), 1);
    QCOMPARE(f.doc.undoStack()->count(), 0);
}

void TestObjects::createAboveCurrentAndUndo()
{
    Fixture f;
    const model::Frame before = f.doc.frameAt(0);
    f.state->setCurrentGroupId(f.groups[0]);
    QCOMPARE(f.actions->newObject()->objectName(), QStringLiteral("object.new"));
    QWidget *button = f.panel->button(f.actions->newObject());
    QVERIFY(button);
    QTest::mouseClick(button, Qt::LeftButton);
    const model::Frame &after = f.doc.frameAt(0);
    QCOMPARE(after.groups.size(), std::size_t(4));
    const Id created = after.groups[1].id; // right above A
    QCOMPARE(f.state->currentGroupId(), created);
    QCOMPARE(after.groups[1].name, QStringLiteral("Object 4"));
    QCOMPARE(f.panel->objectModel()->groupId(f.view()->currentIndex().row()), created);
    f.doc.undoStack()->undo();
    QVERIFY(sameFrame(f.doc.frameAt(0), before));
}

void TestObjects::renameByDoubleClick()
{
    Fixture f;
    const model::Frame before = f.doc.frameAt(0);
    // What a window system sends for a double click: a click, then the double-click event.
    QTest::mouseClick(f.viewport(), Qt::LeftButton, {}, f.rowCenter(1));
    QTest::mouseDClick(f.viewport(), Qt::LeftButton, {}, f.rowCenter(1));
    auto *editor = f.view()->findChild<QLineEdit *>();
    QVERIFY(editor);
    QTRY_VERIFY(editor->isVisible());
    QCOMPARE(editor->text(), QStringLiteral("B"));
    QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(editor, QStringLiteral("Arm"));
    QTest::keyClick(editor, Qt::Key_Return);
    // The delegate commits on the next event-loop turn.
    QTRY_COMPARE(f.doc.group(f.groups[1])->name, QStringLiteral("Arm"));
    QCOMPARE(f.doc.undoStack()->count(), 1);
    QCOMPARE(f.panel->objectModel()->index(1).data().toString(), QStringLiteral("Arm"));
    f.doc.undoStack()->undo();
    QVERIFY(sameFrame(f.doc.frameAt(0), before));
}

void TestObjects::hideAndLockByClickingToggles()
{
    Fixture f;
    const model::Frame before = f.doc.frameAt(0);
    QTest::mouseClick(f.viewport(), Qt::LeftButton, {}, f.panel->visibilityToggleRect(0).center());
    QVERIFY(!f.doc.group(f.groups[2])->visible);
    QTest::mouseClick(f.viewport(), Qt::LeftButton, {}, f.panel->lockToggleRect(2).center());
    QVERIFY(f.doc.group(f.groups[0])->locked);
    QCOMPARE(f.doc.undoStack()->count(), 2);
    // The toggle actions act on the current object and follow it.
    f.state->setCurrentGroupId(f.groups[0]);
    QVERIFY(f.actions->toggleLocked()->isChecked());
    f.actions->toggleLocked()->trigger();
    QVERIFY(!f.doc.group(f.groups[0])->locked);
    f.undoAll();
    QVERIFY(sameFrame(f.doc.frameAt(0), before));
}

void TestObjects::reorderWithActionsAndDrop()
{
    Fixture f;
    const model::Frame before = f.doc.frameAt(0);
    f.state->setCurrentGroupId(f.groups[0]);
    QVERIFY(!f.actions->lower()->isEnabled());
    f.actions->raise()->trigger();
    QCOMPARE(f.doc.frameAt(0).groups[1].id, f.groups[0]);
    QCOMPARE(f.view()->currentIndex().row(), 1); // the selection follows the object
    // A drop on the panel's model: C (top) dragged below A.
    model::ObjectListModel *m = f.panel->objectModel();
    std::unique_ptr<QMimeData> mime(m->mimeData({m->index(0)}));
    QVERIFY(m->dropMimeData(mime.get(), Qt::MoveAction, 3, 0, {}));
    QCOMPARE(f.doc.frameAt(0).groups[0].id, f.groups[2]);
    QCOMPARE(f.doc.undoStack()->count(), 2);
    f.undoAll();
    QVERIFY(sameFrame(f.doc.frameAt(0), before));
}

void TestObjects::mergeDownKeepsOrderAndUndoesExactly()
{
    Fixture f;
    const model::Frame before = f.doc.frameAt(0);
    f.state->setCurrentGroupId(f.groups[2]); // C into B
    f.actions->merge()->trigger();
    const model::Frame &merged = f.doc.frameAt(0);
    QCOMPARE(merged.groups.size(), std::size_t(2));
    QCOMPARE(merged.groups[1].id, f.groups[1]);
    std::vector<Id> ids;
    for (const model::Stroke &s : merged.groups[1].strokes)
        ids.push_back(s.id);
    QCOMPARE(ids, (std::vector<Id>{f.strokes[2], f.strokes[3], f.strokes[4], f.strokes[5]}));
    QCOMPARE(f.state->currentGroupId(), f.groups[1]);
    QCOMPARE(f.panel->objectModel()->rowCount(), 2);
    f.doc.undoStack()->undo();
    QVERIFY(sameFrame(f.doc.frameAt(0), before));
    QCOMPARE(f.panel->objectModel()->rowCount(), 3);
    f.state->setCurrentGroupId(f.groups[0]);
    QVERIFY(!f.actions->merge()->isEnabled()); // nothing below the bottom object
}

void TestObjects::mergeSelectedIsOneUndoStep()
{
    Fixture f;
    const model::Frame before = f.doc.frameAt(0);
    // Select C, then Ctrl-click A: merge both into A (the lowest), B stays between.
    QTest::mouseClick(f.viewport(), Qt::LeftButton, {}, f.rowCenter(0));
    QTest::mouseClick(f.viewport(), Qt::LeftButton, Qt::ControlModifier, f.rowCenter(2));
    QCOMPARE(f.actions->objectSelection().size(), std::size_t(2));
    f.actions->merge()->trigger();
    const model::Frame &merged = f.doc.frameAt(0);
    QCOMPARE(merged.groups.size(), std::size_t(2));
    QCOMPARE(merged.groups[0].id, f.groups[0]);
    QCOMPARE(merged.groups[0].strokes.size(), std::size_t(4));
    QCOMPARE(merged.groups[0].strokes.back().id, f.strokes[5]);
    QCOMPARE(f.doc.undoStack()->count(), 1);
    f.doc.undoStack()->undo();
    QVERIFY(sameFrame(f.doc.frameAt(0), before));
    f.doc.undoStack()->redo();
    QCOMPARE(f.doc.frameAt(0).groups.size(), std::size_t(2));
}

void TestObjects::mergeRefusedWhereLinesWouldCoverAPicture()
{
    Fixture f;
    QImage pixels(40, 30, QImage::Format_ARGB32_Premultiplied);
    pixels.fill(QColor(200, 60, 20));
    auto picture = model::makePictureObject(model::PictureLayer{QStringLiteral("P"), pixels, {}},
                                            QPointF(20, 10));
    QVERIFY(picture.hasValue());
    const Id frame = f.doc.frameAt(0).id;
    auto *import = new model::ImportPictureCommand(&f.doc, frame, -1, {*picture});
    f.doc.undoStack()->push(import);
    const Id pictureObject = import->objectIds().front();
    f.doc.undoStack()->clear(); // deletes the command
    const model::Frame before = f.doc.frameAt(0);
    // The picture (on top) merged down into C, whose lines it covers: refused, with a reason.
    f.state->setCurrentGroupId(pictureObject);
    QSignalSpy message(f.actions.get(), &ui::ObjectActions::message);
    f.actions->merge()->trigger();
    QCOMPARE(message.count(), 1);
    QVERIFY(message.front().front().toString().contains(QStringLiteral("“C”")));
    QCOMPARE(f.doc.undoStack()->count(), 0);
    QVERIFY(sameFrame(f.doc.frameAt(0), before));
    QVERIFY(f.doc.frameAt(0).groups.back().picture == before.groups.back().picture);
}

void TestObjects::moveSelectedStrokesToAnotherObject()
{
    Fixture f;
    const model::Frame before = f.doc.frameAt(0);
    QVERIFY(!f.actions->moveSelection()->isEnabled());
    f.state->setSelectedStrokes({f.strokes[0], f.strokes[3]}); // one of A, one of B
    QVERIFY(f.actions->moveSelection()->isEnabled());
    f.actions->refreshTargets();
    QMenu *menu = f.actions->targetMenu();
    QCOMPARE(menu->actions().size(), 3); // strokes from two objects: all three are targets
    QAction *toC = nullptr;
    for (QAction *a : menu->actions())
        if (Id(a->data().toULongLong()) == f.groups[2])
            toC = a;
    QVERIFY(toC);
    QCOMPARE(toC->text(), QStringLiteral("C"));
    toC->trigger();
    const model::StrokeGroup *c = f.doc.group(f.groups[2]);
    QCOMPARE(c->strokes.size(), std::size_t(4));
    QCOMPARE(c->strokes[2].id, f.strokes[0]);
    QCOMPARE(c->strokes[3].id, f.strokes[3]);
    QCOMPARE(f.doc.group(f.groups[0])->strokes.size(), std::size_t(1));
    QCOMPARE(f.state->currentGroupId(), f.groups[2]);
    f.doc.undoStack()->undo();
    QVERIFY(sameFrame(f.doc.frameAt(0), before));

    // Strokes all from A: A is not offered.
    f.state->setSelectedStrokes({f.strokes[0], f.strokes[1]});
    f.actions->refreshTargets();
    QCOMPARE(menu->actions().size(), 2);
}

void TestObjects::deleteKeepsOneObject()
{
    Fixture f;
    const model::Frame before = f.doc.frameAt(0);
    f.state->setCurrentGroupId(f.groups[1]);
    f.actions->remove()->trigger();
    QCOMPARE(f.doc.frameAt(0).groups.size(), std::size_t(2));
    QCOMPARE(f.state->currentGroupId(), f.groups[0]);
    QCOMPARE(f.view()->currentIndex().row(), 1);
    f.doc.undoStack()->undo();
    QVERIFY(sameFrame(f.doc.frameAt(0), before));
    f.state->setCurrentFrameIndex(1);
    QVERIFY(!f.actions->remove()->isEnabled());
}

void TestObjects::grabScreenshot()
{
    Fixture f;
    f.doc.undoStack()->push(
        new model::SetObjectFlagCommand(&f.doc, f.groups[1], model::ObjectFlag::Visible, false));
    f.doc.undoStack()->push(
        new model::SetObjectFlagCommand(&f.doc, f.groups[0], model::ObjectFlag::Locked, true));
    f.state->setCurrentGroupId(f.groups[1]);
    QCoreApplication::processEvents();
    const QPixmap shot = f.panel->grab();
    QVERIFY(!shot.isNull());
    shot.save(QDir::temp().filePath(QStringLiteral("finbook_objects.png")));
}

QTEST_MAIN(TestObjects)
#include "tst_objects.moc"
