// A recorded shaky hand for the stabiliser's tests and bench: a circle drawn with jitter, as a
// mouse or tablet reports it (one event every ~1.5 px, the hand wobbling ±2 px around the path,
// the pressure flickering ±0.2).
#pragma once

#include <finbook/model/types.h>

#include <QRandomGenerator>

#include <cmath>
#include <vector>

namespace finbook::test {

inline std::vector<model::StrokePoint> shakyCircle(QPointF centre = {300, 250}, double radius = 150,
                                                   int events = 600, double wobble = 2.0,
                                                   quint32 seed = 7)
{
    QRandomGenerator rng(seed);
    std::vector<model::StrokePoint> points;
    for (int i = 0; i <= events; ++i) {
        const double a = 2 * M_PI * i / events;
        const double dx = (rng.generateDouble() * 2 - 1) * wobble;
        const double dy = (rng.generateDouble() * 2 - 1) * wobble;
        const double p = 0.6 + (rng.generateDouble() * 2 - 1) * 0.2;
        points.push_back({float(centre.x() + radius * std::cos(a) + dx),
                          float(centre.y() + radius * std::sin(a) + dy), float(p)});
    }
    return points;
}

// How much a line wobbles: its total turning (radians) beyond the turning of the smooth path it
// follows, measured on the line resampled every `step` px so the sample spacing does not count.
inline double wobbleOf(const std::vector<model::StrokePoint> &points, double step = 3.0)
{
    std::vector<QPointF> even;
    if (points.empty())
        return 0;
    even.emplace_back(points.front().x, points.front().y);
    double carried = 0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        QPointF a(points[i - 1].x, points[i - 1].y);
        const QPointF b(points[i].x, points[i].y);
        double len = std::hypot(b.x() - a.x(), b.y() - a.y());
        while (carried + len >= step) {
            const double t = (step - carried) / len;
            a = a + (b - a) * t;
            even.push_back(a);
            len = std::hypot(b.x() - a.x(), b.y() - a.y());
            carried = 0;
        }
        carried += len;
    }
    double turning = 0;
    for (std::size_t i = 2; i < even.size(); ++i) {
        const QPointF u = even[i - 1] - even[i - 2], v = even[i] - even[i - 1];
        turning +=
            std::abs(std::atan2(u.x() * v.y() - u.y() * v.x(), u.x() * v.x() + u.y() * v.y()));
    }
    return turning;
}

// The pressure's flicker: the mean change from one sample to the next.
inline double pressureFlicker(const std::vector<model::StrokePoint> &points)
{
    double sum = 0;
    for (std::size_t i = 1; i < points.size(); ++i)
        sum += std::abs(points[i].pressure - points[i - 1].pressure);
    return points.size() > 1 ? sum / double(points.size() - 1) : 0.0;
}

} // namespace finbook::test
