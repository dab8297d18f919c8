// The Bone tool driven by real mouse events on the real canvas: build a skeleton with a click,
// turn a bone, pull a joint, move the root, lock a joint; every drag one exact undo step.
#include <finbook/model/finbook_file.h>
#include <finbook/ui/canvas_widget.h>
#include <finbook/ui/deform_actions.h>
#include <finbook/ui/editor_state.h>
#include <finbook/ui/skeleton/skeleton_overlay.h>
#include <finbook/ui/skeleton/tool_bone.h>

#include <QElapsedTimer>
#include <QPainter>
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

struct Fixture {
    Document doc;
    EditorState state{&doc};
    DeformActions actions{&state};
    CanvasWidget canvas{&state};
    BoneTool *tool = nullptr;
    SkeletonOverlay *overlay = nullptr;
    Id group = kNoId;

    Fixture()
    {
        Frame f;
        f.id = doc.allocateId();
        StrokeGroup g;
        g.id = doc.allocateId();
        g.name = QStringLiteral("arm");
        // An L: upper arm along x, forearm down.
        for (int k = 0; k <= 6; ++k) {
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
            if (s && s->matches(object()) && !actions.controller()->isWaiting(group))
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
    void altClickLocksAJoint();
    void showSkeletonPaints();
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

    const int bone = fx.tipBone();
    QVERIFY(bone >= 0);
    const SkeletonRig rest = fx.skeleton();
    const QPointF pivot = rest.joints[std::size_t(rest.parent[std::size_t(bone)])];
    const QPointF tip = rest.joints[std::size_t(bone)];
    // Grab the bone at two thirds of its length and swing it by 0.4 rad.
    const QPointF grab = pivot + (tip - pivot) * (2.0 / 3.0);
    const double theta = 0.4;
    const QPointF v = grab - pivot;
    const QPointF to = pivot + QPointF(v.x() * std::cos(theta) - v.y() * std::sin(theta),
                                       v.x() * std::sin(theta) + v.y() * std::cos(theta));
    fx.drag(grab, to);
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
    QCOMPARE(fx.doc.undoStack()->count(), count); // a lock is not a document edit
    // With its pivot locked, pulling the tip turns only the tip's bone.
    const SkeletonRig before = fx.skeleton();
    const QPointF tip = before.joints[std::size_t(bone)];
    fx.drag(tip, tip + QPointF(0, 25));
    for (std::size_t j = 0; j < before.joints.size(); ++j)
        if (int(j) != bone)
            QCOMPARE(fx.skeleton().angles[j], 0.0);
    QTest::mouseClick(&fx.canvas, Qt::RightButton, {}, fx.at(p));
    QVERIFY(!fx.tool->isLocked(fx.group, parent));
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

QTEST_MAIN(TestBoneTool)
#include "tst_bone_tool.moc"
