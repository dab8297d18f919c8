// finbook-bench erase: the cutting eraser on a long stroke. A 10,000-point wavy stroke is cut
// by a 60-point zigzag rub that crosses it several times. "whole_rub" cuts with the rub at
// once; "per_move" cuts as the tool does, one mouse move (two rub points) at a time, each on
// what the previous moves left. Times are wall clock on whatever machine runs it (a shared
// machine inflates them), median and 90th percentile of --runs repetitions.
#include "bench.h"

#include <finbook/model/erase/stroke_cut.h>

#include <QElapsedTimer>

#include <cmath>
#include <cstdio>

using namespace finbook;

namespace {

int intArgument(const QStringList &args, const QString &name, int fallback)
{
    const int at = int(args.indexOf(name));
    return at >= 0 && at + 1 < args.size() ? args[at + 1].toInt() : fallback;
}

model::StrokeData wavyStroke(int points)
{
    model::StrokeData s;
    s.width = 4.0f;
    for (int i = 0; i < points; ++i) {
        const float x = 0.1f * float(i); // 1000 px long
        s.points.push_back({x, 300.0f + 40.0f * std::sin(x / 25.0f),
                            0.5f + 0.5f * std::abs(std::sin(float(i) * 0.01f))});
    }
    return s;
}

std::vector<QPointF> zigzagRub(int points)
{
    std::vector<QPointF> rub;
    for (int i = 0; i < points; ++i)
        rub.push_back(QPointF(400.0 + 3.0 * i, i % 2 ? 240.0 : 360.0));
    return rub;
}

int benchErase(const QStringList &args)
{
    const int points = intArgument(args, QStringLiteral("--points"), 10000);
    const int rubPoints = intArgument(args, QStringLiteral("--rub"), 60);
    const int runs = intArgument(args, QStringLiteral("--runs"), 200);
    const double radius = 8.0;
    const model::StrokeData stroke = wavyStroke(points);
    const std::vector<QPointF> rub = zigzagRub(rubPoints);

    std::vector<double> whole, perMove;
    std::size_t pieces = 0, movePieces = 0;
    for (int run = 0; run < runs; ++run) {
        QElapsedTimer timer;
        timer.start();
        const auto cut = model::cutStroke(stroke, rub, radius);
        whole.push_back(double(timer.nsecsElapsed()) / 1e6);
        pieces = cut ? cut->size() : 1;

        timer.restart();
        std::vector<model::StrokeDataPtr> left{std::make_shared<model::StrokeData>(stroke)};
        for (std::size_t j = 1; j < rub.size(); ++j) {
            std::vector<model::StrokeDataPtr> next;
            for (const model::StrokeDataPtr &s : left) {
                auto c = model::cutStroke(*s, {rub[j - 1], rub[j]}, radius);
                if (!c)
                    next.push_back(s);
                else
                    next.insert(next.end(), c->begin(), c->end());
            }
            left = std::move(next);
        }
        perMove.push_back(double(timer.nsecsElapsed()) / 1e6);
        movePieces = left.size();
    }
    std::printf("{\"bench\":\"erase\",\"stroke_points\":%d,\"rub_points\":%d,\"radius\":%.1f,"
                "\"runs\":%d,\"pieces\":%zu,\"whole_rub_ms_median\":%.4f,"
                "\"whole_rub_ms_p90\":%.4f,\"per_move_pieces\":%zu,\"per_move_ms_median\":%.4f,"
                "\"per_move_ms_p90\":%.4f}\n",
                points, rubPoints, radius, runs, pieces, bench::median(whole),
                bench::percentile(whole, 0.9), movePieces, bench::median(perMove),
                bench::percentile(perMove, 0.9));
    return 0;
}

} // namespace

FINBOOK_BENCH("erase", "[--points 10000] [--rub 60] [--runs 200]", benchErase);
