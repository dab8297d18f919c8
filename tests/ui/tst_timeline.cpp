// The timeline drives the document: frame actions, clicking, scrubbing and reordering by
// dragging a thumbnail are tested through the real widgets with QTest mouse and key events,
// and every edit is checked in the document and undone.
#include <finbook/model/commands.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/frame_list_model.h>
#include <finbook/ui/timeline/frame_actions.h>
#include <finbook/ui/timeline/thumbnail_cache.h>
#include <finbook/ui/timeline/timeline_view.h>
#include <finbook/ui/timeline/timeline_widget.h>
#include <finbook/ui/window/editor_state.h>

#include <QDir>
#include <QFileInfo>
#include <QScrollBar>
#include <QSpinBox>
#include <QTest>
#include <QToolButton>

#include <memory>
#include <set>

using namespace finbook;
using model::Document;
using model::Id;

namespace {

model::StrokeDataPtr line(float x0, float y0, float x1, float y1, QRgb color = 0xff202020)
{
    auto data = std::make_shared<model::StrokeData>();
    for (int i = 0; i <= 10; ++i)
        data->points.push_back({x0 + (x1 - x0) * float(i) / 10, y0 + (y1 - y0) * float(i) / 10,
                                0.5f + 0.05f * float(i)});
    data->color = color;
    data->width = 12.0f;
    return data;
}

// `count` frames, frame i has a stroke whose position depends on i.
void fill(Document &doc, int count)
{
    for (int i = 0; i < count; ++i) {
        auto *insert = new model::InsertFrameCommand(&doc, doc.frameCount());
        doc.undoStack()->push(insert);
        const Id group = doc.frame(insert->frameId())->groups.front().id;
        const float x = 100.0f + float((i * 97) % 1000);
        doc.undoStack()->push(new model::AddStrokeCommand(&doc, group, line(x, 100, x + 150, 600)));
    }
    doc.undoStack()->clear();
}

std::vector<Id> frameIds(const Document &doc)
{
    std::vector<Id> ids;
    for (const model::Frame &f : doc.frames())
        ids.push_back(f.id);
    return ids;
}

struct Fixture {
    Document doc;
    std::unique_ptr<ui::EditorState> state;
    std::unique_ptr<ui::FrameActions> actions;
    std::unique_ptr<ui::TimelineWidget> timeline;

    explicit Fixture(int frames, QSize size = {800, 120})
    {
        fill(doc, frames);
        state = std::make_unique<ui::EditorState>(&doc);
        actions = std::make_unique<ui::FrameActions>(state.get());
        timeline = std::make_unique<ui::TimelineWidget>(state.get(), actions.get(), nullptr);
        timeline->resize(size);
        timeline->show();
        QVERIFY(QTest::qWaitForWindowExposed(timeline.get()));
        QCoreApplication::processEvents();
    }
    ui::TimelineView *view() const { return timeline->view(); }
    QWidget *viewport() const { return timeline->view()->viewport(); }
};

} // namespace

class TestTimeline : public QObject {
    Q_OBJECT
private slots:
    void duplicateThenEditCopyLeavesOriginal();
    void frameActionsEditAndUndo();
    void deleteIsDisabledOnTheLastFrame();
    void deleteRemovesTheSelectedFrames();
    void clickPicksTheCurrentFrame();
    void draggingTheNumberBandScrubs();
    void draggingAThumbnailReorders();
    void draggingLeftAndEscapeCancels();
    void currentFrameIsScrolledIntoView();
    void thumbnailsRenderOnlyWhenVisible();
    void thumbnailFollowsFrameEdits();
    void onionSkinControlsAreTwoWay();
    void frameShortcutsStepFrames();
    void grabScreenshot();
};

void TestTimeline::duplicateThenEditCopyLeavesOriginal()
{
    Fixture f(3);
    f.state->setCurrentFrameIndex(1);
    const model::Frame original = f.doc.frameAt(1);
    f.actions->duplicate()->trigger();
    QCOMPARE(f.doc.frameCount(), 4);
    QCOMPARE(f.state->currentFrameIndex(), 2);
    const model::Frame &copy = f.doc.frameAt(2);
    QVERIFY(copy.id != original.id);
    QCOMPARE(copy.groups.size(), original.groups.size());
    QVERIFY(copy.groups[0].id != original.groups[0].id);
    QVERIFY(copy.groups[0].strokes[0].id != original.groups[0].strokes[0].id);
    QCOMPARE(*copy.groups[0].strokes[0].data, *original.groups[0].strokes[0].data);

    // Edit the copy: move its stroke and add another one.
    const Id copyStroke = copy.groups[0].strokes[0].id;
    auto moved = std::make_shared<model::StrokeData>(*copy.groups[0].strokes[0].data);
    for (model::StrokePoint &p : moved->points)
        p.x += 40;
    QUndoStack *stack = f.doc.undoStack();
    stack->push(
        new model::ReplaceStrokeDataCommand(&f.doc, {copyStroke}, {moved}, QStringLiteral("Move")));
    stack->push(new model::AddStrokeCommand(&f.doc, f.state->currentGroupId(), line(0, 0, 9, 9)));
    QCOMPARE(f.doc.frameAt(2).groups[0].strokes.size(), std::size_t(2));
    // The original is untouched, point for point.
    const model::Frame &after = f.doc.frameAt(1);
    QCOMPARE(after.id, original.id);
    QCOMPARE(after.groups[0].strokes.size(), std::size_t(1));
    QCOMPARE(after.groups[0].strokes[0].data->points, original.groups[0].strokes[0].data->points);

    while (stack->canUndo())
        stack->undo();
    QCOMPARE(f.doc.frameCount(), 3);
    QCOMPARE(f.doc.frameAt(1).groups[0].strokes[0], original.groups[0].strokes[0]);
}

void TestTimeline::frameActionsEditAndUndo()
{
    Fixture f(3);
    const std::vector<Id> original = frameIds(f.doc);
    f.state->setCurrentFrameIndex(1);
    f.actions->insertBefore()->trigger();
    QCOMPARE(f.doc.frameCount(), 4);
    QCOMPARE(f.state->currentFrameIndex(), 1);
    QCOMPARE(f.doc.frameAt(2).id, original[1]);
    f.actions->insertAfter()->trigger();
    QCOMPARE(f.state->currentFrameIndex(), 2);
    QCOMPARE(f.doc.frameCount(), 5);
    f.actions->remove()->trigger(); // the one inserted after
    QCOMPARE(f.doc.frameAt(2).id, original[1]);
    f.state->setCurrentFrameIndex(1);
    f.actions->remove()->trigger(); // the one inserted before
    QCOMPARE(frameIds(f.doc), original);

    f.state->setCurrentFrameIndex(0);
    QVERIFY(!f.actions->moveLeft()->isEnabled());
    f.actions->moveRight()->trigger();
    QCOMPARE(f.doc.frameAt(1).id, original[0]);
    QCOMPARE(f.state->currentFrameIndex(), 1); // the frame stays current where it went
    f.actions->holdMore()->trigger();
    f.actions->holdMore()->trigger();
    QCOMPARE(f.doc.frameAt(1).hold, 3);
    QVERIFY(f.actions->holdLess()->isEnabled());
    f.actions->holdLess()->trigger();
    QCOMPARE(f.doc.frameAt(1).hold, 2);
    QCOMPARE(f.timeline->frameModel()->index(1).data(model::FrameListModel::HoldRole).toInt(), 2);

    QUndoStack *stack = f.doc.undoStack();
    while (stack->canUndo())
        stack->undo();
    QCOMPARE(frameIds(f.doc), original);
    QCOMPARE(f.doc.frameAt(0).hold, 1);
}

void TestTimeline::deleteIsDisabledOnTheLastFrame()
{
    Fixture f(2);
    QVERIFY(f.actions->remove()->isEnabled());
    f.actions->remove()->trigger();
    QCOMPARE(f.doc.frameCount(), 1);
    QVERIFY(!f.actions->remove()->isEnabled());
    f.actions->remove()->trigger(); // disabled: nothing happens
    QCOMPARE(f.doc.frameCount(), 1);
    QVERIFY(!f.actions->next()->isEnabled());
    QVERIFY(!f.actions->previous()->isEnabled());
    f.doc.undoStack()->undo();
    QVERIFY(f.actions->remove()->isEnabled());
}

// Issue 45: Delete Frame with frames 2–3 selected deleted only the current frame.
void TestTimeline::deleteRemovesTheSelectedFrames()
{
    Fixture f(5);
    const std::vector<Id> before = frameIds(f.doc);
    QTest::mouseClick(f.viewport(), Qt::LeftButton, {}, f.view()->thumbnailRect(1).center());
    QTest::mouseClick(f.viewport(), Qt::LeftButton, Qt::ShiftModifier,
                      f.view()->thumbnailRect(2).center());
    QCOMPARE(f.state->selectedFrames(), (std::vector<int>{1, 2}));
    f.actions->remove()->trigger();
    QCOMPARE(frameIds(f.doc), (std::vector<Id>{before[0], before[3], before[4]}));
    QCOMPARE(f.doc.undoStack()->count(), 1); // one step
    f.doc.undoStack()->undo();
    QCOMPARE(frameIds(f.doc), before);
    // Every frame selected: the first stays.
    f.state->setCurrentFrameIndex(0);
    f.state->setSelectedFrames(before);
    f.actions->remove()->trigger();
    QCOMPARE(frameIds(f.doc), (std::vector<Id>{before[0]}));
}

void TestTimeline::clickPicksTheCurrentFrame()
{
    Fixture f(5);
    QCOMPARE(f.state->currentFrameIndex(), 0);
    QTest::mouseClick(f.viewport(), Qt::LeftButton, {}, f.view()->thumbnailRect(3).center());
    QCOMPARE(f.state->currentFrameIndex(), 3);
    QTest::mouseClick(f.viewport(), Qt::LeftButton, {}, f.view()->bandRect(1).center());
    QCOMPARE(f.state->currentFrameIndex(), 1);
    QCOMPARE(f.doc.undoStack()->count(), 0); // picking a frame is not an edit
}

void TestTimeline::draggingTheNumberBandScrubs()
{
    Fixture f(6);
    QWidget *vp = f.viewport();
    QTest::mousePress(vp, Qt::LeftButton, {}, f.view()->bandRect(0).center());
    QCOMPARE(f.state->currentFrameIndex(), 0);
    for (int row : {1, 2, 4}) {
        QTest::mouseMove(vp, f.view()->bandRect(row).center());
        QCOMPARE(f.state->currentFrameIndex(), row);
    }
    // Past the last frame the scrubber stays on it.
    QTest::mouseMove(vp, QPoint(vp->width() - 2, f.view()->bandRect(0).center().y()));
    QCOMPARE(f.state->currentFrameIndex(), 5);
    QTest::mouseRelease(vp, Qt::LeftButton, {}, QPoint(vp->width() - 2, 5));
    QCOMPARE(f.doc.undoStack()->count(), 0);
    QCOMPARE(f.view()->dropSlot(), -1);
}

void TestTimeline::draggingAThumbnailReorders()
{
    Fixture f(5);
    const std::vector<Id> original = frameIds(f.doc);
    QWidget *vp = f.viewport();
    const QRect target = f.view()->thumbnailRect(2);
    QTest::mousePress(vp, Qt::LeftButton, {}, f.view()->thumbnailRect(0).center());
    QTest::mouseMove(vp, f.view()->thumbnailRect(1).center());
    QTest::mouseMove(vp, QPoint(target.right() - 2, target.center().y()));
    QCOMPARE(f.view()->dropSlot(), 3); // the marker sits after frame 3
    QCOMPARE(f.doc.frameCount(), 5);   // nothing changes until the release
    QCOMPARE(frameIds(f.doc), original);
    QTest::mouseRelease(vp, Qt::LeftButton, {}, QPoint(target.right() - 2, target.center().y()));

    QCOMPARE(f.doc.undoStack()->count(), 1);
    QCOMPARE(frameIds(f.doc),
             (std::vector<Id>{original[1], original[2], original[0], original[3], original[4]}));
    QCOMPARE(f.state->currentFrameIndex(), 2); // the dragged frame stays current
    f.doc.undoStack()->undo();
    QCOMPARE(frameIds(f.doc), original);
    QCOMPARE(f.state->currentFrameIndex(), 0);
}

void TestTimeline::draggingLeftAndEscapeCancels()
{
    Fixture f(5);
    const std::vector<Id> original = frameIds(f.doc);
    QWidget *vp = f.viewport();
    // Frame 4 dragged onto the left half of frame 2 lands before it.
    const QRect target = f.view()->thumbnailRect(1);
    QTest::mousePress(vp, Qt::LeftButton, {}, f.view()->thumbnailRect(3).center());
    QTest::mouseMove(vp, QPoint(target.left() + 2, target.center().y()));
    QTest::mouseRelease(vp, Qt::LeftButton, {}, QPoint(target.left() + 2, target.center().y()));
    QCOMPARE(frameIds(f.doc),
             (std::vector<Id>{original[0], original[3], original[1], original[2], original[4]}));
    f.doc.undoStack()->undo();

    // Escape while carrying a frame drops the drag.
    QTest::mousePress(vp, Qt::LeftButton, {}, f.view()->thumbnailRect(0).center());
    QTest::mouseMove(vp, f.view()->thumbnailRect(3).center());
    QVERIFY(f.view()->dropSlot() >= 0);
    QTest::keyClick(f.view(), Qt::Key_Escape);
    QCOMPARE(f.view()->dropSlot(), -1);
    QTest::mouseRelease(vp, Qt::LeftButton, {}, f.view()->thumbnailRect(3).center());
    QCOMPARE(frameIds(f.doc), original);
    QCOMPARE(f.doc.undoStack()->index(), 0);
    // A click without moving is not a drag.
    QTest::mouseClick(vp, Qt::LeftButton, {}, f.view()->thumbnailRect(2).center());
    QCOMPARE(f.doc.undoStack()->index(), 0);
}

void TestTimeline::currentFrameIsScrolledIntoView()
{
    Fixture f(200);
    f.state->setCurrentFrameIndex(150);
    QCoreApplication::processEvents();
    const std::vector<int> rows = f.view()->visibleRows();
    QVERIFY(std::find(rows.begin(), rows.end(), 150) != rows.end());
    QVERIFY(f.view()->horizontalScrollBar()->value() > 0);
}

void TestTimeline::thumbnailsRenderOnlyWhenVisible()
{
    Fixture f(300, {1000, 120});
    ui::ThumbnailCache *cache = f.timeline->thumbnails();
    QTRY_COMPARE(cache->pendingCount(), 0);
    std::set<int> seen;
    for (int row : f.view()->visibleRows())
        seen.insert(row);
    QVERIFY(!seen.empty());
    QVERIFY(int(seen.size()) < 300);
    QVERIFY(cache->renderedCount() > 0);
    QVERIFY(cache->renderedCount() <= int(seen.size()));
    for (int row : seen)
        QVERIFY(cache->isCurrent(f.doc.frameAt(row).id));

    // Jump to the end: only the frames shown there get rendered; the middle never is.
    QScrollBar *bar = f.view()->horizontalScrollBar();
    bar->setValue(bar->maximum());
    QCoreApplication::processEvents();
    QTRY_COMPARE(cache->pendingCount(), 0);
    for (int row : f.view()->visibleRows())
        seen.insert(row);
    QVERIFY(cache->renderedCount() <= int(seen.size()));
    QVERIFY(cache->isCurrent(f.doc.frameAt(299).id));
    QVERIFY(!cache->isCurrent(f.doc.frameAt(150).id));
}

void TestTimeline::thumbnailFollowsFrameEdits()
{
    Fixture f(3);
    ui::ThumbnailCache *cache = f.timeline->thumbnails();
    QTRY_COMPARE(cache->pendingCount(), 0);
    const Id frame = f.doc.frameAt(1).id;
    QVERIFY(cache->isCurrent(frame));
    const int before = cache->renderedCount();
    const QImage old = cache->thumbnail(frame).toImage();
    f.doc.undoStack()->push(new model::AddStrokeCommand(&f.doc, f.doc.frameAt(1).groups[0].id,
                                                        line(0, 0, 1280, 720, 0xffff0000)));
    QVERIFY(!cache->isCurrent(frame));
    QTRY_VERIFY(cache->isCurrent(frame));
    QCOMPARE(cache->renderedCount(), before + 1); // just the edited frame
    QVERIFY(cache->thumbnail(frame).toImage() != old);
}

void TestTimeline::onionSkinControlsAreTwoWay()
{
    Fixture f(3);
    f.timeline->onionToggle()->click();
    QVERIFY(f.state->onionSkin().enabled);
    f.timeline->onionBefore()->setValue(3);
    QCOMPARE(f.state->onionSkin().before, 3);
    ui::OnionSkin onion = f.state->onionSkin();
    onion.after = 5;
    onion.enabled = false;
    f.state->setOnionSkin(onion);
    QCOMPARE(f.timeline->onionAfter()->value(), 5);
    QVERIFY(!f.timeline->onionToggle()->isChecked());
    QCOMPARE(f.timeline->onionBefore()->maximum(), 5);
}

void TestTimeline::frameShortcutsStepFrames()
{
    Fixture f(4);
    f.timeline->addActions(f.actions->menuActions());
    QApplication::setActiveWindow(f.timeline.get());
    QVERIFY(QTest::qWaitForWindowActive(f.timeline.get()));
    f.view()->setFocus();
    QTest::keyClick(f.view(), Qt::Key_Period);
    QCOMPARE(f.state->currentFrameIndex(), 1);
    QTest::keyClick(f.view(), Qt::Key_Period);
    QTest::keyClick(f.view(), Qt::Key_Comma);
    QCOMPARE(f.state->currentFrameIndex(), 1);
    QTest::keyClick(f.view(), Qt::Key_F6); // duplicate
    QCOMPARE(f.doc.frameCount(), 5);
    QCOMPARE(f.state->currentFrameIndex(), 2);
    QTest::keyClick(f.view(), Qt::Key_Right); // the strip's own arrow keys
    QCOMPARE(f.state->currentFrameIndex(), 3);
}

void TestTimeline::grabScreenshot()
{
    Fixture f(8, {900, 120});
    // The bundled example when it is there: real drawings make a better picture.
    const QString walk = QStringLiteral(FINBOOK_SOURCE_DIR "/resources/examples/walk.finbook");
    if (QFileInfo::exists(walk))
        QVERIFY(!model::openFinbook(f.doc, walk).has_value());
    f.doc.undoStack()->push(new model::SetFrameHoldCommand(&f.doc, f.doc.frameAt(2).id, 3));
    model::DocumentSettings s = f.doc.settings();
    s.playEnd = 5;
    f.doc.undoStack()->push(new model::ChangeSettingsCommand(&f.doc, s));
    f.state->setCurrentFrameIndex(4);
    QTRY_COMPARE(f.timeline->thumbnails()->pendingCount(), 0);
    QCoreApplication::processEvents();
    const QPixmap shot = f.timeline->grab();
    QVERIFY(!shot.isNull());
    shot.save(QDir::temp().filePath(QStringLiteral("finbook_timeline.png")));
}

QTEST_MAIN(TestTimeline)
#include "tst_timeline.moc"
