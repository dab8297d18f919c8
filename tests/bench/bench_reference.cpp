// finbook-bench reference: scrubbing a video reference. Generates a 1080p video with ffmpeg's
// testsrc (by default 60 s at 25 fps, H.264 with ffmpeg's default keyframe interval) in a
// temporary folder, imports it as a document's reference and shows 500 frames: a forward
// sweep, the same sweep backwards, then random jumps. Each "frame shown" is what the canvas
// does: the picture under the frame (decoded or cached) painted onto a canvas-sized image.
// Prints per phase the median and p99 time per frame, frames decoded, and the peak RSS.
#include "bench.h"

#include <finbook/model/document.h>
#include <finbook/model/reference/reference_commands.h>
#include <finbook/model/reference/reference_layer.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPainter>
#include <QProcess>
#include <QRandomGenerator>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <cstdio>

namespace {
using namespace finbook::model;

QString makeVideo(const QString &folder, int seconds, int fps, int gop)
{
    const QString path = folder + QStringLiteral("/reference.mp4");
    QStringList args{
        QStringLiteral("-v"),
        QStringLiteral("error"),
        QStringLiteral("-y"),
        QStringLiteral("-f"),
        QStringLiteral("lavfi"),
        QStringLiteral("-i"),
        QStringLiteral("testsrc=size=1920x1080:rate=%1:duration=%2").arg(fps).arg(seconds),
        QStringLiteral("-c:v"),
        QStringLiteral("libx264"),
        QStringLiteral("-preset"),
        QStringLiteral("veryfast"),
        QStringLiteral("-pix_fmt"),
        QStringLiteral("yuv420p")};
    if (gop > 0)
        args << QStringLiteral("-g") << QString::number(gop);
    args << path;
    QProcess p;
    p.start(QStringLiteral("ffmpeg"), args);
    if (!p.waitForFinished(-1) || p.exitCode() != 0)
        return {};
    return path;
}

int run(const QStringList &args)
{
    int seconds = 60, fps = 25, gop = 0, shown = 500, cacheMb = 256;
    for (const QString &a : args) {
        if (a.startsWith(QLatin1String("--seconds=")))
            seconds = a.mid(10).toInt();
        else if (a.startsWith(QLatin1String("--fps=")))
            fps = a.mid(6).toInt();
        else if (a.startsWith(QLatin1String("--gop=")))
            gop = a.mid(6).toInt();
        else if (a.startsWith(QLatin1String("--frames=")))
            shown = a.mid(9).toInt();
        else if (a.startsWith(QLatin1String("--cache-mb=")))
            cacheMb = a.mid(11).toInt();
    }
    if (QStandardPaths::findExecutable(QStringLiteral("ffmpeg")).isEmpty()) {
        std::fprintf(stderr, "finbook-bench reference: needs the ffmpeg program\n");
        return 1;
    }
    QTemporaryDir dir;
    QElapsedTimer clock;
    clock.start();
    const QString video = makeVideo(dir.path(), seconds, fps, gop);
    if (video.isEmpty()) {
        std::fprintf(stderr, "finbook-bench reference: ffmpeg could not make the video\n");
        return 1;
    }
    const double generateSeconds = clock.nsecsElapsed() / 1e9;

    Document doc;
    DocumentSettings settings;
    settings.canvasSize = QSize(1920, 1080);
    settings.fps = fps;
    std::vector<Frame> frames(static_cast<std::size_t>(seconds * fps));
    for (Frame &f : frames)
        f.id = doc.allocateId();
    doc.reset(std::move(frames), settings, doc.nextId());
    clock.restart();
    auto reference = importReferenceFile(video, QSizeF(settings.canvasSize));
    if (!reference) {
        std::fprintf(stderr, "%s\n", qPrintable(reference.error()));
        return 1;
    }
    doc.undoStack()->push(importReferenceCommand(&doc, std::move(*reference)).release());
    const ReferenceLayer &layer = doc.referenceLayer();
    layer.media()->setCacheLimit(qint64(cacheMb) << 20);
    const double importSeconds = clock.nsecsElapsed() / 1e9;

    QImage canvas(960, 540, QImage::Format_ARGB32_Premultiplied);
    const auto show = [&](int frame) {
        QElapsedTimer t;
        t.start();
        const QImage picture = layer.pictureAt(frame);
        QPainter painter(&canvas);
        painter.scale(0.5, 0.5);
        paintReference(painter, layer.reference(), picture);
        return t.nsecsElapsed() / 1e6;
    };
    const int count = doc.frameCount();
    const int start = std::max(0, count / 2 - shown / 4);
    const auto phase = [&](const char *name, const std::vector<int> &order) {
        const qint64 decodedBefore = layer.media()->decodedFrames();
        std::vector<double> ms;
        for (int f : order)
            ms.push_back(show(f));
        QJsonObject o{
            {QStringLiteral("bench"), QStringLiteral("reference")},
            {QStringLiteral("phase"), QString::fromLatin1(name)},
            {QStringLiteral("framesShown"), int(order.size())},
            {QStringLiteral("medianMs"), finbook::bench::median(ms)},
            {QStringLiteral("p99Ms"), finbook::bench::percentile(ms, 0.99)},
            {QStringLiteral("maxMs"), *std::max_element(ms.begin(), ms.end())},
            {QStringLiteral("framesDecoded"),
             double(layer.media()->decodedFrames() - decodedBefore)},
            {QStringLiteral("cacheMB"), double(layer.media()->cacheBytes()) / 1048576.0},
            {QStringLiteral("peakRssMB"), double(finbook::bench::peakResidentBytes()) / 1048576.0}};
        std::printf("%s\n", QJsonDocument(o).toJson(QJsonDocument::Compact).constData());
        std::fflush(stdout);
    };
    // Back and forth: `shown` frames in all, half forward from `start`, half back again.
    std::vector<int> forward, backward, random;
    for (int i = 0; i < shown / 2; ++i)
        forward.push_back(std::min(count - 1, start + i));
    backward.assign(forward.rbegin(), forward.rend());
    QRandomGenerator rng(24);
    for (int i = 0; i < 50; ++i)
        random.push_back(int(rng.bounded(count)));
    phase("forward", forward);
    phase("backward", backward);
    phase("random", random);
    // What the canvas does: it asks without waiting (the GUI thread's cost) and a worker
    // decodes; measured over fresh random jumps, with the time until the frame is ready.
    {
        ReferenceLayer &canvasLayer = doc.referenceLayer();
        std::vector<double> asking, ready;
        for (int i = 0; i < 30; ++i) {
            const int frame = int(rng.bounded(count));
            QElapsedTimer t;
            t.start();
            canvasLayer.pictureWithoutWaiting(frame);
            asking.push_back(t.nsecsElapsed() / 1e6);
            const qint64 want = canvasLayer.videoFrameAt(frame);
            while (canvasLayer.media()->cachedFrame(want).isNull())
                QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
            ready.push_back(t.nsecsElapsed() / 1e6);
        }
        QJsonObject o{{QStringLiteral("bench"), QStringLiteral("reference")},
                      {QStringLiteral("phase"), QStringLiteral("canvasRandom")},
                      {QStringLiteral("guiMedianMs"), finbook::bench::median(asking)},
                      {QStringLiteral("guiP99Ms"), finbook::bench::percentile(asking, 0.99)},
                      {QStringLiteral("readyMedianMs"), finbook::bench::median(ready)},
                      {QStringLiteral("readyP99Ms"), finbook::bench::percentile(ready, 0.99)}};
        std::printf("%s\n", QJsonDocument(o).toJson(QJsonDocument::Compact).constData());
    }
    QJsonObject summary{
        {QStringLiteral("bench"), QStringLiteral("reference")},
        {QStringLiteral("phase"), QStringLiteral("setup")},
        {QStringLiteral("videoSeconds"), seconds},
        {QStringLiteral("fps"), fps},
        {QStringLiteral("videoMB"), double(QFileInfo(video).size()) / 1048576.0},
        {QStringLiteral("generateSeconds"), generateSeconds},
        {QStringLiteral("importSeconds"), importSeconds},
        {QStringLiteral("cacheLimitMB"), cacheMb},
        {QStringLiteral("peakRssMB"), double(finbook::bench::peakResidentBytes()) / 1048576.0}};
    std::printf("%s\n", QJsonDocument(summary).toJson(QJsonDocument::Compact).constData());
    return 0;
}
} // namespace

FINBOOK_BENCH("reference",
              "[--seconds=60] [--fps=25] [--gop=N] [--frames=500] [--cache-mb=256]: scrub a "
              "generated 1080p video reference; time per frame shown and peak RSS",
              run);
