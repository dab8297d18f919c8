// Pen, eraser and select tools driven with real mouse events on a real canvas.
#include "cut_out_character.h"
#include "stabiliser_support.h"
#include "tst_tools_support.h"

#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/fill/fill_regions.h>
#include <finbook/model/fill/fill_resolve.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/picture/picture_commands.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/rig/rig_commands.h>
#include <finbook/ui/panels/object_actions.h>
#include <finbook/ui/tools/stroke_editing.h>
#include <finbook/ui/tools/tool_eraser.h>
#include <finbook/ui/tools/tool_eyedropper.h>
#include <finbook/ui/tools/tool_hand.h>
#include <finbook/ui/tools/tool_pen.h>
#include <finbook/ui/tools/tool_select.h>
#include <finbook/ui/window/editor_state.h>

#include <QClipboard>
#include <QPainter>
#include <QSignalSpy>
#include <QtEndian>
#include <QtTest>

#include <cmath>
#include <cstring>

using namespace finbook;
using namespace finbook::test;

class TestTools : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void penDrawsOneStrokeUndoRedo();
    void penUsesPressureFromTablet();
    void penRefusesLockedAndHiddenObjects();
    void penCreatesObjectInEmptyFrame();
    void penSmoothingKeepsEnds();
    void penStabiliserSteadiesTheLine();
    void eyedropperTakesALinesOrAFillsColour();
    void eraserErasesTouchedStrokeOnly();
    void eraserLeavesHiddenAndLockedAlone();
    void eraserDragWithoutHitsLeavesNoUndoStep();
    void lassoSelectsMostlyInsideStrokes();
    void picturesAreSelectedMovedAndDeleted();
    void aPicturePaintedInAChildWidgetLandsWhereItIsDrawn();
    void clickSelectsStrokeUnderCursor();
    void dragMovesSelectionAndUndoRestoresExactly();
    void cornerHandleScalesSelection_data();
    void cornerHandleScalesSelection();
    void rotateHandleRotatesSelection();
    void deleteSelection();
    void aCutOutPoseMovesAndDeletesWholeLines();
    void aHeadLassoedAfterApplyPoseMovesAlone();
    void aHeadMovedOffTheArmsShowsTheirTops();
    void copyPasteIntoAnotherFrame();
    void selectAllSkipsLockedObjects();
    void clipboardRefusesMalformedData();
    void handToolPans();

private:
    // tests/data/apply_pose_head.finbook (a figure drawn in the app, Apply Pose made with both
    // arms raised behind the head): the head (the inked line highest up) and its box.
    bool openApplyPoseHead(std::size_t &head, QRectF &box)
    {
        if (model::openFinbook(
                *m_doc, QStringLiteral(FINBOOK_SOURCE_DIR "/tests/data/apply_pose_head.finbook")))
            return false;
        m_state->setCurrentFrameIndex(0);
        if (m_doc->frameAt(0).groups.empty() || m_doc->frameAt(0).groups.front().rig.isPosed())
            return false;
        const model::StrokeGroup &g = m_doc->frameAt(0).groups.front();
        float top = 1e9f;
        for (std::size_t i = 0; i < g.strokes.size(); ++i)
            if (qAlpha(g.strokes[i].data->color) != 0)
                for (const model::StrokePoint &p : g.strokes[i].data->points)
                    if (p.y < top)
                        top = p.y, head = i;
        box = QRectF();
        for (const model::StrokePoint &p : g.strokes[head].data->points)
            box |= QRectF(QPointF(p.x, p.y), QSizeF(0.01, 0.01));
        return !box.isEmpty();
    }
    // A lasso of the Select tool round `box`, a tenth wider than it.
    void lassoRound(const QRectF &box)
    {
        m_canvas->setCurrentTool(QStringLiteral("tool.select"));
        std::vector<QPointF> lasso;
        for (int k = 0; k <= 24; ++k) {
            const double a = 2 * M_PI * k / 24;
            lasso.push_back(
                m_canvas->mapFromCanvas(box.center() + QPointF(0.55 * box.width() * std::cos(a),
                                                               0.55 * box.height() * std::sin(a))));
        }
        drag(m_canvas.get(), lasso);
    }
    model::Id group(int frame, int index = 0) const
    {
        return m_doc->frameAt(frame).groups[std::size_t(index)].id;
    }
    int strokeCount(int frame) const
    {
        int n = 0;
        for (const model::StrokeGroup &g : m_doc->frameAt(frame).groups)
            n += int(g.strokes.size());
        return n;
    }

    std::unique_ptr<model::Document> m_doc;
    std::unique_ptr<ui::EditorState> m_state;
    std::unique_ptr<ui::CanvasWidget> m_canvas;
};

void TestTools::init()
{
    m_doc = std::make_unique<model::Document>();
    resetDocument(*m_doc, 2);
    m_state = std::make_unique<ui::EditorState>(m_doc.get());
    m_canvas = std::make_unique<ui::CanvasWidget>(m_state.get());
    m_canvas->addTool(std::make_unique<ui::PenTool>());
    // These tests keep the whole-stroke mode; tst_eraser covers cutting.
    static_cast<ui::EraserTool *>(m_canvas->addTool(std::make_unique<ui::EraserTool>()))
        ->setMode(ui::EraserMode::WholeStrokes);
    m_canvas->addTool(std::make_unique<ui::SelectTool>());
    m_canvas->addTool(std::make_unique<ui::EyedropperTool>(
        static_cast<ui::PenTool *>(m_canvas->tool(QStringLiteral("tool.pen")))));
    m_canvas->addTool(std::make_unique<ui::HandTool>());
    m_canvas->resize(600, 500);
    m_canvas->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_canvas.get()));
    m_canvas->actualSize();
    QCOMPARE(m_canvas->zoom(), 1.0);
}

void TestTools::cleanup()
{
    m_canvas.reset();
    m_state.reset();
    m_doc.reset();
}

void TestTools::penDrawsOneStrokeUndoRedo()
{
    m_canvas->setCurrentTool(QStringLiteral("tool.pen"));
    dragCanvas(m_canvas.get(), {50, 50}, {250, 120});
    QCOMPARE(strokeCount(0), 1);
    const model::Stroke &s = m_doc->frameAt(0).groups[0].strokes[0];
    QVERIFY(s.data->points.size() >= 10);
    QVERIFY(std::abs(s.data->points.front().x - 50) < 0.01);
    QVERIFY(std::abs(s.data->points.back().y - 120) < 0.01);
    for (const model::StrokePoint &p : s.data->points)
        QCOMPARE(p.pressure, 1.0f); // mouse: full pressure
    QCOMPARE(m_doc->undoStack()->count(), 1);
    m_doc->undoStack()->undo();
    QCOMPARE(strokeCount(0), 0);
    m_doc->undoStack()->redo();
    QCOMPARE(strokeCount(0), 1);
}

void TestTools::penUsesPressureFromTablet()
{
    m_canvas->setCurrentTool(QStringLiteral("tool.pen"));
    const auto tablet = [&](QEvent::Type type, QPointF canvasPos, qreal pressure,
                            Qt::MouseButtons buttons) {
        const QPointF w = m_canvas->mapFromCanvas(canvasPos);
        QTabletEvent e(type, QPointingDevice::primaryPointingDevice(), w, m_canvas->mapToGlobal(w),
                       pressure, 0, 0, 0, 0, 0, Qt::NoModifier, Qt::LeftButton, buttons);
        QApplication::sendEvent(m_canvas.get(), &e);
    };
    tablet(QEvent::TabletPress, {20, 20}, 0.2, Qt::LeftButton);
    for (int i = 1; i <= 10; ++i)
        tablet(QEvent::TabletMove, {20.0 + 10 * i, 20}, 0.2 + 0.07 * i, Qt::LeftButton);
    tablet(QEvent::TabletRelease, {120, 20}, 0.9, Qt::NoButton);
    QCOMPARE(strokeCount(0), 1);
    const auto &points = m_doc->frameAt(0).groups[0].strokes[0].data->points;
    QVERIFY(points.front().pressure < 0.3f);
    QVERIFY(points.back().pressure > 0.8f);
    // Pressure off (the pen's options): the tablet draws every point at full width.
    auto *pen = static_cast<ui::PenTool *>(m_canvas->tool(QStringLiteral("tool.pen")));
    ui::PenSettings s = pen->settings();
    s.pressure = false;
    pen->setSettings(s);
    tablet(QEvent::TabletPress, {20, 60}, 0.2, Qt::LeftButton);
    for (int i = 1; i <= 10; ++i)
        tablet(QEvent::TabletMove, {20.0 + 10 * i, 60}, 0.2 + 0.07 * i, Qt::LeftButton);
    tablet(QEvent::TabletRelease, {120, 60}, 0.9, Qt::NoButton);
    QCOMPARE(strokeCount(0), 2);
    for (const model::StrokePoint &p : m_doc->frameAt(0).groups[0].strokes[1].data->points)
        QCOMPARE(p.pressure, 1.0f);
}

void TestTools::penRefusesLockedAndHiddenObjects()
{
    m_canvas->setCurrentTool(QStringLiteral("tool.pen"));
    QSignalSpy messages(m_canvas.get(), &ui::CanvasWidget::messagePosted);
    m_doc->undoStack()->push(
        new model::SetObjectFlagCommand(m_doc.get(), group(0), model::ObjectFlag::Locked, true));
    dragCanvas(m_canvas.get(), {50, 50}, {150, 50});
    QCOMPARE(strokeCount(0), 0);
    QCOMPARE(messages.count(), 1);
    QVERIFY(messages.first().first().toString().contains(QStringLiteral("locked")));
    m_doc->undoStack()->undo();
    m_doc->undoStack()->push(
        new model::SetObjectFlagCommand(m_doc.get(), group(0), model::ObjectFlag::Visible, false));
    dragCanvas(m_canvas.get(), {50, 50}, {150, 50});
    QCOMPARE(strokeCount(0), 0);
    QCOMPARE(messages.count(), 2);
}

void TestTools::penCreatesObjectInEmptyFrame()
{
    m_doc->undoStack()->push(new model::RemoveObjectCommand(m_doc.get(), group(0)));
    m_doc->undoStack()->setClean();
    const int steps = m_doc->undoStack()->count();
    QVERIFY(m_doc->frameAt(0).groups.empty());
    m_canvas->setCurrentTool(QStringLiteral("tool.pen"));
    dragCanvas(m_canvas.get(), {50, 50}, {150, 80});
    QCOMPARE(m_doc->frameAt(0).groups.size(), std::size_t(1));
    QCOMPARE(strokeCount(0), 1);
    QCOMPARE(m_doc->undoStack()->count(), steps + 1); // object + stroke: one undo step
    m_doc->undoStack()->undo();
    QVERIFY(m_doc->frameAt(0).groups.empty());
}

void TestTools::penSmoothingKeepsEnds()
{
    std::vector<model::StrokePoint> zigzag;
    for (int i = 0; i < 30; ++i)
        zigzag.push_back({float(i * 4), float(i % 2 ? 10 : 0), 1.0f});
    zigzag.push_back(zigzag.back()); // a repeat
    zigzag.push_back({std::numeric_limits<float>::quiet_NaN(), 0, 1});
    const auto smooth = ui::PenTool::finishedPoints(zigzag, 4);
    QCOMPARE(smooth.size(), std::size_t(30));
    QCOMPARE(smooth.front(), zigzag.front());
    QCOMPARE(smooth.back(), zigzag[29]);
    float spread = 0;
    for (std::size_t i = 5; i + 5 < smooth.size(); ++i)
        spread = std::max(spread, std::abs(smooth[i].y - 5.0f));
    QVERIFY(spread < 2.0f); // the zigzag has flattened
    for (const model::StrokePoint &p : smooth)
        QVERIFY(std::isfinite(p.x) && std::isfinite(p.y));
}

void TestTools::penStabiliserSteadiesTheLine()
{
    // The same shaky circle drawn with the mouse twice, without and with the stabiliser (no
    // smoothing on release, so what is kept is what the stabiliser made).
    m_canvas->setCurrentTool(QStringLiteral("tool.pen"));
    auto *pen = static_cast<ui::PenTool *>(m_canvas->tool(QStringLiteral("tool.pen")));
    QVERIFY(pen);
    const auto hand = shakyCircle({300, 250}, 150, 600, 2.0);
    std::vector<QPointF> path;
    for (const model::StrokePoint &p : hand)
        path.push_back(m_canvas->mapFromCanvas(QPointF(p.x, p.y)));
    double wobble[2] = {};
    for (int strength : {0, 5}) {
        ui::PenSettings s = pen->settings();
        s.smoothing = 0;
        s.stabiliser = strength;
        pen->setSettings(s);
        drag(m_canvas.get(), path, Qt::LeftButton);
        const auto &strokes = m_doc->frameAt(0).groups[0].strokes;
        QCOMPARE(strokes.size(), std::size_t(strength == 0 ? 1 : 2));
        const auto &points = strokes.back().data->points;
        wobble[strength == 0 ? 0 : 1] = wobbleOf(points);
        // It starts where the pen touched down and ends where it lifted.
        const QPointF first = m_canvas->mapToCanvas(path.front());
        const QPointF last = m_canvas->mapToCanvas(path.back());
        QVERIFY(std::hypot(points.front().x - first.x(), points.front().y - first.y()) < 0.01);
        QVERIFY(std::hypot(points.back().x - last.x(), points.back().y - last.y()) < 0.01);
    }
    qInfo("drawn wobble: %.1f rad off, %.1f rad at strength 5", wobble[0], wobble[1]);
    QVERIFY(wobble[1] < wobble[0] / 4);
    QCOMPARE(m_doc->undoStack()->count(), 2); // one step per stroke
}

void TestTools::eyedropperTakesALinesOrAFillsColour()
{
    // A blue square outline filled yellow, a red line across it; the pen is black.
    const model::Id g = group(0);
    auto square = std::make_shared<model::StrokeData>();
    square->width = 4.0f;
    square->color = 0xff2040c0;
    for (QPointF p : {QPointF(100, 100), QPointF(300, 100), QPointF(300, 300), QPointF(100, 300),
                      QPointF(100, 100)})
        square->points.push_back({float(p.x()), float(p.y()), 1.0f});
    m_doc->undoStack()->push(new model::AddStrokeCommand(m_doc.get(), g, square));
    m_doc->undoStack()->push(new model::AddStrokeCommand(
        m_doc.get(), g, line(QPointF(120, 200), QPointF(280, 200), 20, 0xffd02020)));
    m_doc->undoStack()->push(
        model::fillRegionCommand(m_doc.get(), g, QPointF(150, 150), 0xfff0d020).release());
    const int steps = m_doc->undoStack()->count();
    auto *pen = static_cast<ui::PenTool *>(m_canvas->tool(QStringLiteral("tool.pen")));
    m_canvas->setCurrentTool(QStringLiteral("tool.eyedropper"));
    QCOMPARE(m_canvas->currentTool()->id(), QStringLiteral("tool.eyedropper"));
    QCOMPARE(pen->settings().color, QColor(Qt::black));
    QSignalSpy messages(m_canvas.get(), &ui::CanvasWidget::messagePosted);
    const auto clickAt = [&](QPointF canvasPos) {
        drag(m_canvas.get(), {m_canvas->mapFromCanvas(canvasPos)});
    };
    clickAt({200, 201}); // on the red line, over the fill: the line is on top
    QCOMPARE(pen->settings().color, QColor(0xd0, 0x20, 0x20));
    clickAt({150, 150}); // inside the fill
    QCOMPARE(pen->settings().color, QColor(0xf0, 0xd0, 0x20));
    clickAt({101, 250}); // on the outline
    QCOMPARE(pen->settings().color, QColor(0x20, 0x40, 0xc0));
    messages.clear();
    clickAt({500, 400}); // empty paper: the colour stays, and a message says why
    QCOMPARE(pen->settings().color, QColor(0x20, 0x40, 0xc0));
    QCOMPARE(messages.count(), 1);
    QCOMPARE(m_doc->undoStack()->count(), steps); // the document did not change
    // With the pen in hand, Ctrl+click takes a colour the same way, and draws nothing (also in
    // a turned view).
    m_canvas->setCurrentTool(QStringLiteral("tool.pen"));
    m_canvas->setRotation(-40);
    drag(m_canvas.get(), {m_canvas->mapFromCanvas({200, 201})}, Qt::LeftButton,
         Qt::ControlModifier);
    QCOMPARE(pen->settings().color, QColor(0xd0, 0x20, 0x20));
    QCOMPARE(m_canvas->currentTool()->id(), QStringLiteral("tool.pen"));
    QCOMPARE(m_doc->undoStack()->count(), steps);
    // Without Ctrl the pen draws.
    drag(m_canvas.get(),
         {m_canvas->mapFromCanvas({350, 350}), m_canvas->mapFromCanvas({380, 360})});
    QCOMPARE(m_doc->undoStack()->count(), steps + 1);
}

void TestTools::eraserErasesTouchedStrokeOnly()
{
    const model::Id top = addStroke(*m_doc, group(0), line({50, 100}, {350, 100}));
    const model::Id bottom = addStroke(*m_doc, group(0), line({50, 200}, {350, 200}));
    const int steps = m_doc->undoStack()->count();
    m_canvas->setCurrentTool(QStringLiteral("tool.eraser"));
    dragCanvas(m_canvas.get(), {200, 60}, {200, 140});
    QVERIFY(!findStroke(*m_doc, top));
    QVERIFY(findStroke(*m_doc, bottom));
    QCOMPARE(m_doc->undoStack()->count(), steps + 1);
    QCOMPARE(m_doc->undoStack()->text(steps), QStringLiteral("Erase"));
    m_doc->undoStack()->undo();
    QVERIFY(findStroke(*m_doc, top));
    QVERIFY(findStroke(*m_doc, bottom));
    QCOMPARE(strokeCount(0), 2);
}

void TestTools::eraserLeavesHiddenAndLockedAlone()
{
    resetDocument(*m_doc, 1, 3);
    const model::Id hidden = addStroke(*m_doc, group(0, 0), line({50, 100}, {350, 100}));
    const model::Id locked = addStroke(*m_doc, group(0, 1), line({50, 110}, {350, 110}));
    const model::Id free = addStroke(*m_doc, group(0, 2), line({50, 120}, {350, 120}));
    QUndoStack *stack = m_doc->undoStack();
    stack->push(new model::SetObjectFlagCommand(m_doc.get(), group(0, 0),
                                                model::ObjectFlag::Visible, false));
    stack->push(
        new model::SetObjectFlagCommand(m_doc.get(), group(0, 1), model::ObjectFlag::Locked, true));
    m_canvas->setCurrentTool(QStringLiteral("tool.eraser"));
    dragCanvas(m_canvas.get(), {200, 60}, {200, 160});
    QVERIFY(findStroke(*m_doc, hidden));
    QVERIFY(findStroke(*m_doc, locked));
    QVERIFY(!findStroke(*m_doc, free));
}

void TestTools::eraserDragWithoutHitsLeavesNoUndoStep()
{
    addStroke(*m_doc, group(0), line({50, 100}, {350, 100}));
    const int steps = m_doc->undoStack()->count();
    m_canvas->setCurrentTool(QStringLiteral("tool.eraser"));
    dragCanvas(m_canvas.get(), {50, 250}, {350, 250});
    QCOMPARE(m_doc->undoStack()->count(), steps);
    QCOMPARE(strokeCount(0), 1);
}

void TestTools::lassoSelectsMostlyInsideStrokes()
{
    const model::Id inside = addStroke(*m_doc, group(0), line({60, 60}, {140, 60}));
    const model::Id half = addStroke(*m_doc, group(0), line({100, 120}, {300, 120}));
    const model::Id outside = addStroke(*m_doc, group(0), line({250, 250}, {350, 250}));
    m_canvas->setCurrentTool(QStringLiteral("tool.select"));
    // A lasso around (40..160, 40..150): all of `inside`, a quarter of `half`.
    std::vector<QPointF> lasso;
    for (QPointF p :
         {QPointF(40, 40), QPointF(160, 40), QPointF(160, 150), QPointF(40, 150), QPointF(40, 41)})
        lasso.push_back(m_canvas->mapFromCanvas(p));
    drag(m_canvas.get(), lasso);
    QCOMPARE(m_state->selectedStrokes(), std::vector<model::Id>{inside});
    Q_UNUSED(half)
    Q_UNUSED(outside)
}

void TestTools::clickSelectsStrokeUnderCursor()
{
    addStroke(*m_doc, group(0), line({60, 60}, {140, 60}));
    const model::Id b = addStroke(*m_doc, group(0), line({60, 200}, {140, 200}));
    m_canvas->setCurrentTool(QStringLiteral("tool.select"));
    drag(m_canvas.get(), {m_canvas->mapFromCanvas({100, 201})});
    QCOMPARE(m_state->selectedStrokes(), std::vector<model::Id>{b});
    drag(m_canvas.get(), {m_canvas->mapFromCanvas({300, 280})});
    QVERIFY(m_state->selectedStrokes().empty());
}

void TestTools::dragMovesSelectionAndUndoRestoresExactly()
{
    const model::Id a = addStroke(*m_doc, group(0), line({60, 60}, {140, 90}));
    const model::Id b = addStroke(*m_doc, group(0), line({250, 250}, {350, 250}));
    const model::StrokeData before = *findStroke(*m_doc, a)->data;
    const model::StrokeData other = *findStroke(*m_doc, b)->data;
    m_canvas->setCurrentTool(QStringLiteral("tool.select"));
    m_state->setSelectedStrokes({a});
    dragCanvas(m_canvas.get(), {100, 75}, {130, 95}, 5);
    const model::StrokeData &after = *findStroke(*m_doc, a)->data;
    QCOMPARE(after.points.size(), before.points.size());
    for (std::size_t i = 0; i < after.points.size(); ++i) {
        QVERIFY(std::abs(after.points[i].x - before.points[i].x - 30) < 1e-3);
        QVERIFY(std::abs(after.points[i].y - before.points[i].y - 20) < 1e-3);
    }
    QCOMPARE(*findStroke(*m_doc, b)->data, other);
    QCOMPARE(m_state->selectedStrokes(), std::vector<model::Id>{a}); // still selected
    m_doc->undoStack()->undo();
    QCOMPARE(*findStroke(*m_doc, a)->data, before);
}

void TestTools::cornerHandleScalesSelection_data()
{
    QTest::addColumn<qreal>("rotation");
    QTest::addColumn<bool>("mirrored");
    QTest::newRow("upright") << 0.0 << false;
    // The handles sit on the box's corners as the turned, mirrored view shows them.
    QTest::newRow("view turned 70 degrees, mirrored") << 70.0 << true;
}

void TestTools::cornerHandleScalesSelection()
{
    QFETCH(qreal, rotation);
    QFETCH(bool, mirrored);
    m_canvas->setMirrored(mirrored);
    m_canvas->setRotation(rotation);
    const model::Id a = addStroke(*m_doc, group(0), line({100, 100}, {200, 150}));
    m_canvas->setCurrentTool(QStringLiteral("tool.select"));
    m_state->setSelectedStrokes({a});
    auto *select = static_cast<ui::SelectTool *>(m_canvas->tool(QStringLiteral("tool.select")));
    const QRectF box = select->selectionBounds();
    // Drag the bottom-right corner so the box doubles about its top-left corner.
    const QPointF to = box.topLeft() + (box.bottomRight() - box.topLeft()) * 2;
    dragCanvas(m_canvas.get(), box.bottomRight(), to, 5);
    const QRectF scaled = select->selectionBounds();
    QVERIFY2(std::abs(scaled.width() - 2 * box.width()) < 2.0,
             qPrintable(QString::number(scaled.width())));
    QVERIFY(std::abs(scaled.left() - box.left()) < 2.0);
    m_doc->undoStack()->undo();
    QCOMPARE(select->selectionBounds(), box);
}

void TestTools::rotateHandleRotatesSelection()
{
    const model::Id a = addStroke(*m_doc, group(0), line({150, 150}, {250, 150}, 11));
    m_canvas->setCurrentTool(QStringLiteral("tool.select"));
    m_state->setSelectedStrokes({a});
    auto *select = static_cast<ui::SelectTool *>(m_canvas->tool(QStringLiteral("tool.select")));
    const QRectF box = select->selectionBounds();
    const QPointF handle(box.center().x(), box.top() - ui::SelectTool::kRotateOffset);
    // Swing the handle from straight above the centre to straight right of it: +90°.
    const QPointF c = box.center();
    const qreal r = c.y() - handle.y();
    std::vector<QPointF> path;
    for (int i = 0; i <= 9; ++i) {
        const qreal t = qDegreesToRadians(90.0 * i / 9);
        path.push_back(m_canvas->mapFromCanvas(c + QPointF(r * std::sin(t), -r * std::cos(t))));
    }
    drag(m_canvas.get(), path, Qt::LeftButton, Qt::ShiftModifier);
    const auto &pts = findStroke(*m_doc, a)->data->points;
    // The horizontal line is now vertical through the centre.
    QVERIFY(std::abs(pts.front().x - 200) < 0.01);
    QVERIFY(std::abs(pts.back().x - 200) < 0.01);
    QVERIFY(std::abs(std::abs(pts.back().y - pts.front().y) - 100) < 0.01);
}

// Picture objects with the select tool (issue 51): a click on the picture picks it, a drag
// moves it exactly (one undo step, undone to the very same picture), a lasso around it picks it
// with the strokes, Delete takes the object away, Escape drops the pick.
void TestTools::picturesAreSelectedMovedAndDeleted()
{
    QImage painted(80, 60, QImage::Format_ARGB32_Premultiplied);
    painted.fill(QColor(30, 120, 200));
    auto made = model::makePictureObject(model::PictureLayer{QStringLiteral("sky"), painted, {}},
                                         QPointF(100, 100));
    QVERIFY(made.hasValue());
    std::vector<model::StrokeGroup> objects{*made};
    auto *import = new model::ImportPictureCommand(m_doc.get(), m_doc->frameAt(0).id, -1, objects);
    m_doc->undoStack()->push(import);
    const model::Id picture = import->objectIds().front();
    const model::Id near = addStroke(*m_doc, group(0), line({300, 300}, {360, 300}));
    m_canvas->setCurrentTool(QStringLiteral("tool.select"));
    drag(m_canvas.get(), {m_canvas->mapFromCanvas({140, 130})});
    QCOMPARE(m_state->selectedPictures(), std::vector<model::Id>{picture});
    QVERIFY(m_state->selectedStrokes().empty());
    const auto before = m_doc->group(picture)->picture;
    const int steps = m_doc->undoStack()->count();
    dragCanvas(m_canvas.get(), {140, 130}, {170, 150}, 5);
    QCOMPARE(m_doc->undoStack()->count(), steps + 1);
    QCOMPARE(m_doc->group(picture)->picture->restRect(), QRectF(130, 120, 80, 60));
    QVERIFY(m_doc->group(picture)->picture->data == before->data); // moved, not resampled
    QCOMPARE(m_state->selectedPictures(), std::vector<model::Id>{picture});
    m_doc->undoStack()->undo();
    QVERIFY(m_doc->group(picture)->picture == before);
    // A lasso around both the picture and the line picks both.
    std::vector<QPointF> lasso;
    for (const QPointF p :
         {QPointF(80, 80), QPointF(400, 80), QPointF(400, 340), QPointF(80, 340), QPointF(80, 80)})
        lasso.push_back(m_canvas->mapFromCanvas(p));
    drag(m_canvas.get(), lasso);
    QCOMPARE(m_state->selectedPictures(), std::vector<model::Id>{picture});
    QCOMPARE(m_state->selectedStrokes(), std::vector<model::Id>{near});
    // Copy puts the picked picture on the clipboard as it shows (for other programs and Paste).
    m_state->setSelection({}, {picture});
    QVERIFY(ui::StrokeEditing::copySelection(*m_state));
    const QImage copied = QApplication::clipboard()->image();
    QCOMPARE(copied.size(), painted.size());
    QCOMPARE(copied.pixelColor(40, 30), QColor(30, 120, 200));
    QApplication::clipboard()->clear();
    // Escape drops the pick; Delete with the picture picked removes its object, undoably.
    QTest::keyClick(m_canvas.get(), Qt::Key_Escape);
    QVERIFY(!m_state->hasSelection());
    drag(m_canvas.get(), {m_canvas->mapFromCanvas({140, 130})});
    QVERIFY(ui::StrokeEditing::deleteSelection(*m_state));
    QVERIFY(!m_doc->group(picture));
    QCOMPARE(strokeCount(0), 1);
    m_doc->undoStack()->undo();
    QVERIFY(m_doc->group(picture) && m_doc->group(picture)->picture == before);
}

namespace {
// A widget that paints a picture object as a tool overlay does.
class PictureWidget : public QWidget {
public:
    model::StrokeGroup group;
    using QWidget::QWidget;

protected:
    void paintEvent(QPaintEvent *) override
    {
        QPainter painter(this);
        painter.translate(10, 5);
        model::paintPicture(painter, group);
    }
};
} // namespace

// A widget is painted into its window's backing store at its offset there; the overlay's
// picture must land where the widget paints it, not that offset farther (it did once: drawn
// through deviceTransform(), which holds the offset, then placed by a painter adding it again).
void TestTools::aPicturePaintedInAChildWidgetLandsWhereItIsDrawn()
{
    QImage painted(20, 10, QImage::Format_ARGB32_Premultiplied);
    painted.fill(QColor(220, 20, 20));
    auto made = model::makePictureObject(model::PictureLayer{QStringLiteral("red"), painted, {}},
                                         QPointF(0, 0));
    QVERIFY(made.hasValue());
    QWidget parent;
    parent.resize(200, 150);
    auto *child = new PictureWidget(&parent);
    child->group = *made;
    child->setGeometry(50, 40, 100, 80);
    const QImage shot = parent.grab().toImage();
    const qreal dpr = shot.devicePixelRatio();
    const auto at = [&](int x, int y) {
        return shot.pixelColor(QPoint(int(x * dpr), int(y * dpr)));
    };
    QCOMPARE(at(50 + 10 + 10, 40 + 5 + 5), QColor(220, 20, 20));   // inside, where it is drawn
    QVERIFY(at(50 + 10 + 30, 40 + 5 + 5) != QColor(220, 20, 20));  // beside it: not drawn
    QVERIFY(at(50 + 60 + 10, 40 + 45 + 5) != QColor(220, 20, 20)); // one offset farther: not
}

void TestTools::deleteSelection()
{
    const model::Id a = addStroke(*m_doc, group(0), line({60, 60}, {140, 90}));
    const model::Id b = addStroke(*m_doc, group(0), line({60, 160}, {140, 190}));
    addStroke(*m_doc, group(0), line({260, 160}, {340, 190}));
    m_state->setSelectedStrokes({a, b});
    const int steps = m_doc->undoStack()->count();
    QVERIFY(ui::StrokeEditing::deleteSelection(*m_state));
    QCOMPARE(strokeCount(0), 1);
    QVERIFY(m_state->selectedStrokes().empty());
    QCOMPARE(m_doc->undoStack()->count(), steps + 1);
    m_doc->undoStack()->undo();
    QCOMPARE(strokeCount(0), 3);
    QVERIFY(!ui::StrokeEditing::deleteSelection(*m_state)); // nothing selected
}

// Issue 45 (an edit that applies a pose first): moving or deleting the strokes of a cut-out
// pose bakes each line into the parts its pieces showed and hid, the first part keeping the
// line's id. The move replaced that part with the whole line moved, and left the others where
// they were: an arm drawn twice, its fill gone. The edit now takes every part of the line.
void TestTools::aCutOutPoseMovesAndDeletesWholeLines()
{
    using namespace finbook::testing;
    const model::Id g = group(0);
    const auto arm = poseCutOutCharacter(*m_doc, g);
    QVERIFY(arm);
    // The left arm's line: the stroke nearest its elbow.
    const model::StrokeGroup &posed = *m_doc->group(g);
    model::Id armLine = model::kNoId;
    double nearest = 1e9;
    for (std::size_t i = 0; i < posed.strokes.size(); ++i)
        for (const model::StrokePoint &p : model::displayedPoints(posed, i))
            if (const double d = std::hypot(p.x - arm->elbow.x(), p.y - arm->elbow.y());
                d < nearest)
                nearest = d, armLine = posed.strokes[i].id;
    QVERIFY(armLine != model::kNoId);
    const QTransform view =
        pictureView(shownBounds(*m_doc->group(g)).adjusted(-80, -80, 80, 80), 480);
    const QImage before = framePicture(*m_doc, 0, view, 480);
    const QByteArray start = model::serializeFinbook(*m_doc);
    m_canvas->setCurrentTool(QStringLiteral("tool.select"));
    m_state->setSelectedStrokes({armLine});
    const QPointF grab = arm->elbow + (arm->across.p1() - arm->elbow) * (14.0 / 30.0);
    dragCanvas(m_canvas.get(), grab, grab + QPointF(-20, -30), 5);
    QCOMPARE(m_doc->undoStack()->count(), 1);
    QVERIFY(m_doc->undoStack()->text(0).contains(QStringLiteral("pose applied")));
    QCOMPARE(doubledLines(*m_doc->group(g)), 0);
    QVERIFY(m_state->selectedStrokes().size() > 1); // every part of the arm's line
    // The arm moved whole with its colour: as much of it shows as before.
    const QImage moved = framePicture(*m_doc, 0, view, 480);
    long long redBefore = 0, redAfter = 0;
    const QRgb armColour = before.pixel(view.map(grab).toPoint());
    for (int y = 0; y < before.height(); ++y)
        for (int x = 0; x < before.width(); ++x) {
            redBefore += sameColour(before.pixel(x, y), armColour);
            redAfter += sameColour(moved.pixel(x, y), armColour);
        }
    QVERIFY2(std::abs(double(redAfter - redBefore)) <= 0.02 * double(redBefore),
             qPrintable(QStringLiteral("%1 -> %2 px").arg(redBefore).arg(redAfter)));
    m_doc->undoStack()->undo();
    QCOMPARE(model::serializeFinbook(*m_doc), start);
    // Delete: the whole line goes, no part of it left behind.
    m_state->setSelectedStrokes({armLine});
    QVERIFY(ui::StrokeEditing::deleteSelection(*m_state));
    for (const model::Stroke &s : m_doc->group(g)->strokes)
        for (const model::StrokePoint &p : s.data->points)
            QVERIFY2(std::hypot(p.x - arm->elbow.x(), p.y - arm->elbow.y()) > 10.0 ||
                         qAlpha(s.data->color) == 0,
                     "a part of the deleted arm is left at its elbow");
}

// The walkthrough of issue 45, drawn in the real window (tests/data/apply_pose_head.finbook):
// a body, a head and two arms, filled, both arms raised 100° behind the head in a cut-out pose,
// then Apply Pose. A lasso just round the head used to pick the hidden parts of the lines under
// it and the lines of no ink beside it; moving the head emptied the body and the left arm and
// took the top of the right arm along.
void TestTools::aHeadLassoedAfterApplyPoseMovesAlone()
{
    using namespace finbook::testing;
    std::size_t head = 0;
    QRectF box;
    QVERIFY(openApplyPoseHead(head, box));
    const model::StrokeGroup &g = m_doc->frameAt(0).groups.front();
    const QTransform view = pictureView(shownBounds(g).adjusted(-40, -40, 40, 40), 480);
    const QImage before = framePicture(*m_doc, 0, view, 480);
    // The body below the arms, and the right arm half way up (the rightmost filled pixels of
    // the row a third of the way down the drawing).
    const QRectF all = shownBounds(g);
    const QPointF belly(all.center().x(), all.bottom() - 0.25 * all.height());
    const QRgb bodyColour = before.pixel(view.map(belly).toPoint());
    lassoRound(box);
    const std::vector<model::Id> picked = m_state->selectedStrokes();
    QVERIFY(std::find(picked.begin(), picked.end(), g.strokes[head].id) != picked.end());
    for (model::Id id : picked)
        QVERIFY2(id == g.strokes[head].id || qAlpha(findStroke(*m_doc, id)->data->color) == 0,
                 "an inked line other than the head was picked");
    dragCanvas(m_canvas.get(), box.center(), box.center() + QPointF(40, 0), 5);
    const QImage moved = framePicture(*m_doc, 0, view, 480);
    QVERIFY2(sameColour(moved.pixel(view.map(belly).toPoint()), bodyColour),
             qPrintable(QStringLiteral("the body shows %1, not %2")
                            .arg(moved.pixel(view.map(belly).toPoint()), 0, 16)
                            .arg(bodyColour, 0, 16)));
    // A lasso round the whole figure takes every line, of ink or not: moved, the figure shows
    // as it did, moved.
    m_doc->undoStack()->undo();
    m_state->setSelectedStrokes({});
    const QRectF whole = all.adjusted(-20, -20, 20, 20);
    drag(m_canvas.get(),
         {m_canvas->mapFromCanvas(whole.topLeft()), m_canvas->mapFromCanvas(whole.topRight()),
          m_canvas->mapFromCanvas(whole.bottomRight()), m_canvas->mapFromCanvas(whole.bottomLeft()),
          m_canvas->mapFromCanvas(whole.topLeft() + QPointF(0, 1))});
    QCOMPARE(m_state->selectedStrokes().size(), g.strokes.size());
    // (By a whole number of the picture's pixels, so the two pictures' edges match.)
    const double dx = std::round(30.0 * view.m11()) / view.m11();
    dragCanvas(m_canvas.get(), belly, belly + QPointF(dx, 0), 5);
    const QImage shifted = framePicture(*m_doc, 0, QTransform(view).translate(-dx, 0), 480);
    const PictureAgreement same = comparePictures(before, shifted);
    QVERIFY2(same.agreePct > 99.5, qPrintable(QString::number(same.agreePct)));
}

// After Apply Pose, the arms raised behind the head are cut at its outline, their tops kept
// hidden. Moved off (or deleted), the head no longer covers them: the tops show again
// (uncovered_lines.h) and the arms keep their fills; the rest of the figure is as it was.
void TestTools::aHeadMovedOffTheArmsShowsTheirTops()
{
    std::size_t head = 0;
    QRectF box;
    QVERIFY(openApplyPoseHead(head, box));
    // An empty object for Object → Move To (added first: the figure's object is held below).
    model::StrokeGroup other;
    other.id = m_doc->allocateId();
    other.name = QStringLiteral("Head");
    const model::Id headObject = other.id;
    m_doc->insertGroup(m_doc->frameAt(0).id, 1, std::move(other));
    const model::StrokeGroup &g = m_doc->frameAt(0).groups.front();
    using namespace finbook::testing;
    const std::vector<model::Stroke> strokes = g.strokes;
    const std::vector<model::Fill> fills = g.fills;
    const auto fillsShown = [&] {
        const auto regions = model::objectRegions(g, m_doc->settings().closeGap);
        std::vector<int> owners = model::faceFills(*regions, g.fills);
        std::sort(owners.begin(), owners.end());
        owners.erase(std::unique(owners.begin(), owners.end()), owners.end());
        owners.erase(std::remove(owners.begin(), owners.end(), -1), owners.end());
        return owners;
    };
    const std::vector<int> shownBefore = fillsShown();
    QVERIFY(shownBefore.size() >= 4);           // body, head, both arms
    std::vector<int> withoutHead = shownBefore; // once the head is deleted
    {
        const auto regions = model::objectRegions(g, m_doc->settings().closeGap);
        const int face = regions->faceAt(box.center());
        QVERIFY(face >= 0);
        const int headFill = model::faceFills(*regions, g.fills).at(std::size_t(face));
        QVERIFY(headFill >= 0);
        withoutHead.erase(std::find(withoutHead.begin(), withoutHead.end(), headFill));
    }
    const QRectF all = shownBounds(g);
    const QTransform view = pictureView(all.adjusted(-40, -40, 3 * box.width(), 40), 480);
    const QImage before = framePicture(*m_doc, 0, view, 480);
    const auto hiddenLength = [](const std::vector<model::Stroke> &lines) { // canvas px
        double length = 0.0;
        for (const model::Stroke &s : lines)
            if (s.data->color == model::kHiddenLineColor)
                for (std::size_t i = 0; i + 1 < s.data->points.size(); ++i)
                    length += std::hypot(s.data->points[i + 1].x - s.data->points[i].x,
                                         s.data->points[i + 1].y - s.data->points[i].y);
        return length;
    };
    const double hiddenBefore = hiddenLength(strokes);
    const QPointF by(2.2 * box.width(), 0);
    enum class Edit { Move, Delete, Erase, ToObject };
    for (const Edit edit : {Edit::Move, Edit::Delete, Edit::Erase, Edit::ToObject}) {
        const bool deleteIt = edit != Edit::Move;
        if (edit == Edit::Erase) { // a rub across the top of the head's outline
            m_canvas->setCurrentTool(QStringLiteral("tool.eraser"));
            dragCanvas(m_canvas.get(), QPointF(box.center().x() - 4, box.top()),
                       QPointF(box.center().x() + 4, box.top()), 2);
        } else if (edit == Edit::ToObject) { // Object → Move To: the head an object of its own
            lassoRound(box);
            m_state->setCurrentGroupId(g.id);
            ui::ObjectActions(m_state.get()).moveSelectionTo(headObject);
        } else {
            lassoRound(box);
            if (deleteIt)
                QVERIFY(ui::StrokeEditing::deleteSelection(*m_state));
            else
                dragCanvas(m_canvas.get(), box.center(), box.center() + by, 5);
        }
        QVERIFY(std::none_of(g.strokes.begin(), g.strokes.end(), [&](const model::Stroke &s) {
            return deleteIt && s.id == strokes[head].id;
        }));
        QCOMPARE(fillsShown(), deleteIt ? withoutHead : shownBefore);
        // The arms' tops: two lines at least the head's width long in all.
        QVERIFY2(hiddenLength(g.strokes) < hiddenBefore - box.width(),
                 qPrintable(QStringLiteral("%1 of %2 px hidden")
                                .arg(hiddenLength(g.strokes))
                                .arg(hiddenBefore)));
        // Away from where the head was and is, the figure shows as it did.
        const QImage after = framePicture(*m_doc, 0, view, 480);
        const QRect was = view.mapRect(box.adjusted(-4, -4, 4, 4)).toAlignedRect();
        const QRect now =
            view.mapRect(box.translated(edit == Edit::Move ? by : QPointF()).adjusted(-4, -4, 4, 4))
                .toAlignedRect();
        long long compared = 0, differ = 0;
        for (int y = 0; y < before.height(); ++y)
            for (int x = 0; x < before.width(); ++x)
                if (!was.contains(x, y) && !now.contains(x, y) &&
                    before.pixel(x, y) != qRgb(255, 255, 255)) {
                    ++compared;
                    differ += !sameColour(before.pixel(x, y), after.pixel(x, y));
                }
        QVERIFY(compared > 1000);
        QVERIFY2(differ * 200 <= compared,
                 qPrintable(QStringLiteral("%1 of %2 px changed").arg(differ).arg(compared)));
        m_doc->undoStack()->undo();
        QCOMPARE(g.strokes, strokes);
        QCOMPARE(g.fills, fills);
        m_state->setSelectedStrokes({});
    }
}

void TestTools::copyPasteIntoAnotherFrame()
{
    const model::Id a = addStroke(*m_doc, group(0), line({60, 60}, {140, 90}, 20, 0xffd03030));
    m_state->setSelectedStrokes({a});
    QVERIFY(ui::StrokeEditing::copySelection(*m_state));
    QVERIFY(ui::StrokeEditing::clipboardHasStrokes());
    m_state->setCurrentFrameIndex(1);
    QVERIFY(ui::StrokeEditing::paste(*m_state));
    QCOMPARE(strokeCount(1), 1);
    const model::Stroke &pasted = m_doc->frameAt(1).groups[0].strokes[0];
    QVERIFY(pasted.id != a);
    QCOMPARE(*pasted.data, *findStroke(*m_doc, a)->data);
    QCOMPARE(m_state->selectedStrokes(), std::vector<model::Id>{pasted.id});
    m_doc->undoStack()->undo();
    QCOMPARE(strokeCount(1), 0);
    QCOMPARE(strokeCount(0), 1);
}

void TestTools::selectAllSkipsLockedObjects()
{
    resetDocument(*m_doc, 1, 2);
    const model::Id a = addStroke(*m_doc, group(0, 0), line({60, 60}, {140, 90}));
    addStroke(*m_doc, group(0, 1), line({60, 160}, {140, 190}));
    m_doc->undoStack()->push(
        new model::SetObjectFlagCommand(m_doc.get(), group(0, 1), model::ObjectFlag::Locked, true));
    ui::StrokeEditing::selectAll(*m_state);
    QCOMPARE(m_state->selectedStrokes(), std::vector<model::Id>{a});
}

void TestTools::clipboardRefusesMalformedData()
{
    const QByteArray good = ui::encodeStrokes({line({0, 0}, {10, 10})});
    QVERIFY(ui::decodeStrokes(good).has_value());
    QVERIFY(!ui::decodeStrokes(good.left(good.size() - 3)).has_value());
    QVERIFY(!ui::decodeStrokes(QByteArray("garbage")).has_value());
    QByteArray huge = good;
    huge[8] = char(0x7f); // stroke count far beyond the bytes
    QVERIFY(!ui::decodeStrokes(huge).has_value());

    // Fills travel after the strokes (version 2) and come back as they went.
    const std::vector<ui::ClipboardFill> fills{{0xffd03030, QPointF(5, 2.5)},
                                               {0x80102030, QPointF(-1e6, 1e-3)}};
    const QByteArray filled = ui::encodeStrokes({line({0, 0}, {10, 10})}, fills);
    const auto back = ui::decodeStrokes(filled);
    QVERIFY(back.has_value());
    QCOMPARE(back->strokes.size(), std::size_t(1));
    QVERIFY(back->fills == fills);
    QVERIFY(!ui::decodeStrokes(filled.left(filled.size() - 1)).has_value());
    QByteArray manyFills = filled;
    manyFills[good.size() - 4] = char(0x7f); // the fill count, far beyond the bytes
    QVERIFY(!ui::decodeStrokes(manyFills).has_value());
    QByteArray notFinite = filled;
    quint64 nan = 0;
    const double value = std::nan("");
    std::memcpy(&nan, &value, 8);
    nan = qToBigEndian(nan);                                  // QDataStream's byte order
    std::memcpy(notFinite.data() + good.size() + 4, &nan, 8); // the first seed's x
    QVERIFY(!ui::decodeStrokes(notFinite).has_value());
    // Version 1 (a Finbook of before fills on the clipboard): strokes, no fill count.
    QByteArray version1 = good.left(good.size() - 4);
    version1[7] = char(1);
    const auto old = ui::decodeStrokes(version1);
    QVERIFY(old.has_value() && old->strokes.size() == 1 && old->fills.empty());
}

void TestTools::handToolPans()
{
    m_canvas->setCurrentTool(QStringLiteral("tool.hand"));
    const QPointF before = m_canvas->mapFromCanvas({0, 0});
    drag(m_canvas.get(), {QPointF(300, 300), QPointF(320, 310), QPointF(340, 330)});
    QCOMPARE(m_canvas->mapFromCanvas({0, 0}), before + QPointF(40, 30));
    QCOMPARE(strokeCount(0), 0);
}

QTEST_MAIN(TestTools)
#include "tst_tools.moc"
