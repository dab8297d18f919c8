// finbook-bench repaint: paint time of the real canvas widget (offscreen, shown) on a frame of
// 50,000 stroke points. Cold = the frame cache dropped before every repaint (what a stroke
// edit, zoom or pan costs); warm = the cache kept (what an overlay update or cursor move costs).
// cpu_ms_* is CPU time per repaint summed over threads: on a busy machine the wall-clock
// figures include waiting for the neighbours, so load_avg is printed alongside.
#include "bench.h"

#include <finbook/model/document.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/tools/tool_pen.h>
#include <finbook/ui/window/editor_state.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QThread>

#include <cmath>
#include <cstdio>
#include <random>
#include <sys/resource.h>

using namespace finbook;

namespace {

int intArgument(const QStringList &args, const QString &name, int fallback)
{
    const int at = int(args.indexOf(name));
    return at >= 0 && at + 1 < args.size() ? args[at + 1].toInt() : fallback;
}

double doubleArgument(const QStringList &args, const QString &name, double fallback)
{
    const int at = int(args.indexOf(name));
    return at >= 0 && at + 1 < args.size() ? args[at + 1].toDouble() : fallback;
}

// One frame of wandering pen strokes, 200 points each, with smoothly varying pressure as a
// tablet gives (so the renderer's width runs break up as they do on real drawings).
model::Frame makeFrame(int points, QSize canvas)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    model::Frame frame;
    frame.id = 1;
    model::StrokeGroup group;
    group.id = 2;
    const int perStroke = 200;
    model::Id next = 3;
    for (int done = 0; done < points; done += perStroke) {
        auto data = std::make_shared<model::StrokeData>();
        float x = unit(rng) * float(canvas.width()), y = unit(rng) * float(canvas.height());
        float heading = unit(rng) * 6.283f;
        for (int i = 0; i < std::min(perStroke, points - done); ++i) {
            heading += (unit(rng) - 0.5f) * 0.3f;
            x = std::clamp(x + 2.5f * std::cos(heading), 0.0f, float(canvas.width()));
            y = std::clamp(y + 2.5f * std::sin(heading), 0.0f, float(canvas.height()));
            data->points.push_back({x, y, 0.6f + 0.4f * std::sin(float(i) * 0.05f)});
        }
        data->width = 3.0f;
        group.strokes.push_back({next++, data});
    }
    frame.groups.push_back(std::move(group));
    return frame;
}

// CPU time of this process (all threads) in ms: on a loaded machine wall time measures the
// neighbours too, CPU time only our work.
double cpuMs()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return (double(usage.ru_utime.tv_sec) + double(usage.ru_stime.tv_sec)) * 1e3 +
           (double(usage.ru_utime.tv_usec) + double(usage.ru_stime.tv_usec)) / 1e3;
}

int benchRepaint(const QStringList &args)
{
    const int points = intArgument(args, QStringLiteral("--points"), 50000);
    const int runs = std::max(1, intArgument(args, QStringLiteral("--runs"), 200));
    model::Document doc;
    model::DocumentSettings settings;
    settings.canvasSize = QSize(1280, 720);
    std::vector<model::Frame> frames;
    frames.push_back(makeFrame(points, settings.canvasSize));
    doc.reset(std::move(frames), settings, 1000000);

    ui::EditorState state(&doc);
    ui::CanvasWidget canvas(&state);
    canvas.addTool(std::make_unique<ui::PenTool>());
    canvas.resize(1280, 800);
    canvas.show();
    QApplication::processEvents();
    // --rotation DEG: the view turned (and fitted again); --mirror: mirrored too.
    const double rotation = doubleArgument(args, QStringLiteral("--rotation"), 0.0);
    canvas.setMirrored(args.contains(QStringLiteral("--mirror")));
    canvas.setRotation(rotation);
    canvas.fitToView();
    canvas.repaint(); // first paint allocates the backing store

    std::vector<double> cold, warm;
    QElapsedTimer timer;
    double cpu = cpuMs();
    for (int i = 0; i < runs; ++i) {
        canvas.invalidateCache();
        timer.start();
        canvas.repaint();
        cold.push_back(double(timer.nsecsElapsed()) / 1e6);
    }
    const double cpuCold = (cpuMs() - cpu) / runs;
    cpu = cpuMs();
    for (int i = 0; i < runs; ++i) {
        timer.start();
        canvas.repaint();
        warm.push_back(double(timer.nsecsElapsed()) / 1e6);
    }
    const double cpuWarm = (cpuMs() - cpu) / runs;
    const double load = [] {
        double avg[1] = {0};
        return getloadavg(avg, 1) == 1 ? avg[0] : -1.0;
    }();
    std::printf("{\"bench\":\"repaint\",\"rotation\":%.1f,\"mirrored\":%s,"
                "\"points\":%lld,\"runs\":%d,\"widget\":\"%dx%d\","
                "\"zoom\":%.3f,\"median_ms_cold\":%.3f,\"p99_ms_cold\":%.3f,"
                "\"median_ms_warm\":%.3f,\"p99_ms_warm\":%.3f,\"cpu_ms_cold\":%.3f,"
                "\"cpu_ms_warm\":%.3f,\"cores\":%d,\"load_avg\":%.2f}\n",
                canvas.rotation(), canvas.isMirrored() ? "true" : "false", doc.pointCount(), runs,
                canvas.width(), canvas.height(), canvas.zoom(), bench::median(cold),
                bench::percentile(cold, 0.99), bench::median(warm), bench::percentile(warm, 0.99),
                cpuCold, cpuWarm, QThread::idealThreadCount(), load);
    return 0;
}

} // namespace

FINBOOK_BENCH("repaint", "[--points 50000] [--runs 200] [--rotation DEG] [--mirror]", benchRepaint);
