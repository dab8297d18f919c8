// Paste never hides: through the Edit menu's action it lands offset from the original (one
// more step for each copy already there), in another frame in place; with Ctrl+V and the
// mouse over the canvas it lands under the mouse. The pasted strokes are selected, with the
// select tool's box around them. Fills whose region the copied strokes bound travel with
// them, and the paste with its fills is one undo step.
#include "tst_window_support.h"

#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/finbook_file.h>
#include <finbook/ui/canvas/canvas_tool.h>
#include <finbook/ui/tools/stroke_editing.h>
#include <finbook/ui/window/editor_state.h>

#include <QtTest>

#include <limits>

using namespace finbook;
using namespace finbook::test;

namespace {
QRectF boundsOf(const model::StrokeData &data)
{
    QPolygonF points;
    for (const model::StrokePoint &p : data.points)
        points << QPointF(p.x, p.y);
    return points.boundingRect();
}
} // namespace

class TestPaste : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { m_settings = std::make_unique<IsolatedSettings>(); }
    void init();
    void cleanup() { m_window.reset(); }

    void menuPasteLandsOffsetAndSelected();
    void pasteIntoAnotherFrameKeepsRegister();
    void ctrlVOverTheCanvasLandsAtTheMouse();
    void fillsTravelWithTheStrokesAroundThem();
    void pasteAcceptsOnlyWhatAFileCanHold();

private:
    ui::EditorState *state() const { return m_window->editorState(); }
    model::Document *doc() const { return m_window->document(); }
    // The one selected stroke (the paste's), or null.
    const model::Stroke *pasted() const
    {
        const auto &ids = state()->selectedStrokes();
        return ids.size() == 1 ? findStroke(*doc(), ids.front()) : nullptr;
    }
    void copyOriginal()
    {
        state()->setSelectedStrokes({m_original});
        m_window->action(QStringLiteral("edit.copy"))->trigger();
        QVERIFY(m_window->action(QStringLiteral("edit.paste"))->isEnabled());
    }
    void mouseAway()
    {
        QEvent leave(QEvent::Leave);
        QApplication::sendEvent(m_window->canvas(), &leave);
    }

    std::unique_ptr<IsolatedSettings> m_settings;
    std::unique_ptr<ui::MainWindow> m_window;
    model::Id m_original = model::kNoId;
};

void TestPaste::init()
{
    m_window = std::make_unique<ui::MainWindow>();
    resetDocument(*doc(), 2);
    m_original = addStroke(*doc(), doc()->frameAt(0).groups[0].id, line({100, 100}, {180, 140}));
    doc()->undoStack()->clear();
    QVERIFY(showActive(*m_window));
    m_window->canvas()->setCurrentTool(QStringLiteral("tool.pen"));
    m_window->canvas()->setFocus();
}

void TestPaste::menuPasteLandsOffsetAndSelected()
{
    copyOriginal();
    mouseAway();
    const model::StrokeData &original = *findStroke(*doc(), m_original)->data;
    QAction *paste = m_window->action(QStringLiteral("edit.paste"));
    for (int copy = 1; copy <= 2; ++copy) {
        paste->trigger();
        const model::Stroke *stroke = pasted();
        QVERIFY(stroke);
        QVERIFY(stroke->id != m_original);
        const QPointF offset = boundsOf(*stroke->data).topLeft() - boundsOf(original).topLeft();
        const qreal step = ui::StrokeEditing::kPasteStep;
        QVERIFY2(QLineF(offset, QPointF(step, step) * copy).length() < 1e-3,
                 qPrintable(QStringLiteral("copy %1 moved by %2, %3")
                                .arg(copy)
                                .arg(offset.x())
                                .arg(offset.y())));
        QCOMPARE(stroke->data->color, original.color);
        QCOMPARE(stroke->data->points.size(), original.points.size());
        QCOMPARE(m_window->canvas()->currentTool()->id(), QStringLiteral("tool.select"));
        QCOMPARE(doc()->undoStack()->count(), copy); // one undo step each
    }
    doc()->undoStack()->undo();
    doc()->undoStack()->undo();
    QCOMPARE(doc()->frameAt(0).groups[0].strokes.size(), std::size_t(1));
}

void TestPaste::pasteIntoAnotherFrameKeepsRegister()
{
    copyOriginal();
    mouseAway();
    state()->setCurrentFrameIndex(1);
    m_window->action(QStringLiteral("edit.paste"))->trigger();
    const model::Stroke *stroke = pasted();
    QVERIFY(stroke);
    QCOMPARE(stroke->data->points, findStroke(*doc(), m_original)->data->points);
    QCOMPARE(doc()->locateStroke(stroke->id).frame, 1);
}

void TestPaste::ctrlVOverTheCanvasLandsAtTheMouse()
{
    copyOriginal();
    ui::CanvasWidget *canvas = m_window->canvas();
    const QPointF target(300, 220); // canvas pixels
    sendMouse(canvas, QEvent::MouseMove, canvas->mapFromCanvas(target), Qt::NoButton, Qt::NoButton);
    typeKey(Qt::Key_V, Qt::ControlModifier);
    const model::Stroke *stroke = pasted();
    QVERIFY(stroke);
    QVERIFY(QLineF(boundsOf(*stroke->data).center(), target).length() < 1e-3);
    QCOMPARE(m_window->canvas()->currentTool()->id(), QStringLiteral("tool.select"));
}

void TestPaste::fillsTravelWithTheStrokesAroundThem()
{
    // A closed square (one stroke) filled red, and a line beside it, in frame 1.
    const model::Id group = doc()->frameAt(0).groups[0].id;
    auto square = std::make_shared<model::StrokeData>();
    const QPointF corners[] = {{300, 100}, {400, 100}, {400, 200}, {300, 200}, {300, 100}};
    for (int side = 0; side < 4; ++side)
        for (int k = 0; k < 10; ++k) {
            const QPointF p = corners[side] + (corners[side + 1] - corners[side]) * (k / 10.0);
            square->points.push_back({float(p.x()), float(p.y()), 1.0f});
        }
    square->points.push_back(square->points.front());
    const model::Id box = addStroke(*doc(), group, square);
    doc()->undoStack()->push(
        model::fillRegionCommand(doc(), group, QPointF(350, 150), 0xffd03030).release());
    QCOMPARE(doc()->frameAt(0).groups[0].fills.size(), std::size_t(1));

    // Copying the line alone carries no fill; copying the square carries its fill.
    state()->setSelectedStrokes({m_original});
    QVERIFY(ui::StrokeEditing::selectedFills(*state()).empty());
    state()->setSelectedStrokes({m_original, box});
    QCOMPARE(ui::StrokeEditing::selectedFills(*state()).size(), std::size_t(1));
    m_window->action(QStringLiteral("edit.copy"))->trigger();

    // Into frame 2, in place: the square comes back filled, bounded by the pasted stroke.
    mouseAway();
    state()->setCurrentFrameIndex(1);
    const int steps = doc()->undoStack()->count();
    m_window->action(QStringLiteral("edit.paste"))->trigger();
    QCOMPARE(doc()->undoStack()->count(), steps + 1);
    const model::StrokeGroup &target = doc()->frameAt(1).groups[0];
    QCOMPARE(target.strokes.size(), std::size_t(2));
    QCOMPARE(target.fills.size(), std::size_t(1));
    QCOMPARE(target.fills[0].color, QRgb(0xffd03030));
    const QPointF seed = doc()->frameAt(0).groups[0].fills[0].seed; // inside, near the click
    QCOMPARE(target.fills[0].seed, seed);
    QCOMPARE(target.fills[0].strokes, std::vector<model::Id>{target.strokes[1].id});

    // In the same frame, under the mouse below the original: so does its fill.
    state()->setCurrentFrameIndex(0);
    QVERIFY(ui::StrokeEditing::paste(*state(), nullptr, QPointF(250, 450))); // bounds' centre
    const model::StrokeGroup &same = doc()->frameAt(0).groups[0];
    QCOMPARE(same.fills.size(), std::size_t(2));
    QCOMPARE(same.fills[1].seed, seed + QPointF(0, 300));
    QCOMPARE(same.fills[1].strokes, std::vector<model::Id>{same.strokes.back().id});

    // One undo takes the strokes and the fill away together, exactly.
    doc()->undoStack()->undo();
    QCOMPARE(doc()->frameAt(0).groups[0].fills.size(), std::size_t(1));
    QCOMPARE(doc()->frameAt(0).groups[0].strokes.size(), std::size_t(2));
    doc()->undoStack()->undo();
    QVERIFY(doc()->frameAt(1).groups[0].fills.empty());
    QVERIFY(doc()->frameAt(1).groups[0].strokes.empty());
}

// Issue 54, item 3: clipboard strokes of width 0, 1e6 or 1e30 were pasted, and every save after
// failed. Paste reads as a file does: what it accepts, a file holds.
void TestPaste::pasteAcceptsOnlyWhatAFileCanHold()
{
    const auto stroke = [](float width) {
        auto s = std::make_shared<model::StrokeData>();
        s->points = {{10, 10, 1}, {60, 40, 0.5f}};
        s->width = width;
        return s;
    };
    for (float bad : {0.0f, -1.0f, 1e6f, 1e30f, std::numeric_limits<float>::quiet_NaN(),
                      std::numeric_limits<float>::infinity()})
        QVERIFY2(!ui::decodeStrokes(ui::encodeStrokes({stroke(bad)}, {})),
                 qPrintable(QString::number(bad)));
    for (float good : {0.01f, 3.0f, model::kMaxStrokeWidth}) {
        const auto clip = ui::decodeStrokes(ui::encodeStrokes({stroke(good)}, {}));
        QVERIFY(clip && clip->strokes.size() == 1);
        model::Document pasted;
        pasted.undoStack()->push(new model::InsertFrameCommand(&pasted, 0));
        pasted.undoStack()->push(new model::AddStrokeCommand(
            &pasted, pasted.frameAt(0).groups.at(0).id, clip->strokes.front()));
        const auto reread = model::readFinbook(model::serializeFinbook(pasted));
        QVERIFY2(reread, qPrintable(QString::number(good)));
    }
}

QTEST_MAIN(TestPaste)
#include "tst_paste.moc"
