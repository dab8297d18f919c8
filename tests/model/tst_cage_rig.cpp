// The cage in the model: placing, posing, editing and removing a cage, switching from pins,
// the checks that refuse bad cages, the CAGE chunk, and the converged pin pose that is kept.
#include <finbook/model/cage/cage_commands.h>
#include <finbook/model/cage/cage_setup.h>
#include <finbook/model/deform_controller.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/pins/pin_commands.h>

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace finbook;
using namespace finbook::model;

namespace {

StrokeDataPtr wave(float x0, float y0, float length, int n)
{
    auto data = std::make_shared<StrokeData>();
    for (int i = 0; i < n; ++i) {
        const float t = float(i) / float(n - 1);
        data->points.push_back({x0 + t * length, y0 + 10.0f * std::sin(t * 7.0f), 1.0f});
    }
    data->width = 4.0f;
    return data;
}

Id makeDrawing(Document &doc)
{
    Frame f;
    f.id = doc.allocateId();
    StrokeGroup g;
    g.id = doc.allocateId();
    g.name = QStringLiteral("worm");
    g.strokes.push_back({doc.allocateId(), wave(100, 100, 300, 150)});
    g.strokes.push_back({doc.allocateId(), wave(100, 130, 300, 150)});
    f.groups.push_back(g);
    doc.reset({f}, DocumentSettings{}, doc.nextId());
    return g.id;
}

// A concave (U-shaped) cage around the drawing: the top edge dips between the ends.
std::vector<QPointF> uCage()
{
    return {{60, 60}, {240, 60}, {250, 80}, {260, 60}, {440, 60}, {440, 180}, {60, 180}};
}

bool waitSolved(DeformController &controller, Id groupId)
{
    QSignalSpy solved(&controller, &DeformController::poseSolved);
    QSignalSpy failed(&controller, &DeformController::errorOccurred);
    if (controller.setup(groupId) && !controller.isWaiting(groupId))
        return true;
    for (int i = 0; i < 200 && solved.isEmpty() && failed.isEmpty(); ++i)
        solved.wait(50);
    for (const auto &args : failed)
        qWarning("deformation failed: %s", qPrintable(args.at(1).toString()));
    return !solved.isEmpty();
}

double worstOffset(const StrokeGroup &g, QPointF offset)
{
    double worst = 0;
    for (std::size_t s = 0; s < g.strokes.size(); ++s) {
        const auto &rest = g.strokes[s].data->points;
        const auto &posed = g.deformed->strokes[s];
        for (std::size_t i = 0; i < rest.size(); ++i)
            worst = std::max(worst, std::hypot(rest[i].x + offset.x() - posed[i].x,
                                               rest[i].y + offset.y() - posed[i].y));
    }
    return worst;
}

std::vector<QPointF> shifted(std::vector<QPointF> corners, QPointF by)
{
    for (QPointF &c : corners)
        c += by;
    return corners;
}

} // namespace

class TestCageRig : public QObject {
    Q_OBJECT
private slots:
    void placeAndPoseMovesTheDrawing();
    void restCageKeepsTheDrawing();
    void dragIsOneUndoStepAndUndoIsExact();
    void badCagesAreRefusedWithAReason();
    void pinsGiveWayToACageAndBack();
    void applyPoseRebasesTheCage();
    void editShapeKeepsThePose();
    void duplicatedFrameSharesTheCoordinates();
    void cageSurvivesSaveAndOpen();
    void malformedCageChunksAreRefused();
    void storedPinPoseIsTheConvergedOne();
    void cageMovesRigidlyUntilCoordinatesArrive();
};

void TestCageRig::placeAndPoseMovesTheDrawing()
{
    Document doc;
    const Id g = makeDrawing(doc);
    DeformController controller(&doc);
    doc.undoStack()->push(new PlaceCageCommand(&doc, g, uCage()));
    QCOMPARE(doc.group(g)->rig.kind(), RigKind::Cage);
    controller.prepare(g);
    QVERIFY(waitSolved(controller, g));
    QVERIFY(controller.setup(g)->cage);
    // Translating every corner translates the drawing (linear reproduction).
    const QPointF by(35, -20);
    doc.undoStack()->push(new MoveCageCornersCommand(&doc, g, shifted(uCage(), by), 1));
    QVERIFY(doc.group(g)->isDeformed());
    QVERIFY2(worstOffset(*doc.group(g), by) < 1e-3,
             qPrintable(QString::number(worstOffset(*doc.group(g), by))));
    // Moving only the right corners stretches the right end and leaves the left end alone.
    std::vector<QPointF> posed = uCage();
    posed[4] += QPointF(80, 0);
    posed[5] += QPointF(80, 0);
    doc.undoStack()->push(new MoveCageCornersCommand(&doc, g, posed, 2));
    const auto &points = doc.group(g)->deformed->strokes[0];
    const auto &rest = doc.group(g)->strokes[0].data->points;
    QVERIFY(points.back().x > rest.back().x + 40);
    QVERIFY(std::abs(points.front().x - rest.front().x) < 15);
    for (const auto &stroke : doc.group(g)->deformed->strokes)
        for (const StrokePoint &p : stroke)
            QVERIFY(std::isfinite(p.x) && std::isfinite(p.y));
}

void TestCageRig::restCageKeepsTheDrawing()
{
    Document doc;
    const Id g = makeDrawing(doc);
    DeformController controller(&doc);
    doc.undoStack()->push(new PlaceCageCommand(&doc, g, uCage()));
    controller.prepare(g);
    QVERIFY(waitSolved(controller, g));
    // Stored points are float: the identity cage reproduces them to float rounding.
    QVERIFY(worstOffset(*doc.group(g), {}) < 1e-4);
}

void TestCageRig::dragIsOneUndoStepAndUndoIsExact()
{
    Document doc;
    const Id g = makeDrawing(doc);
    DeformController controller(&doc);
    doc.undoStack()->push(new PlaceCageCommand(&doc, g, uCage()));
    controller.prepare(g);
    QVERIFY(waitSolved(controller, g));
    const QByteArray before = serializeFinbook(doc);
    const int steps = doc.undoStack()->count();
    for (int i = 1; i <= 10; ++i)
        doc.undoStack()->push(
            new MoveCageCornersCommand(&doc, g, shifted(uCage(), QPointF(3 * i, 2 * i)), 7));
    QCOMPARE(doc.undoStack()->count(), steps + 1);
    const QByteArray after = serializeFinbook(doc);
    doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(doc), before);
    doc.undoStack()->redo();
    QCOMPARE(serializeFinbook(doc), after);
    // A second drag is a second step.
    doc.undoStack()->push(new MoveCageCornersCommand(&doc, g, uCage(), 8));
    QCOMPARE(doc.undoStack()->count(), steps + 2);
}

void TestCageRig::badCagesAreRefusedWithAReason()
{
    Document doc;
    const Id g = makeDrawing(doc);
    const StrokeGroup &group = *doc.group(g);
    QVERIFY(!cageProblem(group, uCage()));
    QVERIFY(cageProblem(group, {{0, 0}, {500, 0}}).has_value());                       // 2 corners
    QVERIFY(cageProblem(group, {{0, 0}, {500, 0}, {1000, 0}}).has_value());            // no area
    QVERIFY(cageProblem(group, {{0, 0}, {500, 300}, {500, 0}, {0, 300}}).has_value()); // crossed
    // Too small: the drawing sticks out, and the sentence says the cage must enclose it.
    const auto small = cageProblem(group, {{90, 60}, {250, 60}, {250, 180}, {90, 180}});
    QVERIFY(small.has_value());
    QVERIFY2(small->contains(QStringLiteral("enclose")), qPrintable(*small));
    // A crossed posed cage still deforms, and is reported as crossed for the warning tint.
    QVERIFY(cageCrossesItself({{0, 0}, {500, 300}, {500, 0}, {0, 300}}));
    QVERIFY(!cageCrossesItself(uCage()));
}

void TestCageRig::pinsGiveWayToACageAndBack()
{
    Document doc;
    const Id g = makeDrawing(doc);
    doc.undoStack()->push(new AddPinCommand(&doc, g, {100, 100}, {100, 100}));
    const QByteArray pinned = serializeFinbook(doc);
    doc.undoStack()->push(new PlaceCageCommand(&doc, g, uCage()));
    QCOMPARE(doc.group(g)->rig.kind(), RigKind::Cage);
    QVERIFY(doc.group(g)->rig.pins.empty());
    doc.undoStack()->push(new AddPinCommand(&doc, g, {120, 100}, {120, 100}));
    QCOMPARE(doc.group(g)->rig.kind(), RigKind::Pins);
    QVERIFY(doc.group(g)->rig.cage.empty());
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(doc), pinned);
}

void TestCageRig::applyPoseRebasesTheCage()
{
    Document doc;
    const Id g = makeDrawing(doc);
    DeformController controller(&doc);
    doc.undoStack()->push(new PlaceCageCommand(&doc, g, uCage()));
    controller.prepare(g);
    QVERIFY(waitSolved(controller, g));
    std::vector<QPointF> posed = uCage();
    posed[5] += QPointF(60, 40);
    doc.undoStack()->push(new MoveCageCornersCommand(&doc, g, posed, 1));
    const QByteArray before = serializeFinbook(doc);
    const auto shown = doc.group(g)->deformed;
    doc.undoStack()->push(new ApplyPoseCommand(&doc, g));
    // The drawing is what was shown; the cage stays where it was shown, now at rest.
    QCOMPARE(doc.group(g)->strokes[1].data->points, shown->strokes[1]);
    QCOMPARE(doc.group(g)->rig.cage.rest, posed);
    QVERIFY(!doc.group(g)->rig.isPosed());
    doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(doc), before);
}

void TestCageRig::editShapeKeepsThePose()
{
    Document doc;
    const Id g = makeDrawing(doc);
    doc.undoStack()->push(new PlaceCageCommand(&doc, g, uCage()));
    std::vector<QPointF> posed = uCage();
    posed[0] += QPointF(-10, -10);
    doc.undoStack()->push(new MoveCageCornersCommand(&doc, g, posed, 1));
    CageRig cage = doc.group(g)->rig.cage;
    cage.rest[2] += QPointF(0, -15); // the notch made shallower, in rest space
    cage.posed[2] += QPointF(0, -15);
    doc.undoStack()->push(new EditCageCommand(&doc, g, cage));
    QCOMPARE(doc.group(g)->rig.cage, cage);
    QCOMPARE(doc.group(g)->rig.cage.posed[0], posed[0]);
    doc.undoStack()->undo();
    QCOMPARE(doc.group(g)->rig.cage.rest, uCage());
    // Without a cage there is nothing to edit.
    Document other;
    const Id h = makeDrawing(other);
    auto *edit = new EditCageCommand(&other, h, cage);
    QVERIFY(edit->isObsolete());
    delete edit;
}

void TestCageRig::duplicatedFrameSharesTheCoordinates()
{
    Document doc;
    const Id g = makeDrawing(doc);
    DeformController controller(&doc);
    doc.undoStack()->push(new PlaceCageCommand(&doc, g, uCage()));
    controller.prepare(g);
    QVERIFY(waitSolved(controller, g));
    doc.undoStack()->push(new DuplicateFrameCommand(&doc, doc.frameAt(0).id, 1));
    const StrokeGroup &copy = doc.frameAt(1).groups[0];
    QCOMPARE(copy.rig.cage, doc.group(g)->rig.cage);
    controller.prepare(copy.id);
    QVERIFY2(!controller.isWaiting(copy.id), "the copy should reuse its source's coordinates");
    doc.undoStack()->push(
        new MoveCageCornersCommand(&doc, copy.id, shifted(uCage(), QPointF(0, 50)), 1));
    QVERIFY(worstOffset(*doc.group(copy.id), QPointF(0, 50)) < 1e-3);
    QVERIFY(!doc.group(g)->rig.isPosed()); // the original keeps its own cage
}

void TestCageRig::cageSurvivesSaveAndOpen()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("caged.finbook"));
    Document doc;
    const Id g = makeDrawing(doc);
    DeformController controller(&doc);
    doc.undoStack()->push(new PlaceCageCommand(&doc, g, uCage()));
    controller.prepare(g);
    QVERIFY(waitSolved(controller, g));
    doc.undoStack()->push(
        new MoveCageCornersCommand(&doc, g, shifted(uCage(), QPointF(12.25, -3.5)), 1));
    QVERIFY(!saveFinbook(doc, path));
    Document reopened;
    QVERIFY(!openFinbook(reopened, path));
    const StrokeGroup &r = reopened.frameAt(0).groups[0];
    QCOMPARE(r.rig.cage, doc.group(g)->rig.cage);
    QVERIFY(r.isDeformed());
    QCOMPARE(*r.deformed, *doc.group(g)->deformed);
    QCOMPARE(serializeFinbook(reopened), serializeFinbook(doc));
}

void TestCageRig::malformedCageChunksAreRefused()
{
    Document doc;
    const Id g = makeDrawing(doc);
    doc.undoStack()->push(new PlaceCageCommand(&doc, g, uCage()));
    const QByteArray good = serializeFinbook(doc);
    QVERIFY(readFinbook(good).hasValue());
    // The corner count sits right after the chunk's tag and length.
    const qsizetype at = good.indexOf("CAGE");
    QVERIFY(at > 0);
    QByteArray twoCorners = good;
    twoCorners[at + 8] = 2;
    QVERIFY(!readFinbook(twoCorners).hasValue());
    // A NaN corner.
    QByteArray nan = good;
    const double bad = std::nan("");
    std::memcpy(nan.data() + at + 12, &bad, sizeof bad);
    const auto loaded = readFinbook(nan);
    QVERIFY(!loaded.hasValue());
}

void TestCageRig::storedPinPoseIsTheConvergedOne()
{
    Document doc;
    const Id g = makeDrawing(doc);
    DeformController controller(&doc);
    controller.setConverged();
    doc.undoStack()->push(new AddPinCommand(&doc, g, {100, 100}, {100, 100}));
    doc.undoStack()->push(new AddPinCommand(&doc, g, {400, 100}, {400, 100}));
    controller.prepare(g);
    QVERIFY(waitSolved(controller, g));
    const Id tip = doc.group(g)->rig.pins[1].id;
    for (int i = 1; i <= 5; ++i)
        doc.undoStack()->push(
            new MovePinCommand(&doc, g, tip, QPointF(400 - 25 * i, 100 + 40 * i), 1));
    QVERIFY(controller.isSettling(g));
    controller.settle();
    QVERIFY(!controller.isSettling(g));
    const DeformedStrokes converged = *doc.group(g)->deformed;
    // The same as solving the final pose from scratch: a function of the pins alone.
    const auto direct = solvePose(*controller.setup(g), *doc.group(g), PoseStage::Final);
    QVERIFY(direct.hasValue());
    QCOMPARE(*direct->strokes, converged);
    // Undo, redo and settle give it back exactly; so does waiting for the worker.
    doc.undoStack()->undo();
    doc.undoStack()->redo();
    QVERIFY(controller.isSettling(g));
    QTRY_VERIFY_WITH_TIMEOUT(!controller.isSettling(g), 10000);
    QCOMPARE(*doc.group(g)->deformed, converged);
}

void TestCageRig::cageMovesRigidlyUntilCoordinatesArrive()
{
    Document doc;
    const Id g = makeDrawing(doc);
    DeformController controller(&doc);
    QSignalSpy ready(controller.service(), &PrecomputeService::setupReady);
    doc.undoStack()->push(new PlaceCageCommand(&doc, g, uCage()));
    controller.prepare(g);
    QVERIFY(controller.isWaiting(g));
    // Corners dragged before the coordinates exist: the drawing follows rigidly at once.
    doc.undoStack()->push(
        new MoveCageCornersCommand(&doc, g, shifted(uCage(), QPointF(30, 10)), 1));
    QVERIFY(doc.group(g)->isDeformed());
    QVERIFY(worstOffset(*doc.group(g), QPointF(30, 10)) < 1e-3);
    doc.undoStack()->push(
        new MoveCageCornersCommand(&doc, g, shifted(uCage(), QPointF(50, 20)), 1));
    QVERIFY(worstOffset(*doc.group(g), QPointF(50, 20)) < 1e-3);
    // Moving targets did not restart the precompute; its result solves the latest targets.
    QVERIFY(waitSolved(controller, g));
    QCOMPARE(ready.count(), 1);
    QVERIFY(controller.setup(g)->cage);
    QVERIFY(worstOffset(*doc.group(g), QPointF(50, 20)) < 1e-3);
}

QTEST_GUILESS_MAIN(TestCageRig)
#include "tst_cage_rig.moc"
