// finbook-bench pose: the app's own drag path on a meshed drawing — pin targets in, deformed
// stroke points out (model::solvePose: ARAP solve, embedding applied, strokes rebuilt) — for
// an object of about 2,000 mesh vertices carrying 5,000 stroke points (--points: more, as more
// strokes packed closer over the same area).
#include "bench.h"

#include <finbook/model/deform_setup.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

using namespace finbook::model;

namespace {

using Clock = std::chrono::steady_clock;

// Wavy strokes of 200 points crossing a 700×420 area, across and down by turns (25 for 5,000
// points): one connected, character-sized object.
StrokeGroup drawing(int points)
{
    StrokeGroup g;
    g.id = 1;
    const int strokes = std::max(2, points / 200);
    const float step = 25.0f / float(strokes); // the 25 strokes' spacing, shared out
    for (int s = 0; s < strokes; ++s) {
        auto data = std::make_shared<StrokeData>();
        data->width = 4.0f;
        const bool across = s % 2 == 0;
        for (int i = 0; i < 200; ++i) {
            const float t = float(i) / 199.0f;
            const float wave = 12.0f * std::sin(t * 12.0f + float(s));
            data->points.push_back(
                across ? StrokePoint{300 + 700 * t, 150 + 17.0f * step * float(s) + wave, 1}
                       : StrokePoint{300 + 28.0f * step * float(s) + wave, 150 + 420 * t, 1});
        }
        g.strokes.push_back({Id(100 + s), std::move(data)});
    }
    g.rig.pins = {{2, {300, 150}, {300, 150}},
                  {3, {1000, 150}, {1000, 150}},
                  {4, {300, 570}, {300, 570}},
                  {5, {1000, 570}, {1000, 570}}};
    return g;
}

int benchPose(const QStringList &args)
{
    const auto option = [&args](const char *name, double fallback) {
        const int at = int(args.indexOf(QLatin1String(name)));
        return at >= 0 && at + 1 < args.size() ? args[at + 1].toDouble() : fallback;
    };
    StrokeGroup g = drawing(int(option("--points", 5000)));
    g.meshDensity = option("--density", 1.0);
    DeformJob job;
    job.key = MeshKey::of(g, -1.0);
    job.rig = g.rig.atRest();
    const auto start = Clock::now();
    auto setup = buildDeformSetup(job);
    const double setupMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    if (!setup) {
        std::fprintf(stderr, "pose: %s\n", qPrintable(setup.error()));
        return 1;
    }
    // Every stage of the app's path: the two-step preview, a mouse move during a drag, and the
    // converged pose stored when the drag ends.
    std::vector<double> preview, samples, converged;
    std::size_t points = 0;
    for (int event = 0; event < 300; ++event) {
        const double a = 0.01 * event;
        g.rig.pins[1].target = QPointF(1000 - 120 * std::sin(a), 150 + 200 * std::sin(a));
        if (event % 10 == 0) {
            auto t = Clock::now();
            if (!solvePose(**setup, g, PoseStage::Preview))
                return 1;
            preview.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t).count());
            t = Clock::now();
            if (!solvePose(**setup, g, PoseStage::Final))
                return 1;
            converged.push_back(
                std::chrono::duration<double, std::milli>(Clock::now() - t).count());
        }
        const auto t0 = Clock::now();
        auto pose = solvePose(**setup, g, PoseStage::Drag);
        samples.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
        if (!pose) {
            std::fprintf(stderr, "pose: %s\n", qPrintable(pose.error()));
            return 1;
        }
        points = 0;
        for (const auto &s : pose->strokes->strokes)
            points += s.size();
    }
    std::printf(
        "{\"bench\":\"pose\",\"vertices\":%lld,\"triangles\":%lld,\"stroke_points\":%zu,"
        "\"setup_ms\":%.2f,\"pin_to_strokes_ms_median\":%.4f,\"pin_to_strokes_ms_p99\":%.4f,"
        "\"two_step_preview_ms_median\":%.4f,\"converged_ms_median\":%.3f}\n",
        (long long)(*setup)->meshed->mesh.V.rows(), (long long)(*setup)->meshed->mesh.F.rows(),
        points, setupMs, finbook::bench::median(samples), finbook::bench::percentile(samples, 0.99),
        finbook::bench::median(preview), finbook::bench::median(converged));
    return 0;
}

} // namespace

FINBOOK_BENCH("pose", "[--density D] [--points 5000]", benchPose);
