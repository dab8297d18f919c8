// Drawing substitution (issue 49): an object showing one drawing of a set, chosen per frame. One
// drawing wherever it is shown (an edit in one frame is the edit in every frame showing it),
// each choice one undo step that undo restores exactly, saved and opened, copied with its cel,
// and a damaged set refused with a reason.
#include "random_edits.h"
#include "stroke_support.h"

#include <finbook/model/document.h>
#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/recovery/recovery_store.h>
#include <finbook/model/swap/swap_commands.h>

#include <QtTest>

using namespace finbook;
using namespace finbook::model;
using finbook::testing::lineStroke;
using finbook::testing::squareOutline;

class TestSwap : public QObject {
    Q_OBJECT

private slots:
    void makingAnObjectSwappableKeepsItsDrawing();
    void anEditReachesEveryFrameShowingTheDrawing();
    void eachFrameChoosesItsDrawing();
    void steppingWrapsRoundTheSet();
    void aRigBelongsToTheDrawing();
    void removingADrawingShowsItsNeighbour();
    void anIndependentDrawingNoLongerFollows();
    void aFrameShowsASetOnce();
    void savedAndOpened();
    void copiedCelsKeepTheirChoice();
    void autosavedWithTheSets();
    void damagedSetsAreRefusedWithAReason_data();
    void damagedSetsAreRefusedWithAReason();
    void repeatedIdsAreRepairedKeepingDrawingsShared_data();
    void repeatedIdsAreRepairedKeepingDrawingsShared();
    void randomEditsUndoExactlyAndKeepDrawingsShared();
};

namespace {
// Two frames; frame 1 has object "Mouth" with a square and a line.
struct Scene {
    Document doc;
    Id mouth = kNoId;
    Id frame1 = kNoId;
    Scene()
    {
        doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
        frame1 = doc.frameAt(0).id;
        auto *add = new AddObjectCommand(&doc, frame1, -1, QStringLiteral("Mouth"));
        doc.undoStack()->push(add);
        mouth = add->groupId();
        doc.undoStack()->push(
            new AddStrokeCommand(&doc, mouth, squareOutline(QPointF(100, 100), 80, 8, 3.0f)));
        doc.undoStack()->push(
            new AddStrokeCommand(&doc, mouth, lineStroke({110, 140}, {170, 140}, 6, 3.0f)));
        doc.undoStack()->clear();
    }
    const StrokeGroup &object(int frame) const
    {
        for (const StrokeGroup &g : doc.frameAt(frame).groups)
            if (g.name == QLatin1String("Mouth"))
                return g;
        throw std::logic_error("no mouth");
    }
    // Makes the mouth swappable and frame 2 a copy of frame 1.
    Id swappableInTwoFrames()
    {
        auto *make =
            new NewSwapSetCommand(&doc, mouth, QStringLiteral("Mouth"), QStringLiteral("A"));
        doc.undoStack()->push(make);
        doc.undoStack()->push(new DuplicateFrameCommand(&doc, frame1, 1));
        return make->setId();
    }
};

// Every linked object shows exactly its drawing.
bool drawingsShared(const Document &doc, QString *why = nullptr)
{
    for (const Layer &l : doc.layers())
        for (const Frame &f : l.cels)
            for (const StrokeGroup &g : f.groups) {
                if (!g.swap.linked())
                    continue;
                const SwapDrawing *d = doc.swapDrawing(g.swap);
                if (!d || d->strokes != g.strokes || d->fills != g.fills ||
                    d->meshDensity != g.meshDensity) {
                    if (why)
                        *why = QStringLiteral("object %1 differs from its drawing").arg(g.id);
                    return false;
                }
            }
    return true;
}

std::unique_ptr<QUndoCommand> randomSwapCommand(Document &doc, QRandomGenerator &rng)
{
    const finbook::testing::Picks p = finbook::testing::randomPicks(doc, rng);
    const StrokeGroup *g = doc.group(p.group);
    const SwapLink link = g ? g->swap : SwapLink{};
    switch (rng.bounded(8)) {
    case 0:
        return std::make_unique<NewSwapSetCommand>(&doc, p.group, QStringLiteral("set"),
                                                   QStringLiteral("one"));
    case 1:
        return std::make_unique<AddSwapDrawingCommand>(
            &doc, p.group, QStringLiteral("d%1").arg(rng.bounded(9)),
            rng.bounded(2) ? AddSwapDrawingCommand::Content::Copy
                           : AddSwapDrawingCommand::Content::Empty);
    case 2:
        if (auto *step = stepSwapDrawing(&doc, p.group, rng.bounded(2) ? 1 : -1))
            return std::unique_ptr<QUndoCommand>(step);
        break;
    case 3:
        return std::make_unique<RemoveSwapDrawingCommand>(&doc, link);
    case 4:
        return std::make_unique<MakeDrawingOwnCommand>(&doc, p.group);
    case 5:
        return std::make_unique<RenameSwapDrawingCommand>(
            &doc, link, QStringLiteral("r%1").arg(rng.bounded(9)));
    default:
        if (!doc.swapSets().empty()) {
            const SwapSet &set = doc.swapSets()[rng.bounded(quint32(doc.swapSets().size()))];
            const SwapDrawing &d = set.drawings[rng.bounded(quint32(set.drawings.size()))];
            return std::make_unique<SetSwapDrawingCommand>(&doc, p.group, SwapLink{set.id, d.id});
        }
    }
    return finbook::testing::randomCommand(doc, rng);
}
} // namespace

void TestSwap::makingAnObjectSwappableKeepsItsDrawing()
{
    Scene s;
    const QByteArray before = serializeFinbook(s.doc);
    const std::vector<Stroke> strokes = s.object(0).strokes;
    s.doc.undoStack()->push(
        new NewSwapSetCommand(&s.doc, s.mouth, QStringLiteral("Mouth"), QStringLiteral("A")));
    QCOMPARE(s.doc.swapSets().size(), std::size_t(1));
    const SwapSet &set = s.doc.swapSets().front();
    QCOMPARE(set.drawings.size(), std::size_t(1));
    QCOMPARE(set.drawings.front().name, QStringLiteral("A"));
    QCOMPARE(set.drawings.front().strokes, strokes);
    QCOMPARE(s.object(0).strokes, strokes); // ids and all: nothing shown changed
    QVERIFY(s.object(0).swap.linked());
    s.doc.undoStack()->undo();
    QVERIFY(s.doc.swapSets().empty());
    QCOMPARE(serializeFinbook(s.doc), before);
}

void TestSwap::anEditReachesEveryFrameShowingTheDrawing()
{
    Scene s;
    s.swappableInTwoFrames();
    QCOMPARE(s.object(1).strokes, s.object(0).strokes); // the copy shows the same drawing
    const QByteArray before = serializeFinbook(s.doc);
    // A stroke drawn in frame 2 is in frame 1 too, and in the drawing.
    s.doc.setFocusFrame(s.doc.frameAt(1).id);
    auto *add =
        new AddStrokeCommand(&s.doc, s.object(1).id, lineStroke({120, 160}, {160, 160}, 4, 2.0f));
    s.doc.undoStack()->push(add);
    QCOMPARE(s.object(0).strokes.size(), std::size_t(3));
    QCOMPARE(s.object(0).strokes, s.object(1).strokes);
    QVERIFY(drawingsShared(s.doc));
    // Erased in frame 1: gone from frame 2.
    s.doc.setFocusFrame(s.frame1);
    s.doc.undoStack()->push(new RemoveStrokeCommand(&s.doc, s.object(0).strokes[0].id));
    QCOMPARE(s.object(1).strokes.size(), std::size_t(2));
    // A fill made in frame 1 colours frame 2.
    if (auto fill = fillAllRegionsCommand(&s.doc, s.object(0).id, qRgb(200, 40, 40)))
        s.doc.undoStack()->push(fill.release());
    QCOMPARE(s.object(1).fills, s.object(0).fills);
    QVERIFY(drawingsShared(s.doc));
    s.doc.undoStack()->setIndex(2);
    QCOMPARE(serializeFinbook(s.doc), before);
}

void TestSwap::eachFrameChoosesItsDrawing()
{
    Scene s;
    const Id setId = s.swappableInTwoFrames();
    const QByteArray before = serializeFinbook(s.doc);
    const std::vector<Stroke> a = s.object(0).strokes;
    // A new empty drawing "B", shown in frame 2 only.
    s.doc.undoStack()->push(new AddSwapDrawingCommand(&s.doc, s.object(1).id, QStringLiteral("B"),
                                                      AddSwapDrawingCommand::Content::Empty));
    QCOMPARE(s.doc.swapSet(setId)->drawings.size(), std::size_t(2));
    QVERIFY(s.object(1).strokes.empty());
    QCOMPARE(s.object(0).strokes, a);
    QCOMPARE(s.doc.swapDrawing(s.object(1).swap)->name, QStringLiteral("B"));
    // Drawn on in frame 2: frame 1 still shows A.
    s.doc.undoStack()->push(
        new AddStrokeCommand(&s.doc, s.object(1).id, lineStroke({0, 0}, {50, 50}, 3, 2.0f)));
    QCOMPARE(s.object(0).strokes, a);
    QCOMPARE(s.object(1).strokes.size(), std::size_t(1));
    // Frame 1 switches to B: it shows B's stroke under B's ids.
    const QByteArray beforeSwitch = serializeFinbook(s.doc);
    s.doc.undoStack()->push(new SetSwapDrawingCommand(&s.doc, s.object(0).id, s.object(1).swap));
    QCOMPARE(s.object(0).strokes, s.object(1).strokes);
    s.doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(s.doc), beforeSwitch);
    QCOMPARE(s.object(0).strokes, a);
    while (s.doc.undoStack()->index() > 2)
        s.doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(s.doc), before);
}

void TestSwap::steppingWrapsRoundTheSet()
{
    Scene s;
    const Id setId = s.swappableInTwoFrames();
    for (const char *name : {"B", "C"})
        s.doc.undoStack()->push(new AddSwapDrawingCommand(
            &s.doc, s.mouth, QString::fromLatin1(name), AddSwapDrawingCommand::Content::Copy));
    const SwapSet &set = *s.doc.swapSet(setId);
    QCOMPARE(s.doc.swapDrawing(s.object(0).swap)->name, QStringLiteral("C"));
    const auto shown = [&] { return s.doc.swapDrawing(s.object(0).swap)->name; };
    s.doc.undoStack()->push(stepSwapDrawing(&s.doc, s.mouth, 1));
    QCOMPARE(shown(), QStringLiteral("A")); // past the last: the first
    s.doc.undoStack()->push(stepSwapDrawing(&s.doc, s.mouth, -1));
    QCOMPARE(shown(), QStringLiteral("C"));
    s.doc.undoStack()->push(stepSwapDrawing(&s.doc, s.mouth, -1));
    QCOMPARE(shown(), QStringLiteral("B"));
    // B is a copy of A under new ids: same points, other ids, edits of one leave the other.
    QCOMPARE(set.drawings[1].strokes.size(), set.drawings[0].strokes.size());
    QVERIFY(set.drawings[1].strokes[0].id != set.drawings[0].strokes[0].id);
    QCOMPARE(*set.drawings[1].strokes[0].data, *set.drawings[0].strokes[0].data);
    QCOMPARE(s.doc.swapDrawing(s.object(1).swap)->name, QStringLiteral("A"));
    // A set of one drawing has nothing to step to.
    Scene single;
    single.doc.undoStack()->push(
        new NewSwapSetCommand(&single.doc, single.mouth, QStringLiteral("M"), QStringLiteral("A")));
    QVERIFY(!stepSwapDrawing(&single.doc, single.mouth, 1));
}

void TestSwap::aRigBelongsToTheDrawing()
{
    Scene s;
    s.swappableInTwoFrames();
    // Frame 1 gets a pin on A, then switches to a new drawing B: its rig is B's (none), and
    // back on A it has A's pin again (kept by A when frame 1 left it, at rest).
    s.doc.undoStack()->push(
        new AddPinCommand(&s.doc, s.mouth, QPointF(100, 100), QPointF(110, 100)));
    QCOMPARE(s.object(0).rig.pins.size(), std::size_t(1));
    const QByteArray before = serializeFinbook(s.doc);
    s.doc.undoStack()->push(new AddSwapDrawingCommand(&s.doc, s.mouth, QStringLiteral("B"),
                                                      AddSwapDrawingCommand::Content::Empty));
    QVERIFY(s.object(0).rig.empty());
    s.doc.undoStack()->push(stepSwapDrawing(&s.doc, s.mouth, -1));
    QCOMPARE(s.object(0).rig.pins.size(), std::size_t(1));
    QCOMPARE(s.object(0).rig.pins[0].rest, QPointF(100, 100));
    QVERIFY(!s.object(0).rig.isPosed()); // a pose is a frame's own
    // Frame 2's rig is its own: it never had a pin.
    QVERIFY(s.object(1).rig.empty());
    s.doc.undoStack()->undo();
    s.doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(s.doc), before);
}

void TestSwap::removingADrawingShowsItsNeighbour()
{
    Scene s;
    const Id setId = s.swappableInTwoFrames();
    s.doc.undoStack()->push(new AddSwapDrawingCommand(&s.doc, s.mouth, QStringLiteral("B"),
                                                      AddSwapDrawingCommand::Content::Empty));
    const QByteArray before = serializeFinbook(s.doc);
    const SwapLink b = s.object(0).swap;
    s.doc.undoStack()->push(new RemoveSwapDrawingCommand(&s.doc, b));
    QCOMPARE(s.doc.swapSet(setId)->drawings.size(), std::size_t(1));
    QCOMPARE(s.doc.swapDrawing(s.object(0).swap)->name, QStringLiteral("A"));
    QVERIFY(drawingsShared(s.doc));
    // The last drawing of a set stays.
    auto *last = new RemoveSwapDrawingCommand(&s.doc, s.object(0).swap);
    QVERIFY(last->isObsolete());
    delete last;
    s.doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(s.doc), before);
}

void TestSwap::anIndependentDrawingNoLongerFollows()
{
    Scene s;
    s.swappableInTwoFrames();
    const QByteArray before = serializeFinbook(s.doc);
    s.doc.undoStack()->push(new MakeDrawingOwnCommand(&s.doc, s.object(1).id));
    QVERIFY(!s.object(1).swap.linked());
    QCOMPARE(s.object(1).strokes.size(), s.object(0).strokes.size());
    QVERIFY(s.object(1).strokes[0].id != s.object(0).strokes[0].id); // its own ids
    s.doc.undoStack()->push(
        new AddStrokeCommand(&s.doc, s.object(1).id, lineStroke({0, 0}, {9, 9}, 3, 2.0f)));
    QCOMPARE(s.object(0).strokes.size(), std::size_t(2));
    // Saved, it opens (no id clash) and stays independent.
    Document reopened;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("own.finbook"));
    if (const auto failed = saveFinbook(s.doc, path))
        QFAIL(qPrintable(failed->message));
    if (const auto failed = openFinbook(reopened, path))
        QFAIL(qPrintable(failed->message));
    s.doc.undoStack()->undo();
    s.doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(s.doc), before);
}

void TestSwap::aFrameShowsASetOnce()
{
    Scene s;
    const Id setId = s.swappableInTwoFrames();
    // A second object in frame 1 cannot show the same set (it would hold the same strokes).
    auto *add = new AddObjectCommand(&s.doc, s.frame1, -1, QStringLiteral("Other"));
    s.doc.undoStack()->push(add);
    auto *link = new SetSwapDrawingCommand(&s.doc, add->groupId(),
                                           {setId, s.doc.swapSet(setId)->drawings[0].id});
    QVERIFY(link->isObsolete());
    delete link;
    // Pasting the mouth again into its own frame gives an ordinary copy.
    StrokeGroup pasted = s.object(0);
    pasted.id = s.doc.allocateId();
    for (Stroke &st : pasted.strokes)
        st.id = s.doc.allocateId();
    s.doc.insertGroup(s.frame1, 0, pasted);
    QVERIFY(!s.doc.frameAt(0).groups[0].swap.linked());
    QVERIFY(drawingsShared(s.doc));
}

void TestSwap::savedAndOpened()
{
    Scene s;
    const Id setId = s.swappableInTwoFrames();
    s.doc.undoStack()->push(new AddSwapDrawingCommand(&s.doc, s.object(1).id, QStringLiteral("B"),
                                                      AddSwapDrawingCommand::Content::Copy));
    s.doc.undoStack()->push(
        new AddStrokeCommand(&s.doc, s.object(1).id, lineStroke({0, 0}, {50, 50}, 3, 2.0f)));
    s.doc.undoStack()->push(
        new AddPinCommand(&s.doc, s.object(1).id, QPointF(100, 100), QPointF(120, 90)));
    // A drawing shown nowhere is kept too.
    s.doc.undoStack()->push(new AddSwapDrawingCommand(&s.doc, s.mouth, QStringLiteral("C"),
                                                      AddSwapDrawingCommand::Content::Empty));
    s.doc.undoStack()->push(stepSwapDrawing(&s.doc, s.mouth, 1));
    s.doc.undoStack()->push(new RenameSwapDrawingCommand(
        &s.doc, {setId, s.doc.swapSet(setId)->drawings[2].id}, QStringLiteral("Rest 休")));
    const QByteArray bytes = serializeFinbook(s.doc);
    const auto loaded = readFinbook(bytes);
    QVERIFY2(loaded.hasValue(), qPrintable(loaded ? QString() : loaded.error().message));
    Document reopened;
    adoptLoadedDocument(reopened, *loaded);
    QCOMPARE(reopened.swapSets(), s.doc.swapSets());
    QCOMPARE(serializeFinbook(reopened), bytes);
    QVERIFY(drawingsShared(reopened));
    QCOMPARE(reopened.swapSets().front().drawings[2].name, QStringLiteral("Rest 休"));
    // An edit after opening still reaches every frame showing the drawing.
    reopened.undoStack()->push(new AddStrokeCommand(&reopened, reopened.frameAt(0).groups.back().id,
                                                    lineStroke({1, 1}, {2, 2}, 2, 1.0f)));
    QVERIFY(drawingsShared(reopened));
    // A file without sets has no SWAP section.
    Scene plain;
    QVERIFY(!serializeFinbook(plain.doc).contains("SWAP"));
    QVERIFY(bytes.contains("SWAP"));
}

void TestSwap::copiedCelsKeepTheirChoice()
{
    Scene s;
    s.swappableInTwoFrames();
    s.doc.undoStack()->push(new AddSwapDrawingCommand(&s.doc, s.object(1).id, QStringLiteral("B"),
                                                      AddSwapDrawingCommand::Content::Empty));
    // Copy frame 2's cel (as Copy does), paste it at the end.
    const Frame cel = s.doc.frameAt(1);
    s.doc.undoStack()->push(
        new DuplicateFrameCommand(&s.doc, cel, s.doc.currentLayerId(), s.doc.frameCount()));
    QCOMPARE(s.doc.frameCount(), 3);
    QCOMPARE(s.object(2).swap, s.object(1).swap);
    QCOMPARE(s.object(2).strokes, s.object(1).strokes);
    QVERIFY(drawingsShared(s.doc));
}

void TestSwap::autosavedWithTheSets()
{
    Scene s;
    s.swappableInTwoFrames();
    const QByteArray copy = recoveryCopyBytes(s.doc.layers(), s.doc.settings(), RecoveryInfo{}, {},
                                              {}, {}, s.doc.palette(), s.doc.swapSets());
    const auto loaded = readFinbook(copy);
    QVERIFY(loaded.hasValue());
    QCOMPARE(loaded->swapSets, s.doc.swapSets());
}

void TestSwap::damagedSetsAreRefusedWithAReason_data()
{
    QTest::addColumn<QByteArray>("from");
    QTest::addColumn<QByteArray>("to");
    QTest::addColumn<QString>("reason");
    // Bytes of the SWAP section are changed by replacing the drawing id in the link table.
    QTest::newRow("link to a missing drawing")
        << QByteArray("link") << QByteArray() << QStringLiteral("do not hold");
    QTest::newRow("no drawings") << QByteArray("count") << QByteArray()
                                 << QStringLiteral("drawings");
    QTest::newRow("one set twice in a frame")
        << QByteArray("twice") << QByteArray() << QStringLiteral("two objects");
}

void TestSwap::damagedSetsAreRefusedWithAReason()
{
    QFETCH(QByteArray, from);
    QFETCH(QString, reason);
    Scene s;
    const Id setId = s.swappableInTwoFrames();
    const SwapSet set = *s.doc.swapSet(setId);
    // Rebuild the file with a damaged set: written from a document whose set is changed after
    // its objects were linked (the writer writes what it is given).
    std::vector<SwapSet> sets{set};
    std::vector<Layer> layers = s.doc.layers();
    if (from == "link") {
        sets.front().drawings.front().id += 1000; // the objects' link names the old id
    } else if (from == "count") {
        sets.front().drawings.clear();
    } else { // a second object of frame 1 showing the set (its own stroke ids)
        StrokeGroup second = s.object(0);
        second.id = s.doc.allocateId();
        for (Stroke &st : second.strokes)
            st.id = s.doc.allocateId();
        layers.front().cels.front().groups.push_back(second);
    }
    const QByteArray bytes = serializeFinbook(layers, s.doc.settings(), {}, {}, {}, sets);
    const auto loaded = readFinbook(bytes);
    QVERIFY(!loaded.hasValue());
    QVERIFY2(loaded.error().message.contains(reason), qPrintable(loaded.error().message));
    // Opened anyway, the drawings shown are kept as ordinary objects.
    QStringList problems;
    const auto recovered = recoverFinbook(bytes, &problems);
    QVERIFY(recovered.hasValue());
    QVERIFY(!problems.isEmpty());
    QVERIFY(recovered->swapSets.empty());
    Document doc;
    adoptLoadedDocument(doc, *recovered);
    QCOMPARE(doc.frameAt(1).groups.back().strokes.size(), std::size_t(2));
    // The copies' ids were made unique again: what is saved opens.
    QVERIFY(doc.frameAt(0).groups.back().strokes[0].id !=
            doc.frameAt(1).groups.back().strokes[0].id);
    const auto again = readFinbook(serializeFinbook(doc));
    QVERIFY2(again.hasValue(), qPrintable(again ? QString() : again.error().message));
}

void TestSwap::repeatedIdsAreRepairedKeepingDrawingsShared_data()
{
    QTest::addColumn<QString>("clash");
    QTest::newRow("a drawing has a frame's id") << QStringLiteral("drawing");
    QTest::newRow("a set has an object's id") << QStringLiteral("set");
    QTest::newRow("a drawing's stroke has another object's stroke id") << QStringLiteral("stroke");
}

// Found by the fuzzer: a recovered file whose ids clashed kept a drawing's id that a frame
// also had, and the document it gave could not be saved and opened again.
void TestSwap::repeatedIdsAreRepairedKeepingDrawingsShared()
{
    QFETCH(QString, clash);
    Scene s;
    const Id setId = s.swappableInTwoFrames();
    // A plain object beside the mouth in frame 1, its stroke's id to be repeated.
    auto *add = new AddObjectCommand(&s.doc, s.frame1, -1, QStringLiteral("Plain"));
    s.doc.undoStack()->push(add);
    s.doc.undoStack()->push(
        new AddStrokeCommand(&s.doc, add->groupId(), lineStroke({10, 10}, {60, 10}, 5, 2.0f)));
    std::vector<SwapSet> sets = s.doc.swapSets();
    std::vector<Layer> layers = s.doc.layers();
    QCOMPARE(sets.size(), std::size_t(1));
    SwapSet &set = sets.front();
    SwapDrawing &drawing = set.drawings.front();
    std::vector<StrokeGroup *> showing;
    StrokeGroup *plain = nullptr;
    for (Frame &f : layers.front().cels)
        for (StrokeGroup &g : f.groups) {
            if (g.swap.set == setId)
                showing.push_back(&g);
            else if (g.name == QLatin1String("Plain"))
                plain = &g;
        }
    QCOMPARE(showing.size(), std::size_t(2));
    QVERIFY(plain);
    // The file is written as damaged: the ids changed everywhere that names them.
    if (clash == QLatin1String("drawing")) {
        drawing.id = layers.front().cels.front().id;
        for (StrokeGroup *g : showing)
            g->swap.drawing = drawing.id;
    } else if (clash == QLatin1String("set")) {
        set.id = plain->id;
        for (StrokeGroup *g : showing)
            g->swap.set = set.id;
    } else {
        drawing.strokes.front().id = plain->strokes.front().id;
        for (StrokeGroup *g : showing)
            g->strokes.front().id = plain->strokes.front().id;
    }
    const QByteArray bytes = serializeFinbook(layers, s.doc.settings(), {}, {}, {}, sets);
    const auto strict = readFinbook(bytes);
    QVERIFY(!strict.hasValue());
    QVERIFY2(strict.error().message.contains(QLatin1String("already used")),
             qPrintable(strict.error().message));
    QStringList problems;
    const auto recovered = recoverFinbook(bytes, &problems);
    QVERIFY(recovered.hasValue());
    QVERIFY2(problems.join(' ').contains(QLatin1String("new ones")),
             qPrintable(problems.join('|')));
    // The set is kept, both frames still show its drawing, and they share its strokes.
    QCOMPARE(recovered->swapSets.size(), std::size_t(1));
    Document doc;
    adoptLoadedDocument(doc, *recovered);
    int linked = 0;
    for (const Frame &f : doc.frames())
        for (const StrokeGroup &g : f.groups)
            linked += g.swap.linked() ? 1 : 0;
    QCOMPARE(linked, 2);
    QString why;
    QVERIFY2(drawingsShared(doc, &why), qPrintable(why));
    // What is saved opens strictly, the same again.
    const QByteArray saved = serializeFinbook(doc);
    const auto again = readFinbook(saved);
    QVERIFY2(again.hasValue(), qPrintable(again ? QString() : again.error().message));
    Document reopened;
    adoptLoadedDocument(reopened, *again);
    QCOMPARE(serializeFinbook(reopened), saved);
    // An edit of the drawing still reaches both frames.
    const auto mouth =
        std::find_if(reopened.frameAt(0).groups.begin(), reopened.frameAt(0).groups.end(),
                     [](const StrokeGroup &g) { return g.name == QLatin1String("Mouth"); });
    QVERIFY(mouth != reopened.frameAt(0).groups.end() && mouth->swap.linked());
    const std::size_t before = mouth->strokes.size();
    reopened.undoStack()->push(
        new AddStrokeCommand(&reopened, mouth->id, lineStroke({1, 1}, {2, 2}, 2, 1.0f)));
    for (const Frame &f : reopened.frames())
        for (const StrokeGroup &g : f.groups)
            if (g.swap.linked())
                QCOMPARE(g.strokes.size(), before + 1);
    QVERIFY2(drawingsShared(reopened, &why), qPrintable(why));
}

void TestSwap::randomEditsUndoExactlyAndKeepDrawingsShared()
{
    const quint32 seed = qEnvironmentVariableIsSet("FINBOOK_SEED")
                             ? quint32(qEnvironmentVariableIntValue("FINBOOK_SEED"))
                             : 20261206u;
    QRandomGenerator rng(seed);
    constexpr int kSequences = 6000;
    int applied = 0, swapped = 0;
    for (int seq = 0; seq < kSequences; ++seq) {
        Scene s;
        s.swappableInTwoFrames();
        s.doc.undoStack()->clear();
        const QByteArray start = serializeFinbook(s.doc);
        const int length = 1 + int(rng.bounded(20));
        for (int i = 0; i < length; ++i) {
            s.doc.undoStack()->push(randomSwapCommand(s.doc, rng).release());
            QString why;
            if (!drawingsShared(s.doc, &why))
                QFAIL(qPrintable(QStringLiteral("seed %1 sequence %2 step %3: %4")
                                     .arg(seed)
                                     .arg(seq)
                                     .arg(i)
                                     .arg(why)));
        }
        applied += s.doc.undoStack()->count();
        swapped += int(s.doc.swapSets().size());
        const QByteArray end = serializeFinbook(s.doc);
        // What is saved opens as it was.
        const auto loaded = readFinbook(end);
        if (!loaded)
            QFAIL(qPrintable(QStringLiteral("seed %1 sequence %2: %3")
                                 .arg(seed)
                                 .arg(seq)
                                 .arg(loaded.error().message)));
        Document reopened;
        adoptLoadedDocument(reopened, *loaded);
        if (seq % 100 == 0) { // through the save's own check of what it wrote
            QTemporaryDir dir;
            if (const auto failed = saveFinbook(s.doc, dir.filePath(QStringLiteral("r.finbook"))))
                QFAIL(qPrintable(failed->message));
        }
        if (serializeFinbook(reopened) != end)
            QFAIL(qPrintable(
                QStringLiteral("reopened differs: seed %1 sequence %2").arg(seed).arg(seq)));
        while (s.doc.undoStack()->canUndo())
            s.doc.undoStack()->undo();
        if (serializeFinbook(s.doc) != start)
            QFAIL(qPrintable(
                QStringLiteral("undo-all differs: seed %1 sequence %2").arg(seed).arg(seq)));
        while (s.doc.undoStack()->canRedo())
            s.doc.undoStack()->redo();
        if (serializeFinbook(s.doc) != end)
            QFAIL(qPrintable(
                QStringLiteral("redo-all differs: seed %1 sequence %2").arg(seed).arg(seq)));
    }
    qInfo("%d sequences, %d commands applied, %d sets at the ends (seed %u)", kSequences, applied,
          swapped, seed);
    QVERIFY(applied > kSequences * 3);
}

QTEST_GUILESS_MAIN(TestSwap)
#include "tst_swap.moc"
