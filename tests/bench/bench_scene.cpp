// finbook-bench scene [--layers 3] [--ticks 2000]: a long shot of several layers (issue 46) —
// a background exposed once, a character with a new drawing every 2 ticks, a third layer with
// one every tick (more layers repeat the character), and 200 camera keys. Prints its open and
// save time, file size, peak memory, playback jitter at 24 fps (how late each tick reaches the
// screen against the clock, the real canvas painting every tick), the time to show a new tick
// when scrubbing (the real canvas repainted), and the time to render one exported picture
// through the camera. Figures only: nothing here gates on time.
#include "bench.h"

#include <finbook/model/camera/camera_track.h>
#include <finbook/model/export/export_plan.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/scene/shot.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/timeline/playback_controller.h>
#include <finbook/ui/window/editor_state.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <cmath>
#include <cstdio>
#include <random>

using namespace finbook;

namespace {

int intArgument(const QStringList &args, const QString &name, int fallback)
{
    const int at = int(args.indexOf(name));
    return at >= 0 && at + 1 < args.size() ? std::max(1, args[at + 1].toInt()) : fallback;
}

// An object of `strokes` wandering strokes of `points` points around `centre`.
model::StrokeGroup scribble(model::Id &next, std::mt19937 &rng, QPointF centre, int strokes,
                            int points, float reach)
{
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    model::StrokeGroup g;
    g.id = next++;
    for (int s = 0; s < strokes; ++s) {
        auto data = std::make_shared<model::StrokeData>();
        data->width = 3.0f;
        float x = float(centre.x()) + (unit(rng) - 0.5f) * reach;
        float y = float(centre.y()) + (unit(rng) - 0.5f) * reach;
        float heading = unit(rng) * 6.283f;
        for (int i = 0; i < points; ++i) {
            heading += (unit(rng) - 0.5f) * 0.4f;
            x += 2.5f * std::cos(heading);
            y += 2.5f * std::sin(heading);
            data->points.push_back({x, y, 0.3f + 0.6f * unit(rng)});
        }
        g.strokes.push_back({next++, std::move(data)});
    }
    return g;
}

// A layer of drawings held `hold` ticks each over `ticks` ticks.
model::Layer layerOf(model::Id &next, std::mt19937 &rng, const QString &name, qint64 ticks,
                     int hold, int strokes, int points, QPointF centre, float reach)
{
    model::Layer l;
    l.id = next++;
    l.properties.name = name;
    for (qint64 t = 0; t < ticks; t += hold) {
        model::Frame cel;
        cel.id = next++;
        cel.hold = int(std::min<qint64>(hold, ticks - t));
        cel.groups.push_back(scribble(next, rng, centre, strokes, points, reach));
        l.cels.push_back(std::move(cel));
    }
    return l;
}

void buildScene(model::Document &doc, int layers, qint64 ticks)
{
    std::mt19937 rng(46);
    model::Id next = 1;
    std::vector<model::Layer> list;
    model::Layer background =
        layerOf(next, rng, QStringLiteral("Background"), ticks,
                int(std::min<qint64>(ticks, model::kMaxHold)), 20, 400, QPointF(640, 360), 1000);
    background.properties.depth = 1.0;
    list.push_back(std::move(background));
    for (int i = 1; i < layers; ++i) {
        const bool everyTick = i == 2;
        list.push_back(layerOf(
            next, rng, everyTick ? QStringLiteral("Mouth") : QStringLiteral("Character %1").arg(i),
            ticks, everyTick ? 1 : 2, everyTick ? 2 : 12, everyTick ? 40 : 200,
            QPointF(400 + 120 * i, 380), everyTick ? 40 : 300));
    }
    model::DocumentSettings settings;
    settings.fps = 24;
    doc.reset(std::move(list), settings, next);
    model::CameraTrack camera;
    for (int k = 0; k < 200; ++k) {
        model::CameraKey key;
        key.tick = ticks * k / 200;
        key.center = QPointF(640 + 200 * std::sin(k * 0.3), 360 + 60 * std::cos(k * 0.2));
        key.zoom = 1.0 + 0.5 * (k % 3);
        key.easing = model::CameraEasing(k % 4);
        camera.keys.push_back(key);
    }
    doc.setCamera(camera);
}

double msSince(const QElapsedTimer &clock)
{
    return double(clock.nsecsElapsed()) / 1e6;
}

int benchScene(const QStringList &args)
{
    const int layers = intArgument(args, QStringLiteral("--layers"), 3);
    const qint64 ticks = intArgument(args, QStringLiteral("--ticks"), 2000);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("scene.finbook"));
    double saveMs = 0, openMs = 0;
    {
        model::Document built;
        buildScene(built, layers, ticks);
        QElapsedTimer clock;
        clock.start();
        if (auto error = model::saveFinbook(built, path)) {
            std::fprintf(stderr, "%s\n", qPrintable(error->message));
            return 1;
        }
        saveMs = msSince(clock);
    }
    model::Document doc;
    QElapsedTimer clock;
    clock.start();
    if (auto error = model::openFinbook(doc, path)) {
        std::fprintf(stderr, "%s\n", qPrintable(error->message));
        return 1;
    }
    openMs = msSince(clock);

    ui::EditorState state(&doc);
    ui::CanvasWidget canvas(&state);
    canvas.resize(1280, 760);
    canvas.show();
    state.setCameraView(true); // the shot, every layer through the camera
    QApplication::processEvents();

    // Scrubbing: the playhead put on a random tick, the canvas repainted at once; on the page
    // (the other layers cached under and over the current one) and in Camera View.
    std::mt19937 rng(7);
    std::vector<double> scrubMs, scrubCameraMs;
    for (bool camera : {false, true}) {
        state.setCameraView(camera);
        for (int i = 0; i < 120; ++i) {
            state.setCurrentTick(qint64(rng() % quint32(ticks)));
            QElapsedTimer shown;
            shown.start();
            canvas.repaint();
            (camera ? scrubCameraMs : scrubMs).push_back(msSince(shown));
        }
    }

    // Playback at 24 fps for 240 ticks: frame-time jitter, how far the time between two
    // shown ticks is from what their distance in ticks asks (41.7 ms a tick), the canvas
    // painting each one (in Camera View: the shot as the audience sees it).
    ui::PlaybackController playback(&state);
    std::vector<double> lateMs;
    QElapsedTimer playClock;
    qint64 lastTick = -1;
    QObject::connect(&state, &ui::EditorState::tickChanged, &canvas, [&](qint64 tick) {
        if (!state.isPlaying() || tick < 0)
            return;
        canvas.repaint(); // what reaching the screen costs
        if (lastTick >= 0 && tick > lastTick)
            lateMs.push_back(
                std::abs(msSince(playClock) - double(tick - lastTick) * 1000.0 / 24.0));
        lastTick = tick;
        playClock.start();
    });
    state.setCurrentTick(0);
    playback.play();
    QElapsedTimer run;
    run.start();
    while (run.elapsed() < 10000 && lateMs.size() < 240)
        QApplication::processEvents(QEventLoop::WaitForMoreEvents, 5);
    playback.pause();

    // One exported picture through the camera, in the middle of the shot.
    const model::ExportSource source = model::exportSource(doc);
    const auto plan = model::planExport(source, model::ExportOptions{});
    std::vector<double> exportMs;
    if (plan && !plan->frames.empty()) {
        const std::size_t entry = plan->frames.size() / 2;
        for (int i = 0; i < 5; ++i) {
            QElapsedTimer rendered;
            rendered.start();
            const QImage picture = model::renderExportFrame(
                source.frames[std::size_t(plan->frames[entry])], source.settings, *plan, nullptr,
                {}, plan->cameras.empty() ? nullptr : &plan->cameras[entry]);
            exportMs.push_back(msSince(rendered));
        }
    }
    qint64 cels = 0;
    for (const model::Layer &l : doc.layers())
        cels += qint64(l.cels.size());
    const QJsonObject o{
        {QStringLiteral("bench"), QStringLiteral("scene")},
        {QStringLiteral("layers"), layers},
        {QStringLiteral("ticks"), double(ticks)},
        {QStringLiteral("cels"), double(cels)},
        {QStringLiteral("points"), double(doc.pointCount())},
        {QStringLiteral("camera_keys"), double(doc.camera().keys.size())},
        {QStringLiteral("save_ms"), saveMs},
        {QStringLiteral("open_ms"), openMs},
        {QStringLiteral("file_mb"), double(QFileInfo(path).size()) / 1e6},
        {QStringLiteral("playback_ticks"), double(lateMs.size())},
        {QStringLiteral("playback_jitter_p50_ms"), finbook::bench::median(lateMs)},
        {QStringLiteral("playback_jitter_p99_ms"), finbook::bench::percentile(lateMs, 0.99)},
        {QStringLiteral("scrub_p50_ms"), finbook::bench::median(scrubMs)},
        {QStringLiteral("scrub_p99_ms"), finbook::bench::percentile(scrubMs, 0.99)},
        {QStringLiteral("scrub_camera_view_p50_ms"), finbook::bench::median(scrubCameraMs)},
        {QStringLiteral("scrub_camera_view_p99_ms"),
         finbook::bench::percentile(scrubCameraMs, 0.99)},
        {QStringLiteral("export_frame_ms"),
         exportMs.empty() ? -1.0 : finbook::bench::median(exportMs)},
        {QStringLiteral("peak_rss_mb"), double(finbook::bench::peakResidentBytes()) / 1e6}};
    std::printf("%s\n", QJsonDocument(o).toJson(QJsonDocument::Compact).constData());
    return 0;
}

} // namespace

FINBOOK_BENCH("scene",
              "[--layers 3] [--ticks 2000] (a long layered shot: open, save, playback, "
              "scrub, export)",
              benchScene);
