// The Bone tool driven by real mouse events on the real canvas: build a skeleton with a click,
// turn a bone, pull a joint, move the root, lock a joint; every drag one exact undo step.
#include "tst_tools_support.h"

#include <finbook/model/commands.h>
#include <finbook/model/deform_setup.h>
#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/render.h>
#include <finbook/model/skeleton/skeleton_carry.h>
#include <finbook/model/skeleton/skeleton_commands.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/panels/object_actions.h>
#include <finbook/ui/rig/deform_actions.h>
#include <finbook/ui/skeleton/skeleton_overlay.h>
#include <finbook/ui/skeleton/tool_bone.h>
#include <finbook/ui/tools/stroke_editing.h>
#include <finbook/ui/tools/tool_eraser.h>
#include <finbook/ui/window/editor_state.h>

#include <QElapsedTimer>
#include <QMenu>
#include <QPainter>
#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace finbook;
using namespace finbook::model;
using namespace finbook::ui;

namespace {

StrokeDataPtr line(QPointF a, QPointF b)
{
    auto data = std::make_shared<StrokeData>();
    for (int i = 0; i <= 60; ++i) {
        const QPointF p = a + (b - a) * (i / 60.0);
        data->points.push_back({float(p.x()), float(p.y()), 1.0f});
    }
    data->width = 6.0f;
    return data;
}

// One closed outline through `corners`, a point every 2 px.
StrokeDataPtr outline(const std::vector<QPointF> &corners)
{
    auto data = std::make_shared<StrokeData>();
    for (std::size_t i = 0; i + 1 < corners.size(); ++i) {
        const QPointF a = corners[i], b = corners[i + 1];
        const int n = std::max(1, int(QLineF(a, b).length() / 2.0));
        for (int k = 0; k < n; ++k) {
            const QPointF p = a + (b - a) * (double(k) / n);
            data->points.push_back({float(p.x()), float(p.y()), 1.0f});
        }
    }
    data->points.push_back({float(corners.back().x()), float(corners.back().y()), 1.0f});
    data->width = 3.0f;
    return data;
}

struct Fixture {
    Document doc;
    EditorState state{&doc};
    DeformActions actions{&state};
    CanvasWidget canvas{&state};
    BoneTool *tool = nullptr;
    SkeletonOverlay *overlay = nullptr;
    Id group = kNoId;

    // `drawing`: the object's strokes; by default an L of hatched lines (an upper arm along x,
    // the forearm down).
    explicit Fixture(std::vector<StrokeDataPtr> drawing = {})
    {
        Frame f;
        f.id = doc.allocateId();
        StrokeGroup g;
        g.id = doc.allocateId();
        g.name = QStringLiteral("arm");
        for (StrokeDataPtr &stroke : drawing)
            g.strokes.push_back({doc.allocateId(), std::move(stroke)});
        for (int k = 0; drawing.empty() && k <= 6; ++k) {
            const double o = 5.0 * k;
            g.strokes.push_back({doc.allocateId(), line({150, 200 + o}, {450, 200 + o})});
            g.strokes.push_back({doc.allocateId(), line({420 + o, 200}, {420 + o, 500})});
        }
        f.groups.push_back(g);
        group = g.id;
        DocumentSettings s;
        s.canvasSize = QSize(800, 600);
        doc.reset({f}, s, doc.nextId());
        tool = static_cast<BoneTool *>(
            canvas.addTool(std::make_unique<BoneTool>(actions.controller())));
        auto o = std::make_unique<SkeletonOverlay>(&state, &canvas);
        overlay = o.get();
        canvas.addOverlay(std::move(o));
        canvas.setCurrentTool(tool->id());
        canvas.resize(800, 600);
        canvas.show();
        canvas.fitToView();
    }

    QPoint at(QPointF canvasPos) const { return canvas.mapFromCanvas(canvasPos).toPoint(); }
    const StrokeGroup &object() const { return *doc.group(group); }
    const SkeletonRig &skeleton() const { return object().rig.skeleton; }

    void drag(QPointF from, QPointF to)
    {
        QTest::mousePress(&canvas, Qt::LeftButton, {}, at(from));
        for (int i = 1; i <= 10; ++i) {
            const QPointF p = from + (to - from) * (i / 10.0);
            QMouseEvent move(QEvent::MouseMove, at(p), canvas.mapToGlobal(at(p)), Qt::NoButton,
                             Qt::LeftButton, {});
            QApplication::sendEvent(&canvas, &move);
        }
        QTest::mouseRelease(&canvas, Qt::LeftButton, {}, at(to));
    }

    bool waitReady()
    {
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < 10000) {
            const DeformSetup *s = actions.controller()->setup(group);
            if (s && s->matches(object(), -1.0) && !actions.controller()->isWaiting(group))
                return true;
            QTest::qWait(10);
        }
        return false;
    }

    // The last non-root joint without children: the tip of a limb.
    int tipBone() const
    {
        const SkeletonRig &s = skeleton();
        std::vector<int> children(s.joints.size(), 0);
        for (int p : s.parent)
            if (p >= 0)
                ++children[std::size_t(p)];
        for (int j = int(s.joints.size()) - 1; j >= 0; --j)
            if (s.parent[std::size_t(j)] >= 0 && children[std::size_t(j)] == 0)
                return j;
        return -1;
    }

    // Grabs the tip bone (tipBone) at two thirds of its length and swings it by `theta` rad
    // about its parent joint. Returns the bone, with its rest pivot and tip.
    struct Swing {
        int bone = -1;
        QPointF pivot, tip;
    };
    Swing swingTipBone(double theta)
    {
        Swing s;
        s.bone = tipBone();
        if (s.bone < 0)
            return s;
        const SkeletonRig &rest = skeleton();
        s.pivot = rest.joints[std::size_t(rest.parent[std::size_t(s.bone)])];
        s.tip = rest.joints[std::size_t(s.bone)];
        const QPointF grab = s.pivot + (s.tip - s.pivot) * (2.0 / 3.0);
        const QPointF v = grab - s.pivot;
        drag(grab, s.pivot + QPointF(v.x() * std::cos(theta) - v.y() * std::sin(theta),
                                     v.x() * std::sin(theta) + v.y() * std::cos(theta)));
        return s;
    }

    // The longest bone: easy to hit away from its joints.
    int longestBone() const
    {
        const SkeletonRig &s = skeleton();
        int best = -1;
        double length = 0.0;
        for (std::size_t j = 0; j < s.joints.size(); ++j)
            if (const int p = s.parent[j];
                p >= 0 && QLineF(s.joints[std::size_t(p)], s.joints[j]).length() > length) {
                length = QLineF(s.joints[std::size_t(p)], s.joints[j]).length();
                best = int(j);
            }
        return best;
    }
};

double angleAbout(QPointF pivot, QPointF p)
{
    return std::atan2(p.y() - pivot.y(), p.x() - pivot.x());
}

} // namespace

class TestBoneTool : public QObject {
    Q_OBJECT
private slots:
    void clickBuildsThenDragTurnsABone();
    void dragJointPullsTheChain();
    void dragRootMovesTheObject();
    void shortLimbTurnsAtItsBase();
    void altClickLocksAJoint();
    void keyLLocksTheJointUnderTheMouse();
    void showSkeletonPaints();
    void lockedJointsLookLocked();
    void limbBasesLookDifferent();
    void contextMenuResetsOneBone();
    void editJointsMovesAJoint();
    void editJointsInsertsAndDeletes();
    void editJointsRefusesAPosedSkeleton();
    void skeletonFollowsTheDrawingWhenShown();
    void skeletonStaysWhenHiddenOrPosed();
    void erasingEverythingRemovesTheSkeleton();
    void erasingALimbRebuildsTheSkeleton();
    void clickInsideAnOutlineBuilds();
    void bodyClosedForTheFillIsRigged();
    void partsJoinWhenBuiltAndShiftDragReattaches();
    void movingStrokesAwayRebuildsTheShownSkeleton();
    void mergingAPosedObjectAppliesItsPoseFirst();
};

void TestBoneTool::clickBuildsThenDragTurnsABone()
{
    Fixture fx;
    QUndoStack *stack = fx.doc.undoStack();
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    QCOMPARE(fx.object().rig.kind(), RigKind::Skeleton);
    QCOMPARE(stack->count(), 1);
    QVERIFY(fx.waitReady());
    const QByteArray built = serializeFinbook(fx.doc);

    // Grab the tip bone at two thirds of its length and swing it by 0.4 rad.
    const double theta = 0.4;
    const auto [bone, pivot, tip] = fx.swingTipBone(theta);
    QVERIFY(bone >= 0);
    QCOMPARE(stack->count(), 2); // the whole drag is one step
    const SkeletonRig &posed = fx.skeleton();
    QVERIFY(std::abs(posed.angles[std::size_t(bone)] - theta) < 0.03);
    const QPointF posedTip = posed.posedJoints()[std::size_t(bone)];
    QVERIFY(std::abs(angleAbout(pivot, posedTip) - angleAbout(pivot, tip) - theta) < 0.03);
    QVERIFY(fx.object().isDeformed());
    const QByteArray swung = serializeFinbook(fx.doc);
    QVERIFY(swung != built);

    stack->undo();
    QCOMPARE(serializeFinbook(fx.doc), built);
    stack->redo();
    QCOMPARE(serializeFinbook(fx.doc), swung);
    stack->undo();
    stack->undo();
    QVERIFY(fx.object().rig.empty());
}

void TestBoneTool::dragJointPullsTheChain()
{
    Fixture fx;
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    QVERIFY(fx.waitReady());
    const int bone = fx.tipBone();
    const SkeletonRig rest = fx.skeleton();
    const QPointF tip = rest.joints[std::size_t(bone)];
    const QPointF pivot = rest.joints[std::size_t(rest.parent[std::size_t(bone)])];
    // A reachable target: the tip swung a little about its own pivot.
    const QPointF target =
        pivot + QLineF(pivot, tip).length() * QPointF(std::cos(angleAbout(pivot, tip) + 0.3),
                                                      std::sin(angleAbout(pivot, tip) + 0.3));
    const int count = fx.doc.undoStack()->count();
    fx.drag(tip, target);
    QCOMPARE(fx.doc.undoStack()->count(), count + 1);
    const QPointF reached = fx.skeleton().posedJoints()[std::size_t(bone)];
    QVERIFY2(QLineF(reached, target).length() < 2.0,
             qPrintable(QString::number(QLineF(reached, target).length())));
    for (const auto &stroke : fx.object().deformed->strokes)
        for (const StrokePoint &p : stroke)
            QVERIFY(std::isfinite(p.x) && std::isfinite(p.y));
}

// A body with a short arm (one bone beyond where it leaves the body): dragging the hand turns
// the arm at its base, as an animator pulls a puppet's arm; the bone inside the body stays, so
// the body does not swing with it.
namespace {

// A 200 × 200 body with an 85 px arm 30 wide: built with a click, the arm is one bone from
// its base (where it leaves the body) to the hand.
std::vector<StrokeDataPtr> bodyWithArm()
{
    return {outline({{100, 100},
                     {300, 100},
                     {300, 185},
                     {385, 185},
                     {385, 215},
                     {300, 215},
                     {300, 300},
                     {100, 300},
                     {100, 100}})};
}

} // namespace

void TestBoneTool::shortLimbTurnsAtItsBase()
{
    Fixture fx(bodyWithArm());
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({200, 200}));
    QVERIFY(fx.waitReady());
    const SkeletonRig rest = fx.skeleton();
    int base = -1;
    for (int j = 0; j < rest.jointCount(); ++j)
        if (rest.isLimbBase(j))
            base = j;
    QVERIFY(base >= 0);
    int hand = -1;
    for (int j = 0; j < rest.jointCount(); ++j)
        if (rest.parent[std::size_t(j)] == base)
            hand = j;
    QVERIFY2(hand >= 0 && rest.joints[std::size_t(hand)].x() > 360,
             "the arm is one bone from its base to the hand");
    const QPointF pivot = rest.joints[std::size_t(base)], from = rest.joints[std::size_t(hand)];
    const double length = QLineF(pivot, from).length();
    const QPointF target = pivot + length * QPointF(std::cos(-0.8), std::sin(-0.8));
    fx.drag(from, target);
    const std::vector<QPointF> posed = fx.skeleton().posedJoints();
    for (int j = 0; j < rest.jointCount(); ++j)
        if (j != hand)
            QVERIFY2(QLineF(posed[std::size_t(j)], rest.joints[std::size_t(j)]).length() < 1e-6,
                     qPrintable(QStringLiteral("joint %1 moved").arg(j)));
    QVERIFY2(QLineF(posed[std::size_t(hand)], target).length() < 1.0,
             qPrintable(QString::number(QLineF(posed[std::size_t(hand)], target).length())));
}

void TestBoneTool::dragRootMovesTheObject()
{
    Fixture fx;
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    QVERIFY(fx.waitReady());
    const SkeletonRig rest = fx.skeleton();
    const QPointF root = rest.joints[std::size_t(rest.root)];
    fx.drag(root, root + QPointF(40, 30));
    const QPointF offset = fx.skeleton().rootOffset;
    QVERIFY(QLineF(offset, QPointF(40, 30)).length() < 2.0);
    // Everything moved by the offset: the drawing translates rigidly.
    const StrokePoint a = fx.object().strokes[0].data->points[0];
    const StrokePoint b = fx.object().deformed->strokes[0][0];
    QVERIFY(QLineF(QPointF(a.x, a.y) + offset, QPointF(b.x, b.y)).length() < 0.05);
}

void TestBoneTool::altClickLocksAJoint()
{
    Fixture fx;
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    QVERIFY(fx.waitReady());
    const int bone = fx.tipBone();
    const int parent = fx.skeleton().parent[std::size_t(bone)];
    const QPointF p = fx.skeleton().joints[std::size_t(parent)];
    const int count = fx.doc.undoStack()->count();
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, Qt::AltModifier, fx.at(p));
    QVERIFY(fx.tool->isLocked(fx.group, parent));
    QVERIFY(fx.skeleton().isLocked(parent)); // in the document: saved, undoable
    QCOMPARE(fx.doc.undoStack()->count(), count + 1);
    // With its pivot locked, pulling the tip turns only the tip's bone.
    const SkeletonRig before = fx.skeleton();
    const QPointF tip = before.joints[std::size_t(bone)];
    fx.drag(tip, tip + QPointF(0, 25));
    QVERIFY(fx.skeleton().angles[std::size_t(bone)] != 0.0);
    for (std::size_t j = 0; j < before.joints.size(); ++j)
        if (int(j) != bone)
            QCOMPARE(fx.skeleton().angles[j], 0.0);
    // The context menu unlocks it.
    QString offered;
    fx.tool->setMenuExec([&offered](QMenu &menu, QPoint) {
        QAction *lock = menu.findChild<QAction *>(QStringLiteral("bone.lock"));
        offered = lock ? lock->text() : QString();
        return lock;
    });
    QTest::mouseClick(&fx.canvas, Qt::RightButton, {}, fx.at(p));
    QCOMPARE(offered, QStringLiteral("Unlock Joint"));
    QVERIFY(!fx.tool->isLocked(fx.group, parent));
    QVERIFY(fx.skeleton().locked.empty());
    fx.doc.undoStack()->undo();
    QVERIFY(fx.tool->isLocked(fx.group, parent));
}

// Issue 22, bug 5: many Linux window managers take Alt-click; L over a joint locks it there.
void TestBoneTool::keyLLocksTheJointUnderTheMouse()
{
    Fixture fx;
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    QVERIFY(fx.waitReady());
    const int bone = fx.tipBone();
    const int parent = fx.skeleton().parent[std::size_t(bone)];
    const QPointF p = fx.skeleton().joints[std::size_t(parent)];
    const int count = fx.doc.undoStack()->count();
    // Away from every joint, L does nothing (and is left to the window).
    const auto hover = [&fx](QPointF canvasPos) {
        QMouseEvent move(QEvent::MouseMove, fx.at(canvasPos),
                         fx.canvas.mapToGlobal(fx.at(canvasPos)), Qt::NoButton, Qt::NoButton, {});
        QApplication::sendEvent(&fx.canvas, &move);
    };
    hover({700, 80});
    QTest::keyClick(&fx.canvas, Qt::Key_L);
    QVERIFY(fx.skeleton().locked.empty());
    hover(p);
    QTest::keyClick(&fx.canvas, Qt::Key_L);
    QVERIFY(fx.skeleton().isLocked(parent));
    QCOMPARE(fx.doc.undoStack()->count(), count + 1);
    QTest::keyClick(&fx.canvas, Qt::Key_L);
    QVERIFY(!fx.skeleton().isLocked(parent));
    fx.doc.undoStack()->undo();
    QVERIFY(fx.skeleton().isLocked(parent));
}

void TestBoneTool::showSkeletonPaints()
{
    Fixture fx;
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    const auto paint = [&fx] {
        QImage image(800, 600, QImage::Format_ARGB32);
        image.fill(Qt::white);
        QPainter painter(&image);
        fx.overlay->paint(painter, fx.canvas.canvasToWidget());
        return image;
    };
    QImage blank(800, 600, QImage::Format_ARGB32);
    blank.fill(Qt::white);
    QCOMPARE(paint(), blank); // off by default
    fx.overlay->setShown(true);
    const QImage image = paint();
    const QPointF root = fx.skeleton().joints[std::size_t(fx.skeleton().root)];
    bool coloured = false; // the root marker's fill (bone colour, darker)
    const QPoint c = fx.at(root);
    for (int dy = -3; dy <= 3 && !coloured; ++dy)
        for (int dx = -3; dx <= 3 && !coloured; ++dx) {
            const QColor px = image.pixelColor(c + QPoint(dx, dy));
            coloured = px.red() > px.blue() + 60 && px.green() > px.blue() + 20;
        }
    QVERIFY(coloured);
}

namespace {
QImage paintOverlay(Fixture &fx)
{
    QImage image(800, 600, QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    fx.overlay->paint(painter, fx.canvas.canvasToWidget());
    return image;
}

// Pixels within `reach` of c (a square) whose colour `is` accepts.
template <class Is> int pixelsNear(const QImage &image, QPoint c, int reach, Is is)
{
    int count = 0;
    for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx)
            count += is(image.pixelColor(c + QPoint(dx, dy))) ? 1 : 0;
    return count;
}

int redPixelsNear(const QImage &image, QPoint c, int reach)
{
    return pixelsNear(image, c, reach, [](const QColor &px) {
        return px.red() > 150 && px.green() < 90 && px.blue() < 90;
    });
}

int bluePixelsNear(const QImage &image, QPoint c, int reach)
{
    return pixelsNear(image, c, reach, [](const QColor &px) {
        return px.blue() > 180 && px.red() < 90 && px.green() < 150;
    });
}

// Chooses the context-menu action named `name` (none when absent).
void choose(Fixture &fx, const char *name)
{
    fx.tool->setMenuExec([name](QMenu &menu, QPoint) {
        return menu.findChild<QAction *>(QString::fromLatin1(name));
    });
}
} // namespace

void TestBoneTool::lockedJointsLookLocked()
{
    Fixture fx;
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    fx.overlay->setShown(true);
    const int joint = fx.tipBone();
    const QPoint c = fx.at(fx.skeleton().joints[std::size_t(joint)]);
    QCOMPARE(redPixelsNear(paintOverlay(fx), c, 8), 0);
    fx.doc.undoStack()->push(new SetJointLockCommand(&fx.doc, fx.group, joint, true));
    QVERIFY(redPixelsNear(paintOverlay(fx), c, 8) > 20);
}

void TestBoneTool::limbBasesLookDifferent()
{
    // The body with an arm of shortLimbTurnsAtItsBase: its base is a blue dot, the hand not.
    Fixture fx(bodyWithArm());
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({200, 200}));
    QVERIFY(fx.waitReady());
    fx.overlay->setShown(true);
    int base = -1, hand = -1;
    for (int j = 0; j < fx.skeleton().jointCount(); ++j)
        base = fx.skeleton().isLimbBase(j) ? j : base;
    QVERIFY(base >= 0);
    for (int j = 0; j < fx.skeleton().jointCount(); ++j)
        hand = fx.skeleton().parent[std::size_t(j)] == base ? j : hand;
    QVERIFY(hand >= 0);
    const QImage shown = paintOverlay(fx);
    QVERIFY(bluePixelsNear(shown, fx.at(fx.skeleton().joints[std::size_t(base)]), 4) > 10);
    QCOMPARE(bluePixelsNear(shown, fx.at(fx.skeleton().joints[std::size_t(hand)]), 4), 0);
    // A locked base shows as locked.
    fx.doc.undoStack()->push(new SetJointLockCommand(&fx.doc, fx.group, base, true));
    QCOMPARE(bluePixelsNear(paintOverlay(fx), fx.at(fx.skeleton().joints[std::size_t(base)]), 4),
             0);
}

void TestBoneTool::contextMenuResetsOneBone()
{
    Fixture fx;
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    QVERIFY(fx.waitReady());
    const int bone = fx.longestBone();
    const int parent = fx.skeleton().parent[std::size_t(bone)];
    const QPointF root = fx.skeleton().joints[std::size_t(fx.skeleton().root)];
    // Turn the tip bone, then move the root: two posed parts.
    const SkeletonRig rest = fx.skeleton();
    const QPointF pivot = rest.joints[std::size_t(parent)];
    const QPointF tip = rest.joints[std::size_t(bone)];
    const QPointF grab = pivot + (tip - pivot) * 0.6;
    fx.drag(grab, grab + QPointF(-(tip - pivot).y(), (tip - pivot).x()) * 0.2);
    fx.drag(root, root + QPointF(20, 10));
    QVERIFY(fx.skeleton().angles[std::size_t(bone)] != 0.0);
    const QPointF offset = fx.skeleton().rootOffset;
    QVERIFY(offset != QPointF());
    const std::vector<QPointF> shown = fx.skeleton().posedJoints();
    const QPointF middle = (shown[std::size_t(parent)] + shown[std::size_t(bone)]) / 2;
    const int count = fx.doc.undoStack()->count();
    choose(fx, "bone.resetBone");
    QTest::mouseClick(&fx.canvas, Qt::RightButton, {}, fx.at(middle));
    QCOMPARE(fx.doc.undoStack()->count(), count + 1);
    QCOMPARE(fx.skeleton().angles[std::size_t(bone)], 0.0);
    QCOMPARE(fx.skeleton().rootOffset, offset); // the other part of the pose stays
    QVERIFY(!fx.tool->canResetSelectedBone());
    // The same through the tool's entry point (Deform → Reset Bone Pose) for the root.
    fx.doc.undoStack()->undo();
    QVERIFY(fx.tool->canResetSelectedBone());
    fx.tool->setMenuExec([](QMenu &, QPoint) -> QAction * { return nullptr; }); // dismissed
    QTest::mouseClick(&fx.canvas, Qt::RightButton, {}, fx.at(root + offset));   // selects it
    fx.tool->resetSelectedBone();
    QCOMPARE(fx.skeleton().rootOffset, QPointF());
    QVERIFY(fx.skeleton().angles[std::size_t(bone)] != 0.0);

    // The selection belongs to its frame: on a duplicate of it (same bones, other ids) there
    // is nothing to reset until a bone there is chosen, and Reset Bone Pose never reaches
    // back into the frame left behind.
    fx.tool->setMenuExec([](QMenu &, QPoint) -> QAction * { return nullptr; });
    // Where the bone is shown now that the root's offset is reset.
    const std::vector<QPointF> now = fx.skeleton().posedJoints();
    QTest::mouseClick(&fx.canvas, Qt::RightButton, {},
                      fx.at((now[std::size_t(parent)] + now[std::size_t(bone)]) / 2));
    QVERIFY(fx.tool->canResetSelectedBone());
    const Id first = fx.state.currentFrameId();
    fx.doc.undoStack()->push(new DuplicateFrameCommand(&fx.doc, first, 1));
    fx.state.setCurrentFrameIndex(1);
    QVERIFY(fx.state.currentFrameId() != first);
    QVERIFY(!fx.tool->canResetSelectedBone());
    const int before = fx.doc.undoStack()->count();
    fx.tool->resetSelectedBone();
    QCOMPARE(fx.doc.undoStack()->count(), before);
    fx.state.setCurrentFrameIndex(0);
    QVERIFY(fx.tool->canResetSelectedBone());
}

void TestBoneTool::editJointsMovesAJoint()
{
    Fixture fx;
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    QVERIFY(fx.waitReady());
    const QByteArray built = serializeFinbook(fx.doc);
    fx.tool->setEditJoints(true);
    const int joint = fx.tipBone();
    const SkeletonRig before = fx.skeleton();
    const QPointF from = before.joints[std::size_t(joint)];
    const int count = fx.doc.undoStack()->count();
    fx.drag(from, from + QPointF(12, -8));
    QCOMPARE(fx.doc.undoStack()->count(), count + 1); // the drag is one step
    QVERIFY(QLineF(fx.skeleton().joints[std::size_t(joint)], from + QPointF(12, -8)).length() <
            1.0);
    QVERIFY(!fx.skeleton().isPosed()); // the rest moved, nothing is posed
    for (std::size_t j = 0; j < before.joints.size(); ++j)
        if (int(j) != joint)
            QCOMPARE(fx.skeleton().joints[j], before.joints[j]);
    // The skinning follows the new rest skeleton.
    QVERIFY(fx.waitReady());
    QCOMPARE(fx.actions.controller()->setup(fx.group)->rest.skeleton.joints, fx.skeleton().joints);
    fx.doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(fx.doc), built);
}

void TestBoneTool::editJointsInsertsAndDeletes()
{
    Fixture fx;
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    QVERIFY(fx.waitReady());
    QSignalSpy edit(fx.tool, &BoneTool::editJointsChanged);
    choose(fx, "bone.editJoints"); // the menu turns the mode on
    const int bone = fx.longestBone();
    const SkeletonRig before = fx.skeleton();
    const QPointF a = before.joints[std::size_t(before.parent[std::size_t(bone)])];
    const QPointF b = before.joints[std::size_t(bone)];
    QTest::mouseClick(&fx.canvas, Qt::RightButton, {}, fx.at(b));
    QVERIFY(fx.tool->editJoints());
    QCOMPARE(edit.count(), 1);
    // A click on the bone's middle inserts a joint there.
    const int count = fx.doc.undoStack()->count();
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at((a + b) / 2));
    QCOMPARE(fx.doc.undoStack()->count(), count + 1);
    QCOMPARE(fx.skeleton().jointCount(), before.jointCount() + 1);
    QVERIFY(fx.skeleton().isValid());
    const BoneTool::Hit inserted = fx.tool->selection();
    QCOMPARE(inserted.part, BoneTool::Part::Joint);
    QVERIFY(QLineF(fx.skeleton().joints[std::size_t(inserted.joint)], (a + b) / 2).length() < 1.5);
    // Delete Joint from the menu takes it out again: the same skeleton as before.
    choose(fx, "bone.deleteJoint");
    QTest::mouseClick(&fx.canvas, Qt::RightButton, {},
                      fx.at(fx.skeleton().joints[std::size_t(inserted.joint)]));
    QCOMPARE(fx.doc.undoStack()->count(), count + 2);
    QCOMPARE(fx.skeleton().joints, before.joints);
    QCOMPARE(fx.skeleton().parent, before.parent);
    fx.doc.undoStack()->undo();
    fx.doc.undoStack()->undo();
    QCOMPARE(fx.skeleton(), before);
}

void TestBoneTool::editJointsRefusesAPosedSkeleton()
{
    Fixture fx;
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    QVERIFY(fx.waitReady());
    const QPointF root = fx.skeleton().joints[std::size_t(fx.skeleton().root)];
    fx.drag(root, root + QPointF(30, 0));
    fx.tool->setEditJoints(true);
    const SkeletonRig posed = fx.skeleton();
    const int count = fx.doc.undoStack()->count();
    const QPointF tip = posed.posedJoints()[std::size_t(fx.tipBone())];
    fx.drag(tip, tip + QPointF(10, 10));
    QCOMPARE(fx.doc.undoStack()->count(), count);
    QCOMPARE(fx.skeleton(), posed);
}

namespace {
// A band of strokes lengthening the upper arm to the left.
std::vector<StrokeDataPtr> longerArm()
{
    std::vector<StrokeDataPtr> band;
    for (int k = 0; k <= 6; ++k)
        band.push_back(line({20, 200 + 5.0 * k}, {170, 200 + 5.0 * k}));
    return band;
}

double leftmostJoint(const SkeletonRig &s)
{
    double x = 1e9;
    for (const QPointF &p : s.joints)
        x = std::min(x, p.x());
    return x;
}
} // namespace

void TestBoneTool::skeletonFollowsTheDrawingWhenShown()
{
    Fixture fx;
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    fx.overlay->setShown(true);
    // A new skeleton turns its limbs cut out; the user's other choice survives the rebuild.
    QCOMPARE(fx.skeleton().mode, SkinningMode::CutOut);
    fx.doc.undoStack()->push(new SetSkinningModeCommand(&fx.doc, fx.group, SkinningMode::Rigid));
    const SkeletonRig before = fx.skeleton();
    QCOMPARE(before.mode, SkinningMode::Rigid);
    QVERIFY(leftmostJoint(before) > 120);
    const QByteArray start = serializeFinbook(fx.doc);
    const int count = fx.doc.undoStack()->count();
    QVERIFY(StrokeEditing::addStrokes(fx.state, longerArm(), QStringLiteral("Draw Stroke")));
    QCOMPARE(fx.doc.undoStack()->count(), count + 1); // strokes and skeleton: one step
    const SkeletonRig &after = fx.skeleton();
    QVERIFY(after.isValid());
    QVERIFY2(leftmostJoint(after) < 60, qPrintable(QString::number(leftmostJoint(after))));
    QCOMPARE(after.settings, before.settings);
    QCOMPARE(after.mode, before.mode);
    // The rebuild is what the builder gives for the new drawing, root near the old root, with
    // the old joints that still fit carried over (hand edits and locks survive).
    auto expected =
        buildSkeletonRig(fx.object(), before.settings, before.joints[std::size_t(before.root)]);
    QVERIFY(expected);
    expected->mode = before.mode;
    QCOMPARE(after, carryHandEdits(before, *expected));
    const QByteArray end = serializeFinbook(fx.doc);
    fx.doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(fx.doc), start);
    fx.doc.undoStack()->redo();
    QCOMPARE(serializeFinbook(fx.doc), end);
}

void TestBoneTool::skeletonStaysWhenHiddenOrPosed()
{
    Fixture fx;
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    const SkeletonRig before = fx.skeleton();
    QVERIFY(StrokeEditing::addStrokes(fx.state, longerArm(), QStringLiteral("Draw Stroke")));
    QCOMPARE(fx.skeleton(), before); // Show Skeleton is off
    fx.doc.undoStack()->undo();
    // Posed: the pose becomes the drawing (as for any rest edit), the bones are not rebuilt.
    fx.overlay->setShown(true);
    QVERIFY(fx.waitReady());
    const QPointF root = before.joints[std::size_t(before.root)];
    fx.drag(root, root + QPointF(15, 5));
    QVERIFY(fx.skeleton().isPosed());
    const SkeletonRig rebased = fx.skeleton().rebased();
    QVERIFY(StrokeEditing::addStrokes(fx.state, longerArm(), QStringLiteral("Draw Stroke")));
    QCOMPARE(fx.skeleton().joints, rebased.joints);
    QCOMPARE(fx.skeleton().parent, rebased.parent);
}

void TestBoneTool::erasingEverythingRemovesTheSkeleton()
{
    Fixture fx;
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    fx.overlay->setShown(true);
    const QByteArray start = serializeFinbook(fx.doc);
    StrokeEditing::selectAll(fx.state);
    QVERIFY(StrokeEditing::deleteSelection(fx.state));
    QVERIFY(fx.object().strokes.empty());
    QVERIFY(fx.object().rig.empty());
    fx.doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(fx.doc), start);
}

void TestBoneTool::erasingALimbRebuildsTheSkeleton()
{
    Fixture fx;
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    fx.overlay->setShown(true);
    const auto lowest = [&fx] {
        double y = -1e9;
        for (const QPointF &p : fx.skeleton().joints)
            y = std::max(y, p.y());
        return y;
    };
    QVERIFY(lowest() > 400); // the forearm has bones
    const QByteArray start = serializeFinbook(fx.doc);
    const int count = fx.doc.undoStack()->count();
    auto *eraser = static_cast<EraserTool *>(fx.canvas.addTool(std::make_unique<EraserTool>()));
    eraser->setMode(EraserMode::WholeStrokes);
    fx.canvas.setCurrentTool(eraser->id());
    fx.drag({380, 420}, {490, 420}); // across every forearm stroke
    QCOMPARE(fx.object().strokes.size(), std::size_t(7));
    QCOMPARE(fx.doc.undoStack()->count(), count + 1); // the erase and the rebuild
    QVERIFY2(lowest() < 260, qPrintable(QString::number(lowest())));
    fx.doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(fx.doc), start);
}

// An outline drawn as one closed stroke: a click in its empty middle, far from any line, gives
// it a skeleton, as the Pin tool takes a click inside a shape; a click outside does nothing.
void TestBoneTool::clickInsideAnOutlineBuilds()
{
    Fixture fx;
    Frame f;
    f.id = fx.doc.allocateId();
    StrokeGroup g;
    g.id = fx.doc.allocateId();
    g.name = QStringLiteral("outline");
    const auto data = test::polyline({{100, 200}, {600, 200}, {600, 320}, {100, 320}, {100, 200}});
    g.strokes.push_back({fx.doc.allocateId(), data});
    f.groups.push_back(g);
    fx.group = g.id;
    fx.doc.reset({f}, fx.doc.settings(), fx.doc.nextId());

    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({350, 420})); // outside
    QVERIFY(fx.object().rig.empty());
    QCOMPARE(fx.doc.undoStack()->count(), 0);
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({350, 260})); // 60 px from lines
    QCOMPARE(fx.object().rig.kind(), RigKind::Skeleton);
    QCOMPARE(fx.doc.undoStack()->count(), 1);
    QVERIFY(fx.skeleton().jointCount() >= 2);
}

// A body left wide open at the bottom (a sketched animal's belly between its legs), closed for
// the Fill tool by raising Close gaps and filled: the rig sees the body the fill shows, not the
// wire of its outline (which the automatic gap leaves).
void TestBoneTool::bodyClosedForTheFillIsRigged()
{
    Fixture fx;
    Frame f;
    f.id = fx.doc.allocateId();
    StrokeGroup g;
    g.id = fx.doc.allocateId();
    const auto data =
        test::polyline({{260, 320}, {100, 320}, {100, 200}, {600, 200}, {600, 320}, {440, 320}});
    g.strokes.push_back({fx.doc.allocateId(), data});
    f.groups.push_back(g);
    fx.group = g.id;
    DocumentSettings settings = fx.doc.settings();
    settings.closeGap = 200.0;
    fx.doc.reset({f}, settings, fx.doc.nextId());
    const QPointF middle(350, 300); // 20 px above the opening, off the ink
    fx.doc.undoStack()->push(
        fillRegionCommand(&fx.doc, fx.group, QPointF(350, 260), qRgb(200, 120, 40)).release());
    QCOMPARE(fx.object().fills.size(), std::size_t(1));
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at(middle));
    QCOMPARE(fx.object().rig.kind(), RigKind::Skeleton);
    // Built from the body as closed for the fill, not from the wire of its outline: bones run
    // through the middle, 60 px from the lines.
    const SkeletonRig &rig = fx.skeleton();
    int middleJoints = 0;
    for (const QPointF &j : rig.joints)
        middleJoints += j.y() > 235 && j.y() < 285 && j.x() > 120 && j.x() < 580 ? 1 : 0;
    QVERIFY2(middleJoints >= 2, qPrintable(QStringLiteral("%1 joints, first at %2, %3")
                                               .arg(rig.joints.size())
                                               .arg(rig.joints[0].x())
                                               .arg(rig.joints[0].y())));
    // The mesh pins and bones deform is that body too.
    const auto wire = meshObject(MeshKey::of(fx.object(), -1.0));
    const auto body = meshObject(MeshKey::of(fx.object(), fx.doc.settings().closeGap));
    QVERIFY(wire && body);
    const auto area = [](const geometry::ObjectMesh &m) {
        double a = 0.0;
        for (Eigen::Index t = 0; t < m.F.rows(); ++t) {
            const Eigen::Vector2d u = m.V.row(m.F(t, 1)) - m.V.row(m.F(t, 0)),
                                  v = m.V.row(m.F(t, 2)) - m.V.row(m.F(t, 0));
            a += 0.5 * std::abs(u.x() * v.y() - u.y() * v.x());
        }
        return a;
    };
    QVERIFY2(area((*body)->mesh) > 0.9 * 500 * 120,
             qPrintable(QString::number(area((*body)->mesh))));
    QVERIFY(area((*wire)->mesh) < 0.5 * 500 * 120);
}

void TestBoneTool::partsJoinWhenBuiltAndShiftDragReattaches()
{
    Fixture fx;
    // A torso drawn under the arm's left end: a vertical bar of its own.
    StrokeGroup torso;
    torso.id = fx.doc.allocateId();
    torso.name = QStringLiteral("torso");
    for (int k = 0; k <= 6; ++k)
        torso.strokes.push_back(
            {fx.doc.allocateId(), line({140 + 5.0 * k, 120}, {140 + 5.0 * k, 560})});
    fx.doc.insertGroup(fx.state.currentFrameId(), 0, torso);
    const auto torsoRig = [&] { return fx.doc.group(torso.id)->rig.skeleton; };

    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({155, 450}));
    QVERIFY(!torsoRig().empty());
    QVERIFY(!torsoRig().join.joined());
    const int steps = fx.doc.undoStack()->count();
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    // Built and joined in one step: the arm overlaps the torso.
    QCOMPARE(fx.doc.undoStack()->count(), steps + 1);
    QVERIFY(fx.skeleton().hangs());
    QCOMPARE(fx.skeleton().join.parent, torso.id);

    // Detach from the menu on the arm's root.
    const QPointF root = fx.skeleton().joints[std::size_t(fx.skeleton().root)];
    choose(fx, "bone.detachPart");
    QTest::mouseClick(&fx.canvas, Qt::RightButton, {}, fx.at(root));
    QVERIFY(!fx.skeleton().join.joined());

    // Shift-drag the root onto the torso's bone, lower down: joined there.
    const QPointF drop(155, 400);
    QTest::mousePress(&fx.canvas, Qt::LeftButton, Qt::ShiftModifier, fx.at(root));
    for (int i = 1; i <= 8; ++i) {
        const QPointF p = root + (drop - root) * (i / 8.0);
        QMouseEvent move(QEvent::MouseMove, fx.at(p), fx.canvas.mapToGlobal(fx.at(p)), Qt::NoButton,
                         Qt::LeftButton, Qt::ShiftModifier);
        QApplication::sendEvent(&fx.canvas, &move);
    }
    QTest::mouseRelease(&fx.canvas, Qt::LeftButton, Qt::ShiftModifier, fx.at(drop));
    QVERIFY(fx.skeleton().hangs());
    QCOMPARE(fx.skeleton().join.parent, torso.id);
    QVERIFY2(QLineF(fx.skeleton().join.parentAt, drop).length() < 8,
             qPrintable(QStringLiteral("%1,%2")
                            .arg(fx.skeleton().join.parentAt.x())
                            .arg(fx.skeleton().join.parentAt.y())));
    QVERIFY(!fx.skeleton().isPosed()); // joining never moves the drawing

    // Dragging the joined arm's root moves the whole character: the torso's root offset.
    const QPointF armRoot = fx.skeleton().posedJoints()[std::size_t(fx.skeleton().root)];
    fx.drag(armRoot, armRoot + QPointF(10, 5));
    QVERIFY(QLineF(torsoRig().rootOffset, QPointF(10, 5)).length() < 2.0);
    QCOMPARE(fx.skeleton().rootOffset, QPointF());
    QVERIFY(fx.skeleton().hangs());
    QVERIFY(QLineF(fx.skeleton().posedJoints()[std::size_t(fx.skeleton().root)],
                   armRoot + torsoRig().rootOffset)
                .length() < 1e-9);
    fx.doc.undoStack()->undo();
    QCOMPARE(torsoRig().rootOffset, QPointF());

    // Moving the torso by its root moves the arm's drawing with it.
    QVERIFY(fx.waitReady());
    const QPointF torsoRoot = torsoRig().joints[std::size_t(torsoRig().root)];
    fx.drag(torsoRoot, torsoRoot + QPointF(30, -20));
    const QPointF offset = torsoRig().rootOffset;
    QVERIFY(QLineF(offset, QPointF(30, -20)).length() < 2.0);
    QVERIFY(fx.skeleton().isPosed());
    QVERIFY(fx.waitReady());
    QTRY_VERIFY_WITH_TIMEOUT(fx.object().deformed, 10000);
    const StrokePoint a = fx.object().strokes[0].data->points[30];
    QTRY_VERIFY_WITH_TIMEOUT(
        QLineF(QPointF(a.x, a.y) + offset, QPointF(fx.object().deformed->strokes[0][30].x,
                                                   fx.object().deformed->strokes[0][30].y))
                .length() < 0.05,
        10000);
}

void TestBoneTool::movingStrokesAwayRebuildsTheShownSkeleton()
{
    Fixture fx;
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    fx.overlay->setShown(true);
    const auto lowest = [&] {
        double y = -HUGE_VAL;
        for (const QPointF &p : fx.skeleton().joints)
            y = std::max(y, p.y());
        return y;
    };
    QVERIFY(lowest() > 400); // the forearm's bones reach down
    StrokeGroup other;
    other.id = fx.doc.allocateId();
    other.name = QStringLiteral("other");
    fx.doc.insertGroup(fx.state.currentFrameId(), 1, other);
    // Select the forearm (the vertical strokes) and move it to the other object.
    std::vector<Id> forearm;
    for (std::size_t i = 1; i < fx.object().strokes.size(); i += 2)
        forearm.push_back(fx.object().strokes[i].id);
    fx.state.setCurrentGroupId(fx.group);
    fx.state.setSelectedStrokes(forearm);
    const QByteArray start = serializeFinbook(fx.doc);
    const int count = fx.doc.undoStack()->count();
    ObjectActions objects(&fx.state);
    objects.moveSelectionTo(other.id);
    QCOMPARE(fx.doc.undoStack()->count(), count + 1); // strokes and skeleton: one step
    QCOMPARE(fx.doc.group(other.id)->strokes.size(), forearm.size());
    QVERIFY(fx.skeleton().isValid());
    QVERIFY2(lowest() < 300, qPrintable(QString::number(lowest())));
    fx.doc.undoStack()->undo();
    QCOMPARE(serializeFinbook(fx.doc), start);
}

// Issue 45: Merge Objects on a posed object applies its pose first, in the same step, as
// every edit of a posed object's strokes does: the merged drawing shows what the pose showed
// (merged as posed lines, a cut-out pose's hidden parts and sockets were lost).
void TestBoneTool::mergingAPosedObjectAppliesItsPoseFirst()
{
    Fixture fx;
    QUndoStack *stack = fx.doc.undoStack();
    QTest::mouseClick(&fx.canvas, Qt::LeftButton, {}, fx.at({300, 215}));
    QVERIFY(fx.waitReady());
    QVERIFY(fx.swingTipBone(0.6).bone >= 0);
    QVERIFY(fx.object().isDeformed());
    StrokeGroup below;
    below.id = fx.doc.allocateId();
    below.name = QStringLiteral("below");
    below.strokes.push_back({fx.doc.allocateId(), line({100, 100}, {160, 100})});
    fx.doc.insertGroup(fx.state.currentFrameId(), 0, below);
    const auto picture = [&] {
        return renderFrame(fx.doc.frameAt(0), fx.doc.settings(), QSize(800, 600));
    };
    const QImage shown = picture();
    const QByteArray start = serializeFinbook(fx.doc);
    const int count = stack->count();
    fx.state.setCurrentGroupId(fx.group);
    ObjectActions objects(&fx.state);
    objects.mergeObjects();
    QCOMPARE(stack->count(), count + 1); // the pose applied and the merge: one step
    QVERIFY2(stack->text(count).contains(QStringLiteral("pose applied")),
             qPrintable(stack->text(count)));
    QCOMPARE(fx.doc.frameAt(0).groups.size(), std::size_t(1));
    QVERIFY(!fx.doc.group(below.id)->isDeformed());
    const QImage merged = picture();
    long long inked = 0, differ = 0;
    for (int y = 0; y < shown.height(); ++y)
        for (int x = 0; x < shown.width(); ++x) {
            const QRgb a = shown.pixel(x, y), b = merged.pixel(x, y);
            inked += qGray(a) < 128;
            differ += std::abs(qGray(a) - qGray(b)) > 64;
        }
    QVERIFY(inked > 1000);
    QVERIFY2(differ <= inked / 200, qPrintable(QStringLiteral("%1 of %2").arg(differ).arg(inked)));
    stack->undo();
    QCOMPARE(serializeFinbook(fx.doc), start);
}

QTEST_MAIN(TestBoneTool)
#include "tst_bone_tool.moc"
