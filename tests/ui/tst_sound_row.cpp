// The soundtrack in the window: File → Import Sound decodes off the GUI thread and adds one
// undoable clip at the current frame (a file that is not sound is refused with a message and
// changes nothing); the sound row draws it under the frames and a drag moves it; playback
// follows the sound player's clock and, with no audio output, runs silently and says so once;
// stepping plays the slice under the frame.
#include "../model/sound_support.h"

#include <finbook/model/commands.h>
#include <finbook/model/export/exporter.h>
#include <finbook/model/sound/sound_cache.h>
#include <finbook/model/sound/sound_mix.h>
#include <finbook/model/sound/soundtrack.h>
#include <finbook/ui/export/export_dialog.h>
#include <finbook/ui/sound/sound_controller.h>
#include <finbook/ui/sound/sound_player.h>
#include <finbook/ui/sound/sound_row.h>
#include <finbook/ui/timeline/playback_controller.h>
#include <finbook/ui/timeline/timeline_view.h>
#include <finbook/ui/timeline/timeline_widget.h>
#include <finbook/ui/window/editor_state.h>

#include <QDockWidget>
#include <QLabel>
#include <QMainWindow>
#include <QSignalSpy>
#include <QTest>

using namespace finbook;
using model::Document;
using model::Id;

namespace {
struct Fixture {
    Document doc;
    std::unique_ptr<ui::EditorState> state;
    std::unique_ptr<ui::PlaybackController> playback;
    std::unique_ptr<ui::TimelineWidget> timeline;
    ui::SoundController *sound = nullptr;
    ui::SoundRow *row = nullptr;
    QTemporaryDir dir;

    explicit Fixture(int frames, int fps = 12)
    {
        for (int i = 0; i < frames; ++i)
            doc.undoStack()->push(new model::InsertFrameCommand(&doc, i));
        model::DocumentSettings s = doc.settings();
        s.fps = fps;
        doc.undoStack()->push(new model::ChangeSettingsCommand(&doc, s));
        doc.undoStack()->clear();
        state = std::make_unique<ui::EditorState>(&doc);
        playback = std::make_unique<ui::PlaybackController>(state.get());
        timeline = std::make_unique<ui::TimelineWidget>(state.get(), nullptr, playback.get());
        sound =
            new ui::SoundController(state.get(), playback.get(), timeline.get(), timeline.get());
        sound->player()->setAudioOutputAllowed(false); // as on CI: no audio device
        row = new ui::SoundRow(sound, timeline->view());
        timeline->addBelowFrames(row);
        timeline->resize(1600, 140);
        timeline->show();
        QVERIFY(QTest::qWaitForWindowExposed(timeline.get()));
        QCoreApplication::processEvents();
    }

    QString write(const QString &name, const QByteArray &bytes)
    {
        QFile f(dir.filePath(name));
        if (f.open(QIODevice::WriteOnly))
            f.write(bytes);
        return f.fileName();
    }

    Id import(const QString &path)
    {
        QSignalSpy done(sound, &ui::SoundController::importFinished);
        sound->importSound(path);
        if (!done.wait(20000))
            return model::kNoId;
        return done.first().first().value<Id>();
    }
};
} // namespace

class TestSoundRow : public QObject {
    Q_OBJECT
private slots:
    void importAddsOneUndoableClipAtTheCurrentFrame();
    void importRefusesWhatIsNotSound();
    void rowDrawsTheClipAndDragMovesIt();
    void clipActionsAreUndoable();
    void soundPastTheLastFrameIsShown();
    void playbackFollowsTheSoundClockSilently();
    void steppingPlaysTheSliceUnderTheFrame();
    void exportDialogSaysWhichFormatsHaveSound();
    void unplayableClipsAreSaidOnce();
    void rowNeverCoversTheFrames();
};

void TestSoundRow::importAddsOneUndoableClipAtTheCurrentFrame()
{
    Fixture f(10);
    f.state->setCurrentFrameIndex(3);
    const Id id = f.import(f.write(QStringLiteral("beat.wav"), sound_test::sineWav(1.0)));
    QVERIFY(id != model::kNoId);
    const model::SoundClip *clip = f.doc.soundtrack().clip(id);
    QVERIFY(clip);
    QCOMPARE(clip->start, qint64(3));
    QCOMPARE(clip->name, QStringLiteral("beat.wav"));
    QCOMPARE(clip->bytes, sound_test::sineWav(1.0)); // the file's bytes, as they were
    QVERIFY(f.sound->cache()->waveform(id));         // decoded once, at import
    QCOMPARE(f.doc.undoStack()->count(), 1);
    f.doc.undoStack()->undo();
    QVERIFY(f.doc.soundtrack().isEmpty());
    f.doc.undoStack()->redo();
    QVERIFY(f.doc.soundtrack().clip(id));
}

void TestSoundRow::importRefusesWhatIsNotSound()
{
    Fixture f(4);
    QSignalSpy failed(f.sound, &ui::SoundController::importFailed);
    QByteArray cut = sound_test::sineWav(3.0);
    cut.truncate(cut.size() / 2);
    for (const QByteArray &bytes : {QByteArray("not a sound at all"), cut}) {
        failed.clear();
        f.sound->importSound(f.write(QStringLiteral("bad.wav"), bytes));
        QVERIFY(failed.wait(20000));
        const QString message = failed.first().at(1).toString();
        QVERIFY2(message.contains(QStringLiteral("bad.wav")), qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("Nothing was changed")), qPrintable(message));
    }
    f.sound->importSound(f.dir.filePath(QStringLiteral("missing.wav")));
    QCOMPARE(failed.count(), 2);
    QVERIFY(f.doc.soundtrack().isEmpty());
    QCOMPARE(f.doc.undoStack()->count(), 0);
}

void TestSoundRow::rowDrawsTheClipAndDragMovesIt()
{
    Fixture f(12);
    const Id id = f.import(f.write(QStringLiteral("beat.wav"), sound_test::sineWav(0.5)));
    QVERIFY(id != model::kNoId);
    // Half a second at 12 fps covers ticks 0 … 6: the clip is under frame 3, not frame 8.
    const int x2 = f.row->xOfTick(2.5);
    const int x9 = f.row->xOfTick(7.5);
    QVERIFY(x2 > 0 && x9 > x2);
    QCOMPARE(f.row->clipAt(x2), id);
    QCOMPARE(f.row->clipAt(x9), model::kNoId);
    const QImage shot = f.row->grab().toImage();
    const int y = f.row->height() / 2;
    QVERIFY(shot.pixelColor(x2, y) != shot.pixelColor(x9, y)); // waveform vs empty row
    // Drag from tick 2.5 to tick 6.5: four ticks later, one command.
    QTest::mousePress(f.row, Qt::LeftButton, {}, QPoint(x2, y));
    QTest::mouseMove(f.row, QPoint((x2 + x9) / 2, y));
    QTest::mouseMove(f.row, QPoint(f.row->xOfTick(6.5), y));
    QCOMPARE(f.row->dragTicks(), qint64(4));
    QCOMPARE(f.doc.soundtrack().clip(id)->start, qint64(0)); // nothing pushed while dragging
    QTest::mouseRelease(f.row, Qt::LeftButton, {}, QPoint(f.row->xOfTick(6.5), y));
    QCOMPARE(f.doc.soundtrack().clip(id)->start, qint64(4));
    QCOMPARE(f.doc.undoStack()->text(f.doc.undoStack()->index() - 1), QStringLiteral("Move Sound"));
    f.doc.undoStack()->undo();
    QCOMPARE(f.doc.soundtrack().clip(id)->start, qint64(0));
    // Escape cancels a drag.
    QTest::mousePress(f.row, Qt::LeftButton, {}, QPoint(x2, y));
    QTest::mouseMove(f.row, QPoint(f.row->xOfTick(8.5), y));
    QTest::keyClick(f.row, Qt::Key_Escape);
    QTest::mouseRelease(f.row, Qt::LeftButton, {}, QPoint(f.row->xOfTick(8.5), y));
    QCOMPARE(f.doc.soundtrack().clip(id)->start, qint64(0));
}

// Issue 45: a sound longer than the animation showed no sign of the part past the last frame.
void TestSoundRow::soundPastTheLastFrameIsShown()
{
    Fixture f(4);
    QCOMPARE(f.row->secondsPastEnd(), 0.0);
    const int lastLeft = f.row->xOfTick(3.0), lastRight = f.row->xOfTick(3.99);
    QVERIFY(lastLeft >= 0 && lastRight > lastLeft);
    const int pastX = lastRight + (lastRight - lastLeft);
    QVERIFY(pastX + 20 < f.row->width());
    const QImage before = f.row->grab().toImage();
    const Id id = f.import(f.write(QStringLiteral("long.wav"), sound_test::sineWav(1.0)));
    QVERIFY(id != model::kNoId);
    // One second at 12 fps: 12 ticks, 8 of them after the 4 frames.
    QTRY_VERIFY(std::abs(f.row->secondsPastEnd() - 8.0 / 12.0) < 0.01);
    const QImage after = f.row->grab().toImage();
    int changed = 0;
    for (int x = pastX; x < f.row->width(); ++x)
        for (int y = 0; y < f.row->height(); ++y)
            changed += before.pixel(x, y) != after.pixel(x, y);
    QVERIFY2(changed > 50, qPrintable(QString::number(changed)));
    f.doc.undoStack()->undo();
    QCOMPARE(f.row->secondsPastEnd(), 0.0);
}

void TestSoundRow::clipActionsAreUndoable()
{
    Fixture f(4);
    const Id id = f.import(f.write(QStringLiteral("beat.wav"), sound_test::sineWav(0.5)));
    f.sound->setMuted(id, true);
    f.sound->setVolume(id, 0.25);
    f.sound->remove(id);
    QVERIFY(f.doc.soundtrack().isEmpty());
    QCOMPARE(f.doc.undoStack()->count(), 4);
    f.doc.undoStack()->undo();
    QVERIFY(f.doc.soundtrack().clip(id)->muted);
    QCOMPARE(f.doc.soundtrack().clip(id)->volume, 0.25);
    f.doc.undoStack()->setIndex(1);
    QVERIFY(!f.doc.soundtrack().clip(id)->muted);
    QCOMPARE(f.doc.soundtrack().clip(id)->volume, 1.0);
}

void TestSoundRow::playbackFollowsTheSoundClockSilently()
{
    Fixture f(24, 24);
    f.import(f.write(QStringLiteral("beat.wav"), sound_test::sineWav(1.0)));
    QSignalSpy silent(f.sound->player(), &ui::SoundPlayer::silent);
    f.state->setCurrentFrameIndex(6);
    f.playback->play();
    QVERIFY(!f.sound->player()->isAudible());
    QCOMPARE(silent.count(), 1); // said once...
    // The player started at frame 7's tick: its source is at that sample.
    QCOMPARE(f.sound->player()->sourcePosition(), model::sampleOfTick(6.0, 24));
    QTRY_VERIFY(f.state->currentFrameIndex() >= 9);
    // The clock the frames follow is the player's (two reads a moment apart).
    const qint64 player = f.sound->player()->nsecsElapsed();
    QVERIFY(player > 0);
    QVERIFY(std::abs(f.playback->elapsedNs() - player) < 1'000'000'000);
    f.playback->pause();
    f.playback->play();
    f.playback->pause();
    QCOMPARE(silent.count(), 1); // ...not again
}

void TestSoundRow::steppingPlaysTheSliceUnderTheFrame()
{
    Fixture f(12);
    const Id id = f.import(f.write(QStringLiteral("beat.wav"), sound_test::sineWav(1.0)));
    QVERIFY(id != model::kNoId);
    f.doc.undoStack()->push(new model::SetFrameHoldCommand(&f.doc, f.doc.frameAt(0).id, 3));
    f.state->setCurrentFrameIndex(2); // starts at tick 3 + 1
    QCOMPARE(ui::startTickOfFrame(f.doc, 2), qint64(4));
    // The silent player still runs the slice through its source: it stands at its start.
    QCOMPARE(f.sound->player()->sourcePosition(), model::sampleOfTick(4.0, 12));
}

void TestSoundRow::exportDialogSaysWhichFormatsHaveSound()
{
    Fixture f(4);
    const auto status = [&f](model::ExportFormat format) {
        ui::ExportDialog dialog(f.doc, QString());
        dialog.setFormat(format);
        return dialog.findChild<QLabel *>(QStringLiteral("export.status"))->text();
    };
    QVERIFY(!status(model::ExportFormat::Gif).contains(QStringLiteral("sound")));
    f.import(f.write(QStringLiteral("beat.wav"), sound_test::sineWav(0.5)));
    if (model::ffmpegProgram().isEmpty())
        QSKIP("the dialog speaks of ffmpeg first");
    for (auto format : {model::ExportFormat::Gif, model::ExportFormat::Apng,
                        model::ExportFormat::PngSequence, model::ExportFormat::SvgSequence})
        QVERIFY2(status(format).contains(QStringLiteral("no sound")), qPrintable(status(format)));
    for (auto format : {model::ExportFormat::Mp4, model::ExportFormat::WebM})
        QVERIFY2(status(format).contains(QStringLiteral("carries the soundtrack")),
                 qPrintable(status(format)));
    QVERIFY(status(model::ExportFormat::Html).contains(QStringLiteral("presses Play")));
}

// In a window as the app lays it out (a bottom dock under a canvas), the dock asks for the
// header, a readable frame strip and the sound row: the row lies under the thumbnails, not
// over them. The dock used to ask for a fixed 120 px, too little once the row was added, and
// the row covered the thumbnails' lower part and the strip's scroll bar.
void TestSoundRow::rowNeverCoversTheFrames()
{
    Document doc;
    for (int i = 0; i < 12; ++i)
        doc.undoStack()->push(new model::InsertFrameCommand(&doc, i));
    ui::EditorState state(&doc);
    ui::PlaybackController playback(&state);
    QMainWindow window;
    auto *canvas = new QWidget(&window);
    canvas->setMinimumSize(200, 150);
    window.setCentralWidget(canvas);
    auto *timeline = new ui::TimelineWidget(&state, nullptr, &playback);
    auto *sound = new ui::SoundController(&state, &playback, timeline, timeline);
    sound->player()->setAudioOutputAllowed(false);
    auto *row = new ui::SoundRow(sound, timeline->view());
    timeline->addBelowFrames(row);
    auto *dock = new QDockWidget(QStringLiteral("Timeline"), &window);
    dock->setWidget(timeline);
    window.addDockWidget(Qt::BottomDockWidgetArea, dock);
    window.resize(1280, 860);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QCoreApplication::processEvents();

    ui::TimelineView *view = timeline->view();
    QVERIFY2(view->geometry().bottom() < row->geometry().top(),
             qPrintable(QStringLiteral("strip ends at %1, the sound row starts at %2")
                            .arg(view->geometry().bottom())
                            .arg(row->geometry().top())));
    QVERIFY(row->geometry().bottom() < timeline->height());
    QVERIFY(view->height() >= view->minimumHeight());
    // The cells fit the strip: no thumbnail is cut at the bottom.
    const QRect cell = view->visualRect(view->model()->index(0, 0));
    QVERIFY(cell.isValid());
    QVERIFY2(cell.bottom() <= view->viewport()->height(),
             qPrintable(QStringLiteral("cell ends at %1 in a viewport of %2")
                            .arg(cell.bottom())
                            .arg(view->viewport()->height())));
}

QTEST_MAIN(TestSoundRow)
// Issue 47: a document of 256 clips that cannot be played (7 KB WAVs at 1 Hz, which once
// asked for 5 GB each) opens with one message that counts them, and costs nothing.
void TestSoundRow::unplayableClipsAreSaidOnce()
{
    Fixture f(2);
    QSignalSpy said(f.sound, &ui::SoundController::message);
    QSignalSpy failed(f.sound->cache(), &model::SoundCache::soundFailed);
    const QByteArray oneHertz = sound_test::sineWav(3500, 1, 0.1);
    auto *macro = new QUndoCommand(QStringLiteral("clips"));
    for (int i = 0; i < model::kMaxSoundClips; ++i) {
        model::SoundClip clip;
        clip.name = QStringLiteral("slow%1.wav").arg(i);
        clip.bytes = oneHertz;
        new model::AddSoundClipCommand(&f.doc, clip, macro);
    }
    f.doc.undoStack()->push(macro);
    QTRY_COMPARE_WITH_TIMEOUT(failed.count(), model::kMaxSoundClips, 20000);
    QTRY_COMPARE(said.count(), 1);
    const QString text = said.first().first().toString();
    QVERIFY2(text.contains(QStringLiteral("256")) && text.contains(QStringLiteral("1 Hz")),
             qPrintable(text));
    QTest::qWait(300);
    QCOMPARE(said.count(), 1);
}

#include "tst_sound_row.moc"
