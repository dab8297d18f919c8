// finbook-bench repaint: paint time of the real canvas widget (offscreen, shown) on a frame of
// 50,000 stroke points. Cold = the frame cache dropped before every repaint (what a stroke
// edit, zoom or pan costs); warm = the cache kept (what an overlay update or cursor move costs).
#include "bench.h"

#include <finbook/model/document.h>
#include <finbook/ui/canvas_widget.h>
#include <finbook/ui/editor_state.h>
#include <finbook/ui/tool_pen.h>

#include <QApplication>
#include <QElapsedTimer>

#include <cmath>
#include <cstdio>
#include <random>

using namespace finbook;

namespace {

int intArgument(const QStringList &args, const QString &name, int fallback)
{
    const int at = int(args.indexOf(name));
    return at >= 0 && at + 1 < args.size() ? args[at + 1].toInt() : fallback;
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
    canvas.fitToView();
    canvas.repaint(); // first paint allocates the backing store

    std::vector<double> cold, warm;
    QElapsedTimer timer;
    for (int i = 0; i < runs; ++i) {
        canvas.invalidateCache();
        timer.start();
        canvas.repaint();
        cold.push_back(double(timer.nsecsElapsed()) / 1e6);
    }
    for (int i = 0; i < runs; ++i) {
        timer.start();
        canvas.repaint();
        warm.push_back(double(timer.nsecsElapsed()) / 1e6);
    }
    std::printf("{\"bench\":\"repaint\",\"points\":%lld,\"runs\":%d,\"widget\":\"%dx%d\","
                "\"zoom\":%.3f,\"median_ms_cold\":%.3f,\"p99_ms_cold\":%.3f,"
                "\"median_ms_warm\":%.3f,\"p99_ms_warm\":%.3f}\n",
                doc.pointCount(), runs, canvas.width(), canvas.height(), canvas.zoom(),
                bench::median(cold), bench::percentile(cold, 0.99), bench::median(warm),
                bench::percentile(warm, 0.99));
    return 0;
}

} // namespace

FINBOOK_BENCH("repaint", "[--points 50000] [--runs 200]", benchRepaint);
