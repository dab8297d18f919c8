// finbook-bench pen: the stabiliser's cost and lag. For each strength 0..10 it runs a recorded
// shaky hand (a circle drawn with ±2 px jitter, 600 events, repeated) through the lazy string
// and prints per strength: the time per event (ns), the visual lag (mean and largest distance
// from the pen to the ink while drawing, screen px at zoom 1) and how much the line still
// wobbles (its total turning beyond the circle's, radians; 2π is a perfect circle).
#include "../ui/stabiliser_support.h"
#include "bench.h"

#include <finbook/ui/tools/tool_pen.h>

#include <QElapsedTimer>

#include <cstdio>

namespace {
using namespace finbook;

int benchPen(const QStringList &)
{
    const std::vector<model::StrokePoint> hand = test::shakyCircle();
    constexpr int kRepeats = 2000;
    for (int strength = 0; strength <= ui::PenTool::kMaxStabiliser; ++strength) {
        const double length = ui::stabiliserLength(strength, 1.0);
        double lagSum = 0, lagMax = 0;
        std::vector<model::StrokePoint> line{hand.front()};
        {
            ui::LazyString string(length);
            string.start(hand.front());
            for (std::size_t i = 1; i + 1 < hand.size(); ++i) {
                if (const auto ink = string.follow(hand[i]))
                    line.push_back(*ink);
                const double lag =
                    std::hypot(string.ink().x - hand[i].x, string.ink().y - hand[i].y);
                lagSum += lag;
                lagMax = std::max(lagMax, lag);
            }
            line.push_back(string.finish(hand.back()));
        }
        QElapsedTimer timer;
        timer.start();
        volatile float sink = 0; // the result is used, so the loop is not optimised away
        for (int r = 0; r < kRepeats; ++r) {
            ui::LazyString string(length);
            string.start(hand.front());
            for (std::size_t i = 1; i < hand.size(); ++i)
                if (const auto ink = string.follow(hand[i]))
                    sink = sink + ink->x;
        }
        const double ns = double(timer.nsecsElapsed()) / (double(kRepeats) * double(hand.size()));
        std::printf("{\"bench\":\"pen\",\"stabiliser\":%d,\"string_px\":%.0f,\"ns_per_event\":%.1f,"
                    "\"lag_mean_px\":%.2f,\"lag_max_px\":%.2f,\"wobble_rad\":%.2f,\"samples\":%zu,"
                    "\"events\":%zu}\n",
                    strength, length, ns, lagSum / double(hand.size() - 2), lagMax,
                    test::wobbleOf(line), line.size(), hand.size());
        std::fflush(stdout);
    }
    return 0;
}
} // namespace

FINBOOK_BENCH("pen", "(the pen stabiliser's time per event, lag and wobble at each strength)",
              benchPen);
