// Characters made of parts (issue 9/10): an arm drawn over a torso joins the torso's skeleton,
// posing the torso moves the arm (and its drawing), the arm's weights include the torso bone
// it hangs from, and joins are undoable, never make the drawing jump, follow Duplicate Frame
// and are saved. A painted picture joins a drawn part the same way.
#include "random_edits.h"
#include "stroke_support.h"

#include <finbook/deform/skeleton/skinning_weights.h>
#include <finbook/model/deform_controller.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/inbetween/inbetween_commands.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/skeleton/skeleton_commands.h>
#include <finbook/model/skeleton/skeleton_join_commands.h>
#include <finbook/model/skeleton/skeleton_setup.h>

#include <QPainter>
#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <map>
#include <numbers>
#include <optional>

using namespace finbook;
using namespace finbook::model;

namespace {

StrokeDataPtr line(QPointF a, QPointF b, int n)
{
    return finbook::testing::lineStroke(a, b, n, 6.0f);
}

// A thick bar of parallel strokes from a to b (`across` px wide).
StrokeGroup bar(Document &doc, const QString &name, QPointF a, QPointF b, double across)
{
    StrokeGroup g;
    g.id = doc.allocateId();
    g.name = name;
    const QPointF d = b - a;
    const QPointF n = QPointF(-d.y(), d.x()) / std::hypot(d.x(), d.y());
    for (double o = -across / 2; o <= across / 2 + 1e-9; o += 5.0)
        g.strokes.push_back({doc.allocateId(), line(a + o * n, b + o * n, 80)});
    return g;
}

struct Character {
    Id torso = kNoId;
    Id arm = kNoId;
};

// The document holding `f` alone (its torso first, its arm second), each part with its
// automatic skeleton.
Character riggedCharacter(Document &doc, const Frame &f)
{
    const Character c{f.groups[0].id, f.groups[1].id};
    doc.reset({f}, DocumentSettings{}, doc.nextId());
    for (Id id : {c.torso, c.arm}) {
        auto rig = buildSkeletonRig(*doc.group(id));
        if (!rig)
            qWarning("%s", qPrintable(rig.error()));
        doc.undoStack()->push(new BuildSkeletonCommand(&doc, id, rig ? *rig : SkeletonRig{}));
    }
    return c;
}

// A tall torso and an arm drawn over its upper end, each with its automatic skeleton.
Character makeCharacter(Document &doc)
{
    Frame f;
    f.id = doc.allocateId();
    f.groups.push_back(bar(doc, QStringLiteral("torso"), {300, 100}, {300, 500}, 40));
    f.groups.push_back(bar(doc, QStringLiteral("arm"), {305, 160}, {600, 160}, 30));
    return riggedCharacter(doc, f);
}

bool waitSolved(DeformController &controller, const Document &doc, Id groupId)
{
    QSignalSpy solved(&controller, &DeformController::poseSolved);
    QSignalSpy failed(&controller, &DeformController::errorOccurred);
    const auto ready = [&] {
        const DeformSetup *s = controller.setup(groupId);
        return s && s->matches(*doc.group(groupId), -1.0) && !controller.isWaiting(groupId) &&
               doc.group(groupId)->deformed;
    };
    for (int i = 0; i < 400 && !ready() && failed.isEmpty(); ++i)
        solved.wait(25);
    for (const auto &args : failed)
        qWarning("deformation failed: %s", qPrintable(args.at(1).toString()));
    return ready();
}

// Both parts precomputed and solved.
bool prepared(DeformController &controller, const Document &doc, const Character &c)
{
    controller.prepare(c.torso);
    controller.prepare(c.arm);
    return waitSolved(controller, doc, c.torso) && waitSolved(controller, doc, c.arm);
}

void poseRoot(Document &doc, Id id, double angle, QPointF offset, int serial)
{
    std::vector<double> angles(std::size_t(doc.group(id)->rig.skeleton.jointCount()), 0.0);
    angles[std::size_t(doc.group(id)->rig.skeleton.root)] = angle;
    doc.undoStack()->push(new PoseBonesCommand(&doc, id, angles, offset, serial));
}

// Turns the torso by `theta` about its root and waits until the arm follows; the root, or
// nullopt when the arm's pose never came.
std::optional<QPointF> turnTorso(Document &doc, DeformController &controller, const Character &c,
                                 double theta)
{
    const SkeletonRig torso = doc.group(c.torso)->rig.skeleton;
    const QPointF pivot = torso.joints[std::size_t(torso.root)];
    poseRoot(doc, c.torso, theta, {}, 1);
    if (!waitSolved(controller, doc, c.arm))
        return std::nullopt;
    controller.settle();
    return pivot;
}

double distance(const std::vector<QPointF> &a, const std::vector<QPointF> &b)
{
    double worst = a.size() == b.size() ? 0.0 : HUGE_VAL;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
        worst = std::max(worst, QLineF(a[i], b[i]).length());
    return worst;
}

// Every layer's rigs (which layer is current is not undo state).
std::vector<Rig> rigsOf(const Document &doc)
{
    std::vector<Rig> rigs;
    for (const Layer &l : doc.layers())
        for (const Frame &f : l.cels)
            for (const StrokeGroup &g : f.groups)
                rigs.push_back(g.rig);
    return rigs;
}

// The arm hung from the torso where it overlaps it best.
Character joined(Document &doc, const Character &c)
{
    const auto join = proposeJoin(doc.frames()[0], c.arm);
    if (join)
        doc.undoStack()->push(new JoinPartCommand(&doc, c.arm, *join));
    return c;
}

Character joinedCharacter(Document &doc)
{
    return joined(doc, makeCharacter(doc));
}

} // namespace

class TestSkeletonJoin : public QObject {
    Q_OBJECT
private slots:
    void overlappingArmJoinsTheTorso();
    void posingTheTorsoMovesTheArm();
    void posedArmFollowsThroughTheController();
    void weightsIncludeTheJoinedBone();
    void joinDetachAndRerootKeepTheShownPose();
    void loopsAreRefused();
    void joinOverlappingPartsJoinsSmallerToBigger();
    void removingTheParentLeavesThePartStanding();
    void duplicateFrameKeepsJoinsWithinTheCopy();
    void fileRoundTripKeepsJoins();
    void applyPoseBakesTheWholeCharacter();
    void joinEditsUndoAndRedoExactly();
    void inbetweensMoveThePartWithItsParent();
    void randomCharacterEditsUndoExactly();
    void aPictureArmJoinsADrawnTorso();
};

void TestSkeletonJoin::overlappingArmJoinsTheTorso()
{
    Document doc;
    const Character c = makeCharacter(doc);
    const auto join = proposeJoin(doc.frames()[0], c.arm);
    QVERIFY(join);
    QCOMPARE(join->parent, c.torso);
    // It attaches at the arm's inner end, inside the torso.
    QVERIFY2(join->childAt.x() < 330, qPrintable(QString::number(join->childAt.x())));
    QVERIFY(std::abs(join->parentAt.x() - 300) < 10);
    QVERIFY(!proposeJoin(doc.frames()[0], c.torso) ||
            proposeJoin(doc.frames()[0], c.torso)->parent == c.arm);

    doc.undoStack()->push(new JoinPartCommand(&doc, c.arm, *join));
    const SkeletonRig &arm = doc.group(c.arm)->rig.skeleton;
    QVERIFY(arm.hangs());
    QCOMPARE(arm.join.parent, c.torso);
    QVERIFY(arm.anchor.motion.isIdentity()); // the torso is at rest
    QVERIFY(!arm.isPosed());
    // Re-rooted where it attaches, so it turns about the shoulder.
    QVERIFY(QLineF(arm.joints[std::size_t(arm.root)], join->childAt).length() < 40);
    QCOMPARE(characterRoot(doc.frames()[0], c.arm), c.torso);
    QCOMPARE(characterParts(doc.frames()[0], c.arm), (std::vector<Id>{c.torso, c.arm}));
}

void TestSkeletonJoin::posingTheTorsoMovesTheArm()
{
    Document doc;
    const Character c = joinedCharacter(doc);
    QVERIFY(doc.group(c.arm)->rig.skeleton.hangs());
    const std::vector<QPointF> armRest = doc.group(c.arm)->rig.skeleton.joints;
    const SkeletonRig torsoRest = doc.group(c.torso)->rig.skeleton;
    const QPointF pivot = torsoRest.joints[std::size_t(torsoRest.root)];
    const double theta = 0.4;
    QSignalSpy changed(&doc, &Document::constraintsChanged);
    poseRoot(doc, c.torso, theta, {10, -5}, 1);
    // The arm's constraints changed too: the controller re-solves it.
    QVERIFY(std::any_of(changed.begin(), changed.end(),
                        [&](const QList<QVariant> &a) { return a.at(0).value<Id>() == c.arm; }));
    const SkeletonRig &arm = doc.group(c.arm)->rig.skeleton;
    QVERIFY(arm.isPosed());
    const std::vector<QPointF> shown = arm.posedJoints();
    const double cs = std::cos(theta), sn = std::sin(theta);
    for (std::size_t j = 0; j < armRest.size(); ++j) {
        const QPointF r = armRest[j] - pivot;
        const QPointF expected =
            pivot + QPointF(cs * r.x() - sn * r.y(), sn * r.x() + cs * r.y()) + QPointF(10, -5);
        QVERIFY2(QLineF(shown[j], expected).length() < 1e-9,
                 qPrintable(QStringLiteral("joint %1 off by %2")
                                .arg(j)
                                .arg(QLineF(shown[j], expected).length())));
    }
    // Undo puts the arm back at rest.
    doc.undoStack()->undo();
    QVERIFY(distance(doc.group(c.arm)->rig.skeleton.posedJoints(), armRest) < 1e-12);
    QVERIFY(!doc.group(c.arm)->rig.skeleton.isPosed());
}

void TestSkeletonJoin::posedArmFollowsThroughTheController()
{
    Document doc;
    DeformController controller(&doc);
    const Character c = joinedCharacter(doc);
    QVERIFY(prepared(controller, doc, c));
    const double theta = 0.3;
    const auto turned = turnTorso(doc, controller, c, theta);
    QVERIFY(turned);
    const QPointF pivot = *turned;
    // The arm's far end turns by θ about the torso's root, like the torso itself.
    const StrokeGroup &arm = *doc.group(c.arm);
    QVERIFY(arm.isDeformed());
    int checked = 0;
    for (std::size_t s = 0; s < arm.strokes.size(); ++s) {
        const auto &rest = arm.strokes[s].data->points;
        const auto &posed = arm.deformed->strokes[s];
        for (std::size_t i = 0; i < rest.size(); ++i) {
            if (rest[i].x < 560)
                continue; // near the tip only
            const double a0 = std::atan2(rest[i].y - pivot.y(), rest[i].x - pivot.x());
            const double a1 = std::atan2(posed[i].y - pivot.y(), posed[i].x - pivot.x());
            QVERIFY2(std::abs(std::remainder(a1 - a0 - theta, 2 * std::numbers::pi)) < 1e-3,
                     qPrintable(QString::number(a1 - a0)));
            QVERIFY(std::isfinite(posed[i].x) && std::isfinite(posed[i].y));
            ++checked;
        }
    }
    QVERIFY(checked > 20);
}

void TestSkeletonJoin::weightsIncludeTheJoinedBone()
{
    Document doc;
    const Character c = joinedCharacter(doc);
    const SkeletonRig &arm = doc.group(c.arm)->rig.skeleton;
    QVERIFY(arm.hangs());
    QVERIFY(arm.anchor.from != arm.anchor.to);
    auto skeleton = skinningSkeleton(arm);
    QVERIFY(skeleton);
    QCOMPARE(skeleton->jointCount(), Eigen::Index(arm.jointCount() + 2));
    auto own = deformSkeleton(arm);
    QVERIFY(own);
    QCOMPARE(own->jointCount(), Eigen::Index(arm.jointCount()));

    auto meshed = meshObject(MeshKey::of(*doc.group(c.arm), -1.0));
    QVERIFY(meshed);
    auto weights = deform::computeSkinningWeights((*meshed)->mesh.V, (*meshed)->mesh.F, *skeleton);
    QVERIFY(weights);
    const Eigen::MatrixXd &W = (*weights)->W;
    const Eigen::Index anchorBone = skeleton->jointCount() - 1;
    // The torso bone holds the arm's vertices where it passes through them, and no more
    // than the shoulder: the far half of the arm is the arm's own.
    double nearShoulder = 0.0, farHalf = 0.0;
    for (Eigen::Index i = 0; i < W.rows(); ++i) {
        QVERIFY(std::abs(W.row(i).sum() - 1.0) < 1e-9);
        QVERIFY(W.row(i).minCoeff() >= -1e-12 && W.row(i).maxCoeff() <= 1.0 + 1e-12);
        const double x = (*meshed)->mesh.V(i, 0);
        if (x < 310)
            nearShoulder = std::max(nearShoulder, W(i, anchorBone));
        if (x > 450)
            farHalf = std::max(farHalf, W(i, anchorBone));
    }
    QVERIFY2(nearShoulder > 0.9, qPrintable(QString::number(nearShoulder)));
    QVERIFY2(farHalf < 0.05, qPrintable(QString::number(farHalf)));
}

void TestSkeletonJoin::joinDetachAndRerootKeepTheShownPose()
{
    Document doc;
    const Character c = makeCharacter(doc);
    // Both posed before they are joined.
    poseRoot(doc, c.torso, 0.5, {20, 10}, 1);
    poseRoot(doc, c.arm, -0.2, {-5, 3}, 2);
    const std::vector<QPointF> torsoShown = doc.group(c.torso)->rig.skeleton.posedJoints();
    const std::vector<QPointF> armShown = doc.group(c.arm)->rig.skeleton.posedJoints();
    const auto join = proposeJoin(doc.frames()[0], c.arm);
    QVERIFY(join);
    doc.undoStack()->push(new JoinPartCommand(&doc, c.arm, *join));
    QVERIFY(doc.group(c.arm)->rig.skeleton.hangs());
    QVERIFY(distance(doc.group(c.arm)->rig.skeleton.posedJoints(), armShown) < 1e-9);
    QVERIFY(distance(doc.group(c.torso)->rig.skeleton.posedJoints(), torsoShown) < 1e-9);

    doc.undoStack()->push(new MakeCharacterRootCommand(&doc, c.arm));
    QCOMPARE(characterRoot(doc.frames()[0], c.torso), c.arm);
    QVERIFY(doc.group(c.torso)->rig.skeleton.hangs());
    QVERIFY(!doc.group(c.arm)->rig.skeleton.hangs());
    QVERIFY(distance(doc.group(c.arm)->rig.skeleton.posedJoints(), armShown) < 1e-9);
    QVERIFY(distance(doc.group(c.torso)->rig.skeleton.posedJoints(), torsoShown) < 1e-9);
    // Now the arm leads: moving it moves the torso.
    const SkeletonRig armNow = doc.group(c.arm)->rig.skeleton;
    doc.undoStack()->push(
        new PoseBonesCommand(&doc, c.arm, armNow.angles, armNow.rootOffset + QPointF(7, 0), 3));
    std::vector<QPointF> moved = torsoShown;
    for (QPointF &p : moved)
        p += QPointF(7, 0);
    QVERIFY(distance(doc.group(c.torso)->rig.skeleton.posedJoints(), moved) < 1e-9);
    doc.undoStack()->undo();

    doc.undoStack()->push(new DetachPartCommand(&doc, c.torso));
    QVERIFY(!doc.group(c.torso)->rig.skeleton.join.joined());
    QVERIFY(distance(doc.group(c.torso)->rig.skeleton.posedJoints(), torsoShown) < 1e-9);
    QCOMPARE(characterParts(doc.frames()[0], c.arm), std::vector<Id>{c.arm});
}

void TestSkeletonJoin::loopsAreRefused()
{
    Document doc;
    const Character c = joinedCharacter(doc);
    const SkeletonRig &torso = doc.group(c.torso)->rig.skeleton;
    const SkeletonRig &arm = doc.group(c.arm)->rig.skeleton;
    JoinPartCommand loop(&doc, c.torso, joinAt(torso, c.arm, arm.joints.back()));
    QVERIFY(loop.isObsolete());
    JoinPartCommand self(&doc, c.arm, joinAt(arm, c.arm, arm.joints.front()));
    QVERIFY(self.isObsolete());
    // A loop written into a file resolves as no join at all.
    Frame f = doc.frames()[0];
    f.groups[0].rig.skeleton.join = joinAt(f.groups[0].rig.skeleton, c.arm, arm.joints.back());
    resolveJoins(f);
    QVERIFY(!f.groups[0].rig.skeleton.hangs() || !f.groups[1].rig.skeleton.hangs());
}

void TestSkeletonJoin::joinOverlappingPartsJoinsSmallerToBigger()
{
    Document doc;
    const Character c = makeCharacter(doc);
    auto *command = new JoinOverlappingPartsCommand(&doc, doc.frames()[0].id);
    QCOMPARE(command->joined(), 1);
    doc.undoStack()->push(command);
    QVERIFY(doc.group(c.arm)->rig.skeleton.hangs());
    QVERIFY(!doc.group(c.torso)->rig.skeleton.join.joined());
    // Nothing left to join.
    JoinOverlappingPartsCommand again(&doc, doc.frames()[0].id);
    QVERIFY(again.isObsolete());
    doc.undoStack()->undo();
    QVERIFY(!doc.group(c.arm)->rig.skeleton.join.joined());
}

void TestSkeletonJoin::removingTheParentLeavesThePartStanding()
{
    Document doc;
    const Character c = joinedCharacter(doc);
    poseRoot(doc, c.torso, 0.3, {}, 1);
    const SkeletonRig before = doc.group(c.arm)->rig.skeleton;
    QVERIFY(before.isPosed());
    doc.undoStack()->push(new RemoveObjectCommand(&doc, c.torso));
    const SkeletonRig &alone = doc.group(c.arm)->rig.skeleton;
    QVERIFY(!alone.hangs());
    QVERIFY(!alone.isPosed());
    QCOMPARE(alone.posedJoints(), alone.joints);
    doc.undoStack()->undo();
    QCOMPARE(doc.group(c.arm)->rig.skeleton, before);
}

void TestSkeletonJoin::duplicateFrameKeepsJoinsWithinTheCopy()
{
    Document doc;
    const Character c = joinedCharacter(doc);
    poseRoot(doc, c.torso, 0.2, {}, 1);
    doc.undoStack()->push(new DuplicateFrameCommand(&doc, doc.frames()[0].id, 1));
    const Frame &copy = doc.frames()[1];
    const StrokeGroup &torso2 = copy.groups[0];
    const StrokeGroup &arm2 = copy.groups[1];
    QVERIFY(torso2.id != c.torso && arm2.id != c.arm);
    QCOMPARE(arm2.rig.skeleton.join.parent, torso2.id);
    QVERIFY(arm2.rig.skeleton.hangs());
    QCOMPARE(arm2.rig.skeleton.posedJoints(), doc.group(c.arm)->rig.skeleton.posedJoints());
    // Posing the copy's torso moves the copy's arm only.
    const std::vector<QPointF> original = doc.group(c.arm)->rig.skeleton.posedJoints();
    const Id arm2Id = arm2.id;
    poseRoot(doc, torso2.id, -0.4, {}, 2);
    QCOMPARE(doc.group(c.arm)->rig.skeleton.posedJoints(), original);
    QVERIFY(distance(doc.group(arm2Id)->rig.skeleton.posedJoints(), original) > 10);
}

void TestSkeletonJoin::fileRoundTripKeepsJoins()
{
    Document doc;
    const Character c = joinedCharacter(doc);
    poseRoot(doc, c.torso, 0.25, {3, 4}, 1);
    const QByteArray bytes = serializeFinbook(doc);
    QVERIFY(bytes.contains("JOIN"));
    auto loaded = readFinbook(bytes);
    QVERIFY2(loaded, loaded ? "" : qPrintable(loaded.error().message));
    // What the reader returns is resolved already (export reads files without a Document).
    QCOMPARE(loaded->frames[0].groups[1].rig, doc.group(c.arm)->rig);
    Document reopened;
    adoptLoadedDocument(reopened, *loaded);
    QCOMPARE(rigsOf(reopened), rigsOf(doc));
    QVERIFY(reopened.group(c.arm)->rig.skeleton.hangs());
    QCOMPARE(serializeFinbook(reopened), bytes);
    // Without the parent object's skeleton the join chunk is still read; it resolves to none.
    Document detached;
    auto frames = loaded->frames;
    frames[0].groups[0].rig = {};
    detached.reset(frames, loaded->settings, loaded->nextId);
    QVERIFY(!detached.group(c.arm)->rig.skeleton.hangs());
    QVERIFY(detached.group(c.arm)->rig.skeleton.join.joined());
}

void TestSkeletonJoin::applyPoseBakesTheWholeCharacter()
{
    Document doc;
    DeformController controller(&doc);
    const Character c = joinedCharacter(doc);
    QVERIFY(prepared(controller, doc, c));
    poseRoot(doc, c.torso, 0.35, {12, 0}, 1);
    QVERIFY(waitSolved(controller, doc, c.torso));
    QVERIFY(waitSolved(controller, doc, c.arm));
    controller.settle();
    const std::vector<Rig> before = rigsOf(doc);
    const auto armShown = doc.group(c.arm)->deformed;
    const auto armJoints = doc.group(c.arm)->rig.skeleton.posedJoints();
    const auto torsoJoints = doc.group(c.torso)->rig.skeleton.posedJoints();
    // Applying from the arm bakes the torso too: one step.
    const int steps = doc.undoStack()->count();
    doc.undoStack()->push(makeApplyPoseCommand(&doc, c.arm));
    QCOMPARE(doc.undoStack()->count(), steps + 1);
    const SkeletonRig &arm = doc.group(c.arm)->rig.skeleton;
    QVERIFY(!arm.isPosed());
    QVERIFY(!doc.group(c.torso)->rig.skeleton.isPosed());
    QVERIFY(arm.hangs());
    QVERIFY(distance(arm.joints, armJoints) < 1e-9);
    QVERIFY(distance(doc.group(c.torso)->rig.skeleton.joints, torsoJoints) < 1e-9);
    for (std::size_t s = 0; s < armShown->strokes.size(); ++s)
        QCOMPARE(doc.group(c.arm)->strokes[s].data->points, armShown->strokes[s]);
    // Posing the baked torso still moves the arm.
    poseRoot(doc, c.torso, 0.1, {}, 2);
    QVERIFY(doc.group(c.arm)->rig.skeleton.isPosed());
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QCOMPARE(rigsOf(doc), before);
}

void TestSkeletonJoin::joinEditsUndoAndRedoExactly()
{
    Document doc;
    const Character c = makeCharacter(doc);
    const int base = doc.undoStack()->index();
    const std::vector<Rig> start = rigsOf(doc);
    const QByteArray startBytes = serializeFinbook(doc);
    poseRoot(doc, c.torso, 0.3, {1, 2}, 1);
    doc.undoStack()->push(new JoinPartCommand(&doc, c.arm, *proposeJoin(doc.frames()[0], c.arm)));
    poseRoot(doc, c.arm, -0.6, {}, 2);
    doc.undoStack()->push(new MakeCharacterRootCommand(&doc, c.arm));
    poseRoot(doc, c.torso, 0.1, {}, 3);
    doc.undoStack()->push(new DetachPartCommand(&doc, c.torso));
    const std::vector<Rig> end = rigsOf(doc);
    const QByteArray endBytes = serializeFinbook(doc);
    QCOMPARE(doc.undoStack()->index(), base + 6);
    while (doc.undoStack()->index() > base)
        doc.undoStack()->undo();
    QCOMPARE(rigsOf(doc), start);
    QCOMPARE(serializeFinbook(doc), startBytes);
    while (doc.undoStack()->canRedo())
        doc.undoStack()->redo();
    QCOMPARE(rigsOf(doc), end);
    QCOMPARE(serializeFinbook(doc), endBytes);
}

void TestSkeletonJoin::inbetweensMoveThePartWithItsParent()
{
    Document doc;
    const Character c = joinedCharacter(doc);
    doc.undoStack()->push(new DuplicateFrameCommand(&doc, doc.frames()[0].id, 1));
    const Id torso2 = doc.frames()[1].groups[0].id;
    poseRoot(doc, torso2, 0.8, {}, 1);
    const SkeletonRig armRest = doc.group(c.arm)->rig.skeleton;
    doc.undoStack()->push(
        new InsertInbetweensCommand(&doc, doc.frames()[0].id, doc.frames()[1].id, 3, {}));
    QCOMPARE(doc.frameCount(), 5);
    const SkeletonRig torsoRest = doc.group(c.torso)->rig.skeleton;
    const QPointF pivot = torsoRest.joints[std::size_t(torsoRest.root)];
    double previous = 0.0;
    for (int f = 1; f <= 3; ++f) {
        const Frame &mid = doc.frames()[std::size_t(f)];
        const SkeletonRig &torso = mid.groups[0].rig.skeleton;
        const SkeletonRig &arm = mid.groups[1].rig.skeleton;
        QCOMPARE(arm.join.parent, mid.groups[0].id);
        QVERIFY(arm.hangs());
        const double phi = torso.angles[std::size_t(torso.root)];
        QVERIFY(phi > previous && phi < 0.8);
        previous = phi;
        const std::vector<QPointF> shown = arm.posedJoints();
        for (std::size_t j = 0; j < shown.size(); ++j) {
            const QPointF r = armRest.joints[j] - pivot;
            const QPointF expected = pivot + QPointF(std::cos(phi) * r.x() - std::sin(phi) * r.y(),
                                                     std::sin(phi) * r.x() + std::cos(phi) * r.y());
            QVERIFY(QLineF(shown[j], expected).length() < 1e-9);
        }
    }
}

void TestSkeletonJoin::randomCharacterEditsUndoExactly()
{
    QRandomGenerator rng(20261124u);
    std::map<QString, int> applied;
    // Three parts: a torso and two arms over it, automatic skeletons, then random edits of
    // any of them (joins, poses, joint edits, rebuilds) and of the document.
    Document base;
    makeCharacter(base);
    {
        StrokeGroup left = bar(base, QStringLiteral("left arm"), {295, 200}, {40, 260}, 30);
        auto rig = buildSkeletonRig(left);
        QVERIFY(rig);
        left.rig.skeleton = *rig;
        base.insertGroup(base.frames()[0].id, 2, left);
    }
    const Frame start = base.frames()[0];
    for (int seq = 0; seq < 600; ++seq) {
        Document doc;
        doc.reset({start}, DocumentSettings{}, base.nextId());
        if (rng.bounded(2))
            doc.undoStack()->push(new JoinOverlappingPartsCommand(&doc, start.id));
        const QByteArray before = serializeFinbook(doc);
        const std::vector<Rig> rigsBefore = rigsOf(doc);
        const int undoBase = doc.undoStack()->index();
        const int length = 1 + int(rng.bounded(25));
        for (int i = 0; i < length; ++i) {
            Id g = kNoId; // a random object of a random frame (there may be none left)
            if (doc.frameCount() > 0) {
                const Frame &f = doc.frameAt(int(rng.bounded(doc.frameCount())));
                if (!f.groups.empty())
                    g = f.groups[rng.bounded(quint32(f.groups.size()))].id;
            }
            auto command = rng.bounded(6) ? finbook::testing::randomSkeletonCommand(doc, g, rng)
                                          : finbook::testing::randomCommand(doc, rng);
            doc.undoStack()->push(command.release());
            for (const Frame &frame : doc.frames()) {
                Frame resolved = frame;
                QVERIFY(resolveJoins(resolved).empty()); // anchors are always current
                for (const StrokeGroup &group : frame.groups) {
                    QVERIFY(group.rig.skeleton.isValid());
                    for (const QPointF &p : group.rig.skeleton.posedJoints())
                        QVERIFY(std::isfinite(p.x()) && std::isfinite(p.y()));
                }
            }
        }
        for (int i = undoBase; i < doc.undoStack()->count(); ++i)
            ++applied[doc.undoStack()->command(i)->text()];
        const QByteArray end = serializeFinbook(doc);
        const std::vector<Rig> rigsEnd = rigsOf(doc);
        while (doc.undoStack()->index() > undoBase)
            doc.undoStack()->undo();
        if (serializeFinbook(doc) != before || rigsOf(doc) != rigsBefore)
            QFAIL(qPrintable(QStringLiteral("undo-all differs: sequence %1").arg(seq)));
        while (doc.undoStack()->canRedo())
            doc.undoStack()->redo();
        if (serializeFinbook(doc) != end || rigsOf(doc) != rigsEnd)
            QFAIL(qPrintable(QStringLiteral("redo-all differs: sequence %1").arg(seq)));
    }
    for (const char *text :
         {"Join Part", "Detach Part", "Make Character Root", "Pose Bones", "Build Skeleton"}) {
        qInfo("%s: %d", text, applied[QString::fromLatin1(text)]);
        QVERIFY2(applied[QString::fromLatin1(text)] > 20, text);
    }
}

void TestSkeletonJoin::aPictureArmJoinsADrawnTorso()
{
    // The arm is a painted picture (an opaque striped bar) over the drawn torso's upper end.
    Document doc;
    Frame f;
    f.id = doc.allocateId();
    f.groups.push_back(bar(doc, QStringLiteral("torso"), {300, 100}, {300, 500}, 40));
    QImage painted(296, 30, QImage::Format_ARGB32_Premultiplied);
    {
        QPainter p(&painted);
        for (int x = 0; x < painted.width(); x += 8) {
            p.fillRect(QRectF(x, 0, 4, 30), QColor(230, 120, 40));
            p.fillRect(QRectF(x + 4, 0, 4, 30), QColor(40, 60, 200));
        }
    }
    auto arm = makePictureObject(PictureLayer{QStringLiteral("arm"), painted, {}}, {305, 145});
    QVERIFY(arm.hasValue());
    arm->id = doc.allocateId();
    f.groups.push_back(*arm);
    const Character c = joined(doc, riggedCharacter(doc, f));
    QCOMPARE(doc.group(c.torso)->rig.kind(), RigKind::Skeleton);
    QCOMPARE(doc.group(c.arm)->rig.kind(), RigKind::Skeleton); // the picture's own skeleton
    QVERIFY(doc.group(c.arm)->rig.skeleton.hangs());
    DeformController controller(&doc);
    QVERIFY(prepared(controller, doc, c));
    // Posing the torso turns the picture with it about the torso's root.
    const double theta = 0.3;
    const auto turned = turnTorso(doc, controller, c, theta);
    QVERIFY(turned);
    const QPointF pivot = *turned;
    const StrokeGroup &shown = *doc.group(c.arm);
    QVERIFY(shown.isDeformed());
    const Eigen::MatrixX2d rest = shown.picture->restVertices();
    const Eigen::MatrixX2d posed = shownPictureVertices(shown);
    QCOMPARE(posed.rows(), rest.rows());
    int checked = 0;
    for (Eigen::Index i = 0; i < rest.rows(); ++i) {
        if (rest(i, 0) < 560)
            continue; // near the tip only
        const double a0 = std::atan2(rest(i, 1) - pivot.y(), rest(i, 0) - pivot.x());
        const double a1 = std::atan2(posed(i, 1) - pivot.y(), posed(i, 0) - pivot.x());
        QVERIFY2(std::abs(std::remainder(a1 - a0 - theta, 2 * std::numbers::pi)) < 1e-3,
                 qPrintable(QString::number(a1 - a0)));
        ++checked;
    }
    QVERIFY(checked > 5);
    // Apply Pose from the picture bakes the whole character in one step: the picture is
    // resampled where it shows, the torso's strokes are its posed strokes; undo restores both.
    const auto before = shown.picture;
    const QRectF shownBounds = shownPictureBounds(shown);
    const std::vector<Rig> rigs = rigsOf(doc);
    doc.undoStack()->push(makeApplyPoseCommand(&doc, c.arm));
    const StrokeGroup &baked = *doc.group(c.arm);
    QVERIFY(baked.picture != before);
    QVERIFY(!baked.rig.skeleton.isPosed() && !doc.group(c.torso)->rig.skeleton.isPosed());
    QVERIFY(baked.rig.skeleton.hangs());
    const QRectF bakedBounds = baked.picture->restRect();
    QVERIFY2(std::abs(bakedBounds.left() - shownBounds.left()) <= 1.0 &&
                 std::abs(bakedBounds.bottom() - shownBounds.bottom()) <= 1.0,
             qPrintable(QStringLiteral("%1 %2").arg(bakedBounds.left()).arg(shownBounds.left())));
    doc.undoStack()->undo();
    QVERIFY(doc.group(c.arm)->picture == before);
    QCOMPARE(rigsOf(doc), rigs);
}

QTEST_GUILESS_MAIN(TestSkeletonJoin)
#include "tst_skeleton_join.moc"
