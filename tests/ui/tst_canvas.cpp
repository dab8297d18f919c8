// The canvas view: zoom about the cursor, panning, fit, onion skin and the frame cache.
#include "tst_tools_support.h"

#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/fill/fill_resolve.h>
#include <finbook/model/render.h>
#include <finbook/ui/tools/tool_pen.h>
#include <finbook/ui/window/editor_state.h>

#include <QtTest>

#include <cmath>
#include <limits>
#include <random>

using namespace finbook;
using namespace finbook::test;

class TestCanvas : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void wheelZoomKeepsPointUnderCursor();
    void zoomIsClamped();
    void fitShowsWholePage();
    void middleButtonAndSpaceDragPan();
    void onionSkinShowsTintedNeighbours_data();
    void onionSkinShowsTintedNeighbours();
    void onionSkinHiddenWhilePlaying();
    void onionGhostIsEvenWhereItemsOverlap();
    void fillsMeetingAlongALineOfNoInkShowNoSeam();
    void cacheFollowsUndo();
    void hiddenObjectsAreNotDrawn();
    void rasterMatchesQPainter_data();
    void rasterMatchesQPainter();
    void turningAndMirroringKeepTheDocument();
    void aTurnedViewDrawsWhereThePenIs();
    void shiftSpaceDragTurnsTheView();
    void aTurnedPageShowsOnlyThePage();

private:
    // Every frame's strokes, point by point: what a view change must never alter.
    QByteArray drawingBytes() const
    {
        QByteArray bytes;
        for (const model::Frame &f : m_doc->frames())
            for (const model::StrokeGroup &g : f.groups)
                for (const model::Stroke &st : g.strokes)
                    for (const model::StrokePoint &p : st.data->points)
                        bytes.append(reinterpret_cast<const char *>(&p), sizeof p);
        return bytes;
    }

    QColor pixelAt(const QPointF &canvasPos)
    {
        const QImage image = m_canvas->grab().toImage();
        const QPointF w = m_canvas->mapFromCanvas(canvasPos) * image.devicePixelRatio();
        return image.pixelColor(w.toPoint());
    }

    std::unique_ptr<model::Document> m_doc;
    std::unique_ptr<ui::EditorState> m_state;
    std::unique_ptr<ui::CanvasWidget> m_canvas;
};

void TestCanvas::init()
{
    m_doc = std::make_unique<model::Document>();
    resetDocument(*m_doc, 3);
    m_state = std::make_unique<ui::EditorState>(m_doc.get());
    m_canvas = std::make_unique<ui::CanvasWidget>(m_state.get());
    m_canvas->addTool(std::make_unique<ui::PenTool>());
    m_canvas->resize(600, 500);
    m_canvas->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_canvas.get()));
}

void TestCanvas::cleanup()
{
    m_canvas.reset();
    m_state.reset();
    m_doc.reset();
}

void TestCanvas::wheelZoomKeepsPointUnderCursor()
{
    const QPointF cursor(170, 130);
    const QPointF under = m_canvas->mapToCanvas(cursor);
    const qreal zoom = m_canvas->zoom();
    wheel(m_canvas.get(), cursor, 120);
    QVERIFY(m_canvas->zoom() > zoom * 1.2);
    QVERIFY(QLineF(m_canvas->mapToCanvas(cursor), under).length() < 1e-9);
    wheel(m_canvas.get(), QPointF(420, 333), -240);
    wheel(m_canvas.get(), cursor, 120, Qt::ControlModifier);
    const QPointF again = m_canvas->mapToCanvas(cursor);
    wheel(m_canvas.get(), cursor, 360);
    QVERIFY(QLineF(m_canvas->mapToCanvas(cursor), again).length() < 1e-9);
}

void TestCanvas::zoomIsClamped()
{
    for (int i = 0; i < 60; ++i)
        m_canvas->zoomIn();
    QCOMPARE(m_canvas->zoom(), ui::CanvasWidget::kMaxZoom);
    for (int i = 0; i < 80; ++i)
        m_canvas->zoomOut();
    QCOMPARE(m_canvas->zoom(), ui::CanvasWidget::kMinZoom);
    m_canvas->setZoom(std::numeric_limits<qreal>::quiet_NaN(), {10, 10});
    QCOMPARE(m_canvas->zoom(), ui::CanvasWidget::kMinZoom);
}

void TestCanvas::fitShowsWholePage()
{
    m_canvas->actualSize();
    m_canvas->zoomIn();
    m_canvas->fitToView();
    const QRectF page = m_canvas->canvasToWidget().mapRect(QRectF(0, 0, 400, 300));
    QVERIFY(QRectF(m_canvas->rect()).contains(page));
    QVERIFY(page.width() > 500 || page.height() > 400); // and it fills the widget
    m_canvas->resize(300, 300);
    const QRectF smaller = m_canvas->canvasToWidget().mapRect(QRectF(0, 0, 400, 300));
    QVERIFY(QRectF(m_canvas->rect()).contains(smaller)); // kept fitted on resize
}

void TestCanvas::middleButtonAndSpaceDragPan()
{
    m_canvas->actualSize();
    QPointF origin = m_canvas->mapFromCanvas({0, 0});
    drag(m_canvas.get(), {QPointF(300, 300), QPointF(310, 305), QPointF(325, 290)},
         Qt::MiddleButton);
    QCOMPARE(m_canvas->mapFromCanvas({0, 0}), origin + QPointF(25, -10));
    origin = m_canvas->mapFromCanvas({0, 0});
    m_canvas->setFocus();
    QTest::keyPress(m_canvas.get(), Qt::Key_Space);
    drag(m_canvas.get(), {QPointF(100, 100), QPointF(80, 90)});
    QTest::keyRelease(m_canvas.get(), Qt::Key_Space);
    QCOMPARE(m_canvas->mapFromCanvas({0, 0}), origin + QPointF(-20, -10));
    int strokes = 0;
    for (const model::Frame &f : m_doc->frames())
        strokes += int(f.groups[0].strokes.size());
    QCOMPARE(strokes, 0); // panning never draws
}

void TestCanvas::onionSkinShowsTintedNeighbours_data()
{
    QTest::addColumn<int>("neighbour");
    QTest::newRow("previous") << 0;
    QTest::newRow("next") << 2;
}

void TestCanvas::onionSkinShowsTintedNeighbours()
{
    QFETCH(int, neighbour);
    auto thick = line({100, 150}, {300, 150});
    auto data = std::make_shared<model::StrokeData>(*thick);
    data->width = 12;
    addStroke(*m_doc, m_doc->frameAt(neighbour).groups[0].id, data);
    m_state->setCurrentFrameIndex(1);
    const QPointF probe(200, 150);
    QCOMPARE(pixelAt(probe), QColor(Qt::white)); // onion skin off: nothing there

    ui::OnionSkin onion = m_state->onionSkin();
    onion.enabled = true;
    onion.before = 1;
    onion.after = 1;
    onion.opacity = 0.5;
    m_state->setOnionSkin(onion);
    const QColor c = pixelAt(probe);
    const QColor tint = neighbour == 0 ? onion.beforeTint : onion.afterTint;
    // Half the tint over white: tinted, lighter than the tint itself, not black.
    QVERIFY2(c != QColor(Qt::white), qPrintable(c.name()));
    if (neighbour == 0)
        QVERIFY2(c.red() > c.blue() + 40 && c.red() > c.green() + 40, qPrintable(c.name()));
    else
        QVERIFY2(c.blue() > c.red() + 40, qPrintable(c.name()));
    QVERIFY(std::abs(c.red() - (255 + tint.red()) / 2) <= 8);

    onion.before = 0;
    onion.after = 0;
    m_state->setOnionSkin(onion);
    QCOMPARE(pixelAt(probe), QColor(Qt::white)); // no neighbours asked for
    onion.before = onion.after = 2;
    onion.enabled = false;
    m_state->setOnionSkin(onion);
    QCOMPARE(pixelAt(probe), QColor(Qt::white));
}

// Issue 45, item 6: a ghost is the frame as drawn, tinted and made translucent once. Painted
// item by item at the onion's opacity, a fill over a fill (a cut-out limb's piece or socket
// over the body) and two lines' round ends on one spot (a line split at a cut) came out
// darker than the rest of the ghost.
void TestCanvas::onionGhostIsEvenWhereItemsOverlap()
{
    resetDocument(*m_doc, 2, 2);
    const model::Frame &first = m_doc->frameAt(0);
    const model::Id back = first.groups[0].id, front = first.groups[1].id;
    addStroke(*m_doc, back, polyline({{100, 60}, {220, 60}, {220, 180}, {100, 180}, {100, 60}}));
    addStroke(*m_doc, front,
              polyline({{160, 120}, {280, 120}, {280, 240}, {160, 240}, {160, 120}}));
    for (const auto &[g, at] : {std::pair{back, QPointF(130, 90)}, {front, QPointF(250, 210)}}) {
        auto fill = model::fillRegionCommand(m_doc.get(), g, at, 0xffe0a040);
        QVERIFY(fill);
        m_doc->undoStack()->push(fill.release());
    }
    // One line drawn as two runs meeting end to end (as a cut-out pose splits it at a cut).
    addStroke(*m_doc, back, line({40, 270}, {120, 270}));
    addStroke(*m_doc, back, line({120, 270}, {200, 270}));
    m_state->setCurrentFrameIndex(1);
    ui::OnionSkin onion = m_state->onionSkin();
    onion.enabled = true;
    onion.before = 1;
    onion.after = 0;
    onion.opacity = 0.5;
    m_state->setOnionSkin(onion);
    m_canvas->fitToView();
    const auto near = [](const QColor &a, const QColor &b) {
        return std::abs(a.red() - b.red()) <= 3 && std::abs(a.green() - b.green()) <= 3 &&
               std::abs(a.blue() - b.blue()) <= 3;
    };
    const QColor oneFill = pixelAt({130, 90}), twoFills = pixelAt({190, 150});
    QVERIFY2(oneFill != QColor(Qt::white), qPrintable(oneFill.name()));
    QVERIFY2(near(twoFills, oneFill), qPrintable(twoFills.name() + " " + oneFill.name()));
    QVERIFY(near(pixelAt({250, 210}), oneFill)); // the front object's own fill
    const QColor run = pixelAt({80, 270}), joint = pixelAt({120, 270});
    QVERIFY2(run.green() < oneFill.green() - 20, qPrintable(run.name())); // ink, not fill
    QVERIFY2(near(joint, run), qPrintable(joint.name() + " " + run.name()));
}

// As tst_fills' test of the same name, on the canvas's own raster: two fills of one colour that
// meet along a line of no ink show no light seam between them.
void TestCanvas::fillsMeetingAlongALineOfNoInkShowNoSeam()
{
    const model::Id g = m_doc->frameAt(0).groups[0].id;
    addStroke(*m_doc, g, polyline({{100, 100}, {200, 100}, {200, 200}, {100, 200}, {100, 100}}));
    addStroke(*m_doc, g, model::lineOfNoInk({QPointF(92, 96), QPointF(208, 204)}, 3.0));
    constexpr QRgb kFill = 0xffe03020;
    for (const QPointF at : {QPointF(175, 125), QPointF(125, 175)}) {
        auto fill = model::fillRegionCommand(m_doc.get(), g, at, kFill);
        QVERIFY(fill);
        m_doc->undoStack()->push(fill.release());
    }
    QCOMPARE(m_doc->frameAt(0).groups[0].fills.size(), std::size_t(2));
    m_canvas->fitToView();
    const QImage image = m_canvas->grab().toImage();
    int worst = 0; // the largest channel difference from the fill's colour along the line
    for (int k = 20; k <= 100; ++k) {
        const QPointF on(92 + k, 96 + k * 108.0 / 116.0);
        for (int d = -2; d <= 2; ++d) {
            const QPoint w =
                (m_canvas->mapFromCanvas(on) * image.devicePixelRatio()).toPoint() + QPoint(0, d);
            const QRgb c = image.pixel(w);
            worst =
                std::max({worst, std::abs(qRed(c) - qRed(kFill)),
                          std::abs(qGreen(c) - qGreen(kFill)), std::abs(qBlue(c) - qBlue(kFill))});
        }
    }
    QVERIFY2(worst <= 8, qPrintable(QString::number(worst)));
}

void TestCanvas::onionSkinHiddenWhilePlaying()
{
    addStroke(*m_doc, m_doc->frameAt(0).groups[0].id, line({100, 150}, {300, 150}));
    m_state->setCurrentFrameIndex(1);
    ui::OnionSkin onion = m_state->onionSkin();
    onion.enabled = true;
    m_state->setOnionSkin(onion);
    QVERIFY(pixelAt({200, 150}) != QColor(Qt::white));
    m_state->setPlaying(true);
    QCOMPARE(pixelAt({200, 150}), QColor(Qt::white));
    m_state->setPlaying(false);
    QVERIFY(pixelAt({200, 150}) != QColor(Qt::white));
}

void TestCanvas::cacheFollowsUndo()
{
    const model::Id g = m_doc->frameAt(0).groups[0].id;
    QCOMPARE(pixelAt({200, 150}), QColor(Qt::white));
    addStroke(*m_doc, g, line({100, 150}, {300, 150}, 20, 0xff000000));
    QCOMPARE(pixelAt({200, 150}), QColor(Qt::black));
    m_doc->undoStack()->undo();
    QCOMPARE(pixelAt({200, 150}), QColor(Qt::white));
    m_doc->undoStack()->redo();
    m_state->setCurrentFrameIndex(1);
    QCOMPARE(pixelAt({200, 150}), QColor(Qt::white));
    m_state->setCurrentFrameIndex(0);
    QCOMPARE(pixelAt({200, 150}), QColor(Qt::black));
}

void TestCanvas::hiddenObjectsAreNotDrawn()
{
    const model::Id g = m_doc->frameAt(0).groups[0].id;
    addStroke(*m_doc, g, line({100, 150}, {300, 150}));
    QCOMPARE(pixelAt({200, 150}), QColor(Qt::black));
    m_doc->undoStack()->push(
        new model::SetObjectFlagCommand(m_doc.get(), g, model::ObjectFlag::Visible, false));
    QCOMPARE(pixelAt({200, 150}), QColor(Qt::white));
}

void TestCanvas::rasterMatchesQPainter_data()
{
    QTest::addColumn<qreal>("rotation");
    QTest::addColumn<bool>("mirrored");
    QTest::newRow("upright") << 0.0 << false;
    QTest::newRow("turned 30 degrees") << 30.0 << false;
    QTest::newRow("mirrored") << 0.0 << true;
    QTest::newRow("mirrored, turned -135 degrees") << -135.0 << true;
}

// The canvas's own rasterizer must draw what model::paintFrame draws (thumbnails, export), in
// a turned and mirrored view too.
void TestCanvas::rasterMatchesQPainter()
{
    QFETCH(qreal, rotation);
    QFETCH(bool, mirrored);
    const model::Id g = m_doc->frameAt(0).groups[0].id;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int s = 0; s < 30; ++s) {
        auto data = std::make_shared<model::StrokeData>();
        float x = 20 + u(rng) * 360, y = 20 + u(rng) * 260, heading = u(rng) * 6.28f;
        const float phase = u(rng) * 6.28f; // pressure varies smoothly, as a tablet's does
        for (int i = 0; i < 60; ++i) {
            heading += (u(rng) - 0.5f) * 0.5f;
            x += 3 * std::cos(heading);
            y += 3 * std::sin(heading);
            data->points.push_back({x, y, 0.65f + 0.35f * std::sin(phase + 0.15f * float(i))});
        }
        data->width = 1.0f + 8.0f * u(rng);
        // Opaque: paintStroke double-blends translucent colours where its width runs meet
        // (dark beads); the rasterizer does not, so only opaque strokes compare like for like.
        data->color = qRgb(int(u(rng) * 255), int(u(rng) * 255), int(u(rng) * 255));
        addStroke(*m_doc, g, data);
    }
    m_canvas->actualSize();
    m_canvas->setMirrored(mirrored);
    m_canvas->setRotation(rotation);
    QCOMPARE(m_canvas->rotation(), rotation);
    const QImage ours = m_canvas->grab().toImage().convertToFormat(QImage::Format_ARGB32);
    QImage ref(ours.size(), QImage::Format_ARGB32);
    ref.setDevicePixelRatio(ours.devicePixelRatio());
    ref.fill(Qt::white);
    {
        QPainter painter(&ref);
        painter.setTransform(m_canvas->canvasToWidget());
        model::RenderOptions options;
        options.paintBackground = false;
        model::paintFrame(painter, m_doc->frameAt(0), m_doc->settings(), options);
    }
    // The page on screen, 2 px in from its edges (whose pixels the page's clip cuts).
    const QPolygonF inner = m_canvas->canvasToWidget().map(QPolygonF(QRectF(3, 3, 394, 294)));
    const QRect page = inner.boundingRect().toAlignedRect();
    qint64 ink = 0, inkRef = 0, far = 0, pixels = 0;
    for (int y = page.top(); y <= page.bottom(); ++y)
        for (int x = page.left(); x <= page.right(); ++x) {
            if (!inner.containsPoint(QPointF(x + 0.5, y + 0.5), Qt::OddEvenFill))
                continue;
            const QColor a = ours.pixelColor(x, y), b = ref.pixelColor(x, y);
            ink += 765 - a.red() - a.green() - a.blue();
            inkRef += 765 - b.red() - b.green() - b.blue();
            const int d = std::max({std::abs(a.red() - b.red()), std::abs(a.green() - b.green()),
                                    std::abs(a.blue() - b.blue())});
            far += d > 96;
            pixels += b != QColor(Qt::white);
        }
    QVERIFY(inkRef > 0);
    if (qEnvironmentVariableIsSet("FINBOOK_DUMP")) {
        ours.save(QStringLiteral("/tmp/raster_ours.png"));
        ref.save(QStringLiteral("/tmp/raster_ref.png"));
    }
    // Same amount of ink within 6 %, and only stray edge pixels differ much.
    QVERIFY2(std::abs(double(ink - inkRef)) / double(inkRef) < 0.06,
             qPrintable(QStringLiteral("ink %1 vs %2").arg(ink).arg(inkRef)));
    QVERIFY2(double(far) / double(pixels) < 0.03,
             qPrintable(QStringLiteral("%1 of %2 pixels differ").arg(far).arg(pixels)));
}

// View > Rotate and Mirror, and the status bar's field, change how the page is shown: never the
// drawing, never the undo history. The point under the widget's centre stays put.
void TestCanvas::turningAndMirroringKeepTheDocument()
{
    const model::Id g = m_doc->frameAt(0).groups[0].id;
    addStroke(*m_doc, g, line({100, 150}, {300, 120}));
    const QByteArray before = drawingBytes();
    const int steps = m_doc->undoStack()->count();
    QSignalSpy turned(m_canvas.get(), &ui::CanvasWidget::viewTurned);
    const QPointF centre = QRectF(m_canvas->rect()).center();
    const QPointF under = m_canvas->mapToCanvas(centre);
    const auto same = [](QPointF a, QPointF b) { return QLineF(a, b).length() < 1e-6; };

    m_canvas->setRotation(30);
    QCOMPARE(m_canvas->rotation(), 30.0);
    QVERIFY(same(m_canvas->mapToCanvas(centre), under));
    // On screen the page's top edge now runs 30° clockwise (Qt's y points down).
    const QPointF edge = m_canvas->mapFromCanvas({1, 0}) - m_canvas->mapFromCanvas({0, 0});
    QCOMPARE(qRound(std::atan2(edge.y(), edge.x()) * 180 / M_PI), 30);
    m_canvas->setMirrored(true);
    QVERIFY(m_canvas->isMirrored());
    QCOMPARE(m_canvas->rotation(), -30.0); // what was on screen, flipped left to right
    QVERIFY(same(m_canvas->mapToCanvas(centre), under));
    const QPointF flipped = m_canvas->mapFromCanvas({1, 0}) - m_canvas->mapFromCanvas({0, 0});
    QVERIFY(std::abs(flipped.x() + edge.x()) < 1e-9 && std::abs(flipped.y() - edge.y()) < 1e-9);
    // Round trips through the turned, mirrored view.
    for (const QPointF p : {QPointF(0, 0), QPointF(123.25, 77.5), QPointF(400, 300)})
        QVERIFY(same(m_canvas->mapToCanvas(m_canvas->mapFromCanvas(p)), p));
    // Zooming keeps the point under the cursor in a turned view too.
    const QPointF cursor(170, 130);
    const QPointF at = m_canvas->mapToCanvas(cursor);
    wheel(m_canvas.get(), cursor, 240);
    QVERIFY(same(m_canvas->mapToCanvas(cursor), at));
    // Steps add up exactly, and wrap into (−180°, 180°].
    m_canvas->setMirrored(false);
    m_canvas->resetRotation();
    for (int i = 0; i < 12; ++i)
        m_canvas->rotateBy(15);
    QCOMPARE(m_canvas->rotation(), 180.0);
    m_canvas->rotateBy(15);
    QCOMPARE(m_canvas->rotation(), -165.0);
    for (int i = 0; i < 11; ++i)
        m_canvas->rotateBy(15);
    QCOMPARE(m_canvas->rotation(), 0.0);
    m_canvas->setRotation(std::numeric_limits<qreal>::quiet_NaN());
    QCOMPARE(m_canvas->rotation(), 0.0);
    // Fit to Window fits the turned page.
    m_canvas->setRotation(45);
    m_canvas->fitToView();
    const QRectF shown = m_canvas->canvasToWidget().mapRect(QRectF(0, 0, 400, 300));
    QVERIFY(QRectF(m_canvas->rect()).adjusted(-1, -1, 1, 1).contains(shown));
    QVERIFY(shown.width() > 500 || shown.height() > 400);
    QVERIFY(turned.count() >= 5);
    QCOMPARE(drawingBytes(), before);
    QCOMPARE(m_doc->undoStack()->count(), steps);
}

// The pen lays its line under the cursor whatever the view's turn and mirror.
void TestCanvas::aTurnedViewDrawsWhereThePenIs()
{
    m_canvas->setMirrored(true);
    m_canvas->setRotation(-60);
    std::vector<QPointF> widget;
    for (int i = 0; i <= 40; ++i)
        widget.emplace_back(200 + 5 * i, 180 + 60 * std::sin(i * 0.15));
    drag(m_canvas.get(), widget);
    const model::StrokeGroup &g = m_doc->frameAt(0).groups[0];
    QCOMPARE(int(g.strokes.size()), 1);
    QPolygonF path;
    for (const QPointF &w : widget)
        path << m_canvas->mapToCanvas(w);
    const std::vector<model::StrokePoint> &points = g.strokes[0].data->points;
    QVERIFY(points.size() >= 2);
    const auto distanceToPath = [&](QPointF p) {
        qreal best = 1e9;
        for (int i = 1; i < path.size(); ++i) {
            const QPointF a = path[i - 1], d = path[i] - a;
            const qreal len2 = QPointF::dotProduct(d, d);
            const qreal t =
                len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, d) / len2, 0.0, 1.0) : 0.0;
            best = std::min(best, QLineF(p, a + d * t).length());
        }
        return best;
    };
    for (const model::StrokePoint &p : points)
        QVERIFY2(distanceToPath(QPointF(p.x, p.y)) < 2.0,
                 qPrintable(QStringLiteral("(%1, %2)").arg(p.x).arg(p.y)));
    QVERIFY(QLineF(QPointF(points.front().x, points.front().y), path.front()).length() < 2.0);
    QVERIFY(QLineF(QPointF(points.back().x, points.back().y), path.back()).length() < 2.0);
    // And the line is drawn where it was drawn: ink under the pen's path on screen.
    const QImage image = m_canvas->grab().toImage();
    const QPointF mid = widget[20] * image.devicePixelRatio();
    QVERIFY(image.pixelColor(mid.toPoint()).lightness() < 128);
}

// Shift+Space-drag turns the view about the widget's centre as the pointer goes round it.
void TestCanvas::shiftSpaceDragTurnsTheView()
{
    const QPointF c = QRectF(m_canvas->rect()).center();
    const QPointF under = m_canvas->mapToCanvas(c);
    m_canvas->setFocus();
    QTest::keyPress(m_canvas.get(), Qt::Key_Space, Qt::ShiftModifier);
    std::vector<QPointF> round;
    for (int i = 0; i <= 9; ++i) // a quarter turn clockwise on screen, 100 px from the centre
        round.push_back(c + 100 * QPointF(std::cos(i * M_PI / 18), std::sin(i * M_PI / 18)));
    drag(m_canvas.get(), round, Qt::LeftButton, Qt::ShiftModifier);
    QTest::keyRelease(m_canvas.get(), Qt::Key_Space, Qt::ShiftModifier);
    QVERIFY2(std::abs(m_canvas->rotation() - 90.0) < 0.01,
             qPrintable(QString::number(m_canvas->rotation())));
    QVERIFY(QLineF(m_canvas->mapToCanvas(c), under).length() < 1e-6);
    QCOMPARE(int(m_doc->frameAt(0).groups[0].strokes.size()), 0); // turning never draws
    // Plain Space still pans.
    const QPointF origin = m_canvas->mapFromCanvas({0, 0});
    QTest::keyPress(m_canvas.get(), Qt::Key_Space);
    drag(m_canvas.get(), {QPointF(100, 100), QPointF(80, 90)});
    QTest::keyRelease(m_canvas.get(), Qt::Key_Space);
    QVERIFY(QLineF(m_canvas->mapFromCanvas({0, 0}), origin + QPointF(-20, -10)).length() < 1e-9);
    QCOMPARE(m_canvas->rotation(), 90.0);
}

// A turned page shows the drawing on the page only: a stroke that runs off the page is cut at
// its edge, as it is upright, and the desk around the turned page stays the desk.
void TestCanvas::aTurnedPageShowsOnlyThePage()
{
    const model::Id g = m_doc->frameAt(0).groups[0].id;
    addStroke(*m_doc, g, line({-200, 150}, {600, 150}, 80));
    m_canvas->setRotation(30);
    m_canvas->fitToView();
    const QImage image = m_canvas->grab().toImage();
    const qreal dpr = image.devicePixelRatio();
    const auto colourAt = [&](QPointF canvasPos) {
        return image.pixelColor((m_canvas->mapFromCanvas(canvasPos) * dpr).toPoint());
    };
    QCOMPARE(colourAt({200, 150}), QColor(Qt::black)); // on the page
    QCOMPARE(colourAt({20, 150}), QColor(Qt::black));
    const QColor desk(0x70, 0x70, 0x70); // off the page, within its bounds on screen
    QCOMPARE(colourAt({-60, 150}), desk);
    QCOMPARE(colourAt({460, 150}), desk);
}

QTEST_MAIN(TestCanvas)
#include "tst_canvas.moc"
