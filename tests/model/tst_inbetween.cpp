// In-betweens from poses: spacing, target interpolation, planning, the synchronous solve, and
// InsertInbetweensCommand with the DeformController.
#include "inbetween_support.h"

#include <finbook/model/cage/cage_setup.h>
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

QPointF pointOf(const StrokePoint &p)
{
    return {p.x, p.y};
}

bool allFinite(const DeformedStrokes &pose)
{
    for (const auto &stroke : pose.strokes)
        for (const StrokePoint &p : stroke)
            if (!std::isfinite(p.x) || !std::isfinite(p.y))
                return false;
    return true;
}

// Keys and in-betweens at `times`, solved the way the dialog's preview and the benchmark do
// (solveInbetweenPoses with one shared setup cache). Fails the test when anything does not
// solve.
struct SolvedSwing {
    std::vector<Frame> keys;
    InbetweenPlan plan;
    std::size_t setups = 0;
};

SolvedSwing solveSwing(const Frame &a, const Frame &b, const std::vector<double> &times)
{
    SolvedSwing out;
    DeformSetupCache cache;
    out.keys = {a, b};
    const auto keys = solveInbetweenPoses(out.keys, {}, &cache);
    if (!keys || *keys != 2)
        qFatal("keys do not solve: %s", keys ? "not posed" : qPrintable(keys.error()));
    out.plan = planInbetweens(out.keys[0], out.keys[1], times, TargetPath::Arc);
    const auto solved = solveInbetweenPoses(out.plan.frames, {}, &cache);
    if (!solved || *solved != int(times.size()))
        qFatal("in-betweens do not solve: %s", solved ? "not posed" : qPrintable(solved.error()));
    out.setups = cache.size();
    return out;
}

// The angle (radians) of `p` seen from `pivot`.
double angleFrom(QPointF pivot, QPointF p)
{
    return std::atan2(p.y() - pivot.y(), p.x() - pivot.x());
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
    void skeletonArmSwingKeepsItsLength_data();
    void skeletonArmSwingKeepsItsLength();
    void cageBendInbetweens();
    void skeletonAnglesLeftOutCountAsRest();
    void mismatchedSkeletonsAreHeld();
    void controllerPosesSkeletonAndCageInbetweens_data();
    void controllerPosesSkeletonAndCageInbetweens();
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
    doc.takeFrame(doc.currentLayerId(), 0);
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

void TestInbetween::skeletonArmSwingKeepsItsLength_data()
{
    QTest::addColumn<bool>("built");
    QTest::addColumn<int>("mode");
    QTest::newRow("three joints, rigid") << false << int(SkinningMode::Rigid);
    QTest::newRow("three joints, linear blend") << false << int(SkinningMode::LinearBlend);
    QTest::newRow("built, rigid") << true << int(SkinningMode::Rigid);
    QTest::newRow("built, linear blend") << true << int(SkinningMode::LinearBlend);
}

// The figure for the skeleton: a 90° swing of the shoulder bone keeps the arm's length
// in the middle in-between, the naive point blend loses about 30 %, and the ends are the keys.
void TestInbetween::skeletonArmSwingKeepsItsLength()
{
    QFETCH(bool, built);
    QFETCH(int, mode);
    const SkeletonRig rest = built ? builtArmSkeleton() : armSkeleton();
    QVERIFY(!rest.empty() && rest.isValid());
    const auto [a, b] = skeletonArmKeys(rest, SkinningMode(mode));
    const SolvedSwing swing = solveSwing(a, b, {0.0, 0.5, 1.0});
    QCOMPARE(swing.plan.interpolatedCount(), 1);
    QCOMPARE(swing.setups, std::size_t(1)); // keys and in-betweens share one skinning setup
    const DeformedStrokes &poseA = *swing.keys[0].groups[0].deformed;
    const DeformedStrokes &poseB = *swing.keys[1].groups[0].deformed;
    const auto &frames = swing.plan.frames;

    // t = 0 and t = 1 are the keys: the same rig, and the same solve to the bit.
    QCOMPARE(frames[0].groups[0].rig, a.groups[0].rig);
    QCOMPARE(frames[2].groups[0].rig.skeleton, b.groups[0].rig.skeleton);
    QCOMPARE(*frames[0].groups[0].deformed, poseA);
    QCOMPARE(*frames[2].groups[0].deformed, poseB);

    // Half way the shoulder bone has turned half as far.
    const SkeletonRig &half = frames[1].groups[0].rig.skeleton;
    for (std::size_t j = 0; j < half.angles.size(); ++j)
        QVERIFY(std::abs(half.angles[j] - b.groups[0].rig.skeleton.angles[j] / 2) < 1e-12);
    const DeformedStrokes &middle = *frames[1].groups[0].deformed;
    QVERIFY(allFinite(middle));

    const double keyA = strokeLength(poseA), keyB = strokeLength(poseB);
    const double resolved = strokeLength(middle);
    const double naive = strokeLength(blendPoints(poseA, poseB, 0.5));
    qInfo("skeleton (%s, %s): keys %.2f px and %.2f px; middle in-between %.2f px (%+.2f %%), "
          "naive point blend %.2f px (%+.2f %%)",
          built ? "built" : "three joints", mode ? "linear blend" : "rigid", keyA, keyB, resolved,
          100 * (resolved / keyA - 1), naive, 100 * (naive / keyA - 1));
    QVERIFY(std::abs(resolved / keyA - 1) < 0.02);
    QVERIFY(std::abs(resolved / keyB - 1) < 0.02);
    QVERIFY(naive / keyA < 0.8); // shortened by more than 20 % (cos 45° ≈ 0.71)

    // The hand is half way round: 45° about the root joint, as far from it as in the keys.
    const QPointF root = rest.joints[std::size_t(rest.root)];
    const QPointF handA = pointOf(poseA.strokes[1].back());
    const QPointF handB = pointOf(poseB.strokes[1].back());
    const QPointF hand = pointOf(middle.strokes[1].back());
    const double turnB = std::remainder(angleFrom(root, handB) - angleFrom(root, handA), 2 * M_PI);
    const double turnMiddle =
        std::remainder(angleFrom(root, hand) - angleFrom(root, handA), 2 * M_PI);
    QVERIFY2(std::abs(turnB - M_PI / 2) < 2 * M_PI / 180, qPrintable(QString::number(turnB)));
    QVERIFY2(std::abs(turnMiddle - M_PI / 4) < 2 * M_PI / 180,
             qPrintable(QString::number(turnMiddle)));
    QVERIFY(std::abs(distance(root, hand) / distance(root, handA) - 1) < 0.02);
}

// A cage bent at the elbow: the in-betweens are finite, the forearm swings through the bend
// step by step, and the ends are the keys.
void TestInbetween::cageBendInbetweens()
{
    const auto [a, b] = cageArmKeys(M_PI / 3);
    QVERIFY(!cageProblem(a.groups[0], a.groups[0].rig.cage.rest));
    const std::vector<double> times{0.0, 0.25, 0.5, 0.75, 1.0};
    const SolvedSwing swing = solveSwing(a, b, times);
    QCOMPARE(swing.plan.interpolatedCount(), 1);
    QCOMPARE(swing.setups, std::size_t(1));
    const DeformedStrokes &poseA = *swing.keys[0].groups[0].deformed;
    const DeformedStrokes &poseB = *swing.keys[1].groups[0].deformed;
    const auto &frames = swing.plan.frames;
    QCOMPARE(frames[0].groups[0].rig, a.groups[0].rig);
    QCOMPARE(frames[4].groups[0].rig.cage, b.groups[0].rig.cage);
    QCOMPARE(*frames[0].groups[0].deformed, poseA);
    QCOMPARE(*frames[4].groups[0].deformed, poseB);

    const QPointF elbow = (kShoulder + kHand) / 2;
    const auto tipTurn = [&](const DeformedStrokes &pose) {
        return angleFrom(elbow, pointOf(pose.strokes[1].back())) -
               angleFrom(elbow, pointOf(poseA.strokes[1].back()));
    };
    QRectF keysBox;
    for (const DeformedStrokes *pose : {&poseA, &poseB})
        for (const auto &stroke : pose->strokes)
            for (const StrokePoint &p : stroke)
                keysBox |= QRectF(pointOf(p), QSizeF(1e-9, 1e-9));
    keysBox.adjust(-2, -2, 2, 2);
    double previous = tipTurn(poseA);
    for (std::size_t i = 1; i + 1 < frames.size(); ++i) {
        const DeformedStrokes &pose = *frames[i].groups[0].deformed;
        QVERIFY(allFinite(pose));
        for (const auto &stroke : pose.strokes)
            for (const StrokePoint &p : stroke)
                QVERIFY2(keysBox.contains(pointOf(p)),
                         qPrintable(QStringLiteral("t %1: (%2, %3) outside the keys")
                                        .arg(times[i])
                                        .arg(p.x)
                                        .arg(p.y)));
        const double turn = tipTurn(pose);
        QVERIFY(turn > previous); // the forearm swings on, step by step
        previous = turn;
    }
    QVERIFY(previous < tipTurn(poseB));
    // Corners that stay put in both keys stay put in between.
    const auto &restCorners = a.groups[0].rig.cage.rest;
    const auto &middleCorners = frames[2].groups[0].rig.cage.posed;
    double drift = 0;
    for (std::size_t i = 0; i < restCorners.size(); ++i)
        if (restCorners[i] == b.groups[0].rig.cage.posed[i])
            drift = std::max(drift, distance(middleCorners[i], restCorners[i]));
    QCOMPARE(drift, 0.0);
    // The corners that move turn about the elbow they were bent about, half way at t = 0.5.
    for (std::size_t i = 0; i < restCorners.size(); ++i)
        if (restCorners[i] != b.groups[0].rig.cage.posed[i]) {
            const QPointF expected = turnedAbout(restCorners[i], elbow, M_PI / 6);
            QVERIFY2(distance(middleCorners[i], expected) < 1e-6,
                     qPrintable(QStringLiteral("corner %1 is %2 px off the arc")
                                    .arg(i)
                                    .arg(distance(middleCorners[i], expected))));
        }
    const double middleTurn = tipTurn(*frames[2].groups[0].deformed);
    const double keyLength = strokeLength(poseA);
    const double middleLength = strokeLength(*frames[2].groups[0].deformed);
    const double naiveLength = strokeLength(blendPoints(poseA, poseB, 0.5));
    qInfo("cage bend %.1f°: forearm tip turned %.2f° half way; still corners drift %.3f px; arm "
          "length keys %.2f / %.2f px, middle %.2f px, naive point blend %.2f px",
          tipTurn(poseB) * 180 / M_PI, middleTurn * 180 / M_PI, drift, keyLength,
          strokeLength(poseB), middleLength, naiveLength);
}

// Regression: a skeleton key that leaves its angles out (valid: empty = at rest) against a
// posed one was held from the first key instead of interpolated, because the angle counts
// differed.
void TestInbetween::skeletonAnglesLeftOutCountAsRest()
{
    auto [a, b] = skeletonArmKeys(armSkeleton(), SkinningMode::Rigid);
    a.groups[0].rig.skeleton.angles.clear();
    QVERIFY(a.groups[0].rig.skeleton.isValid());
    QVERIFY(canInterpolateRigs(a.groups[0].rig, b.groups[0].rig));
    QVERIFY(canInterpolateRigs(b.groups[0].rig, a.groups[0].rig));
    const Rig half = interpolateRig(a.groups[0].rig, b.groups[0].rig, 0.5, TargetPath::Arc);
    QCOMPARE(half.skeleton.angles, (std::vector<double>{0.0, M_PI / 4, 0.0}));
    const Rig back = interpolateRig(b.groups[0].rig, a.groups[0].rig, 0.5, TargetPath::Arc);
    QCOMPARE(back.skeleton.angles, (std::vector<double>{0.0, M_PI / 4, 0.0}));
    QCOMPARE(interpolateRig(a.groups[0].rig, b.groups[0].rig, 0.0, TargetPath::Arc),
             a.groups[0].rig);

    const SolvedSwing swing = solveSwing(a, b, {0.0, 0.5, 1.0});
    QCOMPARE(swing.plan.objects[0].fate, ObjectFate::Interpolated);
    QCOMPARE(*swing.plan.frames[0].groups[0].deformed, *swing.keys[0].groups[0].deformed);
    QCOMPARE(*swing.plan.frames[2].groups[0].deformed, *swing.keys[1].groups[0].deformed);
    const DeformedStrokes &middle = *swing.plan.frames[1].groups[0].deformed;
    QVERIFY(std::abs(strokeLength(middle) / strokeLength(*swing.keys[0].groups[0].deformed) - 1) <
            0.02);

    // A malformed angle list (neither empty nor one per joint) is still not interpolated.
    b.groups[0].rig.skeleton.angles.pop_back();
    QVERIFY(!canInterpolateRigs(a.groups[0].rig, b.groups[0].rig));
}

// Skeletons that differ in their rest bones or skinning mode are held from the first key,
// with its pose; the plan says so.
void TestInbetween::mismatchedSkeletonsAreHeld()
{
    for (int variant = 0; variant < 2; ++variant) {
        auto [a, b] = skeletonArmKeys(armSkeleton(), SkinningMode::Rigid);
        if (variant == 0)
            b.groups[0].rig.skeleton.mode = SkinningMode::LinearBlend;
        else
            b.groups[0].rig.skeleton.joints[1] += QPointF(0, 1);
        std::vector<Frame> keys{a, b};
        QCOMPARE(*solveInbetweenPoses(keys), 2);
        auto plan = planInbetweens(keys[0], keys[1], {0.25, 0.75}, TargetPath::Arc);
        QCOMPARE(plan.objects[0].fate, ObjectFate::HeldRigDiffers);
        QCOMPARE(plan.objects[0].rig, RigKind::Skeleton);
        QCOMPARE(plan.interpolatedCount(), 0);
        for (const Frame &f : plan.frames) {
            QCOMPARE(f.groups[0].rig, keys[0].groups[0].rig);
            QCOMPARE(f.groups[0].deformed, keys[0].groups[0].deformed);
        }
        QCOMPARE(*solveInbetweenPoses(plan.frames), 0); // nothing left to solve
    }
}

void TestInbetween::controllerPosesSkeletonAndCageInbetweens_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<int>("mode");
    QTest::newRow("skeleton, rigid") << int(RigKind::Skeleton) << int(SkinningMode::Rigid);
    QTest::newRow("skeleton, linear blend")
        << int(RigKind::Skeleton) << int(SkinningMode::LinearBlend);
    QTest::newRow("cage") << int(RigKind::Cage) << 0;
}

// The app's path: Generate In-betweens pushes InsertInbetweensCommand and the DeformController
// poses the new frames; they match the synchronous solve, and undo/redo restore the document.
void TestInbetween::controllerPosesSkeletonAndCageInbetweens()
{
    QFETCH(int, kind);
    QFETCH(int, mode);
    const auto [a, b] = RigKind(kind) == RigKind::Skeleton
                            ? skeletonArmKeys(armSkeleton(), SkinningMode(mode))
                            : cageArmKeys();
    Document doc;
    doc.reset({a, b}, {}, 100);
    DeformController controller(&doc);
    const auto posed = [&] {
        return std::all_of(doc.frames().begin(), doc.frames().end(), [&](const Frame &f) {
            // Not the cage's stand-in (a similarity shown while its coordinates are on the way).
            const Id id = f.groups[0].id;
            return f.groups[0].deformed && !controller.isWaiting(id) && !controller.isSettling(id);
        });
    };
    // The keys posed as the user left them (the controller prepares an object when it is
    // edited or shown; a reopened file carries the poses).
    controller.prepare(a.groups[0].id);
    controller.prepare(b.groups[0].id);
    QTRY_VERIFY_WITH_TIMEOUT(posed(), 20000);
    const QByteArray before = serializeFinbook(doc);
    auto *command = new InsertInbetweensCommand(&doc, a.id, b.id, 5, {});
    QCOMPARE(command->plan().interpolatedCount(), 1);
    doc.undoStack()->push(command);
    QCOMPARE(doc.frameCount(), 7);
    QTRY_VERIFY_WITH_TIMEOUT(posed(), 20000);
    controller.settle();

    const SolvedSwing swing = solveSwing(a, b, command->plan().times);
    for (int i = 0; i < 5; ++i) {
        const StrokeGroup &g = doc.frameAt(1 + i).groups[0];
        QCOMPARE(g.rig.kind(), RigKind(kind));
        QCOMPARE(g.rig, swing.plan.frames[std::size_t(i)].groups[0].rig);
        QVERIFY(allFinite(*g.deformed));
        const DeformedStrokes &expected = *swing.plan.frames[std::size_t(i)].groups[0].deformed;
        double worst = 0;
        for (std::size_t s = 0; s < expected.strokes.size(); ++s)
            for (std::size_t k = 0; k < expected.strokes[s].size(); ++k)
                worst = std::max(worst, distance(pointOf(g.deformed->strokes[s][k]),
                                                 pointOf(expected.strokes[s][k])));
        QVERIFY2(worst < 1e-3, qPrintable(QStringLiteral("in-between %1: %2 px from the "
                                                         "synchronous solve")
                                              .arg(i + 1)
                                              .arg(worst)));
    }
    if (RigKind(kind) == RigKind::Skeleton) {
        const double keyLength = strokeLength(*swing.keys[0].groups[0].deformed);
        QVERIFY(std::abs(strokeLength(*doc.frameAt(3).groups[0].deformed) / keyLength - 1) < 0.02);
    }
    const QByteArray after = serializeFinbook(doc);
    doc.undoStack()->undo();
    QCOMPARE(doc.frameCount(), 2);
    QCOMPARE(serializeFinbook(doc), before);
    doc.undoStack()->redo();
    QCOMPARE(serializeFinbook(doc), after);
}

QTEST_MAIN(TestInbetween)
#include "tst_inbetween.moc"
