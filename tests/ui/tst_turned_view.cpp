// Every tool in a turned and mirrored view: the same gestures, made at the same places of the
// drawing, leave the same document as in the upright view (strokes, fills, cuts, moves, pins,
// bones and cage corners), in the real main window. The view is never the document.
#include "tst_window_support.h"

#include <finbook/model/deform_controller.h>
#include <finbook/model/deform_setup.h>
#include <finbook/model/render.h>
#include <finbook/model/skeleton/skeleton_rig.h>
#include <finbook/ui/rig/deform_actions.h>

#include <QtTest>

#include <cmath>

using namespace finbook;
using namespace finbook::test;

namespace {

struct View {
    qreal rotation;
    bool mirrored;
};

// What the gestures left, point by point, in the drawing's own coordinates.
struct Outcome {
    std::vector<std::vector<QPointF>> strokes; // at rest
    // As shown (posed, settled by saving).
    std::vector<std::vector<QPointF>> shown;
    std::vector<QRgb> fills;
    std::vector<QPointF> rig; // pins' targets, cage corners or joints
    int steps = 0;
    QStringList history; // the undo steps' names, said when a check fails
};

} // namespace

class TestTurnedView : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { m_settings = std::make_unique<IsolatedSettings>(); }
    void cleanup() { m_window.reset(); }

    void drawFillEraseSelectAndPinAlike();
    void bonesAndCageAlike();

private:
    void open(View view)
    {
        m_window = std::make_unique<ui::MainWindow>();
        resetDocument(*m_window->document(), 1);
        QVERIFY(showActive(*m_window));
        ui::CanvasWidget *canvas = m_window->canvas();
        canvas->actualSize();
        canvas->setMirrored(view.mirrored);
        canvas->setRotation(view.rotation);
        QCOMPARE(canvas->rotation(), view.rotation);
        QCOMPARE(canvas->isMirrored(), view.mirrored);
    }
    ui::CanvasWidget *canvas() const { return m_window->canvas(); }
    model::Document *doc() const { return m_window->document(); }
    void use(const char *tool) { canvas()->setCurrentTool(QString::fromLatin1(tool)); }
    // A drag through drawing points, each mapped through the view as it is.
    void dragThrough(const std::vector<QPointF> &canvasPoints, qreal step = 4.0)
    {
        std::vector<QPointF> widget;
        for (std::size_t i = 0; i + 1 < canvasPoints.size(); ++i) {
            const QPointF a = canvasPoints[i], b = canvasPoints[i + 1];
            const int n = std::max(1, int(QLineF(a, b).length() / step));
            for (int k = 0; k < n; ++k)
                widget.push_back(canvas()->mapFromCanvas(a + (b - a) * (qreal(k) / n)));
        }
        widget.push_back(canvas()->mapFromCanvas(canvasPoints.back()));
        drag(canvas(), widget);
    }
    // A click at exactly that point of the drawing (QTest::mouseClick would round it to whole
    // widget pixels, a different place in each view).
    void click(QPointF canvasPos)
    {
        const QPointF at = canvas()->mapFromCanvas(canvasPos);
        sendMouse(canvas(), QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton);
        sendMouse(canvas(), QEvent::MouseButtonRelease, at, Qt::LeftButton, Qt::NoButton);
    }
    bool waitReady()
    {
        auto *deform = m_window->findChild<ui::DeformActions *>();
        const model::Id group = doc()->frameAt(0).groups[0].id;
        return QTest::qWaitFor(
            [&] {
                const model::DeformSetup *s = deform->controller()->setup(group);
                return s && !deform->controller()->isWaiting(group);
            },
            20000);
    }
    Outcome outcome() const
    {
        // Saving settles every pose (a saved pose is the converged one): what is compared is
        // then the pose, not how far its solve had got.
        QTemporaryDir dir;
        if (!m_window->saveFile(dir.filePath(QStringLiteral("settled.finbook"))))
            return {};
        Outcome o;
        const model::StrokeGroup &g = doc()->frameAt(0).groups[0];
        for (std::size_t i = 0; i < g.strokes.size(); ++i) {
            std::vector<QPointF> points, shown;
            for (const model::StrokePoint &p : g.strokes[i].data->points)
                points.emplace_back(p.x, p.y);
            for (const model::StrokePoint &p : model::displayedPoints(g, i))
                shown.emplace_back(p.x, p.y);
            o.strokes.push_back(std::move(points));
            o.shown.push_back(std::move(shown));
        }
        for (const model::Fill &f : g.fills)
            o.fills.push_back(f.color);
        for (const model::Pin &p : g.rig.pins)
            o.rig.push_back(p.target);
        for (const QPointF &c : g.rig.cage.posed)
            o.rig.push_back(c);
        for (const QPointF &j : g.rig.skeleton.joints)
            o.rig.push_back(j);
        // A pose: the angles, scaled so that a hundredth of a degree shows.
        for (double a : g.rig.skeleton.angles)
            o.rig.emplace_back(a * 100.0, 0.0);
        o.steps = doc()->undoStack()->count();
        for (int i = 0; i < o.steps; ++i)
            o.history << doc()->undoStack()->text(i);
        return o;
    }
    static void compare(const Outcome &turned, const Outcome &upright)
    {
        QVERIFY2(turned.steps == upright.steps,
                 qPrintable(turned.history.join(QStringLiteral(", ")) + QStringLiteral(" | ") +
                            upright.history.join(QStringLiteral(", "))));
        QCOMPARE(turned.fills, upright.fills);
        QCOMPARE(turned.strokes.size(), upright.strokes.size());
        for (std::size_t s = 0; s < upright.strokes.size(); ++s) {
            QCOMPARE(turned.strokes[s].size(), upright.strokes[s].size());
            for (std::size_t i = 0; i < upright.strokes[s].size(); ++i)
                QVERIFY2(QLineF(turned.strokes[s][i], upright.strokes[s][i]).length() < 0.01,
                         qPrintable(QStringLiteral("stroke %1, point %2: (%3, %4) against (%5, "
                                                   "%6)")
                                        .arg(s)
                                        .arg(i)
                                        .arg(turned.strokes[s][i].x())
                                        .arg(turned.strokes[s][i].y())
                                        .arg(upright.strokes[s][i].x())
                                        .arg(upright.strokes[s][i].y())));
        }
        QCOMPARE(turned.shown.size(), upright.shown.size());
        for (std::size_t s = 0; s < upright.shown.size(); ++s) {
            QCOMPARE(turned.shown[s].size(), upright.shown[s].size());
            for (std::size_t i = 0; i < upright.shown[s].size(); ++i)
                QVERIFY2(QLineF(turned.shown[s][i], upright.shown[s][i]).length() < 0.01,
                         qPrintable(QStringLiteral("shown stroke %1, point %2").arg(s).arg(i)));
        }
        QCOMPARE(turned.rig.size(), upright.rig.size());
        for (std::size_t i = 0; i < upright.rig.size(); ++i)
            QVERIFY2(QLineF(turned.rig[i], upright.rig[i]).length() < 0.05,
                     qPrintable(QStringLiteral("rig point %1").arg(i)));
    }
    void drawBody()
    {
        use("tool.pen");
        dragThrough({{100, 100}, {300, 100}, {300, 250}, {100, 250}, {100, 100}});
        dragThrough({{330, 110}, {360, 180}, {340, 260}});
    }

    Outcome drawFillEraseSelectAndPin(View view)
    {
        open(view);
        drawBody();
        use("tool.fill");
        click({200, 175});
        use("tool.eraser");
        dragThrough({{320, 180}, {380, 185}}, 2.0);
        use("tool.select");
        dragThrough({{80, 80}, {320, 80}, {320, 270}, {80, 270}, {80, 80}}, 6.0);
        dragThrough({{200, 175}, {215, 185}, {230, 190}});
        use("tool.pin"); // inside the body, which the move took 30 px right and 15 down
        click({150, 130});
        click({310, 250});
        if (!waitReady())
            return {};
        dragThrough({{310, 250}, {325, 265}, {340, 280}});
        return outcome();
    }

    Outcome boneOrCage(View view, bool bones)
    {
        open(view);
        drawBody();
        if (bones) {
            use("tool.bone");
            click({200, 175});
            if (!waitReady())
                return {};
            // Swing from the right edge of the body downwards.
            dragThrough({{290, 175}, {292, 200}, {285, 230}});
        } else {
            use("tool.cage");
            m_window->findChild<QAction *>(QStringLiteral("cage.fit"))->trigger();
            if (!waitReady())
                return {};
            const QPointF corner = doc()->frameAt(0).groups[0].rig.cage.posed.front();
            dragThrough({corner, corner + QPointF(20, 10), corner + QPointF(30, 25)});
        }
        return outcome();
    }

    std::unique_ptr<IsolatedSettings> m_settings;
    std::unique_ptr<ui::MainWindow> m_window;
};

void TestTurnedView::drawFillEraseSelectAndPinAlike()
{
    const Outcome upright = drawFillEraseSelectAndPin({0, false});
    QVERIFY2(upright.steps >= 8, qPrintable(upright.history.join(QStringLiteral(", "))));
    QCOMPARE(upright.fills.size(), std::size_t(1));
    QVERIFY(upright.strokes.size() >= 3); // the rub cut the line in two
    QCOMPARE(upright.rig.size(), std::size_t(2));
    m_window.reset();
    const Outcome turned = drawFillEraseSelectAndPin({30, true});
    compare(turned, upright);
    m_window.reset();
    compare(drawFillEraseSelectAndPin({-135, false}), upright);
}

void TestTurnedView::bonesAndCageAlike()
{
    const Outcome bones = boneOrCage({0, false}, true);
    QVERIFY(bones.rig.size() >= 2);
    m_window.reset();
    compare(boneOrCage({70, true}, true), bones);
    m_window.reset();
    const Outcome cage = boneOrCage({0, false}, false);
    QVERIFY(cage.rig.size() >= 3);
    m_window.reset();
    compare(boneOrCage({-40, true}, false), cage);
}

QTEST_MAIN(TestTurnedView)
#include "tst_turned_view.moc"
