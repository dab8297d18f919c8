// The eraser that cuts, driven by real mouse events on a real canvas: a rub takes the part of a
// line under it and leaves pieces with the stroke's colour, width and pressure; one rub is one
// undo step that undoes exactly; a posed object has its pose applied first, in the same step;
// rigs stay valid.
#include "cut_out_character.h"
#include "tst_tools_support.h"

#include <finbook/model/cage/cage_commands.h>
#include <finbook/model/cage/cage_setup.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/pins/pin_commands.h>
#include <finbook/ui/tools/tool_eraser.h>
#include <finbook/ui/window/editor_state.h>

#include <QPainter>
#include <QtTest>

#include <cmath>

using namespace finbook;
using namespace finbook::test;

namespace {
// A line with pressure falling from 1 to 0.5, colour and width of its own.
model::StrokeDataPtr taperedLine(QPointF a, QPointF b, int n = 61)
{
    auto s = std::make_shared<model::StrokeData>();
    for (int i = 0; i < n; ++i) {
        const qreal f = qreal(i) / (n - 1);
        const QPointF p = a + (b - a) * f;
        s->points.push_back({float(p.x()), float(p.y()), float(1.0 - 0.5 * f)});
    }
    s->color = 0xff3060d0;
    s->width = 4.0f;
    return s;
}
} // namespace

class TestEraser : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();
    void cutsInTheMiddle();
    void cutsAtAnEnd();
    void cutsAcrossSeveralStrokes();
    void cutsAPosedObjectAsShown();
    void cutsACutOutPoseOnItsBakedLines();
    void shiftAndWholeStrokesModeTakeWholeStrokes();
    void aMissLeavesNoUndoStep();
    void rigsStayValid();
    void sizeIsClampedAndShownOnTheCanvas();

private:
    model::Id group(int index = 0) const { return m_doc->frameAt(0).groups[std::size_t(index)].id; }
    const std::vector<model::Stroke> &strokes(int index = 0) const
    {
        return m_doc->frameAt(0).groups[std::size_t(index)].strokes;
    }
    ui::EraserTool *eraser() const
    {
        return static_cast<ui::EraserTool *>(m_canvas->tool(QStringLiteral("tool.eraser")));
    }
    // Erasing must be one undo step that gives back exactly the document it started from.
    void checkOneStepUndoesExactly(const QByteArray &before, int steps)
    {
        QCOMPARE(m_doc->undoStack()->count(), steps + 1);
        QCOMPARE(m_doc->undoStack()->text(steps), QStringLiteral("Erase"));
        const QByteArray after = model::serializeFinbook(*m_doc);
        m_doc->undoStack()->undo();
        QCOMPARE(model::serializeFinbook(*m_doc), before);
        m_doc->undoStack()->redo();
        QCOMPARE(model::serializeFinbook(*m_doc), after);
    }

    std::unique_ptr<model::Document> m_doc;
    std::unique_ptr<ui::EditorState> m_state;
    std::unique_ptr<ui::CanvasWidget> m_canvas;
};

void TestEraser::init()
{
    m_doc = std::make_unique<model::Document>();
    resetDocument(*m_doc, 1);
    m_state = std::make_unique<ui::EditorState>(m_doc.get());
    m_canvas = std::make_unique<ui::CanvasWidget>(m_state.get());
    m_canvas->addTool(std::make_unique<ui::EraserTool>());
    m_canvas->resize(600, 500);
    m_canvas->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_canvas.get()));
    m_canvas->actualSize();
    eraser()->setSize(10);
}

void TestEraser::cleanup()
{
    m_canvas.reset();
    m_state.reset();
    m_doc.reset();
}

void TestEraser::cutsInTheMiddle()
{
    QCOMPARE(eraser()->mode(), ui::EraserMode::Cut); // the default
    addStroke(*m_doc, group(), taperedLine({50, 100}, {350, 100}));
    const QByteArray before = model::serializeFinbook(*m_doc);
    const int steps = m_doc->undoStack()->count();
    dragCanvas(m_canvas.get(), {200, 60}, {200, 140});
    QCOMPARE(strokes().size(), std::size_t(2));
    const model::StrokeData &left = *strokes()[0].data, &right = *strokes()[1].data;
    for (const model::StrokeData *piece : {&left, &right}) {
        QCOMPARE(piece->color, QRgb(0xff3060d0));
        QCOMPARE(piece->width, 4.0f);
    }
    // The cut ends where the drawn edge (half width × pressure) meets the eraser's edge.
    QCOMPARE(left.points.front().x, 50.0f);
    QCOMPARE(right.points.back().x, 350.0f);
    const float leftEnd = left.points.back().x, rightStart = right.points.front().x;
    QVERIFY2(leftEnd > 192.5f && leftEnd < 194.0f, qPrintable(QString::number(leftEnd)));
    QVERIFY2(rightStart > 206.0f && rightStart < 207.5f, qPrintable(QString::number(rightStart)));
    // Pressure runs on from where it was: 1 at the left end, 0.5 at the right.
    QCOMPARE(left.points.front().pressure, 1.0f);
    QVERIFY(std::abs(left.points.back().pressure - (1.0f - 0.5f * (leftEnd - 50) / 300)) < 1e-4f);
    QCOMPARE(right.points.back().pressure, 0.5f);
    checkOneStepUndoesExactly(before, steps);
}

void TestEraser::cutsAtAnEnd()
{
    addStroke(*m_doc, group(), taperedLine({50, 100}, {350, 100}));
    const QByteArray before = model::serializeFinbook(*m_doc);
    const int steps = m_doc->undoStack()->count();
    // 4 px from the end: the eraser (radius 5) and the drawn edge (half width 2) reach 53.
    dragCanvas(m_canvas.get(), {46, 60}, {46, 140});
    QCOMPARE(strokes().size(), std::size_t(1));
    const model::StrokeData &rest = *strokes()[0].data;
    QVERIFY2(rest.points.front().x > 52.5f && rest.points.front().x < 53.5f,
             qPrintable(QString::number(rest.points.front().x)));
    QCOMPARE(rest.points.back().x, 350.0f);
    checkOneStepUndoesExactly(before, steps);
}

void TestEraser::cutsAcrossSeveralStrokes()
{
    for (int y : {100, 130, 160})
        addStroke(*m_doc, group(), taperedLine({50, qreal(y)}, {350, qreal(y)}));
    const QByteArray before = model::serializeFinbook(*m_doc);
    const int steps = m_doc->undoStack()->count();
    // A rub that turns: across all three at x = 150, back up to the top line's right part.
    std::vector<QPointF> rub;
    for (QPointF p : {QPointF(150, 80), QPointF(150, 180), QPointF(300, 90)})
        rub.push_back(m_canvas->mapFromCanvas(p));
    std::vector<QPointF> dense;
    for (std::size_t i = 0; i + 1 < rub.size(); ++i)
        for (int k = 0; k < 20; ++k)
            dense.push_back(rub[i] + (rub[i + 1] - rub[i]) * (k / 20.0));
    dense.push_back(rub.back());
    drag(m_canvas.get(), dense);
    // The vertical pass cuts each line once; the slanted return crosses the middle and bottom
    // lines again and ends on the top one: 3 + 2 + 1 cuts, each adding one piece.
    QCOMPARE(strokes().size(), std::size_t(3 + 6));
    for (const model::Stroke &s : strokes())
        QVERIFY(s.data->points.size() >= 2);
    checkOneStepUndoesExactly(before, steps);
}

void TestEraser::cutsAPosedObjectAsShown()
{
    addStroke(*m_doc, group(), taperedLine({50, 100}, {350, 100}));
    // Two pins moved down by 50: the pose is the drawing translated (what the solver gives).
    const model::Id g = group();
    QUndoStack *stack = m_doc->undoStack();
    model::Rig rig;
    rig.pins = {{m_doc->allocateId(), {50, 100}, {50, 150}},
                {m_doc->allocateId(), {350, 100}, {350, 150}}};
    m_doc->setRig(g, rig);
    auto posed = std::make_shared<model::DeformedStrokes>();
    std::vector<model::StrokePoint> moved = strokes()[0].data->points;
    for (model::StrokePoint &p : moved)
        p.y += 50;
    posed->strokes = {moved};
    m_doc->setDeformed(g, posed);
    stack->clear();
    const QByteArray before = model::serializeFinbook(*m_doc);
    // Rub across the rest drawing (y = 100): nothing is shown there, nothing happens.
    dragCanvas(m_canvas.get(), {200, 80}, {200, 120});
    QCOMPARE(stack->count(), 0);
    dragCanvas(m_canvas.get(), {200, 130}, {200, 170});
    QCOMPARE(strokes().size(), std::size_t(2));
    // The pieces are where the posed line was shown, and the rig is rebased on them.
    for (const model::Stroke &s : strokes())
        for (const model::StrokePoint &p : s.data->points)
            QCOMPARE(p.y, 150.0f);
    const model::StrokeGroup &after = m_doc->frameAt(0).groups[0];
    QCOMPARE(after.rig.pins.size(), std::size_t(2));
    QVERIFY(!after.rig.isPosed());
    QCOMPARE(after.rig.pins[0].rest, QPointF(50, 150));
    checkOneStepUndoesExactly(before, 0);
    stack->undo();
    QVERIFY(m_doc->frameAt(0).groups[0].rig.isPosed());
}

// Issue 45's walkthrough: a rub across a cut-out arm at its elbow emptied the arm's fill. The
// rub was worked out on the posed line, then the pose was applied: the cut-out bake splits the
// arm's outline into the parts its pieces showed (the first keeps the line's id) and the parts
// a piece hid, so the whole posed outline came back, cut, beside those parts: the arm drawn
// twice and its fill gone. The cuts are now worked out on the baked strokes.
void TestEraser::cutsACutOutPoseOnItsBakedLines()
{
    using namespace finbook::testing;
    const model::Id g = group();
    QUndoStack *stack = m_doc->undoStack();
    const auto arm = poseCutOutCharacter(*m_doc, g);
    QVERIFY(arm);
    const QPointF at = arm->elbow, across = arm->across.p2() - arm->elbow;
    const QTransform view =
        pictureView(shownBounds(*m_doc->group(g)).adjusted(-40, -40, 40, 40), 480);
    const QImage before = framePicture(*m_doc, 0, view, 480);
    const QByteArray bytes = model::serializeFinbook(*m_doc);
    dragCanvas(m_canvas.get(), at - across, at + across);
    QCOMPARE(stack->count(), 1);
    QVERIFY(!m_doc->group(g)->rig.isPosed());
    QCOMPARE(doubledLines(*m_doc->group(g)), 0); // no line drawn twice
    // Outside the rub, the picture is the posed one: the arm keeps its colour.
    QImage rubbed(480, 480, QImage::Format_ARGB32_Premultiplied);
    rubbed.fill(Qt::transparent);
    {
        QPainter painter(&rubbed);
        painter.setTransform(view);
        painter.setPen(QPen(Qt::black, eraser()->size() + 14, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(at - across, at + across);
    }
    const PictureAgreement agreement =
        comparePictures(before, framePicture(*m_doc, 0, view, 480), &rubbed);
    QVERIFY2(agreement.agreePct >= 99.5, qPrintable(QString::number(agreement.agreePct)));
    checkOneStepUndoesExactly(bytes, 0);
}

void TestEraser::shiftAndWholeStrokesModeTakeWholeStrokes()
{
    const model::Id a = addStroke(*m_doc, group(), taperedLine({50, 100}, {350, 100}));
    const model::Id b = addStroke(*m_doc, group(), taperedLine({50, 200}, {350, 200}));
    dragCanvas(m_canvas.get(), {200, 60}, {200, 140}, 4.0, Qt::ShiftModifier);
    QVERIFY(!findStroke(*m_doc, a));
    QCOMPARE(strokes().size(), std::size_t(1));
    eraser()->setMode(ui::EraserMode::WholeStrokes);
    dragCanvas(m_canvas.get(), {200, 160}, {200, 240});
    QVERIFY(!findStroke(*m_doc, b));
    QVERIFY(strokes().empty());
    // Shift in Whole Strokes mode cuts.
    addStroke(*m_doc, group(), taperedLine({50, 100}, {350, 100}));
    dragCanvas(m_canvas.get(), {200, 60}, {200, 140}, 4.0, Qt::ShiftModifier);
    QCOMPARE(strokes().size(), std::size_t(2));
}

void TestEraser::aMissLeavesNoUndoStep()
{
    addStroke(*m_doc, group(), taperedLine({50, 100}, {350, 100}));
    const int steps = m_doc->undoStack()->count();
    dragCanvas(m_canvas.get(), {50, 250}, {350, 250});
    QCOMPARE(m_doc->undoStack()->count(), steps);
    QCOMPARE(strokes().size(), std::size_t(1));
}

void TestEraser::rigsStayValid()
{
    resetDocument(*m_doc, 1, 2);
    const model::Id caged = group(0), pinned = group(1);
    addStroke(*m_doc, caged, taperedLine({50, 100}, {350, 100}));
    addStroke(*m_doc, caged, taperedLine({50, 120}, {350, 120}));
    addStroke(*m_doc, pinned, taperedLine({100, 300}, {140, 300}, 9));
    QUndoStack *stack = m_doc->undoStack();
    const std::vector<QPointF> cage{{30, 80}, {370, 80}, {370, 140}, {30, 140}};
    stack->push(new model::PlaceCageCommand(m_doc.get(), caged, cage));
    stack->push(new model::AddPinCommand(m_doc.get(), pinned, {120, 300}, {120, 300}));
    // Cut through both lines of the caged object: the cage still encloses it and is the same.
    dragCanvas(m_canvas.get(), {200, 90}, {200, 130});
    const model::StrokeGroup *c = m_doc->group(caged);
    QCOMPARE(c->strokes.size(), std::size_t(4));
    QCOMPARE(c->rig.cage.rest, cage);
    QVERIFY(!model::cageProblem(*c, c->rig.cage.rest));
    // Erase the pinned object entirely: no pin is left around nothing, and undo brings it back.
    const QByteArray before = model::serializeFinbook(*m_doc);
    const int steps = stack->count();
    eraser()->setSize(60);
    dragCanvas(m_canvas.get(), {90, 300}, {150, 300});
    QVERIFY(m_doc->group(pinned)->strokes.empty());
    QVERIFY(m_doc->group(pinned)->rig.empty());
    checkOneStepUndoesExactly(before, steps);
    stack->undo();
    QCOMPARE(m_doc->group(pinned)->rig.pins.size(), std::size_t(1));
}

void TestEraser::sizeIsClampedAndShownOnTheCanvas()
{
    eraser()->setSize(1e9);
    QCOMPARE(eraser()->size(), ui::EraserTool::kMaxSize);
    eraser()->setSize(std::nan(""));
    QCOMPARE(eraser()->size(), ui::EraserTool::kMaxSize);
    eraser()->setSize(40);
    m_canvas->setZoom(2.0, QPointF(0, 0));
    // The cursor ring is the eraser on the canvas: 40 px at 200 % is 80 screen px across.
    const QPointF centre(300, 250); // the middle of the widget
    ui::ToolEvent hover;
    hover.pos = m_canvas->mapToCanvas(centre);
    hover.widgetPos = centre;
    eraser()->hover(hover);
    QImage shot(m_canvas->size(), QImage::Format_ARGB32);
    shot.fill(Qt::white);
    // The ring shows while the mouse is over the canvas, which no real mouse is here.
    m_canvas->setAttribute(Qt::WA_UnderMouse, true);
    QPainter painter(&shot);
    eraser()->paintOverlay(painter, m_canvas->canvasToWidget());
    painter.end();
    // The ring is antialiased: some pixel within a pixel or two of 40 is clearly grey.
    const auto dark = [&shot](QPointF p) { return qGray(shot.pixel(p.toPoint())) < 200; };
    bool ring = false;
    for (int dx = 38; dx <= 42; ++dx)
        ring = ring || dark(centre + QPointF(dx, 0));
    QVERIFY(ring);
    QVERIFY(!dark(centre + QPointF(20, 0)));
    QVERIFY(!dark(centre + QPointF(60, 0)));
}

QTEST_MAIN(TestEraser)
#include "tst_eraser.moc"
