// In-betweens from poses: spacing, target interpolation, planning, the synchronous solve, and
// InsertInbetweensCommand with the DeformController.
#include "inbetween_support.h"

#include <finbook/model/deform_controller.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/inbetween/inbetween_commands.h>
#include <finbook/model/inbetween/inbetween_solve.h>
#include <finbook/model/inbetween/rig_interpolation.h>

#include <QTest>

#include <set>

using namespace finbook::model;
using namespace finbook::inbetween_test;

namespace {

// The keys with their poses solved the way in-betweens are (shared setups in `cache`).
std::pair<Frame, Frame> solvedArmKeys(DeformSetupCache &cache, Id firstId = 1)
{
    auto [a, b] = armKeys(firstId);
    std::vector<Frame> keys{a, b};
    const auto solved = solveInbetweenPoses(keys, {}, &cache);
    if (!solved || *solved != 2)
        qFatal("arm keys do not solve");
    return {keys[0], keys[1]};
}

double distance(QPointF a, QPointF b)
{
    return std::hypot(a.x() - b.x(), a.y() - b.y());
}

} // namespace

class TestInbetween : public QObject {
    Q_OBJECT
private slots:
    void spacingCurves();
    void targetsAlongArcsAndLines();
    void armSwingKeepsItsLength();
    void endsEqualTheKeys();
    void matchingAndHolding();
    void commandInsertsOneUndoStep();
    void commandRejectsBadInput();
    void skeletonAnglesTakeTheShorterArc();
};

void TestInbetween::spacingCurves()
{
    const SpacingKind kinds[] = {SpacingKind::Linear, SpacingKind::EaseIn, SpacingKind::EaseOut,
                                 SpacingKind::EaseInOut, SpacingKind::Favour};
    for (SpacingKind kind : kinds)
        for (double favour : {-1.0, -0.4, 0.0, 0.7, 1.0}) {
            const Spacing s{kind, favour};
            QCOMPARE(spacedTime(0.0, s), 0.0);
            QCOMPARE(spacedTime(1.0, s), 1.0);
            QCOMPARE(spacedTime(std::nan(""), s), 0.0);
            const auto times = inbetweenTimes(11, s);
            QCOMPARE(times.size(), std::size_t(11));
            for (std::size_t i = 0; i < times.size(); ++i) {
                QVERIFY(times[i] > 0.0 && times[i] < 1.0);
                if (i > 0)
                    QVERIFY(times[i] > times[i - 1]);
            }
        }
    const auto mean = [](const Spacing &s) {
        double sum = 0;
        for (double t : inbetweenTimes(9, s))
            sum += t;
        return sum / 9;
    };
    QCOMPARE(mean({SpacingKind::Linear, 0}), 0.5);
    QVERIFY(mean({SpacingKind::EaseIn, 0}) < 0.45);  // bunched at the first key
    QVERIFY(mean({SpacingKind::EaseOut, 0}) > 0.55); // bunched at the second key
    QVERIFY(std::abs(mean({SpacingKind::EaseInOut, 0}) - 0.5) < 1e-12);
    QVERIFY(mean({SpacingKind::Favour, -1}) < mean({SpacingKind::Favour, -0.3}));
    QVERIFY(mean({SpacingKind::Favour, -0.3}) < 0.5);
    QVERIFY(mean({SpacingKind::Favour, 0.6}) > 0.5);
    QCOMPARE(inbetweenTimes(3, {SpacingKind::Favour, 0}), inbetweenTimes(3, {}));
    QVERIFY(inbetweenTimes(0, {}).empty());
}

void TestInbetween::targetsAlongArcsAndLines()
{
    const std::vector<QPointF> a{{0, 0}, {200, 0}, {100, 50}};
    std::vector<QPointF> b;
    for (QPointF p : a) // turned 90° about (40, -30)
        b.push_back(QPointF(40, -30) + QPointF(-(p.y() + 30), p.x() - 40));
    for (TargetPath path : {TargetPath::Arc, TargetPath::Straight}) {
        QCOMPARE(interpolateTargets(a, b, 0.0, path), a);
        QCOMPARE(interpolateTargets(a, b, 1.0, path), b);
        QCOMPARE(interpolateTargets(a, b, std::nan(""), path), a);
        QCOMPARE(interpolateTargets(a, {b[0]}, 0.5, path), a); // sizes differ
    }
    const auto arc = interpolateTargets(a, b, 0.5, TargetPath::Arc);
    const auto line = interpolateTargets(a, b, 0.5, TargetPath::Straight);
    // The rigid part travels on the circle: the first two keep their distance on the arc.
    QVERIFY(std::abs(distance(arc[0], arc[1]) - 200.0) < 1e-9);
    QVERIFY(distance(line[0], line[1]) < 150.0);
    // Whatever is not rigid is blended on top: the ends stay exact with a nudged point.
    auto nudged = b;
    nudged[2] += QPointF(6, -4);
    QCOMPARE(interpolateTargets(a, nudged, 1.0, TargetPath::Arc), nudged);
    const auto half = interpolateTargets(a, nudged, 0.5, TargetPath::Arc);
    QVERIFY(std::abs(distance(half[0], half[1]) - 200.0) < 5.0);
    for (std::size_t i = 0; i < a.size(); ++i)
        QVERIFY(distance(line[i], (a[i] + b[i]) / 2) < 1e-12);
    // A pure translation and a single pin move along the line either way.
    const std::vector<QPointF> moved{{10, 20}, {210, 20}, {110, 70}};
    QVERIFY(distance(interpolateTargets(a, moved, 0.25, TargetPath::Arc)[1], {202.5, 5}) < 1e-9);
    QVERIFY(distance(interpolateTargets({a[0]}, {b[0]}, 0.5, TargetPath::Arc)[0],
                     (a[0] + b[0]) / 2) < 1e-12);
}

void TestInbetween::armSwingKeepsItsLength()
{
    DeformSetupCache cache;
    const auto [a, b] = solvedArmKeys(cache);
    const double keyA = strokeLength(*a.groups[0].deformed);
    const double keyB = strokeLength(*b.groups[0].deformed);

    auto arc = planInbetweens(a, b, {0.5}, TargetPath::Arc);
    auto line = planInbetweens(a, b, {0.5}, TargetPath::Straight);
    QCOMPARE(*solveInbetweenPoses(arc.frames, {}, &cache), 1);
    QCOMPARE(*solveInbetweenPoses(line.frames, {}, &cache), 1);
    QCOMPARE(cache.size(), std::size_t(1)); // one factorization for keys and in-betweens
    const double middle = strokeLength(*arc.frames[0].groups[0].deformed);
    const double straight = strokeLength(*line.frames[0].groups[0].deformed);
    const double naive =
        strokeLength(blendPoints(*a.groups[0].deformed, *b.groups[0].deformed, 0.5));
    qInfo("arm length: keys %.2f px and %.2f px; middle in-between re-solved (arc) %.2f px (%+.2f "
          "%%), "
          "targets on straight lines %.2f px (%+.2f %%), naive point blend %.2f px (%+.2f %%)",
          keyA, keyB, middle, 100 * (middle / keyA - 1), straight, 100 * (straight / keyA - 1),
          naive, 100 * (naive / keyA - 1));
    QVERIFY(std::abs(middle / keyA - 1) < 0.02);
    QVERIFY(std::abs(middle / keyB - 1) < 0.02);
    QVERIFY(naive / keyA < 0.75); // a 90° swing blended point by point: cos 45° ≈ 0.71
    QVERIFY(straight < middle);
    // The hand travels on the circle about the shoulder.
    const Rig &rig = arc.frames[0].groups[0].rig;
    QVERIFY(distance(rig.pins[0].target, kShoulder) < 1e-9);
    QVERIFY(std::abs(distance(rig.pins[1].target, kShoulder) - 200) < 1e-9);
}

void TestInbetween::endsEqualTheKeys()
{
    DeformSetupCache cache;
    const auto [a, b] = solvedArmKeys(cache);
    for (TargetPath path : {TargetPath::Arc, TargetPath::Straight}) {
        auto plan = planInbetweens(a, b, {0.0, 1.0}, path);
        QCOMPARE(*solveInbetweenPoses(plan.frames, {}, &cache), 2);
        QCOMPARE(plan.frames[0].groups[0].rig, a.groups[0].rig);
        for (std::size_t i = 0; i < 2; ++i)
            QCOMPARE(plan.frames[1].groups[0].rig.pins[i].target, b.groups[0].rig.pins[i].target);
        QCOMPARE(*plan.frames[0].groups[0].deformed, *a.groups[0].deformed);
        QCOMPARE(*plan.frames[1].groups[0].deformed, *b.groups[0].deformed);
    }
}

void TestInbetween::matchingAndHolding()
{
    DeformSetupCache cache;
    auto [a, b] = solvedArmKeys(cache);
    StrokeGroup prop; // same drawing in both keys, no rig
    prop.id = 90;
    prop.name = QStringLiteral("Prop");
    prop.strokes.push_back({91, line({50, 50}, {80, 90}, 10)});
    StrokeGroup onlyA = prop;
    onlyA.name = QStringLiteral("Only A");
    onlyA.strokes = {{92, line({600, 50}, {650, 90}, 10)}};
    StrokeGroup onlyB = onlyA;
    onlyB.name = QStringLiteral("Only B");
    onlyB.strokes = {{93, line({600, 50}, {650, 90}, 10)}}; // equal points, other data: not one
    StrokeGroup extraB = onlyB;
    extraB.name = QStringLiteral("Extra B");
    a.groups.push_back(prop);
    a.groups.push_back(onlyA);
    b.groups.push_back(prop);
    b.groups.push_back(onlyB);
    b.groups.push_back(extraB);
    b.groups[0].rig.pins[0].rest += QPointF(1, 0); // arm: another rest definition
    auto plan = planInbetweens(a, b, {0.25, 0.5}, TargetPath::Arc);
    QCOMPARE(plan.objects.size(), std::size_t(5));
    QCOMPARE(plan.objects[0].fate, ObjectFate::HeldRigDiffers);
    QCOMPARE(plan.objects[1].fate, ObjectFate::HeldNoRig);
    QCOMPARE(plan.objects[2].fate, ObjectFate::FirstKeyOnly);
    QCOMPARE(plan.objects[3].fate, ObjectFate::SecondKeyOnly);
    QCOMPARE(plan.objects[3].name, QStringLiteral("Only B"));
    QCOMPARE(plan.objects[4].fate, ObjectFate::SecondKeyOnly);
    QCOMPARE(plan.objects[4].secondIndex, 3);
    QCOMPARE(plan.interpolatedCount(), 0);
    const Frame &early = plan.frames[0];
    const Frame &late = plan.frames[1];
    QCOMPARE(early.groups.size(), std::size_t(3));
    QCOMPARE(late.groups.size(), std::size_t(4));
    for (const Frame *f : {&early, &late}) {
        QCOMPARE(f->groups[0].rig, a.groups[0].rig); // held from the first key, with its pose
        QCOMPARE(f->groups[0].deformed, a.groups[0].deformed);
        QCOMPARE(f->groups[1].strokes, prop.strokes);
    }
    QCOMPARE(early.groups[2].name, QStringLiteral("Only A"));
    QCOMPARE(late.groups[2].name, QStringLiteral("Only B"));
    QCOMPARE(late.groups[3].name, QStringLiteral("Extra B"));

    b.groups[0].rig.pins[0].rest = a.groups[0].rig.pins[0].rest; // the arm matches again
    plan = planInbetweens(a, b, {0.5}, TargetPath::Arc);
    QCOMPARE(plan.objects[0].fate, ObjectFate::Interpolated);
    QCOMPARE(plan.interpolatedCount(), 1);
    QVERIFY(!plan.frames[0].groups[0].deformed); // to be solved
}

void TestInbetween::commandInsertsOneUndoStep()
{
    Document doc;
    auto [a, b] = armKeys(1);
    doc.reset({a, b}, {}, 100);
    DeformController controller(&doc);
    const QByteArray before = serializeFinbook(doc);
    auto *command = new InsertInbetweensCommand(&doc, b.id, a.id, 5, {}); // either order
    QCOMPARE(command->plan().interpolatedCount(), 1);
    doc.undoStack()->push(command);
    QCOMPARE(doc.frameCount(), 7);
    QCOMPARE(doc.undoStack()->count(), 1);
    QCOMPARE(doc.frameAt(0).id, a.id);
    QCOMPARE(doc.frameAt(6).id, b.id);
    std::set<Id> ids;
    for (const Frame &f : doc.frames()) {
        ids.insert(f.id);
        for (const StrokeGroup &g : f.groups) {
            ids.insert(g.id);
            for (const Stroke &s : g.strokes)
                ids.insert(s.id);
            for (const Pin &p : g.rig.pins)
                ids.insert(p.id);
        }
    }
    QCOMPARE(ids.size(), std::size_t(2 * 6 + 5 * 6)); // every id distinct
    // The controller poses the new frames (one precompute on the worker, shared by all).
    QTRY_VERIFY_WITH_TIMEOUT(
        std::all_of(doc.frames().begin() + 1, doc.frames().end() - 1,
                    [](const Frame &f) { return f.groups[0].deformed != nullptr; }),
        10000);
    const Frame &middle = doc.frameAt(3);
    QVERIFY(std::abs(strokeLength(*middle.groups[0].deformed) / 200.0 - 1) < 0.02);
    const QByteArray after = serializeFinbook(doc);
    doc.undoStack()->undo();
    QCOMPARE(doc.frameCount(), 2);
    QCOMPARE(serializeFinbook(doc), before);
    doc.undoStack()->redo();
    QCOMPARE(serializeFinbook(doc), after);
}

void TestInbetween::commandRejectsBadInput()
{
    Document doc;
    auto [a, b] = armKeys(1);
    doc.reset({a, b}, {}, 100);
    QVERIFY(InsertInbetweensCommand(&doc, a.id, a.id, 3, {}).isObsolete());
    QVERIFY(InsertInbetweensCommand(&doc, a.id, 999, 3, {}).isObsolete());
    QVERIFY(InsertInbetweensCommand(&doc, a.id, b.id, 0, {}).isObsolete());
    QVERIFY(InsertInbetweensCommand(&doc, a.id, b.id, 61, {}).isObsolete());
    QVERIFY(!InsertInbetweensCommand(&doc, a.id, b.id, 60, {}).isObsolete());
    // A key deleted before redo: the command gives up instead of inserting anywhere.
    InsertInbetweensCommand late(&doc, a.id, b.id, 2, {});
    doc.takeFrame(0);
    late.redo();
    QVERIFY(late.isObsolete());
    QCOMPARE(doc.frameCount(), 1);
}

void TestInbetween::skeletonAnglesTakeTheShorterArc()
{
    Rig first;
    first.skeleton.joints = {QPointF(0, 0), QPointF(100, 0), QPointF(200, 0)};
    first.skeleton.parent = {-1, 0, 1};
    first.skeleton.radius = {5, 5, 5};
    first.skeleton.root = 0;
    first.skeleton.angles = {0.0, 170.0 * M_PI / 180.0, 0.0};
    Rig second = first;
    second.skeleton.angles = {0.0, -170.0 * M_PI / 180.0, M_PI / 2};
    second.skeleton.rootOffset = QPointF(40, -20);
    QVERIFY(canInterpolateRigs(first, second));
    const Rig middle = interpolateRig(first, second, 0.5, TargetPath::Arc);
    // 170° to −170° goes the short way, through 180°, not back through 0°.
    QVERIFY(std::abs(std::abs(middle.skeleton.angles[1]) - M_PI) < 1e-12);
    QVERIFY(std::abs(middle.skeleton.angles[2] - M_PI / 4) < 1e-12);
    QCOMPARE(middle.skeleton.rootOffset, QPointF(20, -10));
    QCOMPARE(interpolateRig(first, second, 0.0, TargetPath::Arc).skeleton, first.skeleton);
    QCOMPARE(interpolateRig(first, second, 1.0, TargetPath::Arc).skeleton, second.skeleton);
}

QTEST_MAIN(TestInbetween)
#include "tst_inbetween.moc"
