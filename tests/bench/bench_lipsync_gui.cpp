// finbook-bench lipsync-gui [--sentences N] [--with-text]: Deform > Lip Sync… as the window runs
// it. For each of the first N sentences of tests/bench/lipsync_sentences.txt, espeak-ng speaks
// it to a WAV, which becomes the soundtrack of a document holding a mouth chart on its own
// layer; the Lip Sync dialog recognises it on its worker and keys the mouth. Printed per
// sentence: the GUI thread's stalls meanwhile (a 2 ms timer's lateness, p99 and max, keying
// included), the time until keyed, and the cels the mouth's layer ends with. Summary: the worst
// stall (target: under 16 ms, so the window never drops a frame at 60 Hz).
#include "bench.h"

#include <finbook/model/commands.h>
#include <finbook/model/scene/layer_commands.h>
#include <finbook/model/sound/sound_commands.h>
#include <finbook/model/swap/mouth_chart.h>
#include <finbook/model/swap/swap_commands.h>
#include <finbook/ui/lipsync/lip_sync_dialog.h>
#include <finbook/ui/window/editor_state.h>

#include <QComboBox>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QPlainTextEdit>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cstdio>

using namespace finbook;

namespace {

QStringList sentences(int count)
{
    QFile file(QStringLiteral(FINBOOK_SOURCE_DIR "/tests/bench/lipsync_sentences.txt"));
    QStringList out;
    if (file.open(QIODevice::ReadOnly))
        for (const QByteArray &line : file.readAll().split('\n'))
            if (!line.trimmed().isEmpty() && !line.startsWith('#') && out.size() < count)
                out << QString::fromUtf8(line.trimmed());
    return out;
}

// A document with a mouth chart on its own layer and `wav` as its soundtrack; the mouth's id.
model::Id buildShot(model::Document &doc, const QByteArray &wav)
{
    std::vector<model::Frame> frames(1);
    frames[0].id = 1;
    frames[0].hold = 24;
    model::DocumentSettings settings;
    settings.fps = 24;
    doc.reset(std::move(frames), settings, 2);
    auto *layer = new model::AddLayerCommand(&doc, 1, QStringLiteral("Mouth"));
    doc.undoStack()->push(layer);
    const model::Id mouth = doc.layer(layer->layerId())->cels.front().groups.front().id;
    doc.undoStack()->push(new model::NewSwapSetCommand(
        &doc, mouth, model::mouthChart(doc, QPointF(640, 360), 60, 0xff000000, 2.0f), 8));
    model::SoundClip clip;
    clip.name = QStringLiteral("speech.wav");
    clip.bytes = wav;
    doc.undoStack()->push(new model::AddSoundClipCommand(&doc, clip));
    doc.setCurrentLayer(layer->layerId());
    return mouth;
}

int benchLipSyncGui(const QStringList &args)
{
    const int at = int(args.indexOf(QStringLiteral("--sentences")));
    const int count = at >= 0 && at + 1 < args.size() ? args[at + 1].toInt() : 10;
    const bool withText = args.contains(QStringLiteral("--with-text"));
    const QString espeak = QStandardPaths::findExecutable(QStringLiteral("espeak-ng"));
    if (espeak.isEmpty()) {
        std::fprintf(stderr, "lipsync-gui: espeak-ng is not installed\n");
        return 1;
    }
    QTemporaryDir dir;
    double worst = 0;
    std::vector<double> allLate;
    int index = 0;
    for (const QString &sentence : sentences(count)) {
        const QString wavPath = dir.filePath(QStringLiteral("s%1.wav").arg(index));
        QProcess::execute(espeak, {QStringLiteral("-w"), wavPath, sentence});
        QFile wav(wavPath);
        if (!wav.open(QIODevice::ReadOnly))
            return 1;
        model::Document doc;
        const model::Id mouth = buildShot(doc, wav.readAll());
        ui::EditorState state(&doc);
        ui::LipSyncDialog dialog(&state, mouth);
        if (withText)
            dialog.dialogue()->setPlainText(sentence);
        std::vector<double> lateMs;
        QTimer probe;
        probe.setTimerType(Qt::PreciseTimer);
        QElapsedTimer sinceTick, clock;
        QObject::connect(&probe, &QTimer::timeout, [&] {
            lateMs.push_back(std::max(0.0, double(sinceTick.nsecsElapsed()) / 1e6 - 2.0));
            sinceTick.restart();
        });
        QEventLoop loop;
        QTimer done;
        QObject::connect(&done, &QTimer::timeout, [&] {
            if (!dialog.isRunning())
                loop.quit();
        });
        const int stepsBefore = doc.undoStack()->count();
        clock.start();
        sinceTick.start();
        probe.start(2);
        dialog.run();
        done.start(5);
        loop.exec();
        probe.stop();
        const double ms = double(clock.nsecsElapsed()) / 1e6;
        const double maxLate =
            lateMs.empty() ? 0.0 : *std::max_element(lateMs.begin(), lateMs.end());
        worst = std::max(worst, maxLate);
        allLate.insert(allLate.end(), lateMs.begin(), lateMs.end());
        std::printf("{\"bench\":\"lipsync-gui\",\"sentence\":%d,\"keyed\":%s,\"ms\":%.0f,"
                    "\"gui_stall_p99_ms\":%.2f,\"gui_stall_max_ms\":%.2f,\"mouth_cels\":%d}\n",
                    index, doc.undoStack()->count() > stepsBefore ? "true" : "false", ms,
                    bench::percentile(lateMs, 0.99), maxLate, int(doc.currentLayer().cels.size()));
        ++index;
    }
    std::printf("{\"bench\":\"lipsync-gui\",\"summary\":true,\"sentences\":%d,\"with_text\":%s,"
                "\"gui_stall_p99_ms\":%.2f,\"gui_stall_max_ms\":%.2f}\n",
                index, withText ? "true" : "false", bench::percentile(allLate, 0.99), worst);
    return 0;
}

} // namespace

FINBOOK_BENCH("lipsync-gui",
              "[--sentences N] [--with-text]  GUI stalls while Lip Sync recognises and keys",
              benchLipSyncGui);
