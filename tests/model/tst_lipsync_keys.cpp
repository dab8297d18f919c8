// Keying a mouth from lip sync (issue 49): each tick shows the drawing of its shape, cels are
// split where the mouth changes inside them without changing anything else they show, the
// layer grows to the end of the speech, it is one undo step, and keying again replaces.
#include "stroke_support.h"

#include <finbook/model/commands.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/lipsync/lipsync_keys.h>
#include <finbook/model/lipsync/mouth_cues.h>
#include <finbook/model/swap/mouth_chart.h>
#include <finbook/model/swap/swap_commands.h>

#include <QtTest>

using namespace finbook;
using namespace finbook::model;
using namespace finbook::model::lipsync;
using finbook::testing::lineStroke;

class TestLipSyncKeys : public QObject {
    Q_OBJECT

private slots:
    void eachTickShowsItsShape();
    void splitCelsLookTheSameOtherwise();
    void keyingAgainReplaces();
    void speechPastTheLayerHoldsItsLastCel();
    void aSetWithoutMouthShapesIsRefused();
    void standInsForTheExtendedShapes();
    void closuresOfASentenceLandOnClosedMouths();
};

namespace {
// One layer, one cel held `hold` ticks, holding "Head" (a line) and a mouth chart.
struct Shot {
    Document doc;
    Id mouth = kNoId;
    explicit Shot(int hold, int cels = 1)
    {
        for (int i = 0; i < cels; ++i)
            doc.undoStack()->push(new InsertFrameCommand(&doc, i));
        const Id first = doc.frameAt(0).id;
        auto *head = new AddObjectCommand(&doc, first, -1, QStringLiteral("Head"));
        doc.undoStack()->push(head);
        doc.undoStack()->push(
            new AddStrokeCommand(&doc, head->groupId(), lineStroke({0, 0}, {90, 40}, 5, 3.0f)));
        auto *add = new AddObjectCommand(&doc, first, -1, QStringLiteral("Mouth"));
        doc.undoStack()->push(add);
        mouth = add->groupId();
        doc.undoStack()->push(new NewSwapSetCommand(
            &doc, mouth, mouthChart(doc, QPointF(200, 200), 60, 0xff000000, 2.0f), 8));
        // Later cels are copies of the first (the mouth linked in each).
        for (int i = 1; i < cels; ++i) {
            doc.undoStack()->push(new DeleteFrameCommand(&doc, doc.frameAt(i).id));
            doc.undoStack()->push(new DuplicateFrameCommand(&doc, first, i));
        }
        doc.undoStack()->push(new SetFrameHoldCommand(&doc, first, hold));
        doc.undoStack()->clear();
    }
    // The shape each tick shows (-1: no mouth there).
    std::vector<int> shapesShown() const
    {
        std::vector<int> out;
        for (const Frame &cel : doc.frames()) {
            int shape = -1;
            for (const StrokeGroup &g : cel.groups)
                if (const SwapDrawing *d = doc.swapDrawing(g.swap))
                    shape = mouthChartShape(d->name);
            for (int t = 0; t < cel.hold; ++t)
                out.push_back(shape);
        }
        return out;
    }
};

std::vector<MouthShape> shapes(const char *letters)
{
    std::vector<MouthShape> out;
    for (const char *c = letters; *c; ++c)
        out.push_back(*mouthShapeFromLetter(QLatin1Char(*c)));
    return out;
}

std::vector<int> asInts(const std::vector<MouthShape> &s)
{
    std::vector<int> out;
    for (MouthShape m : s)
        out.push_back(int(m));
    return out;
}
} // namespace

void TestLipSyncKeys::eachTickShowsItsShape()
{
    Shot shot(12);
    const QByteArray before = serializeFinbook(shot.doc);
    const auto keys = shapes("XXAABBCCCDDX");
    const LipSyncResult r = keyMouth(&shot.doc, shot.mouth, 0, keys, QStringLiteral("Lip Sync"));
    QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
    QCOMPARE(r.keyed, 12);
    QCOMPARE(shot.shapesShown(), asInts(keys));
    QCOMPARE(shot.doc.frameCount(), 6); // one cel per run of one shape
    QCOMPARE(shot.doc.undoStack()->count(), 1);
    shot.doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(shot.doc), before);
}

void TestLipSyncKeys::splitCelsLookTheSameOtherwise()
{
    Shot shot(8);
    const StrokeGroup head = shot.doc.frameAt(0).groups[1];
    keyMouth(&shot.doc, shot.mouth, 2, shapes("AAD"), QStringLiteral("Lip Sync"));
    // Ticks 0–1 as they were, 2–4 keyed, 5–7 as they were.
    QCOMPARE(shot.shapesShown(), (std::vector<int>{8, 8, 0, 0, 3, 8, 8, 8}));
    for (const Frame &cel : shot.doc.frames()) {
        const StrokeGroup *h = nullptr;
        for (const StrokeGroup &g : cel.groups)
            if (g.name == QLatin1String("Head"))
                h = &g;
        QVERIFY(h);
        QCOMPARE(h->strokes.size(), head.strokes.size());
        QCOMPARE(*h->strokes[0].data, *head.strokes[0].data); // the same drawing, its own ids
    }
}

void TestLipSyncKeys::keyingAgainReplaces()
{
    Shot shot(1, 10); // a cel per frame, as a drawn animation has
    keyMouth(&shot.doc, shot.mouth, 0, shapes("AAAACCCCXX"), QStringLiteral("Lip Sync"));
    QCOMPARE(shot.doc.frameCount(), 10); // nothing to split
    const auto again = shapes("DDDDDDDDDD");
    keyMouth(&shot.doc, shot.mouth, 0, again, QStringLiteral("Lip Sync"));
    QCOMPARE(shot.shapesShown(), asInts(again));
    shot.doc.undoStack()->undo();
    QCOMPARE(shot.shapesShown(), asInts(shapes("AAAACCCCXX")));
}

void TestLipSyncKeys::speechPastTheLayerHoldsItsLastCel()
{
    Shot shot(4);
    keyMouth(&shot.doc, shot.mouth, 2, shapes("BBBBBB"), QStringLiteral("Lip Sync"));
    QCOMPARE(shot.shapesShown(), (std::vector<int>{8, 8, 1, 1, 1, 1, 1, 1}));
}

void TestLipSyncKeys::aSetWithoutMouthShapesIsRefused()
{
    Shot shot(4);
    // An ordinary swappable object ("1", "2"): no shapes to key.
    auto *add = new AddObjectCommand(&shot.doc, shot.doc.frameAt(0).id, -1, QStringLiteral("Hand"));
    shot.doc.undoStack()->push(add);
    shot.doc.undoStack()->push(
        new AddStrokeCommand(&shot.doc, add->groupId(), lineStroke({0, 0}, {9, 9}, 3, 1.0f)));
    shot.doc.undoStack()->push(new NewSwapSetCommand(&shot.doc, add->groupId(),
                                                     QStringLiteral("Hand"), QStringLiteral("1")));
    const int steps = shot.doc.undoStack()->count();
    const LipSyncResult r =
        keyMouth(&shot.doc, add->groupId(), 0, shapes("AB"), QStringLiteral("Lip Sync"));
    QVERIFY(r.error.contains(QStringLiteral("A to F")));
    QCOMPARE(shot.doc.undoStack()->count(), steps);
    // Not swappable at all, and nothing to key.
    QVERIFY(
        !keyMouth(&shot.doc, shot.doc.frameAt(0).groups[0].id, 0, shapes("A"), {}).error.isEmpty());
    QVERIFY(!keyMouth(&shot.doc, shot.mouth, 0, {}, {}).error.isEmpty());
    QCOMPARE(shot.doc.undoStack()->count(), steps);
}

void TestLipSyncKeys::standInsForTheExtendedShapes()
{
    SwapSet set;
    for (const char *name : {"A", "B", "C", "D", "E", "F"})
        set.drawings.push_back(SwapDrawing{Id(set.drawings.size() + 1),
                                           QString::fromLatin1(name),
                                           {},
                                           {},
                                           kDefaultMeshDensity,
                                           {}});
    const auto ids = drawingsForShapes(set);
    QVERIFY(ids);
    QCOMPARE((*ids)[std::size_t(MouthShape::G)], (*ids)[std::size_t(MouthShape::B)]);
    QCOMPARE((*ids)[std::size_t(MouthShape::H)], (*ids)[std::size_t(MouthShape::C)]);
    QCOMPARE((*ids)[std::size_t(MouthShape::X)], (*ids)[std::size_t(MouthShape::A)]);
    set.drawings.pop_back(); // no F
    QVERIFY(!drawingsForShapes(set));
}

void TestLipSyncKeys::closuresOfASentenceLandOnClosedMouths()
{
    // "Bob made my mom a pie", timed by hand at speaking pace: every M, B and P must be a
    // closed mouth (A) on the frame it is heard or the one before.
    const std::vector<TimedPhone> phones = {
        {"SIL", 0.0, 0.20}, {"B", 0.20, 0.26},  {"AA", 0.26, 0.40}, {"B", 0.40, 0.46},
        {"M", 0.50, 0.58},  {"EY", 0.58, 0.74}, {"D", 0.74, 0.80},  {"M", 0.82, 0.90},
        {"AY", 0.90, 1.06}, {"M", 1.10, 1.18},  {"AA", 1.18, 1.32}, {"M", 1.32, 1.40},
        {"AH", 1.40, 1.48}, {"P", 1.52, 1.58},  {"AY", 1.58, 1.80}, {"SIL", 1.80, 2.2}};
    const double fps = 24.0;
    const auto cues = mouthCuesFromPhones(phones, fps);
    const auto perFrame = mouthShapesPerFrame(cues, fps, int(2.2 * fps));
    Shot shot(1);
    QVERIFY(
        keyMouth(&shot.doc, shot.mouth, 0, perFrame, QStringLiteral("Lip Sync")).error.isEmpty());
    const std::vector<int> shown = shot.shapesShown();
    QCOMPARE(shown.size(), perFrame.size());
    for (const TimedPhone &p : phones) {
        if (p.phone != QLatin1String("M") && p.phone != QLatin1String("B") &&
            p.phone != QLatin1String("P"))
            continue;
        const int heard = int(p.start * fps);
        const bool closed =
            shown[std::size_t(heard)] == 0 || (heard > 0 && shown[std::size_t(heard - 1)] == 0);
        QVERIFY2(closed, qPrintable(QStringLiteral("%1 at %2 s").arg(p.phone).arg(p.start)));
    }
    QCOMPARE(shown.back(), 8); // rests at the end
}

QTEST_GUILESS_MAIN(TestLipSyncKeys)
#include "tst_lipsync_keys.moc"
