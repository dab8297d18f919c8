// The document model and its commands: structure, ids, sharing, signals, undo.
#include "random_edits.h"

#include <finbook/model/commands.h>
#include <finbook/model/finbook_file.h>

#include <QSignalSpy>
#include <QTest>

using namespace finbook::model;

namespace {

StrokeDataPtr line(float x0, float y0, float x1, float y1, int n = 5)
{
    auto data = std::make_shared<StrokeData>();
    for (int i = 0; i < n; ++i) {
        const float t = float(i) / float(n - 1);
        data->points.push_back({x0 + t * (x1 - x0), y0 + t * (y1 - y0), 1.0f});
    }
    return data;
}

// A document with two frames, two objects in the first, a few strokes.
void makeStarter(Document &doc)
{
    doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
    doc.undoStack()->push(new InsertFrameCommand(&doc, 1));
    const Id f0 = doc.frameAt(0).id;
    doc.undoStack()->push(new AddObjectCommand(&doc, f0, -1, QStringLiteral("arm")));
    const Id g0 = doc.frameAt(0).groups[0].id;
    const Id g1 = doc.frameAt(0).groups[1].id;
    doc.undoStack()->push(new AddStrokeCommand(&doc, g0, line(0, 0, 100, 0)));
    doc.undoStack()->push(new AddStrokeCommand(&doc, g1, line(0, 10, 100, 50)));
    doc.undoStack()->push(new AddStrokeCommand(&doc, g1, line(5, 5, 5, 80)));
    doc.undoStack()->clear();
}

std::vector<Id> allIds(const Document &doc)
{
    std::vector<Id> ids;
    for (const Frame &f : doc.frames()) {
        ids.push_back(f.id);
        for (const StrokeGroup &g : f.groups) {
            ids.push_back(g.id);
            for (const Stroke &s : g.strokes)
                ids.push_back(s.id);
            for (const Pin &p : g.rig.pins)
                ids.push_back(p.id);
        }
    }
    return ids;
}

} // namespace

class TestModel : public QObject {
    Q_OBJECT
private slots:
    void idsAreUniqueAndStable();
    void duplicateFrameSharesPointsAndIsIndependent();
    void signalsArePastTenseFacts();
    void eachCommandUndoesExactly_data();
    void eachCommandUndoesExactly();
    void commandOnVanishedTargetIsObsolete();
    void moveStrokesKeepsOrderAndUndoes();
    void settingsAreSanitized();
    void randomizedUndoRedo();
};

void TestModel::idsAreUniqueAndStable()
{
    Document doc;
    makeStarter(doc);
    auto ids = allIds(doc);
    std::sort(ids.begin(), ids.end());
    QVERIFY(std::adjacent_find(ids.begin(), ids.end()) == ids.end());
    QVERIFY(std::find(ids.begin(), ids.end(), kNoId) == ids.end());
    QVERIFY(doc.nextId() > ids.back());

    // Undo then redo an insertion: the same ids come back.
    const Id g = doc.frameAt(0).groups[0].id;
    doc.undoStack()->push(new AddStrokeCommand(&doc, g, line(1, 1, 2, 2)));
    const Id added = doc.frameAt(0).groups[0].strokes.back().id;
    doc.undoStack()->undo();
    QVERIFY(!doc.locateStroke(added).isValid());
    doc.undoStack()->redo();
    QCOMPARE(doc.frameAt(0).groups[0].strokes.back().id, added);
}

void TestModel::duplicateFrameSharesPointsAndIsIndependent()
{
    Document doc;
    makeStarter(doc);
    const Frame &original = doc.frameAt(0);
    const Id originalId = original.id;
    doc.undoStack()->push(new DuplicateFrameCommand(&doc, originalId, 1));
    QCOMPARE(doc.frameCount(), 3);
    const Frame &a = *doc.frame(originalId);
    const Frame &b = doc.frameAt(1);
    QVERIFY(a.id != b.id);
    QCOMPARE(a.groups.size(), b.groups.size());
    for (std::size_t g = 0; g < a.groups.size(); ++g) {
        QVERIFY(a.groups[g].id != b.groups[g].id);
        QCOMPARE(a.groups[g].name, b.groups[g].name);
        for (std::size_t s = 0; s < a.groups[g].strokes.size(); ++s) {
            QVERIFY(a.groups[g].strokes[s].id != b.groups[g].strokes[s].id);
            // No point was copied: both frames point at the same immutable data.
            QCOMPARE(a.groups[g].strokes[s].data.get(), b.groups[g].strokes[s].data.get());
        }
    }
    // Editing the copy leaves the original alone.
    const auto before = a.groups[1].strokes;
    const Id copyStroke = b.groups[1].strokes[0].id;
    doc.undoStack()->push(new ReplaceStrokeDataCommand(&doc, {copyStroke}, {line(9, 9, 10, 10)},
                                                       QStringLiteral("edit")));
    doc.undoStack()->push(new RemoveStrokeCommand(&doc, doc.frameAt(1).groups[1].strokes[1].id));
    QVERIFY(doc.frame(originalId)->groups[1].strokes == before);
}

void TestModel::signalsArePastTenseFacts()
{
    Document doc;
    makeStarter(doc);
    QSignalSpy inserted(&doc, &Document::framesInserted);
    QSignalSpy removed(&doc, &Document::framesRemoved);
    QSignalSpy moved(&doc, &Document::frameMoved);
    QSignalSpy strokes(&doc, &Document::strokesChanged);
    QSignalSpy changed(&doc, &Document::frameChanged);
    doc.undoStack()->push(new InsertFrameCommand(&doc, 1));
    QCOMPARE(inserted.count(), 1);
    QCOMPARE(inserted.at(0).at(0).toInt(), 1);
    doc.undoStack()->push(new MoveFrameCommand(&doc, 0, 2));
    QCOMPARE(moved.count(), 1);
    doc.undoStack()->undo();
    QCOMPARE(moved.count(), 2);
    doc.undoStack()->undo();
    QCOMPARE(removed.count(), 1);
    const Id g = doc.frameAt(0).groups[0].id;
    doc.undoStack()->push(new AddStrokeCommand(&doc, g, line(0, 0, 1, 1)));
    QCOMPARE(strokes.count(), 1);
    QCOMPARE(strokes.at(0).at(0).value<Id>(), g);
    QVERIFY(changed.count() >= 1);
}

void TestModel::eachCommandUndoesExactly_data()
{
    QTest::addColumn<int>("kind");
    const char *names[] = {"add stroke", "remove stroke", "add object",   "remove object",
                           "rename",     "reorder",       "move strokes", "insert frame",
                           "duplicate",  "delete frame",  "move frame",   "settings",
                           "hold",       "replace data",  "flag visible", "flag locked"};
    for (int i = 0; i < 16; ++i)
        QTest::newRow(names[i]) << i;
}

void TestModel::eachCommandUndoesExactly()
{
    QFETCH(int, kind);
    Document doc;
    makeStarter(doc);
    const QByteArray before = serializeFinbook(doc);
    const Frame &f0 = doc.frameAt(0);
    const Id g0 = f0.groups[0].id, g1 = f0.groups[1].id;
    const Id s1 = f0.groups[1].strokes[0].id;
    QUndoCommand *cmd = nullptr;
    DocumentSettings s = doc.settings();
    s.fps = 24;
    switch (kind) {
    case 0:
        cmd = new AddStrokeCommand(&doc, g0, line(3, 3, 4, 4), 0);
        break;
    case 1:
        cmd = new RemoveStrokeCommand(&doc, s1);
        break;
    case 2:
        cmd = new AddObjectCommand(&doc, f0.id, 0, QStringLiteral("new"));
        break;
    case 3:
        cmd = new RemoveObjectCommand(&doc, g1);
        break;
    case 4:
        cmd = new RenameObjectCommand(&doc, g1, QStringLiteral("leg"));
        break;
    case 5:
        cmd = new ReorderObjectCommand(&doc, g1, 0);
        break;
    case 6:
        cmd = new MoveStrokesCommand(&doc, {s1}, g0);
        break;
    case 7:
        cmd = new InsertFrameCommand(&doc, 1);
        break;
    case 8:
        cmd = new DuplicateFrameCommand(&doc, f0.id, 0);
        break;
    case 9:
        cmd = new DeleteFrameCommand(&doc, f0.id);
        break;
    case 10:
        cmd = new MoveFrameCommand(&doc, 0, 1);
        break;
    case 11:
        cmd = new ChangeSettingsCommand(&doc, s);
        break;
    case 12:
        cmd = new SetFrameHoldCommand(&doc, f0.id, 3);
        break;
    case 13:
        cmd = new ReplaceStrokeDataCommand(&doc, {s1}, {line(7, 7, 8, 9)}, QStringLiteral("t"));
        break;
    case 14:
        cmd = new SetObjectFlagCommand(&doc, g1, ObjectFlag::Visible, false);
        break;
    default:
        cmd = new SetObjectFlagCommand(&doc, g1, ObjectFlag::Locked, true);
        break;
    }
    doc.undoStack()->push(cmd);
    const QByteArray after = serializeFinbook(doc);
    QVERIFY2(after != before, "the command changed nothing");
    doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(doc), before);
    doc.undoStack()->redo();
    QCOMPARE(serializeFinbook(doc), after);
}

void TestModel::commandOnVanishedTargetIsObsolete()
{
    Document doc;
    makeStarter(doc);
    const Id s1 = doc.frameAt(0).groups[1].strokes[0].id;
    doc.undoStack()->push(new RemoveStrokeCommand(&doc, s1));
    const QByteArray state = serializeFinbook(doc);
    // Targets that do not exist: the commands do nothing and drop off the stack.
    const int count = doc.undoStack()->count();
    doc.undoStack()->push(new RemoveStrokeCommand(&doc, s1));
    doc.undoStack()->push(new RenameObjectCommand(&doc, 999999, QStringLiteral("x")));
    doc.undoStack()->push(new AddStrokeCommand(&doc, 999999, line(0, 0, 1, 1)));
    doc.undoStack()->push(new DeleteFrameCommand(&doc, 999999));
    doc.undoStack()->push(new MoveFrameCommand(&doc, 0, 7));
    QCOMPARE(doc.undoStack()->count(), count);
    QCOMPARE(serializeFinbook(doc), state);
}

void TestModel::moveStrokesKeepsOrderAndUndoes()
{
    Document doc;
    makeStarter(doc);
    const Frame &f0 = doc.frameAt(0);
    const Id g0 = f0.groups[0].id, g1 = f0.groups[1].id;
    const std::vector<Id> moving{f0.groups[1].strokes[1].id, f0.groups[1].strokes[0].id};
    const QByteArray before = serializeFinbook(doc);
    doc.undoStack()->push(new MoveStrokesCommand(&doc, moving, g0));
    QCOMPARE(doc.group(g1)->strokes.size(), std::size_t(0));
    QCOMPARE(doc.group(g0)->strokes.size(), std::size_t(3));
    doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(doc), before);
}

void TestModel::settingsAreSanitized()
{
    DocumentSettings s;
    s.fps = 500;
    s.canvasSize = QSize(0, 99999);
    s.playStart = 5;
    s.playEnd = 2;
    const DocumentSettings t = sanitizedSettings(s);
    QCOMPARE(t.fps, kMaxFps);
    QCOMPARE(t.canvasSize, QSize(1, kMaxCanvasSide));
    QVERIFY(t.playStart <= t.playEnd);
}

// Long random command sequences: undo everything, redo everything, and the canonical file
// bytes must match at both ends. Seeded so a failure reproduces.
void TestModel::randomizedUndoRedo()
{
    const quint32 seed = qEnvironmentVariableIsSet("FINBOOK_SEED")
                             ? quint32(qEnvironmentVariableIntValue("FINBOOK_SEED"))
                             : 20261121u;
    QRandomGenerator rng(seed);
    constexpr int kSequences = 10000;
    int applied = 0;
    for (int seq = 0; seq < kSequences; ++seq) {
        Document doc;
        makeStarter(doc);
        const QByteArray start = serializeFinbook(doc);
        const int length = 1 + int(rng.bounded(24));
        for (int i = 0; i < length; ++i)
            doc.undoStack()->push(finbook::testing::randomCommand(doc, rng).release());
        applied += doc.undoStack()->count();
        const QByteArray end = serializeFinbook(doc);
        while (doc.undoStack()->canUndo())
            doc.undoStack()->undo();
        if (serializeFinbook(doc) != start)
            QFAIL(qPrintable(
                QStringLiteral("undo-all differs: seed %1 sequence %2").arg(seed).arg(seq)));
        while (doc.undoStack()->canRedo())
            doc.undoStack()->redo();
        if (serializeFinbook(doc) != end)
            QFAIL(qPrintable(
                QStringLiteral("redo-all differs: seed %1 sequence %2").arg(seed).arg(seq)));
    }
    // Most random commands must have done something, or the test proves little.
    qInfo("%d sequences, %d commands applied (seed %u)", kSequences, applied, seed);
    QVERIFY2(applied > kSequences * 4, qPrintable(QString::number(applied)));
}

QTEST_GUILESS_MAIN(TestModel)
#include "tst_model.moc"
