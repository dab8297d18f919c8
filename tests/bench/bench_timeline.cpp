// finbook-bench timeline: scroll a 1,000-frame strip end to end and count the thumbnails the
// cache rendered against the frames that were ever on screen.
// finbook-bench playback: play the walk example at 24 fps and measure how late each frame
// change comes against its ideal time (the tick where that frame should appear).
#include "bench.h"

#include <finbook/model/commands.h>
#include <finbook/model/finbook_file.h>
#include <finbook/ui/timeline/frame_actions.h>
#include <finbook/ui/timeline/playback_controller.h>
#include <finbook/ui/timeline/thumbnail_cache.h>
#include <finbook/ui/timeline/timeline_view.h>
#include <finbook/ui/timeline/timeline_widget.h>
#include <finbook/ui/window/editor_state.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QScrollBar>
#include <QTimer>

#include <cmath>
#include <cstdio>
#include <set>

using namespace finbook;

namespace {

int intArg(const QStringList &args, const QString &name, int fallback)
{
    const int at = int(args.indexOf(name));
    return at >= 0 && at + 1 < args.size() ? args[at + 1].toInt() : fallback;
}

// `count` frames, each one object with `strokes` wavy strokes of 60 points.
void generate(model::Document &doc, int count, int strokes)
{
    std::vector<model::Frame> frames(static_cast<std::size_t>(count));
    model::Id next = 1;
    for (int f = 0; f < count; ++f) {
        model::Frame &frame = frames[std::size_t(f)];
        frame.id = next++;
        model::StrokeGroup group;
        group.id = next++;
        group.name = QStringLiteral("Object");
        for (int s = 0; s < strokes; ++s) {
            auto data = std::make_shared<model::StrokeData>();
            for (int i = 0; i < 60; ++i) {
                const float t = float(i) / 59.0f;
                data->points.push_back(
                    {200.0f + 900.0f * t,
                     150.0f + 80.0f * float(s) + 40.0f * std::sin(6.0f * t + 0.05f * float(f)),
                     0.4f + 0.6f * t});
            }
            data->width = 6.0f;
            group.strokes.push_back({next++, std::move(data)});
        }
        frame.groups.push_back(std::move(group));
    }
    doc.reset(std::move(frames), doc.settings(), next);
}

void settle(ui::ThumbnailCache *cache)
{
    // Paint, then let the zero-timer render what the paint asked for, then paint the result.
    for (int i = 0; i < 50; ++i) {
        QCoreApplication::processEvents();
        if (cache->pendingCount() == 0)
            break;
    }
    QCoreApplication::processEvents();
}

// Scrolls the strip from start to end in steps of `stepCells` cells and prints one line.
void scrollOnce(const char *mode, int frameCount, double stepCells)
{
    model::Document doc;
    generate(doc, frameCount, 6);
    ui::EditorState state(&doc);
    ui::FrameActions actions(&state);
    ui::TimelineWidget timeline(&state, &actions, nullptr);
    timeline.resize(1200, 120);
    timeline.show();
    ui::TimelineView *view = timeline.view();
    ui::ThumbnailCache *cache = timeline.thumbnails();
    settle(cache);

    QScrollBar *bar = view->horizontalScrollBar();
    const int step = std::max(1, int(view->cellSize().width() * stepCells));
    std::set<int> everVisible;
    std::size_t visibleMax = 0;
    std::vector<double> stepMs;
    int steps = 0;
    QElapsedTimer total;
    total.start();
    for (int value = 0;; value = std::min(value + step, bar->maximum())) {
        QElapsedTimer clock;
        clock.start();
        bar->setValue(value);
        settle(cache);
        stepMs.push_back(double(clock.nsecsElapsed()) / 1e6);
        const std::vector<int> rows = view->visibleRows();
        everVisible.insert(rows.begin(), rows.end());
        visibleMax = std::max(visibleMax, rows.size());
        ++steps;
        if (value >= bar->maximum())
            break;
    }
    const int rendered = cache->renderedCount();
    std::printf("{\"bench\":\"timeline\",\"mode\":\"%s\",\"frames\":%d,\"visible_max\":%zu,"
                "\"distinct_visible\":%zu,\"thumbnails_rendered\":%d,\"scroll_steps\":%d,"
                "\"rendered_le_visible\":%s,\"thumb_w\":%d,\"thumb_h\":%d,"
                "\"step_ms_p50\":%.2f,\"step_ms_p99\":%.2f,\"total_ms\":%.1f}\n",
                mode, frameCount, visibleMax, everVisible.size(), rendered, steps,
                rendered <= int(everVisible.size()) ? "true" : "false",
                cache->thumbnailSize().width(), cache->thumbnailSize().height(),
                bench::median(stepMs), bench::percentile(stepMs, 0.99),
                double(total.nsecsElapsed()) / 1e6);
}

int benchTimeline(const QStringList &args)
{
    const int frameCount = intArg(args, QStringLiteral("--frames"), 1000);
    // Smooth scrolling shows every frame once; jumping a few screens at a time skips most.
    scrollOnce("scroll", frameCount, 1.5);
    scrollOnce("jump", frameCount, 40.0);
    return 0;
}

QString findExample(const QStringList &args)
{
    const int at = int(args.indexOf(QStringLiteral("--file")));
    if (at >= 0 && at + 1 < args.size())
        return args[at + 1];
    const QString name = QStringLiteral("resources/examples/walk.finbook");
    const QString bin = QCoreApplication::applicationDirPath();
    for (const QString &candidate :
         {name, bin + QStringLiteral("/../../") + name, bin + QStringLiteral("/../") + name})
        if (QFileInfo::exists(candidate))
            return candidate;
    return {};
}

struct Change {
    qint64 ns;
    int frame;
};

// How late each change came after the tick where its frame should have appeared.
std::vector<double> latenessMs(const model::Document &doc, const std::vector<Change> &changes,
                               qint64 startTick, int fps, bool loop)
{
    std::vector<double> late;
    qint64 previous = startTick;
    for (const Change &c : changes) {
        qint64 tick = startTick + c.ns * fps / 1'000'000'000;
        while (tick > previous + 1 && ui::frameAtTick(doc, tick - 1, loop) == c.frame)
            --tick;
        const double ideal = double(tick - startTick) * 1000.0 / fps;
        late.push_back(double(c.ns) / 1e6 - ideal);
        previous = tick;
    }
    return late;
}

int benchPlayback(const QStringList &args)
{
    const int fps = intArg(args, QStringLiteral("--fps"), 24);
    const int seconds = intArg(args, QStringLiteral("--seconds"), 5);
    model::Document doc;
    const QString path = findExample(args);
    QString source = QStringLiteral("generated");
    if (!path.isEmpty()) {
        if (const auto error = model::openFinbook(doc, path)) {
            std::fprintf(stderr, "%s\n", qPrintable(error->message));
            return 1;
        }
        source = QFileInfo(path).fileName();
    } else {
        generate(doc, 12, 6);
    }
    model::DocumentSettings settings = doc.settings();
    settings.fps = fps;
    settings.loop = true;
    doc.setSettings(model::sanitizedSettings(settings));

    // Play with the timeline on screen, following every frame change like in the editor.
    ui::EditorState state(&doc);
    ui::FrameActions actions(&state);
    ui::PlaybackController playback(&state);
    ui::TimelineWidget timeline(&state, &actions, &playback);
    timeline.resize(1200, 120);
    timeline.show();
    settle(timeline.thumbnails());
    state.setCurrentFrameIndex(doc.playFirst());

    std::vector<Change> changes;
    QObject::connect(&state, &ui::EditorState::currentFrameChanged, &state, [&](int index) {
        if (playback.isPlaying())
            changes.push_back({playback.elapsedNs(), index});
    });
    const int renderedBefore = timeline.thumbnails()->renderedCount();
    playback.play();
    const qint64 startTick = playback.startTick();
    QEventLoop loop;
    QTimer::singleShot(seconds * 1000, Qt::PreciseTimer, &loop, &QEventLoop::quit);
    loop.exec();
    const qint64 ranNs = playback.elapsedNs();
    playback.pause();

    qint64 expected = 0;
    const qint64 lastTick = startTick + ranNs * fps / 1'000'000'000;
    for (qint64 t = startTick + 1; t <= lastTick; ++t)
        expected += ui::frameAtTick(doc, t, true) != ui::frameAtTick(doc, t - 1, true);
    const std::vector<double> late = latenessMs(doc, changes, startTick, fps, true);
    if (qEnvironmentVariableIsSet("FINBOOK_BENCH_VERBOSE"))
        for (std::size_t i = 0; i < late.size(); ++i)
            if (late[i] > 5.0)
                std::fprintf(stderr, "change %zu to frame %d at %.3f ms: %.3f ms late\n", i,
                             changes[i].frame, double(changes[i].ns) / 1e6, late[i]);
    if (qEnvironmentVariableIsSet("FINBOOK_BENCH_VERBOSE"))
        std::fprintf(stderr, "thumbnails rendered while playing: %d\n",
                     timeline.thumbnails()->renderedCount() - renderedBefore);
    const double worst = late.empty() ? 0.0 : *std::max_element(late.begin(), late.end());
    std::printf("{\"bench\":\"playback\",\"source\":\"%s\",\"frames\":%d,\"fps\":%d,"
                "\"seconds\":%.2f,\"frames_shown\":%zu,\"changes_expected\":%lld,"
                "\"jitter_p50_ms\":%.3f,\"jitter_p99_ms\":%.3f,\"max_ms\":%.3f}\n",
                qPrintable(source), doc.frameCount(), fps, double(ranNs) / 1e9, changes.size(),
                static_cast<long long>(expected), bench::median(late),
                bench::percentile(late, 0.99), worst);
    return 0;
}

} // namespace

FINBOOK_BENCH("timeline", "[--frames N]  scroll a long timeline, count rendered thumbnails",
              benchTimeline);
FINBOOK_BENCH("playback", "[--file F] [--fps N] [--seconds S]  frame timing while playing",
              benchPlayback);
