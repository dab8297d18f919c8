// ARAP in the model: pin commands, the worker-thread precompute service and the controller.
#include "stroke_support.h"

#include <finbook/model/deform_controller.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/pins/pin_commands.h>

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <cmath>

using namespace finbook;
using namespace finbook::model;

namespace {

// A regular grid of about `vertices` vertices as a ready mesh (what a big object gives).
std::shared_ptr<const MeshedObject> gridMesh(int vertices)
{
    const int side = std::max(2, int(std::lround(std::sqrt(double(vertices)))));
    auto meshed = std::make_shared<MeshedObject>();
    Eigen::MatrixX2d &V = meshed->mesh.V;
    Eigen::MatrixX3i &F = meshed->mesh.F;
    V.resize(side * side, 2);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            V.row(y * side + x) << x * 4.0, y * 4.0;
    F.resize(2 * (side - 1) * (side - 1), 3);
    int f = 0;
    for (int y = 0; y + 1 < side; ++y)
        for (int x = 0; x + 1 < side; ++x) {
            const int a = y * side + x, b = a + 1, c = a + side, d = c + 1;
            F.row(f++) << a, b, d;
            F.row(f++) << a, d, c;
        }
    meshed->strokeOffsets = {0};
    return meshed;
}

DeformJob gridJob(Id groupId, const std::shared_ptr<const MeshedObject> &meshed)
{
    DeformJob job;
    job.groupId = groupId;
    job.meshed = meshed;
    const Eigen::MatrixX2d &V = meshed->mesh.V;
    const Eigen::Vector2d lo = V.colwise().minCoeff(), hi = V.colwise().maxCoeff();
    Id pinId = 1;
    for (const QPointF p : {QPointF(lo.x(), lo.y()), QPointF(hi.x(), lo.y()),
                            QPointF(lo.x(), hi.y()), QPointF(hi.x(), hi.y())})
        job.rig.pins.push_back(Pin{pinId++, p, p});
    return job;
}

StrokeDataPtr wobble(float x0, float y0, float length, int n)
{
    auto data = std::make_shared<StrokeData>();
    for (int i = 0; i < n; ++i) {
        const float t = float(i) / float(n - 1);
        data->points.push_back({x0 + t * length, y0 + 6.0f * std::sin(t * 9.0f), 1.0f});
    }
    data->width = 4.0f;
    return data;
}

// The document becomes one frame with one object of these strokes; returns the object's id.
Id makeObject(Document &doc, const QString &name, std::initializer_list<StrokeDataPtr> strokes)
{
    Frame f;
    f.id = doc.allocateId();
    StrokeGroup g;
    g.id = doc.allocateId();
    g.name = name;
    for (const StrokeDataPtr &data : strokes)
        g.strokes.push_back({doc.allocateId(), data});
    f.groups.push_back(g);
    doc.reset({f}, DocumentSettings{}, doc.nextId());
    return g.id;
}

// An object of two long overlapping strokes (an "arm"; they overlap: one lobe).
Id makeArm(Document &doc)
{
    return makeObject(doc, QStringLiteral("arm"),
                      {wobble(100, 100, 300, 120), wobble(100, 106, 300, 120)});
}

// An object of a closed square outline from (100, 100) to (400, 400), solid inside.
Id makeTile(Document &doc)
{
    return makeObject(doc, QStringLiteral("tile"),
                      {testing::squareOutline({100, 100}, 300, 30, 4.0f)});
}

// Pins at both ends of the arm, at rest.
void pinBothEnds(Document &doc, Id g)
{
    doc.undoStack()->push(new AddPinCommand(&doc, g, {100, 100}, {100, 100}));
    doc.undoStack()->push(new AddPinCommand(&doc, g, {400, 100}, {400, 100}));
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

double maxDistance(const std::vector<StrokePoint> &a, const std::vector<StrokePoint> &b,
                   QPointF offset = {})
{
    double worst = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        worst =
            std::max(worst, std::hypot(a[i].x + offset.x() - b[i].x, a[i].y + offset.y() - b[i].y));
    return worst;
}

} // namespace

class TestDeformService : public QObject {
    Q_OBJECT
private slots:
    void pinCommandsUndoExactly();
    void onePinTranslates();
    void dragSolvesSynchronouslyAndMergesPerDrag();
    void storedPoseIgnoresTheDragPath();
    void bakeMakesPoseTheRestAndUndoes();
    void duplicatedFrameSharesSetupButNotPins();
    void extraPassesReprepareAndStayStateless();
    void unpinnedPartFollowsThePinnedOne();
    void foldsThePinsForceAreReported();
    void reopenedFileContinuesWhereItStopped();
    void serviceDeliversOnlyLatestGeneration();
    void guiStaysResponsiveDuringBigPrecompute();
};

void TestDeformService::pinCommandsUndoExactly()
{
    Document doc;
    const Id g = makeArm(doc);
    QUndoStack *stack = doc.undoStack();
    const QByteArray start = serializeFinbook(doc);
    stack->push(new AddPinCommand(&doc, g, {100, 100}, {100, 100}));
    const Id pin = doc.group(g)->rig.pins.back().id;
    stack->push(new AddPinCommand(&doc, g, {400, 100}, {400, 100}));
    stack->push(new MovePinCommand(&doc, g, pin, {120, 140}, 1));
    stack->push(new MovePinCommand(&doc, g, pin, {130, 150}, 1)); // same drag: merges
    QCOMPARE(stack->count(), 3);
    stack->push(new MovePinCommand(&doc, g, pin, {10, 10}, 2)); // next drag: its own step
    QCOMPARE(stack->count(), 4);
    stack->push(new ResetPoseCommand(&doc, g));
    stack->push(new RemovePinCommand(&doc, g, pin));
    const QByteArray end = serializeFinbook(doc);
    while (stack->canUndo())
        stack->undo();
    QCOMPARE(serializeFinbook(doc), start);
    while (stack->canRedo())
        stack->redo();
    QCOMPARE(serializeFinbook(doc), end);
    // Non-finite targets are refused, never stored.
    const int count = stack->count();
    stack->push(new AddPinCommand(&doc, g, {qQNaN(), 0}, {0, 0}));
    QCOMPARE(stack->count(), count);
}

void TestDeformService::onePinTranslates()
{
    Document doc;
    const Id g = makeArm(doc);
    DeformController controller(&doc);
    doc.undoStack()->push(new AddPinCommand(&doc, g, {250, 100}, {250, 100}));
    QVERIFY(waitSolved(controller, g));
    doc.undoStack()->push(new MovePinCommand(&doc, g, doc.group(g)->rig.pins[0].id, {275, 60}, 1));
    const StrokeGroup *group = doc.group(g);
    QVERIFY(group->isDeformed());
    for (std::size_t s = 0; s < group->strokes.size(); ++s)
        QVERIFY(maxDistance(group->strokes[s].data->points, group->deformed->strokes[s],
                            {25, -40}) < 1e-3);
}

void TestDeformService::dragSolvesSynchronouslyAndMergesPerDrag()
{
    Document doc;
    const Id g = makeArm(doc);
    DeformController controller(&doc);
    doc.undoStack()->push(new AddPinCommand(&doc, g, {100, 100}, {100, 100}));
    doc.undoStack()->push(new AddPinCommand(&doc, g, {250, 100}, {250, 100}));
    doc.undoStack()->push(new AddPinCommand(&doc, g, {400, 100}, {400, 100}));
    QVERIFY(waitSolved(controller, g));
    const auto restPose = doc.group(g)->deformed;
    QVERIFY(restPose);
    // Pins at rest give the rest drawing.
    QVERIFY(maxDistance(doc.group(g)->strokes[0].data->points, restPose->strokes[0]) < 1e-3);
    // Every move re-solves at once: no waiting for the worker while dragging.
    const Id tip = doc.group(g)->rig.pins[2].id;
    for (int step = 1; step <= 20; ++step) {
        doc.undoStack()->push(new MovePinCommand(&doc, g, tip, {400, 100.0 + 5 * step}, 7));
        QVERIFY(!controller.isWaiting(g));
        QVERIFY(doc.group(g)->deformed->strokes[0].back().y > 100.0f);
    }
    const auto bent = doc.group(g)->deformed;
    for (const auto &stroke : bent->strokes)
        for (const StrokePoint &p : stroke)
            QVERIFY(std::isfinite(p.x) && std::isfinite(p.y));
    doc.undoStack()->undo(); // the whole drag at once
    QVERIFY(maxDistance(doc.group(g)->deformed->strokes[0], restPose->strokes[0]) < 1e-3);
}

// Drag events continue from the pose shown (issue 26), but the pose kept once the pins rest is
// solved from the pins alone: two different drags to the same place store the same points.
void TestDeformService::storedPoseIgnoresTheDragPath()
{
    Document doc;
    const Id g = makeArm(doc);
    DeformController controller(&doc);
    controller.setSettleDelay(1000000); // settled only when asked
    pinBothEnds(doc, g);
    QVERIFY(waitSolved(controller, g));
    const Id tip = doc.group(g)->rig.pins[1].id;
    for (int step = 1; step <= 12; ++step)
        doc.undoStack()->push(
            new MovePinCommand(&doc, g, tip, QPointF(400 - 8 * step, 100 + 12 * step), 5));
    QVERIFY(controller.isSettling(g));
    const auto dragged = doc.group(g)->deformed;
    controller.settle();
    const auto stored = doc.group(g)->deformed;
    QVERIFY(!controller.isSettling(g));
    const auto direct = solvePose(*controller.setup(g), *doc.group(g), PoseStage::Final);
    QVERIFY(direct);
    QCOMPARE(*stored, *direct->strokes);
    QVERIFY(maxDistance(dragged->strokes[0], stored->strokes[0]) < 5.0); // the drag was close
    // Another way there: one jump far past the target, then back in two events.
    doc.undoStack()->undo();
    doc.undoStack()->push(new MovePinCommand(&doc, g, tip, {150, 380}, 6));
    doc.undoStack()->push(new MovePinCommand(&doc, g, tip, {250, 300}, 6));
    doc.undoStack()->push(new MovePinCommand(&doc, g, tip, {304, 244}, 6));
    QVERIFY(controller.isSettling(g));
    controller.settle();
    QCOMPARE(*doc.group(g)->deformed, *stored);
}

void TestDeformService::bakeMakesPoseTheRestAndUndoes()
{
    Document doc;
    const Id g = makeArm(doc);
    DeformController controller(&doc);
    pinBothEnds(doc, g);
    QVERIFY(waitSolved(controller, g));
    doc.undoStack()->push(new MovePinCommand(&doc, g, doc.group(g)->rig.pins[1].id, {380, 220}, 1));
    const QByteArray before = serializeFinbook(doc);
    const auto pose = doc.group(g)->deformed;
    const Rig posedRig = doc.group(g)->rig;
    doc.undoStack()->push(new ApplyPoseCommand(&doc, g));
    QCOMPARE(doc.group(g)->strokes[0].data->points, pose->strokes[0]);
    // The pins stay where they were shown, now at rest on the new drawing.
    QCOMPARE(doc.group(g)->rig.pins.size(), posedRig.pins.size());
    for (std::size_t i = 0; i < posedRig.pins.size(); ++i) {
        QCOMPARE(doc.group(g)->rig.pins[i].rest, posedRig.pins[i].target);
        QCOMPARE(doc.group(g)->rig.pins[i].target, posedRig.pins[i].target);
    }
    QVERIFY(!doc.group(g)->rig.isPosed());
    doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(doc), before);
}

void TestDeformService::duplicatedFrameSharesSetupButNotPins()
{
    Document doc;
    const Id g = makeArm(doc);
    DeformController controller(&doc);
    pinBothEnds(doc, g);
    QVERIFY(waitSolved(controller, g));
    doc.undoStack()->push(new DuplicateFrameCommand(&doc, doc.frameAt(0).id, 1));
    const Id copy = doc.frameAt(1).groups[0].id;
    const Id copyTip = doc.frameAt(1).groups[0].rig.pins[1].id;
    controller.prepare(copy);
    QVERIFY2(!controller.isWaiting(copy), "the copy should reuse its source's factorization");
    doc.undoStack()->push(new MovePinCommand(&doc, copy, copyTip, {300, 250}, 1));
    QVERIFY(doc.group(copy)->deformed->strokes[0].back().y > 200);
    // The original keeps its own pins and pose.
    QCOMPARE(doc.group(g)->rig.pins[1].target, QPointF(400, 100));
    QVERIFY(doc.group(g)->deformed->strokes[0].back().y < 120);
}

void TestDeformService::extraPassesReprepareAndStayStateless()
{
    Document doc;
    const Id g = makeArm(doc);
    DeformController controller(&doc);
    controller.setExtraPasses(0); // the paper's method
    pinBothEnds(doc, g);
    QVERIFY(waitSolved(controller, g));
    const Id tip = doc.group(g)->rig.pins[1].id;
    doc.undoStack()->push(new MovePinCommand(&doc, g, tip, {330, 260}, 1));
    const auto paper = doc.group(g)->deformed;
    controller.setExtraPasses(3);
    QVERIFY(controller.isWaiting(g));
    QVERIFY(waitSolved(controller, g));
    const auto stiffer = doc.group(g)->deformed;
    QVERIFY(!(*stiffer == *paper)); // the passes change the pose...
    // ...and the pose stays a function of the targets: away and back gives the same points.
    doc.undoStack()->push(new MovePinCommand(&doc, g, tip, {200, 300}, 2));
    doc.undoStack()->push(new MovePinCommand(&doc, g, tip, {330, 260}, 3));
    QCOMPARE(*doc.group(g)->deformed, *stiffer);
    controller.setExtraPasses(0);
    QVERIFY(waitSolved(controller, g));
    QCOMPARE(*doc.group(g)->deformed, *paper);
}

void TestDeformService::reopenedFileContinuesWhereItStopped()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bent.finbook"));
    Document doc;
    const Id g = makeArm(doc);
    {
        DeformController controller(&doc);
        pinBothEnds(doc, g);
        QVERIFY(waitSolved(controller, g));
        doc.undoStack()->push(
            new MovePinCommand(&doc, g, doc.group(g)->rig.pins[1].id, {380, 200}, 1));
        // As the app saves: the converged pose (a drag pose depends on the drag's path).
        controller.settle();
        QVERIFY(!saveFinbook(doc, path));
    }
    Document reopened;
    QVERIFY(!openFinbook(reopened, path));
    const StrokeGroup *r = reopened.group(g);
    QVERIFY(r && r->isDeformed());
    QCOMPARE(r->rig.pins, doc.group(g)->rig.pins);
    QCOMPARE(*r->deformed, *doc.group(g)->deformed); // shown at once, without solving
    // Dragging on: the same solver gives the same converged pose for the same targets, then
    // follows.
    DeformController controller(&reopened);
    controller.prepare(g);
    QVERIFY(waitSolved(controller, g));
    controller.settle();
    QCOMPARE(*reopened.group(g)->deformed, *doc.group(g)->deformed);
    reopened.undoStack()->push(new MovePinCommand(&reopened, g, r->rig.pins[1].id, {380, 260}, 1));
    QVERIFY(reopened.group(g)->deformed->strokes[0].back().y > 230);
}

void TestDeformService::serviceDeliversOnlyLatestGeneration()
{
    PrecomputeService service;
    service.setCoalesceInterval(0);
    QSignalSpy ready(&service, &PrecomputeService::setupReady);
    QSignalSpy failed(&service, &PrecomputeService::setupFailed);
    const auto big = gridMesh(60000);
    const auto small = gridMesh(400);
    service.request(gridJob(7, big));
    QTest::qWait(30); // let the big job start on the worker
    service.request(gridJob(7, big));
    const quint64 last = service.request(gridJob(7, small));
    QTRY_VERIFY_WITH_TIMEOUT(!service.isBusy(), 20000);
    for (const auto &args : failed)
        qWarning("precompute failed: %s", qPrintable(args.at(2).toString()));
    QCOMPARE(failed.count(), 0);
    QCOMPARE(ready.count(), 1);
    QCOMPARE(ready.at(0).at(1).value<quint64>(), last);
    const auto setup = ready.at(0).at(2).value<std::shared_ptr<const DeformSetup>>();
    QCOMPARE(setup->meshed.get(), small.get());
}

// Event-loop lateness: a 2 ms probe timer records how late each tick fires.
namespace {
std::vector<double> probeLateness(const std::function<bool()> &done, int timeoutMs)
{
    std::vector<double> lateness;
    QElapsedTimer clock;
    clock.start();
    qint64 expected = 2;
    QTimer probe;
    probe.setTimerType(Qt::PreciseTimer);
    probe.setInterval(2);
    QObject::connect(&probe, &QTimer::timeout, [&] {
        const qint64 now = clock.elapsed();
        lateness.push_back(double(std::max<qint64>(0, now - expected)));
        expected = now + 2;
    });
    probe.start();
    while (!done() && clock.elapsed() < timeoutMs)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 5);
    // A few more ticks: the one due while the loop was blocked fires only now.
    const qint64 until = clock.elapsed() + 30;
    while (clock.elapsed() < until)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 5);
    return lateness;
}

double p99(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[std::size_t(0.99 * double(v.size() - 1))];
}
} // namespace

void TestDeformService::guiStaysResponsiveDuringBigPrecompute()
{
    const auto big = gridMesh(100000);
    // Control: the same precompute on the GUI thread must show up as a block in the probe,
    // or the probe proves nothing.
    bool controlDone = false;
    QElapsedTimer controlClock;
    controlClock.start();
    QTimer::singleShot(20, [&] {
        auto setup = buildDeformSetup(gridJob(1, big));
        QVERIFY2(setup.hasValue(), setup ? "" : qPrintable(setup.error()));
        controlDone = true;
    });
    const auto blocked = probeLateness([&] { return controlDone; }, 300000);
    // The worker does the same work: on a busy machine (sanitizers, parallel tests) it may
    // take several times as long as the control did, so the wait scales with the control.
    const int workerWait = int(std::min<qint64>(30000 + 5 * controlClock.elapsed(), 600000));
    const double blockedWorst = *std::max_element(blocked.begin(), blocked.end());
    qInfo("control on GUI thread: worst lateness %.1f ms over %zu ticks", blockedWorst,
          blocked.size());
    QVERIFY2(blockedWorst > 50.0, "the probe did not notice a blocked GUI thread");

    PrecomputeService service;
    QSignalSpy ready(&service, &PrecomputeService::setupReady);
    service.request(gridJob(1, big));
    const auto lateness = probeLateness([&] { return !ready.isEmpty(); }, workerWait);
    QCOMPARE(ready.count(), 1);
    qInfo("worker precompute: p99 lateness %.2f ms over %zu ticks", p99(lateness), lateness.size());
    QVERIFY(lateness.size() > 20);
    // Relative, not a wall-clock bound (a busy machine delays any tick now and then): the GUI
    // thread is never held for anything like the precompute, as it is in the control.
    const double worst = *std::max_element(lateness.begin(), lateness.end());
    QVERIFY2(worst < blockedWorst / 2,
             qPrintable(QStringLiteral("worst %1 ms, control %2 ms").arg(worst).arg(blockedWorst)));
}

void TestDeformService::unpinnedPartFollowsThePinnedOne()
{
    // An arm and, drawn apart from it, a hand: one object, two separate parts. Only the arm
    // is pinned; dragging its tip must carry the hand along rather than leave it behind.
    Document doc;
    const Id g = makeArm(doc);
    auto hand = wobble(430, 100, 40, 30);
    doc.undoStack()->push(new AddStrokeCommand(&doc, g, hand));
    DeformController controller(&doc);
    pinBothEnds(doc, g);
    QVERIFY(waitSolved(controller, g));
    const Id tip = doc.group(g)->rig.pins[1].id;
    doc.undoStack()->push(new MovePinCommand(&doc, g, tip, {400, 180}, 1));
    controller.settle();
    const auto &posedHand = doc.group(g)->deformed->strokes.back();
    const auto &restHand = hand->points;
    double moved = 0;
    for (std::size_t i = 0; i < restHand.size(); ++i)
        moved = std::max(moved, double(posedHand[i].y - restHand[i].y));
    QVERIFY2(moved > 40, qPrintable(QString::number(moved)));
}

// Issue 26: where the pins force a fold, the pose is kept as it is and the controller says so
// (the window posts it). A bend that leaves room reports nothing.
void TestDeformService::foldsThePinsForceAreReported()
{
    Document doc;
    const Id g = makeTile(doc);
    DeformController controller(&doc);
    controller.setSettleDelay(1000000); // settled only when asked
    QSignalSpy folds(&controller, &DeformController::foldsForced);
    for (const QPointF p : {QPointF(130, 130), QPointF(370, 130), QPointF(250, 370)})
        doc.undoStack()->push(new AddPinCommand(&doc, g, p, p));
    QVERIFY(waitSolved(controller, g));
    const DeformSetup &setup = *controller.setup(g);
    QVERIFY(setup.pins);
    QVERIFY(setup.meshVertices().rows() > 200); // the inside is meshed, not only the outline
    const auto turnedOver = [&] {
        return deform::arapFlippedTriangles(setup.meshVertices(), setup.meshTriangles(),
                                            *controller.poseVertices(g));
    };
    const Id apex = doc.group(g)->rig.pins[2].id;
    // Stretched and turned a little: room everywhere.
    doc.undoStack()->push(new MovePinCommand(&doc, g, apex, {290, 420}, 1));
    controller.settle();
    QCOMPARE(turnedOver(), 0);
    QVERIFY(folds.isEmpty());
    // The apex pulled through the line of the other two: the pinned triangle turns inside out,
    // and the mesh between the pins must fold.
    for (int step = 1; step <= 10; ++step)
        doc.undoStack()->push(new MovePinCommand(&doc, g, apex, {250, 370 - 51.0 * step}, 2));
    controller.settle();
    const int forced = turnedOver();
    QVERIFY(forced > 0);
    QCOMPARE(folds.size(), 1);
    QCOMPARE(folds.at(0).at(0).value<Id>(), g);
    QCOMPARE(folds.at(0).at(1).toInt(), forced);
    // The pose is stored all the same: the converged pose of these pins.
    const auto direct = solvePose(setup, *doc.group(g), PoseStage::Final);
    QVERIFY(direct);
    QCOMPARE(*doc.group(g)->deformed, *direct->strokes);
    // Back where there is room: nothing more to say.
    doc.undoStack()->undo();
    controller.settle();
    QCOMPARE(turnedOver(), 0);
    QCOMPARE(folds.size(), 1);
}

QTEST_GUILESS_MAIN(TestDeformService)
#include "tst_deform_service.moc"
