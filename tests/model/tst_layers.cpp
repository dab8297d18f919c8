// Layers (issue 46): cels over ticks, composing a shot, layer edits undone exactly, time inserted
// and deleted on chosen layers only, multiplane parallax checked by pixels, the "LAYR" section,
// and old files opening as one layer.
#include "stroke_support.h"
#include "tst_file_sample.h"

#include <finbook/model/camera/camera_commands.h>
#include <finbook/model/commands.h>
#include <finbook/model/document.h>
#include <finbook/model/export/export_plan.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/scene/layer_commands.h>
#include <finbook/model/scene/shot.h>

#include <QtTest>

#include <cmath>

using namespace finbook;
using namespace finbook::model;

namespace {

// A cel of `hold` ticks holding one object with a short dot of ink at `at` (none: empty).
Frame cel(Id &next, int hold, std::optional<QPointF> at = std::nullopt)
{
    Frame f;
    f.id = next++;
    f.hold = hold;
    if (at) {
        StrokeGroup g;
        g.id = next++;
        g.strokes.push_back(
            {next++, testing::lineStroke(*at - QPointF(0.5, 0), *at + QPointF(0.5, 0), 2, 8.0f)});
        f.groups.push_back(std::move(g));
    }
    return f;
}

Layer layer(Id &next, const QString &name, std::vector<int> holds, QPointF at = {20, 20})
{
    Layer l;
    l.id = next++;
    l.properties.name = name;
    for (int h : holds)
        l.cels.push_back(cel(next, h, at));
    return l;
}

// Background (one cel, 8 ticks), character (cels of 2), blink (empty 3, shut 1, empty 2).
void scene(Document &doc, QSize page = QSize(200, 100))
{
    Id next = 1;
    std::vector<Layer> layers;
    layers.push_back(layer(next, QStringLiteral("bg"), {8}, {150, 50}));
    layers.push_back(layer(next, QStringLiteral("walk"), {2, 2, 2, 2}, {60, 50}));
    Layer blink;
    blink.id = next++;
    blink.properties.name = QStringLiteral("blink");
    blink.cels.push_back(cel(next, 3));
    blink.cels.push_back(cel(next, 1, QPointF(100, 20)));
    blink.cels.push_back(cel(next, 2));
    layers.push_back(std::move(blink));
    DocumentSettings settings;
    settings.canvasSize = page;
    doc.reset(std::move(layers), settings, next);
}

std::vector<Id> celIds(const Layer &l)
{
    std::vector<Id> ids;
    for (const Frame &f : l.cels)
        ids.push_back(f.id);
    return ids;
}

} // namespace

class TestLayers : public QObject {
    Q_OBJECT
private slots:
    void celsFollowEachOther();
    void shotComposesTheLayersAtATick();
    void shotsSplitWhereAnyLayerChanges();
    void currentLayerIsWhatFramesMean();
    void layerEditsUndoExactly();
    void lastLayerStays();
    void exposureEditsMoveOnlyTheirLayer();
    void insertAndDeleteTimeOnChosenLayers();
    void editsOnAnotherLayerUndoExactly();
    void celsMoveWithinALayer();
    void celsMoveAcrossLayers();
    void altDragCopiesCels();
    void pastedCelsGoWhereTheyAreDropped();
    void removedCelsPullWhatFollows();
    void lockedLayersRefuseCelEdits();
    void parallaxFollowsTheFactor();
    void exportThroughTheCameraMovesDepthLayersLess();
    void opacityAndVisibilityReachTheExport();
    void layersRoundTripByteIdentical();
    void badLayerListsAreRefusedOrMended();
    void olderFilesOpenAsOneLayer();
};

void TestLayers::celsFollowEachOther()
{
    Document doc;
    scene(doc);
    const Layer &blink = doc.layerAt(2);
    QCOMPARE(celTicks(blink.cels), qint64(6));
    QCOMPARE(celStart(blink.cels, 0), qint64(0));
    QCOMPARE(celStart(blink.cels, 2), qint64(4));
    QCOMPARE(celStart(blink.cels, 3), qint64(6));
    QCOMPARE(celAt(blink.cels, 0), 0);
    QCOMPARE(celAt(blink.cels, 2), 0);
    QCOMPARE(celAt(blink.cels, 3), 1);
    QCOMPARE(celAt(blink.cels, 5), 2);
    QCOMPARE(celAt(blink.cels, 6), -1); // past the layer's end
    QCOMPARE(celAt(blink.cels, -1), -1);
    QCOMPARE(shotTicks(doc.layers()), qint64(8));
}

void TestLayers::shotComposesTheLayersAtATick()
{
    Document doc;
    scene(doc);
    const Frame at3 = composeShot(doc.layers(), 3);
    QCOMPARE(at3.planes.size(), std::size_t(3));
    QCOMPARE(at3.groups.size(), std::size_t(3)); // bg, walk, the shut blink
    QCOMPARE(at3.groups[0].id, doc.layerAt(0).cels[0].groups[0].id);
    QCOMPARE(at3.groups[1].id, doc.layerAt(1).cels[1].groups[0].id);
    QCOMPARE(at3.groups[2].id, doc.layerAt(2).cels[1].groups[0].id);
    QCOMPARE(at3.planes[0].groupEnd, 1);
    QCOMPARE(at3.planes[2].groupEnd, 3);
    // Past the blink layer's end only the others show; a hidden layer does not.
    QCOMPARE(composeShot(doc.layers(), 7).planes.size(), std::size_t(2));
    LayerProperties hidden = doc.layerAt(0).properties;
    hidden.visible = false;
    doc.undoStack()->push(new SetLayerPropertiesCommand(&doc, doc.layerAt(0).id, hidden, "h"));
    QCOMPARE(composeShot(doc.layers(), 3).groups.size(), std::size_t(2));
    ShotFilter all;
    all.hiddenToo = true;
    QCOMPARE(composeShot(doc.layers(), 3, all).groups.size(), std::size_t(3));
    ShotFilter only;
    only.onlyLayers = {doc.layerAt(1).id};
    QCOMPARE(composeShot(doc.layers(), 3, only).groups.size(), std::size_t(1));
}

void TestLayers::shotsSplitWhereAnyLayerChanges()
{
    Document doc;
    scene(doc);
    const std::vector<Frame> shots = composeShots(doc.layers());
    // Changes at 2 (walk), 3 (blink), 4 (walk, blink), 6 (walk; blink ends), 8 (end).
    std::vector<int> holds;
    qint64 total = 0;
    for (const Frame &f : shots) {
        holds.push_back(f.hold);
        total += f.hold;
    }
    QCOMPARE(holds, (std::vector<int>{2, 1, 1, 2, 2}));
    QCOMPARE(total, shotTicks(doc.layers()));
    // Each stretch shows what composeShot shows at its first tick.
    qint64 tick = 0;
    for (const Frame &f : shots) {
        const Frame at = composeShot(doc.layers(), tick);
        QCOMPARE(f.groups.size(), at.groups.size());
        for (std::size_t i = 0; i < f.groups.size(); ++i)
            QCOMPARE(f.groups[i].id, at.groups[i].id);
        QCOMPARE(f.planes, at.planes);
        tick += f.hold;
    }
}

void TestLayers::currentLayerIsWhatFramesMean()
{
    Document doc;
    scene(doc);
    // Opened on the layer with the most drawings.
    QCOMPARE(doc.currentLayer().properties.name, QStringLiteral("walk"));
    QCOMPARE(doc.frameCount(), 4);
    QSignalSpy current(&doc, &Document::currentLayerChanged);
    doc.setCurrentLayer(doc.layerAt(2).id);
    QCOMPARE(current.count(), 1);
    QCOMPARE(doc.frameCount(), 3);
    // Ids reach every layer; locations say which.
    const Id bgGroup = doc.layerAt(0).cels[0].groups[0].id;
    const GroupLocation at = doc.locateGroup(bgGroup);
    QCOMPARE(at.layer, 0);
    QCOMPARE(at.frame, 0);
    QCOMPARE(doc.frameAt(at).groups[0].id, bgGroup);
    QCOMPARE(doc.frameIndex(doc.layerAt(0).cels[0].id), -1); // not in the current layer
    QCOMPARE(doc.celIndex(doc.layerAt(0).cels[0].id), 0);
    QCOMPARE(doc.layerOfFrame(doc.layerAt(0).cels[0].id), doc.layerAt(0).id);
    // Frame commands work on the current layer.
    doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
    QCOMPARE(doc.layerAt(2).cels.size(), std::size_t(4));
    QCOMPARE(doc.layerAt(1).cels.size(), std::size_t(4));
}

void TestLayers::layerEditsUndoExactly()
{
    Document doc;
    scene(doc);
    const QByteArray before = serializeFinbook(doc);
    QUndoStack &stack = *doc.undoStack();
    auto *add = new AddLayerCommand(&doc, 1, QStringLiteral("new"));
    stack.push(add);
    QCOMPARE(doc.layerCount(), 4);
    QCOMPARE(doc.layerAt(1).properties.name, QStringLiteral("new"));
    QCOMPARE(celTicks(doc.layerAt(1).cels), qint64(8)); // exposed for the whole shot
    auto *copy = new DuplicateLayerCommand(&doc, doc.layerAt(3).id);
    stack.push(copy);
    QCOMPARE(doc.layerCount(), 5);
    const Layer &source = doc.layerAt(3), &dup = doc.layerAt(4);
    QCOMPARE(dup.id, copy->layerId());
    QCOMPARE(dup.cels.size(), source.cels.size());
    QVERIFY(dup.cels[1].id != source.cels[1].id);
    QVERIFY(dup.cels[1].groups[0].id != source.cels[1].groups[0].id);
    QCOMPARE(dup.cels[1].groups[0].strokes[0].data, source.cels[1].groups[0].strokes[0].data);
    stack.push(new MoveLayerCommand(&doc, doc.layerAt(0).id, 4));
    QCOMPARE(doc.layerAt(4).properties.name, QStringLiteral("bg"));
    LayerProperties p = doc.layerAt(2).properties;
    p.opacity = 0.25;
    p.depth = 2.0;
    p.locked = true;
    p.name = QStringLiteral("renamed");
    stack.push(new SetLayerPropertiesCommand(&doc, doc.layerAt(2).id, p, QStringLiteral("p")));
    QCOMPARE(doc.layerAt(2).properties, p);
    stack.push(new RemoveLayerCommand(&doc, doc.layerAt(1).id));
    QCOMPARE(doc.layerCount(), 4);
    const QByteArray after = serializeFinbook(doc);
    while (stack.canUndo())
        stack.undo();
    QCOMPARE(serializeFinbook(doc), before);
    while (stack.canRedo())
        stack.redo();
    QCOMPARE(serializeFinbook(doc), after);
}

void TestLayers::lastLayerStays()
{
    Document doc;
    QCOMPARE(doc.layerCount(), 1); // a new document has one
    RemoveLayerCommand remove(&doc, doc.currentLayerId());
    QVERIFY(remove.isObsolete());
    doc.undoStack()->push(new AddLayerCommand(&doc, 1, QStringLiteral("two")));
    const Id two = doc.layerAt(1).id;
    doc.setCurrentLayer(two);
    doc.undoStack()->push(new RemoveLayerCommand(&doc, two));
    QCOMPARE(doc.layerCount(), 1);
    QCOMPARE(doc.currentLayerIndex(), 0); // the one below took over
    doc.undoStack()->undo();
    QCOMPARE(doc.layerCount(), 2);
}

void TestLayers::exposureEditsMoveOnlyTheirLayer()
{
    Document doc;
    scene(doc);
    const std::vector<Id> bgBefore = celIds(doc.layerAt(0));
    const Id walk1 = doc.layerAt(1).cels[1].id;
    doc.undoStack()->push(new SetFrameHoldCommand(&doc, walk1, 5));
    QCOMPARE(celStart(doc.layerAt(1).cels, 2), qint64(7));
    QCOMPARE(celAt(doc.layerAt(1).cels, 6), 1);
    QCOMPARE(celTicks(doc.layerAt(2).cels), qint64(6)); // others keep their timing
    QCOMPARE(celIds(doc.layerAt(0)), bgBefore);
    QCOMPARE(shotTicks(doc.layers()), qint64(11));
    doc.undoStack()->undo();
    QCOMPARE(shotTicks(doc.layers()), qint64(8));
}

void TestLayers::insertAndDeleteTimeOnChosenLayers()
{
    Document doc;
    scene(doc);
    const QByteArray before = serializeFinbook(doc);
    const Id walk = doc.layerAt(1).id, blink = doc.layerAt(2).id;
    // Two ticks at tick 3 on the walk and the blink: their cels there last longer.
    auto insert = insertTimeCommand(&doc, {walk, blink}, 3, 2);
    QVERIFY(insert);
    doc.undoStack()->push(insert.release());
    QCOMPARE(doc.layerAt(1).cels[1].hold, 4);
    QCOMPARE(doc.layerAt(2).cels[1].hold, 3);
    QCOMPARE(celTicks(doc.layerAt(0).cels), qint64(8)); // not chosen: unmoved
    QCOMPARE(celAt(doc.layerAt(2).cels, 5), 1);
    // Nothing at the tick: no command.
    QVERIFY(!insertTimeCommand(&doc, {blink}, 50, 1));
    // Deleting 3 ticks from tick 2 on the walk: cel 1 (ticks 2..5) loses 3, keeps 1 tick.
    auto removed = deleteTimeCommand(&doc, {walk}, 2, 3);
    QVERIFY(removed);
    doc.undoStack()->push(removed.release());
    QCOMPARE(doc.layerAt(1).cels[1].hold, 1);
    QCOMPARE(doc.layerAt(1).cels.size(), std::size_t(4));
    // A stretch covering whole cels deletes them (a layer keeps one).
    auto wide = deleteTimeCommand(&doc, {walk}, 0, 100);
    QVERIFY(wide);
    doc.undoStack()->push(wide.release());
    QCOMPARE(doc.layerAt(1).cels.size(), std::size_t(1));
    while (doc.undoStack()->canUndo())
        doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(doc), before);
}

// Cel edits undo and redo to the same bytes.
namespace {
void pushAndCheckUndo(Document &doc, std::unique_ptr<QUndoCommand> command)
{
    const QByteArray before = serializeFinbook(doc);
    QVERIFY(command);
    doc.undoStack()->push(command.release());
    const QByteArray after = serializeFinbook(doc);
    QVERIFY(after != before);
    doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(doc), before);
    doc.undoStack()->redo();
    QCOMPARE(serializeFinbook(doc), after);
}
} // namespace

void TestLayers::celsMoveWithinALayer()
{
    Document doc;
    scene(doc);
    const std::vector<Id> walk = celIds(doc.layerAt(1)); // cels at ticks 0, 2, 4, 6
    // Boundaries of 2-tick cels are at 0, 2, 4, 6, 8: the nearest to a tick.
    QCOMPARE(celBoundaryNear(doc.layerAt(1).cels, 0), 0);
    QCOMPARE(celBoundaryNear(doc.layerAt(1).cels, 3), 1); // a tie goes to the earlier
    QCOMPARE(celBoundaryNear(doc.layerAt(1).cels, 5), 2);
    QCOMPARE(celBoundaryNear(doc.layerAt(1).cels, 100), 4);
    QCOMPARE(celBoundaryNear({}, 7), 0);
    // The first cel dragged 6 ticks later lands at tick 6, the end once it is gone (the rest
    // start at 0, 2, 4 and end at 6).
    pushAndCheckUndo(doc, rearrangeCelsCommand(&doc, {walk[0]}, 0, 6, false));
    QCOMPARE(celIds(doc.layerAt(1)), (std::vector<Id>{walk[1], walk[2], walk[3], walk[0]}));
    // Two cels dragged to the start keep their order.
    pushAndCheckUndo(doc, rearrangeCelsCommand(&doc, {walk[3], walk[2]}, 0, -10, false));
    QCOMPARE(celIds(doc.layerAt(1)), (std::vector<Id>{walk[2], walk[3], walk[1], walk[0]}));
    // A drag that lands where the cels are is no edit.
    QVERIFY(!rearrangeCelsCommand(&doc, {walk[2]}, 0, 0, false));
    QVERIFY(!rearrangeCelsCommand(&doc, {walk[2]}, 0, 1, false));
    QCOMPARE(celTicks(doc.layerAt(1).cels), qint64(8)); // holds travel with their cels
}

void TestLayers::celsMoveAcrossLayers()
{
    Document doc;
    scene(doc);
    const QByteArray start = serializeFinbook(doc);
    const std::vector<Id> walk = celIds(doc.layerAt(1)), blink = celIds(doc.layerAt(2));
    // The walk's second cel (ticks 2..3) up one row onto the blink at tick 4: between the
    // blink's "shut" cel (ends at 4) and its last.
    pushAndCheckUndo(doc, rearrangeCelsCommand(&doc, {walk[1]}, +1, 2, false));
    QCOMPARE(celIds(doc.layerAt(1)), (std::vector<Id>{walk[0], walk[2], walk[3]}));
    QCOMPARE(celIds(doc.layerAt(2)), (std::vector<Id>{blink[0], blink[1], walk[1], blink[2]}));
    QCOMPARE(doc.layerOfFrame(walk[1]), doc.layerAt(2).id);
    QVERIFY(!doc.layerAt(2).cels[2].groups.empty()); // the drawing went with it
    // Outside the layers, or onto a locked one: refused.
    QVERIFY(!rearrangeCelsCommand(&doc, {walk[0]}, +2, 0, false));
    QVERIFY(!rearrangeCelsCommand(&doc, {doc.layerAt(0).cels[0].id}, -1, 0, false));
    // Every cel of the blink down one row: the blink keeps an empty tick.
    pushAndCheckUndo(doc, rearrangeCelsCommand(&doc, celIds(doc.layerAt(2)), -1, 0, false));
    QCOMPARE(doc.layerAt(2).cels.size(), std::size_t(1));
    QVERIFY(doc.layerAt(2).cels[0].groups.empty());
    QCOMPARE(doc.layerAt(2).cels[0].hold, 1);
    QCOMPARE(doc.layerAt(1).cels.size(), std::size_t(7));
    // Two rows at once: the background's cel and the walk's first up one row each.
    pushAndCheckUndo(
        doc, rearrangeCelsCommand(&doc, {doc.layerAt(0).cels[0].id, doc.layerAt(1).cels[0].id}, +1,
                                  0, false));
    while (doc.undoStack()->canUndo())
        doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(doc), start);
}

void TestLayers::altDragCopiesCels()
{
    Document doc;
    scene(doc);
    const std::vector<Id> walk = celIds(doc.layerAt(1));
    const Frame original = doc.layerAt(1).cels[0];
    pushAndCheckUndo(doc, rearrangeCelsCommand(&doc, {walk[0]}, +1, 6, true));
    QCOMPARE(celIds(doc.layerAt(1)), walk); // the original stays
    const Layer &blink = doc.layerAt(2);
    QCOMPARE(blink.cels.size(), std::size_t(4));
    const Frame &copy = blink.cels[3]; // tick 6 is the blink's end
    QVERIFY(copy.id != original.id);
    QCOMPARE(copy.hold, original.hold);
    QCOMPARE(copy.groups.size(), original.groups.size());
    QVERIFY(copy.groups[0].id != original.groups[0].id);
    QVERIFY(copy.groups[0].strokes[0].id != original.groups[0].strokes[0].id);
    QCOMPARE(copy.groups[0].strokes[0].data->points, original.groups[0].strokes[0].data->points);
    // Copies of two cels land in order.
    pushAndCheckUndo(doc, rearrangeCelsCommand(&doc, {walk[0], walk[1]}, 0, 8, true));
    QCOMPARE(doc.layerAt(1).cels.size(), std::size_t(6));
    QCOMPARE(doc.layerAt(1).cels[4].groups[0].strokes[0].data->points,
             doc.layerAt(1).cels[0].groups[0].strokes[0].data->points);
    QCOMPARE(doc.layerAt(1).cels[5].groups[0].strokes[0].data->points,
             doc.layerAt(1).cels[1].groups[0].strokes[0].data->points);
}

void TestLayers::pastedCelsGoWhereTheyAreDropped()
{
    Document doc;
    scene(doc);
    // Two rows copied (walk cel 0, blink cel 1), pasted into the background at tick 8: the
    // walk's cel after the background's, the blink's onto the walk after its last.
    std::vector<std::vector<Frame>> rows{{doc.layerAt(1).cels[0]}, {doc.layerAt(2).cels[1]}};
    pushAndCheckUndo(doc, pasteCelsCommand(&doc, rows, doc.layerAt(0).id, 8));
    QCOMPARE(doc.layerAt(0).cels.size(), std::size_t(2));
    QCOMPARE(doc.layerAt(1).cels.size(), std::size_t(5));
    QCOMPARE(doc.layerAt(1).cels[4].hold, 1);
    QCOMPARE(doc.layerAt(2).cels.size(), std::size_t(3)); // no third row
    // Pasted twice, the copies have ids of their own.
    pushAndCheckUndo(doc, pasteCelsCommand(&doc, rows, doc.layerAt(0).id, 0));
    std::vector<Id> all;
    for (const Layer &l : doc.layers())
        for (const Frame &f : l.cels)
            all.push_back(f.id);
    std::sort(all.begin(), all.end());
    QVERIFY(std::adjacent_find(all.begin(), all.end()) == all.end());
    QCOMPARE(doc.layerAt(0).cels.size(), std::size_t(3));
    // Rows above the front layer go nowhere.
    QVERIFY(!pasteCelsCommand(&doc, {{}, {doc.layerAt(2).cels[1]}}, doc.layerAt(2).id, 0));
}

void TestLayers::removedCelsPullWhatFollows()
{
    Document doc;
    scene(doc);
    const std::vector<Id> walk = celIds(doc.layerAt(1));
    pushAndCheckUndo(doc, removeCelsCommand(&doc, {walk[1], doc.layerAt(0).cels[0].id}));
    QCOMPARE(celIds(doc.layerAt(1)), (std::vector<Id>{walk[0], walk[2], walk[3]}));
    QCOMPARE(celStart(doc.layerAt(1).cels, 1), qint64(2));
    // The background's only cel went: it keeps an empty tick.
    QCOMPARE(doc.layerAt(0).cels.size(), std::size_t(1));
    QVERIFY(doc.layerAt(0).cels[0].groups.empty());
    QVERIFY(!removeCelsCommand(&doc, {}));
}

void TestLayers::lockedLayersRefuseCelEdits()
{
    Document doc;
    scene(doc);
    LayerProperties p = doc.layerAt(1).properties;
    p.locked = true;
    doc.undoStack()->push(new SetLayerPropertiesCommand(&doc, doc.layerAt(1).id, p, {}));
    const std::vector<Id> walk = celIds(doc.layerAt(1));
    QVERIFY(!rearrangeCelsCommand(&doc, {walk[0]}, 0, 5, false));
    QVERIFY(!rearrangeCelsCommand(&doc, {doc.layerAt(2).cels[0].id}, -1, 0, false));
    QVERIFY(!removeCelsCommand(&doc, walk));
    QVERIFY(!pasteCelsCommand(&doc, {{doc.layerAt(0).cels[0]}}, doc.layerAt(1).id, 0));
    QCOMPARE(celIds(doc.layerAt(1)), walk);
}

void TestLayers::editsOnAnotherLayerUndoExactly()
{
    // A stroke added to the background while the walk is current, then the blink made
    // current: undo and redo still reach the background.
    Document doc;
    scene(doc);
    const QByteArray before = serializeFinbook(doc);
    const Id bgGroup = doc.layerAt(0).cels[0].groups[0].id;
    doc.undoStack()->push(new AddStrokeCommand(
        &doc, bgGroup, testing::lineStroke(QPointF(1, 1), QPointF(30, 30), 5, 2.0f)));
    QCOMPARE(doc.layerAt(0).cels[0].groups[0].strokes.size(), std::size_t(2));
    doc.setCurrentLayer(doc.layerAt(2).id);
    doc.undoStack()->push(new RemoveObjectCommand(&doc, bgGroup));
    QVERIFY(doc.layerAt(0).cels[0].groups.empty());
    const QByteArray after = serializeFinbook(doc);
    doc.setCurrentLayer(doc.layerAt(1).id);
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(doc), before);
    doc.undoStack()->redo();
    doc.undoStack()->redo();
    QCOMPARE(serializeFinbook(doc), after);
}

void TestLayers::parallaxFollowsTheFactor()
{
    const QSizeF page(200, 100);
    const CameraState rest = restCamera(page);
    CameraState moved = rest;
    moved.center = rest.center + QPointF(40, -20);
    moved.zoom = 4.0;
    moved.rotation = 30.0;
    QCOMPARE(planeCamera(moved, 0.0, page), moved);
    const CameraState far = planeCamera(moved, 1.0, page); // f = 1/2
    QCOMPARE(far.center, rest.center + QPointF(20, -10));
    QVERIFY(std::abs(far.zoom - 2.0) < 1e-12); // 4^(1/2)
    QCOMPARE(far.rotation, 30.0);
    const CameraState near = planeCamera(moved, -0.5, page); // f = 2
    QCOMPARE(near.center, rest.center + QPointF(80, -40));
    QVERIFY(std::abs(near.zoom - 16.0) < 1e-9);
    QCOMPARE(planeCamera(rest, 3.0, page), rest); // at rest every plane is as drawn
}

void TestLayers::exportThroughTheCameraMovesDepthLayersLess()
{
    // Two dots at (100, 50), the middle of a 200 × 100 page: one on a layer at depth 0, one
    // on a layer at depth 1. The camera pans 40 px right: the page's dot moves 40 px left in
    // the shot, the deep one 20 px.
    for (const double depth : {0.0, 1.0}) {
        Document doc;
        Id next = 1;
        std::vector<Layer> layers;
        layers.push_back(layer(next, QStringLiteral("a"), {1}, {100, 50}));
        layers.back().properties.depth = depth;
        layers.push_back(layer(next, QStringLiteral("b"), {1}));
        layers.back().cels[0].groups.clear(); // an empty stretch over it
        DocumentSettings settings;
        settings.canvasSize = QSize(200, 100);
        doc.reset(std::move(layers), settings, next);
        CameraKey k;
        k.center = QPointF(140, 50);
        doc.undoStack()->push(setCameraKeyCommand(&doc, k).release());
        const ExportSource source = exportSource(doc);
        const auto plan = planExport(source, ExportOptions{});
        QVERIFY(plan);
        QCOMPARE(source.frames.size(), std::size_t(1));
        const QImage shot = renderExportFrame(source.frames[0], source.settings, *plan, nullptr, {},
                                              &plan->cameras.at(0));
        const QPointF expected(100 - 40 / (1 + depth), 50);
        QVERIFY2(QLineF(testing::darkCentre(shot), expected).length() < 0.75,
                 qPrintable(QStringLiteral("depth %1: dot at %2,%3")
                                .arg(depth)
                                .arg(testing::darkCentre(shot).x())
                                .arg(testing::darkCentre(shot).y())));
    }
}

void TestLayers::opacityAndVisibilityReachTheExport()
{
    Document doc;
    scene(doc);
    const auto plan = planExport(exportSource(doc), ExportOptions{});
    QVERIFY(plan);
    // At tick 0: the background's dot at (150, 50) is dark.
    const auto darkAt = [&](const ExportSource &s, QPoint p) {
        const QImage image = renderExportFrame(s.frames.at(0), s.settings, *plan);
        return qGray(image.pixel(p));
    };
    const int full = darkAt(exportSource(doc), QPoint(150, 50));
    QVERIFY(full < 60);
    LayerProperties p = doc.layerAt(0).properties;
    p.opacity = 0.5;
    doc.undoStack()->push(new SetLayerPropertiesCommand(&doc, doc.layerAt(0).id, p, "o"));
    const int half = darkAt(exportSource(doc), QPoint(150, 50));
    QVERIFY2(half > 100 && half < 160, qPrintable(QString::number(half)));
    p.visible = false;
    doc.undoStack()->push(new SetLayerPropertiesCommand(&doc, doc.layerAt(0).id, p, "v"));
    QCOMPARE(darkAt(exportSource(doc), QPoint(150, 50)), 255);
    // --layers picks a hidden layer too.
    ShotFilter only;
    only.hiddenToo = true;
    only.onlyLayers = {doc.layerAt(0).id};
    QVERIFY(darkAt(exportSource(doc, only), QPoint(150, 50)) < 160);
    QCOMPARE(darkAt(exportSource(doc, only), QPoint(60, 50)), 255);
}

void TestLayers::layersRoundTripByteIdentical()
{
    Document doc;
    scene(doc);
    LayerProperties p = doc.layerAt(2).properties;
    p.opacity = 0.3;
    p.depth = -0.25;
    p.locked = true;
    p.visible = false;
    p.onionSkin = false;
    p.name = QStringLiteral("Blink — 瞬き");
    doc.undoStack()->push(new SetLayerPropertiesCommand(&doc, doc.layerAt(2).id, p, "p"));
    const QByteArray bytes = serializeFinbook(doc);
    QVERIFY(bytes.contains("LAYR"));
    auto loaded = readFinbook(bytes);
    QVERIFY2(loaded, loaded ? "" : qPrintable(loaded.error().message));
    QCOMPARE(loaded->layers.size(), std::size_t(3));
    QCOMPARE(loaded->layers[2].properties, p);
    Document reopened;
    adoptLoadedDocument(reopened, std::move(*loaded));
    QCOMPARE(reopened.layerCount(), 3);
    for (int i = 0; i < 3; ++i) {
        QCOMPARE(reopened.layerAt(i).id, doc.layerAt(i).id);
        QCOMPARE(celIds(reopened.layerAt(i)), celIds(doc.layerAt(i)));
    }
    QCOMPARE(serializeFinbook(reopened), bytes);
}

void TestLayers::badLayerListsAreRefusedOrMended()
{
    Document doc;
    scene(doc);
    const QByteArray good = serializeFinbook(doc);
    // The layer list's first cel count says 2 instead of 1: the counts no longer add up.
    QByteArray bad = good;
    bad[file_test::sectionPayload(bad, "LAYR") + 4 + 8] = 2;
    file_test::refreshChecksums(bad); // only the count is wrong, not the bytes
    auto refused = readFinbook(bad);
    QVERIFY(!refused);
    QVERIFY2(refused.error().message.contains(QLatin1String("layers hold")),
             qPrintable(refused.error().message));
    QStringList problems;
    auto recovered = recoverFinbook(bad, &problems);
    QVERIFY(recovered);
    qint64 cels = 0;
    for (const LoadedLayer &l : recovered->layers)
        cels += l.cels;
    QCOMPARE(cels, qint64(recovered->frames.size())); // every frame kept, on some layer
    QVERIFY(!problems.isEmpty());
}

void TestLayers::olderFilesOpenAsOneLayer()
{
    const QString v2 = QStringLiteral(FINBOOK_SOURCE_DIR "/tests/data/walk_v2.finbook");
    Document doc;
    const auto error = openFinbook(doc, v2);
    QVERIFY2(!error, error ? qPrintable(error->message) : "");
    QCOMPARE(doc.layerCount(), 1);
    auto loaded = loadFinbook(v2);
    QVERIFY(loaded);
    QVERIFY(loaded->layers.empty());
    QCOMPARE(doc.frames().size(), loaded->frames.size());
    // The drawings as they were: the same frames give the same bytes.
    QCOMPARE(serializeFinbook(doc.frames(), doc.settings()),
             serializeFinbook(loaded->frames, loaded->settings));
    // The layer's id is new (the file's next free id), and saving writes today's format.
    QVERIFY(doc.currentLayerId() >= loaded->nextId);
    QVERIFY(serializeFinbook(doc).contains("LAYR"));
}

QTEST_GUILESS_MAIN(TestLayers)
#include "tst_layers.moc"
