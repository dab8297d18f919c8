// Playback shows the frame that elapsed time calls for (floor(elapsed × fps) ticks through
// the frames' holds), loops or stops at the end of the play range, and the settings it
// depends on change only through undoable commands.
#include <finbook/model/commands.h>
#include <finbook/ui/dialogs/document_settings_dialog.h>
#include <finbook/ui/timeline/playback_controller.h>
#include <finbook/ui/window/editor_state.h>

#include <QCheckBox>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>

using namespace finbook;
using model::Document;
using ui::frameAtTick;

namespace {

void fill(Document &doc, int count, int fps, bool loop, std::vector<int> holds = {})
{
    for (int i = 0; i < count; ++i)
        doc.undoStack()->push(new model::InsertFrameCommand(&doc, i));
    for (std::size_t i = 0; i < holds.size(); ++i)
        doc.undoStack()->push(
            new model::SetFrameHoldCommand(&doc, doc.frameAt(int(i)).id, holds[i]));
    model::DocumentSettings s = doc.settings();
    s.fps = fps;
    s.loop = loop;
    doc.undoStack()->push(new model::ChangeSettingsCommand(&doc, s));
    doc.undoStack()->clear();
}

void setRange(Document &doc, int start, int end)
{
    model::DocumentSettings s = doc.settings();
    s.playStart = start;
    s.playEnd = end;
    doc.setSettings(s);
}

} // namespace

class TestPlayback : public QObject {
    Q_OBJECT
private slots:
    void frameAtTickFollowsHolds();
    void frameAtTickLoopsOrStops();
    void frameAtTickStaysInThePlayRange();
    void advancesAtTheSetRate();
    void holdsLastTheirTicksWhilePlaying();
    void stopsAtTheEndWithoutLoop();
    void loopsWithLoop();
    void startsFromCurrentOrRestarts();
    void pickingAFrameWhilePlayingContinuesFromIt();
    void actionsAndLoopAreUndoable();
    void settingsDialogIsOneUndoStep();
};

void TestPlayback::frameAtTickFollowsHolds()
{
    Document doc;
    fill(doc, 3, 12, false, {1, 2, 3});
    QCOMPARE(ui::playRangeTicks(doc), qint64(6));
    const int expected[] = {0, 1, 1, 2, 2, 2};
    for (int t = 0; t < 6; ++t)
        QCOMPARE(frameAtTick(doc, t, false), expected[t]);
    QCOMPARE(ui::tickOfFrame(doc, 0), qint64(0));
    QCOMPARE(ui::tickOfFrame(doc, 2), qint64(3));
    QCOMPARE(frameAtTick(doc, -5, false), 0);
    QCOMPARE(frameAtTick(Document(), 3, true), -1);
}

void TestPlayback::frameAtTickLoopsOrStops()
{
    Document doc;
    fill(doc, 3, 12, false, {1, 2, 3});
    for (qint64 t : {6, 7, 100})
        QCOMPARE(frameAtTick(doc, t, false), 2);
    const int expected[] = {0, 1, 1, 2, 2, 2};
    for (qint64 t = 6; t < 30; ++t)
        QCOMPARE(frameAtTick(doc, t, true), expected[t % 6]);
}

void TestPlayback::frameAtTickStaysInThePlayRange()
{
    Document doc;
    fill(doc, 6, 12, true, {1, 1, 2, 1, 1, 1});
    setRange(doc, 2, 4); // frames 3..5: 2 + 1 + 1 ticks
    QCOMPARE(ui::playRangeTicks(doc), qint64(4));
    const int expected[] = {2, 2, 3, 4};
    for (qint64 t = 0; t < 12; ++t)
        QCOMPARE(frameAtTick(doc, t, true), expected[t % 4]);
    QCOMPARE(frameAtTick(doc, 9, false), 4);
    QCOMPARE(ui::tickOfFrame(doc, 0), qint64(0)); // clamped into the range
}

void TestPlayback::advancesAtTheSetRate()
{
    Document doc;
    fill(doc, 40, 12, false);
    ui::EditorState state(&doc);
    ui::PlaybackController playback(&state);
    QSignalSpy playing(&state, &ui::EditorState::playingChanged);
    playback.play();
    QVERIFY(state.isPlaying());
    QCOMPARE(playing.count(), 1);
    QTest::qWait(1000);
    const double elapsed = double(playback.elapsedNs()) / 1e9;
    const int expected = int(elapsed * 12);
    QVERIFY2(std::abs(state.currentFrameIndex() - expected) <= 1,
             qPrintable(QStringLiteral("frame %1 after %2 s, expected %3")
                            .arg(state.currentFrameIndex())
                            .arg(elapsed)
                            .arg(expected)));
    QVERIFY(state.currentFrameIndex() >= 10);
    playback.pause();
    QVERIFY(!state.isPlaying());
    const int stopped = state.currentFrameIndex();
    QTest::qWait(200);
    QCOMPARE(state.currentFrameIndex(), stopped);
}

void TestPlayback::holdsLastTheirTicksWhilePlaying()
{
    Document doc;
    fill(doc, 4, 10, false, {1, 4, 1, 1}); // 7 ticks of 100 ms
    ui::EditorState state(&doc);
    ui::PlaybackController playback(&state);
    std::vector<std::pair<int, double>> shown; // frame, seconds since play
    connect(&state, &ui::EditorState::currentFrameChanged, &state,
            [&](int index) { shown.emplace_back(index, double(playback.elapsedNs()) / 1e9); });
    playback.play();
    QTRY_VERIFY_WITH_TIMEOUT(!playback.isPlaying(), 3000);
    QCOMPARE(state.currentFrameIndex(), 3);
    std::vector<int> order;
    for (const auto &[frame, at] : shown)
        order.push_back(frame);
    QCOMPARE(order, (std::vector<int>{1, 2, 3}));
    // Frame 2 (held 4) appears at tick 1 and frame 3 at tick 5: 400 ms apart.
    QVERIFY2(std::abs((shown[1].second - shown[0].second) - 0.4) < 0.08,
             qPrintable(QString::number(shown[1].second - shown[0].second)));
}

void TestPlayback::stopsAtTheEndWithoutLoop()
{
    Document doc;
    fill(doc, 6, 30, false);
    ui::EditorState state(&doc);
    ui::PlaybackController playback(&state);
    playback.play();
    QTRY_VERIFY_WITH_TIMEOUT(!playback.isPlaying(), 2000);
    QCOMPARE(state.currentFrameIndex(), 5);
    QVERIFY(!state.isPlaying());
    QVERIFY(!playback.toggleAction()->isChecked());
}

void TestPlayback::loopsWithLoop()
{
    Document doc;
    fill(doc, 4, 40, true);
    ui::EditorState state(&doc);
    ui::PlaybackController playback(&state);
    std::vector<int> shown;
    connect(&state, &ui::EditorState::currentFrameChanged, &state,
            [&](int index) { shown.push_back(index); });
    playback.play();
    QTest::qWait(300); // 12 ticks: three times round
    QVERIFY(playback.isPlaying());
    playback.pause();
    QVERIFY(shown.size() >= 8);
    QVERIFY(std::count(shown.begin(), shown.end(), 0) >= 2);
    // Always forward (a busy machine may skip a frame, never go back).
    for (std::size_t i = 1; i < shown.size(); ++i)
        QVERIFY(shown[i] != shown[i - 1] && (shown[i] - shown[i - 1] + 4) % 4 <= 2);
}

void TestPlayback::startsFromCurrentOrRestarts()
{
    Document doc;
    fill(doc, 10, 1, false);
    ui::EditorState state(&doc);
    ui::PlaybackController playback(&state);
    state.setCurrentFrameIndex(4);
    playback.play();
    QCOMPARE(state.currentFrameIndex(), 4);
    QCOMPARE(playback.startTick(), qint64(4));
    playback.pause();
    state.setCurrentFrameIndex(9); // at the end: play starts over
    playback.play();
    QCOMPARE(state.currentFrameIndex(), 0);
    playback.pause();
    setRange(doc, 2, 6);
    state.setCurrentFrameIndex(8); // outside the range
    playback.toggle();
    QVERIFY(playback.isPlaying());
    QCOMPARE(state.currentFrameIndex(), 2);
    playback.toggle();
    QVERIFY(!playback.isPlaying());
}

void TestPlayback::pickingAFrameWhilePlayingContinuesFromIt()
{
    Document doc;
    fill(doc, 30, 10, false);
    ui::EditorState state(&doc);
    ui::PlaybackController playback(&state);
    playback.play();
    state.setCurrentFrameIndex(20);
    QCOMPARE(playback.startTick(), qint64(20));
    QTest::qWait(250);
    QVERIFY(playback.isPlaying());
    QVERIFY(state.currentFrameIndex() >= 21 && state.currentFrameIndex() <= 23);
}

void TestPlayback::actionsAndLoopAreUndoable()
{
    Document doc;
    fill(doc, 5, 12, true);
    ui::EditorState state(&doc);
    ui::PlaybackController playback(&state);
    QCOMPARE(playback.toggleAction()->objectName(), QStringLiteral("playback.toggle"));
    QCOMPARE(playback.loopAction()->objectName(), QStringLiteral("playback.loop"));
    QVERIFY(playback.loopAction()->isChecked());

    playback.toggleAction()->trigger();
    QVERIFY(playback.isPlaying());
    QVERIFY(playback.toggleAction()->isChecked());
    playback.toggleAction()->trigger();
    QVERIFY(!playback.isPlaying());

    playback.loopAction()->trigger();
    QVERIFY(!doc.settings().loop);
    QCOMPARE(doc.undoStack()->count(), 1);
    doc.undoStack()->undo();
    QVERIFY(doc.settings().loop);
    QVERIFY(playback.loopAction()->isChecked()); // the action follows the document
}

void TestPlayback::settingsDialogIsOneUndoStep()
{
    Document doc;
    fill(doc, 8, 12, true);
    const model::DocumentSettings before = doc.settings();
    ui::DocumentSettingsDialog dialog(&doc);
    QCOMPARE(dialog.fpsBox()->value(), 12);
    QCOMPARE(dialog.playEndBox()->text(), QStringLiteral("Last"));
    dialog.fpsBox()->setValue(24);
    dialog.widthBox()->setValue(640);
    dialog.heightBox()->setValue(480);
    dialog.loopBox()->setChecked(false);
    dialog.playStartBox()->setValue(2);
    dialog.playEndBox()->setValue(5);
    dialog.setBackground(QColor(250, 240, 220));
    dialog.accept();
    QCOMPARE(doc.undoStack()->count(), 1);
    const model::DocumentSettings &s = doc.settings();
    QCOMPARE(s.fps, 24);
    QCOMPARE(s.canvasSize, QSize(640, 480));
    QVERIFY(!s.loop);
    QCOMPARE(s.playStart, 1);
    QCOMPARE(s.playEnd, 4);
    QCOMPARE(s.background, QColor(250, 240, 220).rgba());
    QCOMPARE(doc.playFirst(), 1);
    QCOMPARE(doc.playLast(), 4);
    doc.undoStack()->undo();
    QVERIFY(doc.settings() == before);

    // OK without changes pushes nothing.
    ui::DocumentSettingsDialog unchanged(&doc);
    QVERIFY(!unchanged.apply());
    QCOMPARE(doc.undoStack()->index(), 0);
}

QTEST_MAIN(TestPlayback)
#include "tst_playback.moc"
