// finbook-bench autosave: what autosave costs the GUI thread on a large document (by default
// 100 frames × 10 objects × 1,000 points = 1M points). Reports the time autosaveNow() blocks
// the calling thread (the snapshot) as median and p99 over many copies, the longest gap of a
// 1 ms GUI timer while the worker writes copies, and how long a copy takes on the worker.
#include "bench.h"

#include <finbook/model/commands.h>
#include <finbook/model/recovery/autosaver.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTimer>

#include <cmath>
#include <cstdio>

namespace {
using namespace finbook::model;

void buildDocument(Document &doc, int frames, int objects, int points)
{
    std::vector<Frame> list;
    for (int f = 0; f < frames; ++f) {
        Frame frame;
        frame.id = doc.allocateId();
        for (int o = 0; o < objects; ++o) {
            StrokeGroup g;
            g.id = doc.allocateId();
            g.name = QStringLiteral("object %1").arg(o + 1);
            for (int s = 0; s < 4; ++s) {
                auto data = std::make_shared<StrokeData>();
                for (int i = 0; i < points / 4; ++i) {
                    const float t = float(i) * 0.01f + float(f) * 0.1f + float(o + s);
                    data->points.push_back({100 + 80 * std::cos(t) + float(o * 90),
                                            300 + 60 * std::sin(1.3f * t), 0.5f});
                }
                g.strokes.push_back({doc.allocateId(), std::move(data)});
            }
            frame.groups.push_back(std::move(g));
        }
        list.push_back(std::move(frame));
    }
    doc.reset(std::move(list), DocumentSettings(), doc.nextId());
}

int runAutosave(const QStringList &args)
{
    const int copies = args.value(0).toInt() > 0 ? args.value(0).toInt() : 40;
    Document doc;
    buildDocument(doc, 100, 10, 1000);
    QTemporaryDir dir;
    RecoverySession session(dir.path());
    Autosaver autosaver(&doc, &session);
    autosaver.setInterval(3600 * 1000); // copies only when asked below
    std::vector<double> stallMs, copyMs, gapsMs;
    QElapsedTimer sinceTick;
    QTimer probe; // the GUI thread's own heartbeat while the worker writes
    probe.setInterval(1);
    QObject::connect(&probe, &QTimer::timeout, [&] {
        if (sinceTick.isValid())
            gapsMs.push_back(double(sinceTick.nsecsElapsed()) / 1e6);
        sinceTick.restart();
    });
    QElapsedTimer written;
    QObject::connect(&autosaver, &Autosaver::copyWritten,
                     [&] { copyMs.push_back(double(written.nsecsElapsed()) / 1e6); });
    probe.start();
    for (int i = 0; i < copies; ++i) {
        // An edit, as drawing makes them, then a copy: what the interval timer does.
        doc.undoStack()->push(new SetFrameHoldCommand(&doc, doc.frameAt(i % 100).id, 1 + i % 5));
        written.start();
        QElapsedTimer clock;
        clock.start();
        autosaver.autosaveNow();
        stallMs.push_back(double(clock.nsecsElapsed()) / 1e6);
        // Keep the GUI loop turning until the copy is on disk, as the editor would.
        const std::size_t before = copyMs.size();
        while (copyMs.size() == before)
            QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 5);
    }
    probe.stop();
    const QJsonObject o{
        {QStringLiteral("bench"), QStringLiteral("autosave")},
        {QStringLiteral("points"), double(doc.pointCount())},
        {QStringLiteral("copies"), copies},
        {QStringLiteral("copy_bytes"), double(QFileInfo(autosaver.copyPath()).size())},
        {QStringLiteral("gui_stall_median_ms"), finbook::bench::median(stallMs)},
        {QStringLiteral("gui_stall_p99_ms"), finbook::bench::percentile(stallMs, 0.99)},
        {QStringLiteral("gui_stall_max_ms"), *std::max_element(stallMs.begin(), stallMs.end())},
        {QStringLiteral("timer_gap_median_ms"), finbook::bench::median(gapsMs)},
        {QStringLiteral("timer_gap_p99_ms"), finbook::bench::percentile(gapsMs, 0.99)},
        {QStringLiteral("copy_on_worker_median_ms"), finbook::bench::median(copyMs)},
        {QStringLiteral("peak_rss_mb"), double(finbook::bench::peakResidentBytes()) / 1e6}};
    std::printf("%s\n", QJsonDocument(o).toJson(QJsonDocument::Compact).constData());
    return 0;
}
} // namespace

FINBOOK_BENCH("autosave", "autosave [COPIES]  GUI-thread stall of autosave on a 1M-point document",
              runAutosave);
