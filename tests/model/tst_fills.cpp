// Fills: the Fill tool's commands, fills following stroke edits (split, erase, move, undo),
// every deformer, Apply Pose, Duplicate Frame, in-betweens, rendering and the file.
#include "bake_support.h"
#include "fill_support.h"

#include <finbook/model/deform_setup.h>
#include <finbook/model/erase/stroke_cut.h>
#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/fill/fill_regions.h>
#include <finbook/model/fill/fill_render.h>
#include <finbook/model/fill/fill_resolve.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/rig/rig_commands.h>

#include <QTest>

using namespace finbook::model;
using finbook::testing::polylineStroke;
using finbook::testing::squareCorners;
using finbook::testing::squareDocument;

namespace {
constexpr QRgb kRed = 0xffe03020;
constexpr QRgb kBlue = 0xff2040e0;

void push(Document &doc, std::unique_ptr<QUndoCommand> command)
{
    QVERIFY(command);
    doc.undoStack()->push(command.release());
}

std::vector<FillItem> shown(const Document &doc, Id g)
{
    return fillList(*doc.group(g), doc.settings().closeGap);
}

QRectF shownRect(const Document &doc, Id g)
{
    QRectF r;
    for (const FillItem &item : shown(doc, g))
        r = r.united(item.path.boundingRect());
    return r;
}

// How many faces show a fill.
int filledFaces(const Document &doc, Id g)
{
    const StrokeGroup &group = *doc.group(g);
    const auto regions = objectRegions(group, doc.settings().closeGap);
    const auto owners = faceFills(*regions, group.fills);
    return int(std::count_if(owners.begin(), owners.end(), [](int f) { return f >= 0; }));
}

bool near(QRectF a, QRectF b, double tolerance)
{
    return std::abs(a.left() - b.left()) <= tolerance && std::abs(a.top() - b.top()) <= tolerance &&
           std::abs(a.right() - b.right()) <= tolerance &&
           std::abs(a.bottom() - b.bottom()) <= tolerance;
}

// The distance from p to the nearest segment of the object's strokes as shown.
double distanceToInk(const StrokeGroup &g, QPointF p)
{
    double best = 1e300;
    for (std::size_t s = 0; s < g.strokes.size(); ++s) {
        const auto &pts = displayedPoints(g, s);
        for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
            const QPointF a(pts[i].x, pts[i].y), b(pts[i + 1].x, pts[i + 1].y);
            const QPointF d = b - a;
            const double len2 = QPointF::dotProduct(d, d);
            const double t =
                len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, d) / len2, 0.0, 1.0) : 0.0;
            best = std::min(best, QLineF(p, a + t * d).length());
        }
    }
    return best;
}

Rig translatedRig(RigKind kind, QPointF by)
{
    Rig rig;
    switch (kind) {
    case RigKind::Pins:
        rig.pins = {{1, QPointF(100, 100), QPointF(100, 100) + by},
                    {2, QPointF(200, 200), QPointF(200, 200) + by}};
        break;
    case RigKind::Cage:
        rig.cage.rest = {{80, 80}, {220, 80}, {220, 220}, {80, 220}};
        for (const QPointF &p : rig.cage.rest)
            rig.cage.posed.push_back(p + by);
        break;
    case RigKind::Skeleton:
        rig.skeleton.joints = {{150, 110}, {150, 190}};
        rig.skeleton.parent = {-1, 0};
        rig.skeleton.radius = {5, 5};
        rig.skeleton.root = 0;
        rig.skeleton.angles = {0.0, 0.0};
        rig.skeleton.rootOffset = by;
        break;
    case RigKind::None:
        break;
    }
    return rig;
}

// Bends the rig: pins one corner further, the cage's one corner, the skeleton's second bone.
Rig bentRig(RigKind kind)
{
    Rig rig = translatedRig(kind, QPointF(0, 0));
    switch (kind) {
    case RigKind::Pins:
        rig.pins[1].target = QPointF(240, 170);
        break;
    case RigKind::Cage:
        rig.cage.posed[2] = QPointF(260, 250);
        break;
    case RigKind::Skeleton:
        rig.skeleton.angles = {0.0, 0.5};
        break;
    case RigKind::None:
        break;
    }
    return rig;
}

// Poses object g with `rig` as the deform service would (bake_support.h).
bool pose(Document &doc, Id g, const Rig &rig)
{
    return finbook::testing::poseObject(doc, g, rig).isEmpty();
}
} // namespace

class TestFills : public QObject {
    Q_OBJECT
private slots:
    void linesOfNoInkGoWithTheInkedLinesTheyJoin();
    void fillRecolourRemoveEachOneUndoStep();
    void clickOutsideAnyRegionFillsNothing();
    void fillAllEnclosedRegions();
    void splitRegionKeepsFillOnBothHalves();
    void vanishedRegionDropsFillUndoBringsItBack();
    void movedOutlineKeepsItsFill();
    void fillsFollowEveryDeformer_data();
    void fillsFollowEveryDeformer();
    void applyPoseKeepsFills();
    void duplicateFrameCopiesFills();
    void closeGapSettingIsOneUndoStep();
    void closeGapSessionIsOneStep();
    void renderPaintsFillUnderStrokes();
    void fillsMeetingAlongALineOfNoInkShowNoSeam();
    void onionSkinTintsFills();
    void saveLoadRoundTrip();
    void olderFilesOpenWithoutFills();
    void damagedFillChunkIsRefused();
    void fillIdNoStrokeCanHaveIsRefusedAndRecovered();
    void aFillOfSeveralRegionsIsOneFill();
    void aFillWhoseOutlineLeftTheFaceYieldsIt();
    void erasingTheLineBetweenTwoFillsKeepsTheLargersColour();
};

void TestFills::fillRecolourRemoveEachOneUndoStep()
{
    Document doc;
    const Id g = squareDocument(doc);
    push(doc, fillRegionCommand(&doc, g, QPointF(150, 150), kRed));
    QCOMPARE(doc.undoStack()->count(), 1);
    QCOMPARE(doc.undoStack()->text(0), QStringLiteral("Fill Region"));
    QCOMPARE(doc.group(g)->fills.size(), std::size_t(1));
    QCOMPARE(doc.group(g)->fills[0].color, kRed);
    QCOMPARE(doc.group(g)->fills[0].strokes, std::vector<Id>{doc.group(g)->strokes[0].id});
    QVERIFY(near(shownRect(doc, g), QRectF(100, 100, 100, 100), 2.0));
    // The same colour again changes nothing: no command.
    QVERIFY(!fillRegionCommand(&doc, g, QPointF(120, 170), kRed));
    push(doc, fillRegionCommand(&doc, g, QPointF(120, 170), kBlue));
    QCOMPARE(doc.undoStack()->text(1), QStringLiteral("Recolour Fill"));
    QCOMPARE(doc.group(g)->fills.size(), std::size_t(1));
    QCOMPARE(doc.group(g)->fills[0].color, kBlue);
    push(doc, removeFillCommand(&doc, g, QPointF(150, 150)));
    QVERIFY(doc.group(g)->fills.empty());
    QVERIFY(shown(doc, g).empty());
    QVERIFY(!removeFillCommand(&doc, g, QPointF(150, 150)));
    doc.undoStack()->undo();
    QCOMPARE(doc.group(g)->fills[0].color, kBlue);
    doc.undoStack()->undo();
    QCOMPARE(doc.group(g)->fills[0].color, kRed);
    doc.undoStack()->undo();
    QVERIFY(doc.group(g)->fills.empty());
    doc.undoStack()->redo();
    QCOMPARE(doc.group(g)->fills[0].color, kRed);
}

void TestFills::clickOutsideAnyRegionFillsNothing()
{
    Document doc;
    const Id g = squareDocument(doc);
    QVERIFY(!fillRegionCommand(&doc, g, QPointF(400, 400), kRed));
    QVERIFY(!fillRegionCommand(&doc, g, QPointF(150, 50), kRed));
    QCOMPARE(doc.undoStack()->count(), 0);
}

void TestFills::fillAllEnclosedRegions()
{
    Document doc;
    const Id g = squareDocument(doc);
    // A divider makes two regions.
    doc.undoStack()->push(new AddStrokeCommand(
        &doc, g, polylineStroke(QPolygonF{QPointF(150, 100), QPointF(150, 200)})));
    push(doc, fillAllRegionsCommand(&doc, g, kRed));
    QCOMPARE(doc.undoStack()->text(1), QStringLiteral("Fill All Enclosed Regions"));
    QCOMPARE(doc.group(g)->fills.size(), std::size_t(2));
    QCOMPARE(filledFaces(doc, g), 2);
    QVERIFY(!fillAllRegionsCommand(&doc, g, kRed)); // nothing left to fill
    doc.undoStack()->undo();
    QVERIFY(doc.group(g)->fills.empty());
}

void TestFills::splitRegionKeepsFillOnBothHalves()
{
    Document doc;
    const Id g = squareDocument(doc);
    push(doc, fillRegionCommand(&doc, g, QPointF(150, 150), kRed));
    const std::vector<Fill> before = doc.group(g)->fills;
    doc.undoStack()->push(new AddStrokeCommand(
        &doc, g, polylineStroke(QPolygonF{QPointF(150, 95), QPointF(150, 205)})));
    QCOMPARE(objectRegions(*doc.group(g), -1)->faceCount(), 2);
    QCOMPARE(filledFaces(doc, g), 2);
    QVERIFY(near(shownRect(doc, g), QRectF(100, 100, 100, 100), 2.0));
    QCOMPARE(doc.group(g)->fills, before); // the fill itself did not change
    doc.undoStack()->undo();
    QCOMPARE(filledFaces(doc, g), 1);
    QCOMPARE(doc.group(g)->fills, before);
}

void TestFills::vanishedRegionDropsFillUndoBringsItBack()
{
    Document doc;
    doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
    const Id g = doc.frameAt(0).groups.at(0).id;
    // Four sides, one stroke each.
    const QPolygonF c = squareCorners(QRectF(100, 100, 100, 100));
    for (int i = 0; i < 4; ++i)
        doc.undoStack()->push(new AddStrokeCommand(&doc, g, polylineStroke({c[i], c[i + 1]})));
    push(doc, fillRegionCommand(&doc, g, QPointF(150, 150), kRed));
    QCOMPARE(doc.group(g)->fills.front().strokes.size(), std::size_t(4));
    // One side gone leaves a cup: its mouth is closed (regions.h), and the region keeps its
    // fill. A second side gone leaves an L, which closes nothing: the fill goes.
    doc.undoStack()->push(new RemoveStrokeCommand(&doc, doc.group(g)->strokes[1].id));
    QCOMPARE(objectRegions(*doc.group(g), -1)->faceCount(), 1);
    QVERIFY(objectRegions(*doc.group(g), -1)->regions().closures.at(0).mouth);
    QCOMPARE(filledFaces(doc, g), 1);
    doc.undoStack()->push(new RemoveStrokeCommand(&doc, doc.group(g)->strokes[1].id));
    QCOMPARE(objectRegions(*doc.group(g), -1)->faceCount(), 0);
    QVERIFY(shown(doc, g).empty());
    doc.undoStack()->undo();
    QCOMPARE(filledFaces(doc, g), 1);
    doc.undoStack()->undo();
    QCOMPARE(filledFaces(doc, g), 1);
    QVERIFY(near(shownRect(doc, g), QRectF(100, 100, 100, 100), 2.0));
}

void TestFills::movedOutlineKeepsItsFill()
{
    Document doc;
    const Id g = squareDocument(doc);
    push(doc, fillRegionCommand(&doc, g, QPointF(150, 150), kRed));
    // The Select tool's move replaces the strokes, ids kept: the seed is left behind.
    std::vector<Stroke> moved = doc.group(g)->strokes;
    auto data = std::make_shared<StrokeData>(*moved[0].data);
    for (StrokePoint &p : data->points)
        p.x += 300;
    moved[0].data = data;
    doc.setStrokes(g, moved);
    QCOMPARE(filledFaces(doc, g), 1);
    QVERIFY(near(shownRect(doc, g), QRectF(400, 100, 100, 100), 2.0));
}

void TestFills::fillsFollowEveryDeformer_data()
{
    QTest::addColumn<int>("kind");
    QTest::newRow("pins") << int(RigKind::Pins);
    QTest::newRow("cage") << int(RigKind::Cage);
    QTest::newRow("skeleton") << int(RigKind::Skeleton);
}

void TestFills::fillsFollowEveryDeformer()
{
    QFETCH(int, kind);
    Document doc;
    const Id g = squareDocument(doc);
    push(doc, fillRegionCommand(&doc, g, QPointF(150, 150), kRed));
    // A rigid move moves the fill with it.
    const QPointF by(40, -25);
    QVERIFY(pose(doc, g, translatedRig(RigKind(kind), by)));
    QVERIFY(doc.group(g)->isDeformed());
    QVERIFY2(near(shownRect(doc, g), QRectF(100, 100, 100, 100).translated(by), 2.5),
             qPrintable(QStringLiteral("%1 %2 %3 %4")
                            .arg(shownRect(doc, g).left())
                            .arg(shownRect(doc, g).top())
                            .arg(shownRect(doc, g).right())
                            .arg(shownRect(doc, g).bottom())));
    // A bend: every corner of the fill's outline stays on the posed ink.
    QVERIFY(pose(doc, g, bentRig(RigKind(kind))));
    const StrokeGroup &group = *doc.group(g);
    const auto items = shown(doc, g);
    QCOMPARE(items.size(), std::size_t(1));
    const QRectF rest(100, 100, 100, 100);
    QVERIFY(!near(items[0].path.boundingRect(), rest, 3.0)); // it did move
    for (const QPolygonF &ring : items[0].path.toSubpathPolygons())
        for (const QPointF &p : ring)
            QVERIFY2(distanceToInk(group, p) < 1.5,
                     qPrintable(QStringLiteral("(%1, %2) is %3 px off the ink")
                                    .arg(p.x())
                                    .arg(p.y())
                                    .arg(distanceToInk(group, p))));
    // A click on the posed region finds it (recolour).
    const QPointF centre = items[0].path.boundingRect().center();
    push(doc, fillRegionCommand(&doc, g, centre, kBlue));
    QCOMPARE(doc.group(g)->fills.size(), std::size_t(1));
    QCOMPARE(doc.group(g)->fills[0].color, kBlue);
}

void TestFills::applyPoseKeepsFills()
{
    Document doc;
    const Id g = squareDocument(doc);
    push(doc, fillRegionCommand(&doc, g, QPointF(150, 150), kRed));
    const std::vector<Fill> rest = doc.group(g)->fills;
    const QPointF by(200, 50);
    QVERIFY(pose(doc, g, translatedRig(RigKind::Pins, by)));
    const QRectF posed = shownRect(doc, g);
    doc.undoStack()->push(new ApplyPoseCommand(&doc, g));
    QVERIFY(!doc.group(g)->isDeformed() || !doc.group(g)->rig.isPosed());
    QVERIFY(near(shownRect(doc, g), posed, 1.0));
    // The seed moved with the drawing: it lies inside the region where it is now.
    QVERIFY(QRectF(100, 100, 100, 100).translated(by).contains(doc.group(g)->fills[0].seed));
    doc.undoStack()->undo();
    QCOMPARE(doc.group(g)->fills, rest);
    QVERIFY(near(shownRect(doc, g), posed, 1.0));
}

void TestFills::duplicateFrameCopiesFills()
{
    Document doc;
    const Id g = squareDocument(doc);
    push(doc, fillRegionCommand(&doc, g, QPointF(150, 150), kRed));
    doc.undoStack()->push(new DuplicateFrameCommand(&doc, doc.frameAt(0).id, 1));
    QCOMPARE(doc.frameCount(), 2);
    const StrokeGroup &copy = doc.frameAt(1).groups.at(0);
    QCOMPARE(copy.fills.size(), std::size_t(1));
    // The copy's fill names the copy's strokes.
    QCOMPARE(copy.fills[0].strokes, std::vector<Id>{copy.strokes[0].id});
    QCOMPARE(filledFaces(doc, copy.id), 1);
}

// The Close gaps box's arrow clicks of one session are one step; a session that ends where it
// began leaves none; the command changes no other setting.
void TestFills::closeGapSessionIsOneStep()
{
    Document doc;
    doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
    doc.undoStack()->clear();
    for (double gap : {1.0, 2.0, 5.0, 10.0})
        push(doc, setCloseGapCommand(&doc, gap, 1));
    QCOMPARE(doc.undoStack()->count(), 1);
    QCOMPARE(doc.settings().closeGap, 10.0);
    push(doc, setCloseGapCommand(&doc, 20.0, 2));
    push(doc, setCloseGapCommand(&doc, 10.0, 2)); // back where session 2 began
    QCOMPARE(doc.undoStack()->count(), 1);
    QCOMPARE(doc.settings().closeGap, 10.0);
    DocumentSettings faster = doc.settings();
    faster.fps = doc.settings().fps + 6;
    doc.undoStack()->push(new ChangeSettingsCommand(&doc, faster));
    push(doc, setCloseGapCommand(&doc, 30.0, 3));
    doc.undoStack()->undo();
    QCOMPARE(doc.settings(), faster);
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QCOMPARE(doc.settings().closeGap, -1.0);
    QCOMPARE(doc.settings().fps, faster.fps - 6);
}

void TestFills::closeGapSettingIsOneUndoStep()
{
    Document doc;
    doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
    const Id g = doc.frameAt(0).groups.at(0).id;
    // A C: a square open by 20 px on the right side.
    doc.undoStack()->push(new AddStrokeCommand(
        &doc, g,
        polylineStroke(QPolygonF{QPointF(200, 140), QPointF(200, 100), QPointF(100, 100),
                                 QPointF(100, 200), QPointF(200, 200), QPointF(200, 160)})));
    doc.undoStack()->clear();
    push(doc, setCloseGapCommand(&doc, 0.0));
    QCOMPARE(doc.settings().closeGap, 0.0);
    QCOMPARE(objectRegions(*doc.group(g), doc.settings().closeGap)->faceCount(), 0);
    QVERIFY(!fillRegionCommand(&doc, g, QPointF(150, 150), kRed));
    push(doc, setCloseGapCommand(&doc, 30.0));
    QCOMPARE(objectRegions(*doc.group(g), doc.settings().closeGap)->faceCount(), 1);
    push(doc, fillRegionCommand(&doc, g, QPointF(150, 150), kRed));
    QVERIFY(!setCloseGapCommand(&doc, 30.0));
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QCOMPARE(doc.settings().closeGap, 0.0);
    doc.undoStack()->undo();
    QCOMPARE(doc.settings().closeGap, -1.0);
}

void TestFills::renderPaintsFillUnderStrokes()
{
    Document doc;
    const Id g = squareDocument(doc);
    push(doc, fillRegionCommand(&doc, g, QPointF(150, 150), kRed));
    DocumentSettings settings = doc.settings();
    settings.canvasSize = QSize(300, 300);
    const QImage image = renderFrame(doc.frameAt(0), settings, QSize(300, 300));
    QCOMPARE(image.pixel(150, 150), kRed);
    QCOMPARE(image.pixel(250, 250), 0xffffffffu); // outside: the background
    // The ink is drawn over the fill.
    QCOMPARE(image.pixel(100, 150), 0xff000000u);
}

// Two fills of one colour that meet along a line of no ink (a closed gap; Apply Pose's cut-out
// closers) paint as one: the paper does not show through between their anti-aliased edges.
void TestFills::fillsMeetingAlongALineOfNoInkShowNoSeam()
{
    Document doc;
    const Id g = squareDocument(doc);
    doc.undoStack()->push(
        new AddStrokeCommand(&doc, g, lineOfNoInk({QPointF(92, 96), QPointF(208, 204)}, 3.0)));
    push(doc, fillRegionCommand(&doc, g, QPointF(175, 125), kRed));
    push(doc, fillRegionCommand(&doc, g, QPointF(125, 175), kRed));
    // A square inside one of them, of the same colour: a face nested in a face's hole.
    doc.undoStack()->push(
        new AddStrokeCommand(&doc, g, polylineStroke(squareCorners(QRectF(160, 112, 24, 24)))));
    push(doc, fillRegionCommand(&doc, g, QPointF(172, 124), kRed));
    QCOMPARE(filledFaces(doc, g), 3);
    QCOMPARE(doc.group(g)->fills.size(), std::size_t(3));
    DocumentSettings settings = doc.settings();
    settings.canvasSize = QSize(300, 300);
    const QImage image = renderFrame(doc.frameAt(0), settings, QSize(300, 300));
    int worst = 0; // the largest channel difference from the fill's colour along the line
    for (int x = 110; x <= 190; ++x)
        for (int y = 90; y <= 210; ++y) {
            const QRgb c = image.pixel(x, y);
            if (std::abs(y - (96 + (x - 92) * 108.0 / 116.0)) > 3)
                continue;
            worst =
                std::max({worst, std::abs(qRed(c) - qRed(kRed)), std::abs(qGreen(c) - qGreen(kRed)),
                          std::abs(qBlue(c) - qBlue(kRed))});
        }
    QVERIFY2(worst <= 8, qPrintable(QString::number(worst)));
    // Joined into one path, the nested face and the one round it are both painted.
    for (const QPoint p : {QPoint(172, 124), QPoint(190, 110), QPoint(120, 180)})
        QCOMPARE(image.pixel(p), kRed);
}

void TestFills::onionSkinTintsFills()
{
    Document doc;
    const Id g = squareDocument(doc);
    push(doc, fillRegionCommand(&doc, g, QPointF(150, 150), kRed));
    RenderOptions options;
    options.tint = QColor(0, 200, 0);
    const auto items = fillList(*doc.group(g), -1, options);
    QCOMPARE(items.size(), std::size_t(1));
    QCOMPARE(qGreen(items[0].color), 200);
    QCOMPARE(qRed(items[0].color), 0);
    QVERIFY(qAlpha(items[0].color) < 255);
}

void TestFills::saveLoadRoundTrip()
{
    Document doc;
    const Id g = squareDocument(doc);
    doc.undoStack()->push(new AddStrokeCommand(
        &doc, g, polylineStroke(QPolygonF{QPointF(150, 100), QPointF(150, 200)})));
    push(doc, fillRegionCommand(&doc, g, QPointF(120, 150), kRed));
    push(doc, fillRegionCommand(&doc, g, QPointF(180, 150), 0x80102030));
    push(doc, setCloseGapCommand(&doc, 12.0));
    const QByteArray bytes = serializeFinbook(doc);
    auto loaded = readFinbook(bytes);
    QVERIFY2(loaded, loaded ? "" : qPrintable(loaded.error().message));
    QCOMPARE(loaded->formatVersion, kFinbookFormatVersion);
    QCOMPARE(loaded->settings.closeGap, 12.0);
    QCOMPARE(loaded->frames.at(0).groups.at(0).fills, doc.group(g)->fills);
    Document reopened;
    adoptLoadedDocument(reopened, std::move(*loaded));
    QCOMPARE(serializeFinbook(reopened), bytes);
}

void TestFills::olderFilesOpenWithoutFills()
{
    for (const char *name : {"/tests/data/format_v1_sample.finbook", "/tests/data/walk_v2.finbook",
                             "/tests/data/walk_v1.finbook"}) {
        auto loaded = loadFinbook(QStringLiteral(FINBOOK_SOURCE_DIR) + QLatin1String(name));
        QVERIFY2(loaded, name);
        QVERIFY(loaded->formatVersion < kFinbookFormatVersion);
        QCOMPARE(loaded->settings.closeGap, -1.0);
        for (const Frame &f : loaded->frames)
            for (const StrokeGroup &group : f.groups)
                QVERIFY(group.fills.empty());
    }
}

void TestFills::damagedFillChunkIsRefused()
{
    Document doc;
    const Id g = squareDocument(doc);
    push(doc, fillRegionCommand(&doc, g, QPointF(150, 150), kRed));
    // A fill whose seed is NaN (written by hand: the commands never make one).
    std::vector<Fill> fills = doc.group(g)->fills;
    fills[0].seed = QPointF(std::nan(""), 0);
    doc.setFills(g, fills);
    const auto loaded = readFinbook(serializeFinbook(doc.frames(), doc.settings()));
    QVERIFY(!loaded);
    QVERIFY2(loaded.error().message.contains(QStringLiteral("fill")),
             qPrintable(loaded.error().message));
}

void TestFills::fillIdNoStrokeCanHaveIsRefusedAndRecovered()
{
    // A fill naming an id above kMaxId (found by the fuzzer): the writer counts fill ids
    // towards the next free id, so once loaded such a file saved as one no Finbook could open.
    Document doc;
    const Id g = squareDocument(doc);
    push(doc, fillRegionCommand(&doc, g, QPointF(150, 150), kRed));
    std::vector<Fill> fills = doc.group(g)->fills;
    QVERIFY(!fills.at(0).strokes.empty());
    const std::vector<Id> kept = fills[0].strokes;
    fills[0].strokes.push_back(kMaxId + 7);
    doc.setFills(g, fills);
    const QByteArray bytes = serializeFinbook(doc.frames(), doc.settings());
    QVERIFY(!readFinbook(bytes));

    QStringList problems;
    auto recovered = recoverFinbook(bytes, &problems);
    QVERIFY2(recovered, recovered ? "" : qPrintable(recovered.error().message));
    QVERIFY2(problems.join(u'\n').contains(QStringLiteral("fill")),
             qPrintable(problems.join(u'\n')));
    QCOMPARE(recovered->frames.at(0).groups.at(0).fills.at(0).strokes, kept);
    QVERIFY(recovered->nextId <= kMaxId + 1);
    Document again;
    adoptLoadedDocument(again, std::move(*recovered));
    auto reread = readFinbook(serializeFinbook(again));
    QVERIFY2(reread, reread ? "" : qPrintable(reread.error().message));

    // A valid id above every stroke's still counts: the next free id is past it.
    Document valid;
    const Id h = squareDocument(valid);
    push(valid, fillRegionCommand(&valid, h, QPointF(150, 150), kRed));
    std::vector<Fill> far = valid.group(h)->fills;
    far[0].strokes.push_back(Id(1) << 40);
    valid.setFills(h, far);
    auto loaded = readFinbook(serializeFinbook(valid.frames(), valid.settings()));
    QVERIFY2(loaded, loaded ? "" : qPrintable(loaded.error().message));
    QVERIFY(loaded->nextId > (Id(1) << 40));
}

// A fill of two regions (Fill::more, as Apply Pose makes where crossing lines cut one region
// in parts): both show its colour; the Fill tool recolours both with one click and empties
// only the region clicked; a cut stroke, Duplicate Frame and the file keep both regions.
void TestFills::aFillOfSeveralRegionsIsOneFill()
{
    Document doc;
    const Id g = squareDocument(doc);
    doc.undoStack()->push(
        new AddStrokeCommand(&doc, g, polylineStroke(squareCorners(QRectF(300, 100, 100, 100)))));
    push(doc, fillRegionCommand(&doc, g, QPointF(150, 150), kRed));
    const Id left = doc.group(g)->strokes[0].id, right = doc.group(g)->strokes[1].id;
    std::vector<Fill> fills = doc.group(g)->fills;
    QCOMPARE(fills.size(), std::size_t(1));
    fills[0].more.push_back({QPointF(350, 150), {right}});
    doc.setFills(g, fills);
    doc.undoStack()->clear();
    QCOMPARE(filledFaces(doc, g), 2);
    QVERIFY(near(shownRect(doc, g), QRectF(100, 100, 300, 100), 2.0));

    push(doc, fillRegionCommand(&doc, g, QPointF(360, 170), kBlue)); // one click: both
    QCOMPARE(doc.group(g)->fills.size(), std::size_t(1));
    QCOMPARE(doc.group(g)->fills[0].color, kBlue);
    QCOMPARE(doc.group(g)->fills[0].more.size(), std::size_t(1));
    QCOMPARE(filledFaces(doc, g), 2);

    push(doc, removeFillCommand(&doc, g, QPointF(360, 170))); // only the region clicked
    QCOMPARE(doc.group(g)->fills.size(), std::size_t(1));
    QVERIFY(doc.group(g)->fills[0].more.empty());
    QCOMPARE(filledFaces(doc, g), 1);
    QVERIFY(near(shownRect(doc, g), QRectF(100, 100, 100, 100), 2.0));
    doc.undoStack()->undo();
    QCOMPARE(filledFaces(doc, g), 2);
    push(doc, removeFillCommand(&doc, g, QPointF(150, 150))); // its first: the other stays
    QCOMPARE(doc.group(g)->fills.size(), std::size_t(1));
    QCOMPARE(doc.group(g)->fills[0].strokes, std::vector<Id>{right});
    QVERIFY(near(shownRect(doc, g), QRectF(300, 100, 100, 100), 2.0));
    doc.undoStack()->undo();
    QCOMPARE(doc.group(g)->fills[0].strokes, std::vector<Id>{left});

    // Cutting the right square's outline: the region's strokes follow the pieces.
    const auto pieces = cutStroke(*doc.group(g)->strokes[1].data, {QPointF(350, 100)}, 2.0);
    QVERIFY(pieces && pieces->size() == 2);
    std::vector<Id> ids = pushStrokeCut(&doc, right, *pieces);
    std::sort(ids.begin(), ids.end());
    QCOMPARE(doc.group(g)->fills[0].more.at(0).strokes, ids);
    QCOMPARE(filledFaces(doc, g), 2); // the gap is narrower than Close gaps

    // Duplicate Frame: the copy's regions name the copy's strokes, and both show.
    doc.undoStack()->push(new DuplicateFrameCommand(&doc, doc.frameAt(0).id, 1));
    const StrokeGroup &copy = doc.frameAt(1).groups.at(0);
    QCOMPARE(copy.fills.at(0).strokes, std::vector<Id>{copy.strokes[0].id});
    QCOMPARE(copy.fills.at(0).more.at(0).strokes,
             (std::vector<Id>{copy.strokes[1].id, copy.strokes[2].id}));
    QCOMPARE(filledFaces(doc, copy.id), 2);

    // The file: both regions come back, and the bytes are the same when saved again.
    const QByteArray bytes = serializeFinbook(doc);
    QVERIFY(bytes.contains("FPLC"));
    auto loaded = readFinbook(bytes);
    QVERIFY2(loaded, loaded ? "" : qPrintable(loaded.error().message));
    QCOMPARE(loaded->frames.at(0).groups.at(0).fills, doc.group(g)->fills);
    Document reopened;
    adoptLoadedDocument(reopened, std::move(*loaded));
    QCOMPARE(serializeFinbook(reopened), bytes);
    // A further region whose seed is not a number is refused, as a first one is.
    fills = doc.group(g)->fills;
    fills[0].more[0].seed = QPointF(0, std::nan(""));
    doc.setFills(g, fills);
    const auto damaged = readFinbook(serializeFinbook(doc.frames(), doc.settings()));
    QVERIFY(!damaged);
    QVERIFY2(damaged.error().message.contains(QStringLiteral("fill")),
             qPrintable(damaged.error().message));
}

// Two fills whose seeds lie in one face (a head moved over the seed of the region where it
// overlapped the body, in the random characters of tst_pose_bake): the face goes to the fill
// all of whose strokes still bound it, not to the one a stroke of which now bounds another
// face only, even when that one shares more strokes with the face (a moved head that touches
// an arm gains the arm's line; the overlap's fill had it too).
void TestFills::aFillWhoseOutlineLeftTheFaceYieldsIt()
{
    Document doc;
    doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
    const Id g = doc.frameAt(0).groups.at(0).id;
    // A square of four lines that cross at its corners (a top, b right, d bottom, e left),
    // and a small square c apart.
    const QPolygonF lines[] = {{QPointF(90, 100), QPointF(210, 100)},
                               {QPointF(200, 90), QPointF(200, 210)},
                               {QPointF(210, 200), QPointF(90, 200)},
                               {QPointF(100, 210), QPointF(100, 90)},
                               squareCorners(QRectF(300, 100, 50, 50))};
    for (const QPolygonF &line : lines)
        doc.undoStack()->push(new AddStrokeCommand(&doc, g, polylineStroke(line)));
    const auto &s = doc.group(g)->strokes;
    const Id a = s[0].id, b = s[1].id, d = s[2].id, c = s[4].id;
    const auto regions = objectRegions(*doc.group(g), doc.settings().closeGap);
    const int face = regions->faceAt(QPointF(150, 150));
    QVERIFY(face >= 0);
    QCOMPARE(regions->faceStrokeIds(face).size(), std::size_t(4));
    const auto sorted = [](std::vector<Id> ids) {
        std::sort(ids.begin(), ids.end());
        return ids;
    };
    const Fill kept{kRed, QPointF(140, 140), sorted({a, b}), {}, {}};
    const Fill moved{kBlue, QPointF(160, 160), sorted({a, b, d, c}), {}, {}};
    // The share of strokes in common alone would give the face to `moved` (3 of 5 against 2 of
    // 4), and so would its place later in the list.
    QCOMPARE(faceFills(*regions, {kept, moved})[std::size_t(face)], 0);
    QCOMPARE(faceFills(*regions, {moved, kept})[std::size_t(face)], 1);
    // Without c, `moved` ties best and, later, wins.
    Fill alsoHere = moved;
    alsoHere.strokes = sorted({a, b, d});
    QCOMPARE(faceFills(*regions, {kept, alsoHere})[std::size_t(face)], 1);
}

// Two regions made one by erasing the line between them: both fills are tied equally to the
// strokes left, and the merged region shows the larger one's colour, whichever was filled last.
// Undo brings both back.
void TestFills::erasingTheLineBetweenTwoFillsKeepsTheLargersColour()
{
    for (const bool smallFirst : {false, true}) {
        Document doc;
        const Id g = squareDocument(doc, QRectF(100, 100, 200, 100));
        doc.undoStack()->push(new AddStrokeCommand(
            &doc, g, polylineStroke(QPolygonF{QPointF(250, 95), QPointF(250, 205)})));
        const Id divider = doc.group(g)->strokes.back().id;
        const QPointF big(150, 150), small(275, 150);
        push(doc, fillRegionCommand(&doc, g, smallFirst ? small : big, smallFirst ? kBlue : kRed));
        push(doc, fillRegionCommand(&doc, g, smallFirst ? big : small, smallFirst ? kRed : kBlue));
        QCOMPARE(filledFaces(doc, g), 2);
        const std::vector<Fill> before = doc.group(g)->fills;
        doc.undoStack()->push(new RemoveStrokeCommand(&doc, divider));
        const auto regions = objectRegions(*doc.group(g), doc.settings().closeGap);
        QCOMPARE(regions->faceCount(), 1);
        const std::vector<int> owners = faceFills(*regions, doc.group(g)->fills);
        QVERIFY(owners.at(0) >= 0);
        QCOMPARE(doc.group(g)->fills.at(std::size_t(owners.at(0))).color, kRed);
        QCOMPARE(doc.group(g)->fills, before); // the fills themselves did not change
        doc.undoStack()->undo();
        QCOMPARE(filledFaces(doc, g), 2);
        const auto again = objectRegions(*doc.group(g), doc.settings().closeGap);
        const std::vector<int> two = faceFills(*again, doc.group(g)->fills);
        for (const QPointF p : {big, small}) {
            const int face = again->faceAt(p);
            QVERIFY(face >= 0);
            QCOMPARE(doc.group(g)->fills.at(std::size_t(two.at(std::size_t(face)))).color,
                     p == big ? kRed : kBlue);
        }
    }
}

// What a lasso picks after Apply Pose (tool_select): a line of no ink stays picked only when
// every inked line its ends lie on is picked, and joins when all of them are; the parts of a
// line that Apply Pose split share their ends across the hidden ones and are one line.
void TestFills::linesOfNoInkGoWithTheInkedLinesTheyJoin()
{
    StrokeGroup g;
    const auto add = [&](Id id, QPolygonF points, QRgb colour) {
        g.strokes.push_back({id, polylineStroke(points, 4.0, 3.0f, colour)});
    };
    // A and B: two inked lines; C: a gap closer from A to B; D: a closer from A back to A; H:
    // a hidden part of B's line, beginning where B ends; E: the shown part after H.
    add(1, {QPointF(0, 0), QPointF(100, 0)}, 0xff000000);                        // A
    add(2, {QPointF(0, 50), QPointF(100, 50)}, 0xff000000);                      // B
    add(3, {QPointF(50, 0), QPointF(50, 50)}, kGapCloserColor);                  // C
    add(4, {QPointF(20, 0), QPointF(20, -20), QPointF(40, 0)}, kGapCloserColor); // D
    add(5, {QPointF(100, 50), QPointF(150, 50)}, kHiddenLineColor);              // H
    add(6, {QPointF(150, 50), QPointF(200, 50)}, 0xff000000);                    // E
    const auto sorted = [](std::vector<Id> ids) {
        std::sort(ids.begin(), ids.end());
        return ids;
    };
    // A lassoed with every line of no ink near it: C goes (it ends on B), H goes (it joins B
    // and E), D stays.
    QCOMPARE(sorted(withLinesOfNoInk(g, {1, 3, 4, 5})), (std::vector<Id>{1, 4}));
    // A alone: D, both of whose ends lie on A, joins.
    QCOMPARE(sorted(withLinesOfNoInk(g, {1})), (std::vector<Id>{1, 4}));
    // Everything inked: every line of no ink joins.
    QCOMPARE(sorted(withLinesOfNoInk(g, {1, 2, 6})), (std::vector<Id>{1, 2, 3, 4, 5, 6}));
    // The lines as drawn: B, H and E are one (B's end is H's start, H's end E's start).
    std::vector<std::vector<std::size_t>> lines = linesOfParts(g);
    for (auto &line : lines)
        std::sort(line.begin(), line.end());
    std::sort(lines.begin(), lines.end());
    QCOMPARE(lines, (std::vector<std::vector<std::size_t>>{{0}, {1, 4, 5}, {2}, {3}}));
}

QTEST_MAIN(TestFills)
#include "tst_fills.moc"
