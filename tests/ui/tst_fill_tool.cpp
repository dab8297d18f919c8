// The Fill tool driven by real mouse events on the real canvas and in the main window: fill,
// recolour, Shift-click and right-click remove, undo, the highlight, Fill All, Close gaps.
#include "tst_window_support.h"

#include <finbook/model/fill/fill_regions.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/fill/tool_fill.h>
#include <finbook/ui/tools/tool_pen.h>
#include <finbook/ui/window/editor_state.h>
#include <finbook/ui/window/main_window.h>

#include <QMenuBar>
#include <QSpinBox>
#include <QTest>

#include <cmath>

using namespace finbook;
using namespace finbook::model;
using namespace finbook::ui;

namespace {
// A stroke 4 px wide through `corners`, 40 points per side.
StrokeDataPtr through(const QPolygonF &corners)
{
    auto data = std::make_shared<StrokeData>();
    data->width = 4.0f;
    for (qsizetype i = 0; i + 1 < corners.size(); ++i)
        for (int k = 0; k < 40; ++k) {
            const QPointF p = corners[i] + (corners[i + 1] - corners[i]) * (k / 40.0);
            data->points.push_back({float(p.x()), float(p.y()), 1.0f});
        }
    data->points.push_back({float(corners.back().x()), float(corners.back().y()), 1.0f});
    return data;
}

// A square outline from (200, 150) to (400, 350), open by `gap` px on its right side.
StrokeDataPtr outline(double gap)
{
    return through({QPointF(400, 250 - gap / 2), QPointF(400, 150), QPointF(200, 150),
                    QPointF(200, 350), QPointF(400, 350), QPointF(400, 250 + gap / 2)});
}

// A mitten: the square's outline from (200, 350) up, over and down to (400, 350), left open
// along its whole bottom side, as a hand is drawn open at the wrist.
StrokeDataPtr mitten()
{
    return through({QPointF(200, 350), QPointF(200, 150), QPointF(400, 150), QPointF(400, 350)});
}

struct Fixture {
    Document doc;
    EditorState state{&doc};
    CanvasWidget canvas{&state};
    PenTool *pen = nullptr;
    FillTool *tool = nullptr;
    Id group = kNoId;

    explicit Fixture(double gap = 0.0, StrokeDataPtr drawn = nullptr)
    {
        Frame f;
        f.id = doc.allocateId();
        StrokeGroup g;
        g.id = doc.allocateId();
        g.strokes.push_back({doc.allocateId(), drawn ? drawn : outline(gap)});
        f.groups.push_back(g);
        group = g.id;
        DocumentSettings s;
        s.canvasSize = QSize(800, 600);
        doc.reset({f}, s, doc.nextId());
        pen = static_cast<PenTool *>(canvas.addTool(std::make_unique<PenTool>()));
        tool = static_cast<FillTool *>(canvas.addTool(std::make_unique<FillTool>(pen)));
        canvas.setCurrentTool(tool->id());
        canvas.resize(800, 600);
        canvas.show();
        canvas.fitToView();
    }

    QPoint at(QPointF canvasPos) const { return canvas.mapFromCanvas(canvasPos).toPoint(); }
    const StrokeGroup &object() const { return *doc.group(group); }
    void setColor(QColor c)
    {
        PenSettings s = pen->settings();
        s.color = c;
        pen->setSettings(s);
    }
    QRgb shownAt(QPointF canvasPos)
    {
        const QImage image = canvas.grab().toImage();
        const QPoint p = at(canvasPos) * image.devicePixelRatio();
        return image.pixel(p) | 0xff000000u;
    }
};
} // namespace

class TestFillTool : public QObject {
    Q_OBJECT
private slots:
    void clickFillsRecoloursAndRemoves();
    void rightClickRemoves();
    void hoverHighlightsTheRegion();
    void gapUnderTheSettingIsClosed();
    void openMouthIsClosedDashedAndFilled();
    void mainWindowHasToolMenuAndCloseGaps();
    void closeGapArrowsStartAtTheAutomaticGap();
};

void TestFillTool::clickFillsRecoloursAndRemoves()
{
    Fixture f;
    QCOMPARE(f.tool->defaultShortcut(), QKeySequence(Qt::Key_F));
    QVERIFY(!f.tool->icon().isNull());
    f.setColor(QColor(220, 40, 30));
    QTest::mouseClick(&f.canvas, Qt::LeftButton, {}, f.at(QPointF(300, 250)));
    QCOMPARE(f.object().fills.size(), std::size_t(1));
    QCOMPARE(f.object().fills[0].color, QColor(220, 40, 30).rgba());
    QCOMPARE(f.doc.undoStack()->count(), 1);
    QCOMPARE(f.shownAt(QPointF(300, 250)), QColor(220, 40, 30).rgb());
    QCOMPARE(f.shownAt(QPointF(500, 250)), 0xffffffffu); // outside stays paper
    // Another colour recolours the same fill.
    f.setColor(QColor(30, 60, 200));
    QTest::mouseClick(&f.canvas, Qt::LeftButton, {}, f.at(QPointF(250, 300)));
    QCOMPARE(f.object().fills.size(), std::size_t(1));
    QCOMPARE(f.object().fills[0].color, QColor(30, 60, 200).rgba());
    QCOMPARE(f.shownAt(QPointF(300, 250)), QColor(30, 60, 200).rgb());
    // Shift-click removes it.
    QTest::mouseClick(&f.canvas, Qt::LeftButton, Qt::ShiftModifier, f.at(QPointF(300, 250)));
    QVERIFY(f.object().fills.empty());
    // Only the light highlight of the region under the cursor is left.
    const QRgb removed = f.shownAt(QPointF(300, 250));
    QVERIFY(qRed(removed) > 150 && qGreen(removed) > 150);
    QCOMPARE(f.doc.undoStack()->count(), 3);
    f.doc.undoStack()->undo();
    QCOMPARE(f.object().fills.size(), std::size_t(1));
    QCOMPARE(f.shownAt(QPointF(300, 250)), QColor(30, 60, 200).rgb());
    // A click outside every region changes nothing.
    QTest::mouseClick(&f.canvas, Qt::LeftButton, {}, f.at(QPointF(600, 500)));
    QCOMPARE(f.doc.undoStack()->index(), 2);
}

void TestFillTool::rightClickRemoves()
{
    Fixture f;
    QTest::mouseClick(&f.canvas, Qt::LeftButton, {}, f.at(QPointF(300, 250)));
    QCOMPARE(f.object().fills.size(), std::size_t(1));
    QTest::mouseClick(&f.canvas, Qt::RightButton, {}, f.at(QPointF(300, 250)));
    QVERIFY(f.object().fills.empty());
}

void TestFillTool::hoverHighlightsTheRegion()
{
    Fixture f;
    const QRgb before = f.shownAt(QPointF(300, 250));
    test::sendMouse(&f.canvas, QEvent::MouseMove, f.at(QPointF(300, 250)), Qt::NoButton,
                    Qt::NoButton);
    const FillTool::Target target = f.tool->targetAt(QPointF(300, 250));
    QCOMPARE(target.groupId, f.group);
    QVERIFY(target.outline.boundingRect().contains(QRectF(210, 160, 180, 180)));
    QVERIFY(f.shownAt(QPointF(300, 250)) != before); // tinted before any click
    QVERIFY(f.object().fills.empty());
}

void TestFillTool::gapUnderTheSettingIsClosed()
{
    Fixture f(12.0); // an opening of 12 px
    QVERIFY(!objectRegions(f.object(), -1.0)->regions().closures.empty());
    QTest::mouseClick(&f.canvas, Qt::LeftButton, {}, f.at(QPointF(300, 250)));
    QCOMPARE(f.object().fills.size(), std::size_t(1));
}

void TestFillTool::openMouthIsClosedDashedAndFilled()
{
    Fixture f(0.0, mitten());
    const ObjectRegionsPtr regions = objectRegions(f.object(), -1.0);
    const auto &closures = regions->regions().closures;
    QCOMPARE(int(closures.size()), 1);
    QVERIFY(closures[0].mouth);
    // Shown dashed with the gap closers, across the whole mouth.
    const std::vector<QLineF> dashed = regions->displayedClosures(f.object());
    QCOMPARE(int(dashed.size()), 1);
    const QLineF mouth(QPointF(200, 350), QPointF(400, 350));
    QVERIFY((dashed[0].p1() - mouth.p1()).manhattanLength() +
                    (dashed[0].p2() - mouth.p2()).manhattanLength() <
                1e-3 ||
            (dashed[0].p1() - mouth.p2()).manhattanLength() +
                    (dashed[0].p2() - mouth.p1()).manhattanLength() <
                1e-3);
    f.setColor(QColor(30, 60, 200));
    QTest::mouseClick(&f.canvas, Qt::LeftButton, {}, f.at(QPointF(300, 320)));
    QCOMPARE(f.object().fills.size(), std::size_t(1));
    QCOMPARE(f.shownAt(QPointF(300, 320)), QColor(30, 60, 200).rgb());
    QVERIFY(f.shownAt(QPointF(300, 380)) != QColor(30, 60, 200).rgb()); // not past the mouth
    // "Don't close gaps" (0) turns mouths off as well.
    QVERIFY(objectRegions(f.object(), 0.0)->regions().closures.empty());
}

void TestFillTool::mainWindowHasToolMenuAndCloseGaps()
{
    ui::MainWindow window;
    QVERIFY(test::showActive(window));
    QAction *fill = window.findChild<QAction *>(QStringLiteral("tool.fill"));
    QVERIFY(fill);
    QCOMPARE(fill->shortcut(), QKeySequence(Qt::Key_F));
    QVERIFY(!fill->icon().isNull());
    QAction *fillAll = window.findChild<QAction *>(QStringLiteral("object.fillAll"));
    QVERIFY(fillAll);
    auto *objectMenu = window.menuBar()->findChild<QMenu *>(QStringLiteral("objectMenu"));
    QVERIFY(objectMenu && objectMenu->actions().contains(fillAll));
    auto *spin = window.findChild<QSpinBox *>(QStringLiteral("fill.closeGap"));
    QVERIFY(spin);
    // The tool's options show with the tool.
    fill->trigger();
    QVERIFY(spin->isVisible());
    window.findChild<QAction *>(QStringLiteral("tool.pen"))->trigger();
    QVERIFY(!spin->isVisible());
    QCOMPARE(spin->value(), -1);
    QCOMPARE(spin->text(), spin->specialValueText());
    model::Document *doc = window.document();
    spin->setValue(20);
    QCOMPARE(doc->settings().closeGap, 20.0);
    doc->undoStack()->undo();
    QCOMPARE(doc->settings().closeGap, -1.0);
    QCOMPARE(spin->value(), -1);
}

// Animators raise Close gaps with the arrows: the first step up leaves "automatic" at the gap it
// closed (shown in its text), the steps grow with the value, and the whole session of clicks is
// one undo step.
void TestFillTool::closeGapArrowsStartAtTheAutomaticGap()
{
    ui::MainWindow window;
    QVERIFY(test::showActive(window));
    model::Document *doc = window.document();
    const Id group = doc->frameAt(0).groups.at(0).id;
    doc->undoStack()->push(new AddStrokeCommand(doc, group, outline(8.0)));
    doc->undoStack()->clear();
    const double automatic = objectRegions(*doc->group(group), -1.0)->regions().closeGap;
    QVERIFY(automatic > 1.0);
    window.findChild<QAction *>(QStringLiteral("tool.fill"))->trigger();
    auto *spin = window.findChild<QSpinBox *>(QStringLiteral("fill.closeGap"));
    QVERIFY(spin && spin->isVisible());
    QCOMPARE(spin->text(),
             QStringLiteral("Close gaps: automatic (%1 px)").arg(std::lround(automatic)));
    spin->stepBy(1);
    const int start = int(std::ceil(automatic));
    QCOMPARE(spin->value(), start);
    QCOMPARE(doc->settings().closeGap, double(start));
    std::vector<int> seen;
    for (int i = 0; i < 40 && spin->value() < 120; ++i) {
        spin->stepBy(1);
        seen.push_back(spin->value());
    }
    for (std::size_t i = 1; i < seen.size(); ++i) {
        const int step = seen[i] - seen[i - 1];
        QVERIFY2(step == (seen[i - 1] < 10   ? 1
                          : seen[i - 1] < 50 ? 5
                                             : 10),
                 qPrintable(QStringLiteral("%1 -> %2").arg(seen[i - 1]).arg(seen[i])));
    }
    QVERIFY(seen.size() < 30); // 1 px steps would take over 100 clicks
    QCOMPARE(doc->undoStack()->count(), 1);
    spin->stepBy(-1); // back down by the finer step below 120
    QCOMPARE(spin->value(), 110);
    doc->undoStack()->undo();
    QCOMPARE(doc->settings().closeGap, -1.0);
    QCOMPARE(spin->value(), -1);
}

QTEST_MAIN(TestFillTool)
#include "tst_fill_tool.moc"
