// Deform > Lip Sync… (issue 49) on a mouth chart with a spoken clip: recognised on a worker and
// keyed as one undo step, closures on closed mouths; Cancel, a damaged clip and timings files
// that do not read change nothing and say why; without the speech models the mouth follows the
// loudness and the dialog says so.
#include <finbook/model/commands.h>
#include <finbook/model/scene/layer_commands.h>
#include <finbook/model/sound/sound_commands.h>
#include <finbook/model/swap/mouth_chart.h>
#include <finbook/model/swap/swap_commands.h>
#include <finbook/ui/lipsync/lip_sync_dialog.h>
#include <finbook/ui/window/editor_state.h>

#include <QComboBox>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProcess>
#include <QPushButton>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace finbook;

class TestLipSyncDialog : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void keysTheMouthFromSpeechAndText();
    void cancelChangesNothing();
    void aDamagedClipChangesNothing();
    void withoutModelsTheMouthFollowsLoudness();
    void importsTimingsAndRefusesDamagedOnes();
    void withoutSoundOnlyImportIsOffered();

private:
    // A shot at 24 fps: a character layer, a mouth chart on its own layer, and `wav` (if any) as
    // its sound from frame 3.
    model::Id build(model::Document &doc, const QByteArray &wav);
    bool waitDone(ui::LipSyncDialog &dialog)
    {
        return QTest::qWaitFor([&] { return !dialog.isRunning(); }, 60000);
    }
    // The shape letter each tick of the mouth's layer shows.
    QString shown(const model::Document &doc) const;

    QTemporaryDir m_dir;
    QByteArray m_wav;
};

void TestLipSyncDialog::initTestCase()
{
    const QString espeak = QStandardPaths::findExecutable(QStringLiteral("espeak-ng"));
    if (espeak.isEmpty())
        QSKIP("espeak-ng is not installed");
    const QString path = m_dir.filePath(QStringLiteral("bob.wav"));
    QCOMPARE(QProcess::execute(
                 espeak, {QStringLiteral("-w"), path, QStringLiteral("Bob made my mom a pie.")}),
             0);
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    m_wav = f.readAll();
}

model::Id TestLipSyncDialog::build(model::Document &doc, const QByteArray &wav)
{
    std::vector<model::Frame> frames(1);
    frames[0].id = 1;
    frames[0].hold = 48;
    model::DocumentSettings settings;
    settings.fps = 24;
    doc.reset(std::move(frames), settings, 2);
    auto *layer = new model::AddLayerCommand(&doc, 1, QStringLiteral("Mouth"));
    doc.undoStack()->push(layer);
    const model::Id mouth = doc.layer(layer->layerId())->cels.front().groups.front().id;
    doc.undoStack()->push(new model::NewSwapSetCommand(
        &doc, mouth, model::mouthChart(doc, QPointF(300, 200), 60, 0xff000000, 2.0f), 8));
    if (!wav.isEmpty()) {
        model::SoundClip clip;
        clip.name = QStringLiteral("bob.wav");
        clip.bytes = wav;
        clip.start = 2;
        doc.undoStack()->push(new model::AddSoundClipCommand(&doc, clip));
    }
    doc.setCurrentLayer(layer->layerId());
    doc.undoStack()->clear();
    return mouth;
}

QString TestLipSyncDialog::shown(const model::Document &doc) const
{
    QString out;
    for (const model::Frame &cel : doc.currentLayer().cels) {
        QChar letter = QLatin1Char('-');
        for (const model::StrokeGroup &g : cel.groups)
            if (const model::SwapDrawing *d = doc.swapDrawing(g.swap))
                letter = d->name.front();
        out += QString(cel.hold, letter);
    }
    return out;
}

void TestLipSyncDialog::keysTheMouthFromSpeechAndText()
{
    model::Document doc;
    const model::Id mouth = build(doc, m_wav);
    ui::EditorState state(&doc);
    ui::LipSyncDialog dialog(&state, mouth);
    QCOMPARE(dialog.clips()->count(), 1);
    dialog.dialogue()->setPlainText(QStringLiteral("Bob made my mom a pie."));
    dialog.run();
    QVERIFY(dialog.isRunning());
    QVERIFY(dialog.progress()->isVisible() || !dialog.isVisible());
    QVERIFY(waitDone(dialog));
    QVERIFY2(dialog.status()->text().contains(QStringLiteral("Keyed")),
             qPrintable(dialog.status()->text()));
    QCOMPARE(doc.undoStack()->count(), 1);
    const QString keys = shown(doc);
    // Rest before the clip starts (frames 1–2), then speech with closed mouths for B, M, P,
    // and rest at the end.
    QVERIFY2(keys.startsWith(QStringLiteral("XX")), qPrintable(keys));
    QVERIFY2(keys.count(QLatin1Char('A')) >= 4, qPrintable(keys));
    QVERIFY2(keys.contains(QLatin1Char('D')) || keys.contains(QLatin1Char('C')), qPrintable(keys));
    QVERIFY2(keys.endsWith(QLatin1Char('X')), qPrintable(keys));
    QVERIFY(doc.currentLayer().cels.size() > 5);
    // One step takes it all back; running again replaces what it keyed.
    doc.undoStack()->undo();
    QCOMPARE(doc.currentLayer().cels.size(), std::size_t(1));
    doc.undoStack()->redo();
    dialog.run();
    QVERIFY(waitDone(dialog));
    QCOMPARE(shown(doc), keys);
}

void TestLipSyncDialog::cancelChangesNothing()
{
    model::Document doc;
    const model::Id mouth = build(doc, m_wav);
    ui::EditorState state(&doc);
    ui::LipSyncDialog dialog(&state, mouth);
    dialog.run();
    dialog.cancel();
    QVERIFY(waitDone(dialog));
    QVERIFY2(dialog.status()->text().contains(QStringLiteral("Cancelled")),
             qPrintable(dialog.status()->text()));
    QCOMPARE(doc.undoStack()->count(), 0);
}

void TestLipSyncDialog::aDamagedClipChangesNothing()
{
    model::Document doc;
    QByteArray damaged = m_wav.left(44); // a WAV header and no sound
    damaged.append(QByteArray(7, '\x7f'));
    const model::Id mouth = build(doc, damaged);
    ui::EditorState state(&doc);
    ui::LipSyncDialog dialog(&state, mouth);
    dialog.run();
    QVERIFY(waitDone(dialog));
    QVERIFY2(dialog.status()->text().contains(QStringLiteral("Nothing was changed")),
             qPrintable(dialog.status()->text()));
    QCOMPARE(doc.undoStack()->count(), 0);
}

void TestLipSyncDialog::withoutModelsTheMouthFollowsLoudness()
{
    qputenv("FINBOOK_SPEECH_MODEL_DIR", m_dir.filePath(QStringLiteral("no-models")).toUtf8());
    model::Document doc;
    const model::Id mouth = build(doc, m_wav);
    ui::EditorState state(&doc);
    ui::LipSyncDialog dialog(&state, mouth);
    const QList<QLabel *> labels = dialog.findChildren<QLabel *>();
    const bool saysSo = std::any_of(labels.begin(), labels.end(), [](const QLabel *l) {
        return l->text().contains(QStringLiteral("loudness"));
    });
    dialog.run();
    const bool done = waitDone(dialog);
    qunsetenv("FINBOOK_SPEECH_MODEL_DIR");
    QVERIFY(saysSo);
    QVERIFY(done);
    QVERIFY2(dialog.status()->text().contains(QStringLiteral("loudness")),
             qPrintable(dialog.status()->text()));
    const QString keys = shown(doc);
    // Closed, half open and open only.
    for (const QChar c : keys)
        QVERIFY2(c == QLatin1Char('X') || c == QLatin1Char('B') || c == QLatin1Char('D'),
                 qPrintable(keys));
    QVERIFY2(keys.contains(QLatin1Char('D')), qPrintable(keys));
}

void TestLipSyncDialog::importsTimingsAndRefusesDamagedOnes()
{
    model::Document doc;
    const model::Id mouth = build(doc, m_wav);
    ui::EditorState state(&doc);
    ui::LipSyncDialog dialog(&state, mouth);
    // Rhubarb's TSV: seconds and a shape; from the clip's first frame (frame 3).
    const QString tsv = m_dir.filePath(QStringLiteral("bob.tsv"));
    QFile f(tsv);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("0.00\tX\n0.25\tA\n0.5\tD\n0.75\tX\n");
    f.close();
    QVERIFY(dialog.importTimings(tsv));
    QCOMPARE(doc.undoStack()->count(), 1);
    QVERIFY2(shown(doc).startsWith(QStringLiteral("XXXXXXXXAAAAAADDDDDDX")),
             qPrintable(shown(doc)));
    // A damaged one: the line is named, nothing changes.
    const QString bad = m_dir.filePath(QStringLiteral("bad.tsv"));
    QFile g(bad);
    QVERIFY(g.open(QIODevice::WriteOnly));
    g.write("0.00\tX\n0.25\tQ\n");
    g.close();
    QVERIFY(!dialog.importTimings(bad));
    QVERIFY2(dialog.status()->text().contains(QStringLiteral("bad.tsv")),
             qPrintable(dialog.status()->text()));
    QVERIFY2(dialog.status()->text().contains(QLatin1Char('2')),
             qPrintable(dialog.status()->text()));
    QCOMPARE(doc.undoStack()->count(), 1);
}

void TestLipSyncDialog::withoutSoundOnlyImportIsOffered()
{
    model::Document doc;
    const model::Id mouth = build(doc, {});
    ui::EditorState state(&doc);
    ui::LipSyncDialog dialog(&state, mouth);
    QVERIFY(!dialog.runButton()->isEnabled());
    QVERIFY(dialog.importButton()->isEnabled());
    QVERIFY(dialog.status()->text().contains(QStringLiteral("no sound")));
}

QTEST_MAIN(TestLipSyncDialog)
#include "tst_lip_sync_dialog.moc"
