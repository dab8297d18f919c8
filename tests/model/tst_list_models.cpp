// FrameListModel and ObjectListModel follow the document through edits, undo and redo with
// correct row signals (QAbstractItemModelTester watches every change), and every edit made
// through them is one undoable command.
#include <finbook/model/commands.h>
#include <finbook/model/fill/fill_resolve.h>
#include <finbook/model/frame_list_model.h>
#include <finbook/model/object_commands.h>
#include <finbook/model/object_list_model.h>

#include <QAbstractItemModelTester>
#include <QMimeData>
#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace finbook::model;

namespace {

StrokeDataPtr line(float x0, float y0, float x1, float y1)
{
    auto data = std::make_shared<StrokeData>();
    data->points = {{x0, y0, 1.0f}, {x1, y1, 0.5f}};
    return data;
}

// `count` frames, each with one object holding one stroke.
void fill(Document &doc, int count)
{
    for (int i = 0; i < count; ++i) {
        auto *insert = new InsertFrameCommand(&doc, doc.frameCount());
        doc.undoStack()->push(insert);
        const Id group = doc.frame(insert->frameId())->groups.front().id;
        doc.undoStack()->push(new AddStrokeCommand(&doc, group, line(float(i), 0, 10, 10)));
    }
    doc.undoStack()->clear();
}

std::vector<Id> frameIds(const Document &doc)
{
    std::vector<Id> ids;
    for (const Frame &f : doc.frames())
        ids.push_back(f.id);
    return ids;
}

std::vector<Id> modelIds(const QAbstractItemModel &model, int role)
{
    std::vector<Id> ids;
    for (int r = 0; r < model.rowCount(); ++r)
        ids.push_back(Id(model.index(r, 0).data(role).toULongLong()));
    return ids;
}

} // namespace

class TestListModels : public QObject {
    Q_OBJECT
private slots:
    void frameRowsFollowInsertRemoveMove();
    void frameRowsFollowResetAndChanges();
    void frameDropPushesOneMove();
    void frameHoldIsEditableAndUndoable();
    void objectRowsAreTopFirst();
    void objectRowsFollowEdits();
    void objectEditsAreCommands();
    void objectDropReorders();
    void mergeKeepsDrawingOrderAndUndoesExactly();
};

void TestListModels::frameRowsFollowInsertRemoveMove()
{
    Document doc;
    fill(doc, 3);
    FrameListModel model(&doc);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QCOMPARE(model.rowCount(), 3);

    QSignalSpy inserted(&model, &QAbstractItemModel::rowsInserted);
    QSignalSpy removed(&model, &QAbstractItemModel::rowsRemoved);
    QSignalSpy moved(&model, &QAbstractItemModel::rowsMoved);
    QUndoStack *stack = doc.undoStack();
    stack->push(new InsertFrameCommand(&doc, 1));
    QCOMPARE(model.rowCount(), 4);
    QCOMPARE(inserted.count(), 1);
    stack->push(new DuplicateFrameCommand(&doc, doc.frameAt(0).id, 4));
    QCOMPARE(model.rowCount(), 5);
    stack->push(new DeleteFrameCommand(&doc, doc.frameAt(2).id));
    QCOMPARE(model.rowCount(), 4);
    QCOMPARE(removed.count(), 1);
    stack->push(new MoveFrameCommand(&doc, 0, 3));
    stack->push(new MoveFrameCommand(&doc, 3, 1));
    QCOMPARE(moved.count(), 2);
    QCOMPARE(modelIds(model, FrameListModel::FrameIdRole), frameIds(doc));

    while (stack->canUndo()) {
        stack->undo();
        QCOMPARE(modelIds(model, FrameListModel::FrameIdRole), frameIds(doc));
    }
    QCOMPARE(model.rowCount(), 3);
    while (stack->canRedo())
        stack->redo();
    QCOMPARE(modelIds(model, FrameListModel::FrameIdRole), frameIds(doc));
    for (int r = 0; r < model.rowCount(); ++r)
        QCOMPARE(model.index(r).data(FrameListModel::FrameNumberRole).toInt(), r + 1);
}

void TestListModels::frameRowsFollowResetAndChanges()
{
    Document doc;
    fill(doc, 2);
    FrameListModel model(&doc);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);

    const Id second = doc.frameAt(1).id;
    const quint64 before = model.index(1).data(FrameListModel::RevisionRole).toULongLong();
    const Id group = doc.frameAt(1).groups.front().id;
    doc.undoStack()->push(new AddStrokeCommand(&doc, group, line(0, 0, 5, 5)));
    QVERIFY(!changed.isEmpty());
    QCOMPARE(changed.last().at(0).value<QModelIndex>().row(), 1);
    QVERIFY(model.index(1).data(FrameListModel::RevisionRole).toULongLong() > before);
    QCOMPARE(model.revision(second),
             model.index(1).data(FrameListModel::RevisionRole).toULongLong());

    QSignalSpy reset(&model, &QAbstractItemModel::modelReset);
    std::vector<Frame> frames(5);
    for (int i = 0; i < 5; ++i)
        frames[std::size_t(i)].id = Id(100 + i);
    doc.reset(std::move(frames), doc.settings(), 200);
    QCOMPARE(reset.count(), 1);
    QCOMPARE(model.rowCount(), 5);
    QCOMPARE(model.frameId(4), Id(104));
}

void TestListModels::frameDropPushesOneMove()
{
    Document doc;
    fill(doc, 4);
    FrameListModel model(&doc);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    const std::vector<Id> original = frameIds(doc);

    std::unique_ptr<QMimeData> mime(model.mimeData({model.index(0)}));
    QVERIFY(model.canDropMimeData(mime.get(), Qt::MoveAction, 3, 0, {}));
    QVERIFY(!model.canDropMimeData(mime.get(), Qt::CopyAction, 3, 0, {}));
    // Dropped between rows 2 and 3: the first frame lands third.
    QVERIFY(model.dropMimeData(mime.get(), Qt::MoveAction, 3, 0, {}));
    QCOMPARE(doc.undoStack()->count(), 1);
    QCOMPARE(frameIds(doc), (std::vector<Id>{original[1], original[2], original[0], original[3]}));
    QCOMPARE(modelIds(model, FrameListModel::FrameIdRole), frameIds(doc));

    // Dropped at the end (row -1).
    std::unique_ptr<QMimeData> last(model.mimeData({model.index(1)}));
    QVERIFY(model.dropMimeData(last.get(), Qt::MoveAction, -1, -1, {}));
    QCOMPARE(doc.frameAt(3).id, original[2]);

    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QCOMPARE(frameIds(doc), original);
    QCOMPARE(modelIds(model, FrameListModel::FrameIdRole), original);
    // A drop that changes nothing pushes nothing.
    std::unique_ptr<QMimeData> same(model.mimeData({model.index(1)}));
    QVERIFY(!model.dropMimeData(same.get(), Qt::MoveAction, 2, 0, {}));
    QCOMPARE(doc.undoStack()->index(), 0);
}

void TestListModels::frameHoldIsEditableAndUndoable()
{
    Document doc;
    fill(doc, 2);
    FrameListModel model(&doc);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QVERIFY(model.setData(model.index(1), 3, FrameListModel::HoldRole));
    QCOMPARE(doc.frameAt(1).hold, 3);
    QCOMPARE(model.index(1).data(FrameListModel::HoldRole).toInt(), 3);
    QVERIFY(!model.setData(model.index(1), 0, FrameListModel::HoldRole));
    doc.undoStack()->undo();
    QCOMPARE(doc.frameAt(1).hold, 1);
}

void TestListModels::objectRowsAreTopFirst()
{
    Document doc;
    fill(doc, 1);
    const Id frameId = doc.frameAt(0).id;
    auto *add = new AddObjectCommand(&doc, frameId, -1, QStringLiteral("Top"));
    doc.undoStack()->push(add);
    ObjectListModel model(&doc);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QCOMPARE(model.rowCount(), 0);
    model.setFrameId(frameId);
    QCOMPARE(model.rowCount(), 2);
    QCOMPARE(model.index(0).data().toString(), QStringLiteral("Top"));
    QCOMPARE(model.groupId(0), add->groupId());
    QCOMPARE(model.index(1).data(ObjectListModel::StrokeCountRole).toInt(), 1);
    QCOMPARE(model.zIndexOfRow(0), 1);
    // A line of no ink (a gap closer Apply Pose added) is not counted: the animator drew one
    // stroke and sees one.
    const Id bottom = doc.frameAt(0).groups.front().id;
    auto closer = std::make_shared<StrokeData>();
    closer->color = kGapCloserColor;
    closer->points = {{0, 0, 1}, {10, 0, 1}};
    doc.undoStack()->push(new AddStrokeCommand(&doc, bottom, closer));
    QCOMPARE(doc.group(bottom)->strokes.size(), std::size_t(2));
    QCOMPARE(model.index(1).data(ObjectListModel::StrokeCountRole).toInt(), 1);
    QVERIFY(model.index(1).data(Qt::ToolTipRole).toString().contains(QStringLiteral("1 stroke")));
}

void TestListModels::objectRowsFollowEdits()
{
    Document doc;
    fill(doc, 2);
    const Id frameId = doc.frameAt(1).id;
    ObjectListModel model(&doc);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    model.setFrameId(frameId);
    QSignalSpy inserted(&model, &QAbstractItemModel::rowsInserted);
    QSignalSpy removed(&model, &QAbstractItemModel::rowsRemoved);
    QSignalSpy moved(&model, &QAbstractItemModel::rowsMoved);
    QSignalSpy reset(&model, &QAbstractItemModel::modelReset);
    QUndoStack *stack = doc.undoStack();
    const Id bottom = doc.frameAt(1).groups.front().id;
    stack->push(new AddObjectCommand(&doc, frameId, -1, QStringLiteral("B")));
    stack->push(new AddObjectCommand(&doc, frameId, -1, QStringLiteral("C")));
    QCOMPARE(inserted.count(), 2);
    stack->push(new ReorderObjectCommand(&doc, bottom, 2));
    QCOMPARE(moved.count(), 1);
    QCOMPARE(model.groupId(0), bottom);
    stack->push(new RemoveObjectCommand(&doc, bottom));
    QCOMPARE(removed.count(), 1);
    // Edits in another frame do not touch this model.
    stack->push(new AddObjectCommand(&doc, doc.frameAt(0).id, -1, QStringLiteral("X")));
    QCOMPARE(inserted.count(), 2);
    while (stack->canUndo())
        stack->undo();
    QCOMPARE(model.rowCount(), 1);
    QCOMPARE(model.groupId(0), bottom);
    QCOMPARE(reset.count(), 0);
    // The frame itself going away empties the model.
    stack->push(new DeleteFrameCommand(&doc, frameId));
    QCOMPARE(model.rowCount(), 0);
}

void TestListModels::objectEditsAreCommands()
{
    Document doc;
    fill(doc, 1);
    ObjectListModel model(&doc);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    model.setFrameId(doc.frameAt(0).id);
    const QModelIndex row = model.index(0);
    const QString oldName = row.data().toString();
    QVERIFY(model.setData(row, QStringLiteral("Arm"), Qt::EditRole));
    QVERIFY(model.setData(row, false, ObjectListModel::VisibleRole));
    QVERIFY(model.setData(row, true, ObjectListModel::LockedRole));
    QVERIFY(!model.setData(row, QStringLiteral("  "), Qt::EditRole));
    QCOMPARE(doc.undoStack()->count(), 3);
    const StrokeGroup &g = doc.frameAt(0).groups.front();
    QCOMPARE(g.name, QStringLiteral("Arm"));
    QVERIFY(!g.visible);
    QVERIFY(g.locked);
    QCOMPARE(row.data(Qt::CheckStateRole).value<Qt::CheckState>(), Qt::Unchecked);
    QVERIFY(model.setData(row, Qt::Checked, Qt::CheckStateRole));
    QVERIFY(doc.frameAt(0).groups.front().visible);
    while (doc.undoStack()->canUndo())
        doc.undoStack()->undo();
    QCOMPARE(doc.frameAt(0).groups.front().name, oldName);
    QVERIFY(doc.frameAt(0).groups.front().visible);
    QVERIFY(!doc.frameAt(0).groups.front().locked);
}

void TestListModels::objectDropReorders()
{
    Document doc;
    fill(doc, 1);
    const Id frameId = doc.frameAt(0).id;
    for (const char *name : {"B", "C"})
        doc.undoStack()->push(new AddObjectCommand(&doc, frameId, -1, QString::fromLatin1(name)));
    ObjectListModel model(&doc);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    model.setFrameId(frameId);
    const std::vector<Id> before = modelIds(model, ObjectListModel::GroupIdRole);
    // Drag the top object to the bottom.
    std::unique_ptr<QMimeData> mime(model.mimeData({model.index(0)}));
    QVERIFY(model.dropMimeData(mime.get(), Qt::MoveAction, 3, 0, {}));
    QCOMPARE(modelIds(model, ObjectListModel::GroupIdRole),
             (std::vector<Id>{before[1], before[2], before[0]}));
    QCOMPARE(doc.frameAt(0).groups.front().id, before[0]); // now at the back
    doc.undoStack()->undo();
    QCOMPARE(modelIds(model, ObjectListModel::GroupIdRole), before);
}

void TestListModels::mergeKeepsDrawingOrderAndUndoesExactly()
{
    Document doc;
    fill(doc, 1);
    const Id frameId = doc.frameAt(0).id;
    const Id bottom = doc.frameAt(0).groups.front().id;
    auto *add = new AddObjectCommand(&doc, frameId, -1, QStringLiteral("Top"));
    doc.undoStack()->push(add);
    const Id top = add->groupId();
    auto *s1 = new AddStrokeCommand(&doc, top, line(1, 1, 2, 2));
    doc.undoStack()->push(s1);
    auto *s2 = new AddStrokeCommand(&doc, top, line(3, 3, 4, 4));
    doc.undoStack()->push(s2);
    const Frame before = doc.frameAt(0);
    const Id bottomStroke = before.groups[0].strokes[0].id;

    doc.undoStack()->push(new MergeObjectsCommand(&doc, top, bottom));
    const Frame &merged = doc.frameAt(0);
    QCOMPARE(merged.groups.size(), std::size_t(1));
    const std::vector<Stroke> &strokes = merged.groups[0].strokes;
    QCOMPARE(strokes.size(), std::size_t(3));
    QCOMPARE(strokes[0].id, bottomStroke);
    QCOMPARE(strokes[1].id, s1->strokeId());
    QCOMPARE(strokes[2].id, s2->strokeId());

    doc.undoStack()->undo();
    const Frame &restored = doc.frameAt(0);
    QCOMPARE(restored.groups.size(), before.groups.size());
    for (std::size_t g = 0; g < before.groups.size(); ++g) {
        QCOMPARE(restored.groups[g].id, before.groups[g].id);
        QCOMPARE(restored.groups[g].name, before.groups[g].name);
        QVERIFY(restored.groups[g].strokes == before.groups[g].strokes);
    }
    // Merging upward puts the lower object's strokes underneath.
    doc.undoStack()->push(new MergeObjectsCommand(&doc, bottom, top));
    const std::vector<Stroke> &up = doc.frameAt(0).groups[0].strokes;
    QCOMPARE(doc.frameAt(0).groups[0].id, top);
    QCOMPARE(up.front().id, bottomStroke);
    QCOMPARE(up.back().id, s2->strokeId());
    // Objects in different frames cannot merge.
    doc.undoStack()->push(new InsertFrameCommand(&doc, 1));
    MergeObjectsCommand across(&doc, top, doc.frameAt(1).groups.front().id);
    QVERIFY(across.isObsolete());
}

QTEST_GUILESS_MAIN(TestListModels)
#include "tst_list_models.moc"
