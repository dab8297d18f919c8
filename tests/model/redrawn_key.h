// Key B of Between Drawings (issue 50) made from a posed drawing, as finbook-bench between
// and tst_between_drawings make it: the posed lines redrawn. Shared so that the test fits the
// key the bench measures.
#pragma once

#include "bake_support.h"

#include <finbook/model/render.h>

#include <QLineF>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace finbook::testing {

constexpr double kSpacingFactor = 1.37; // B's point spacing against A's

// The median, halfway between the two middle values of an even count.
inline double medianOf(std::vector<double> values)
{
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    const double rank = 0.5 * double(values.size() - 1);
    const auto lo = std::size_t(rank);
    const std::size_t hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (rank - double(lo)) * (values[hi] - values[lo]);
}

// Points every `spacing` along a polyline, its ends kept.
inline std::vector<QPointF> resampledLine(const std::vector<model::StrokePoint> &points,
                                          double spacing)
{
    std::vector<QPointF> out;
    if (points.empty())
        return out;
    out.emplace_back(points.front().x, points.front().y);
    double carry = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        const QPointF a(points[i - 1].x, points[i - 1].y), b(points[i].x, points[i].y);
        const double length = std::hypot(b.x() - a.x(), b.y() - a.y());
        double at = spacing - carry;
        for (; at < length; at += spacing)
            out.push_back(a + (b - a) * (at / length));
        carry = length - (at - spacing);
    }
    const QPointF last(points.back().x, points.back().y);
    if (QLineF(out.back(), last).length() > 0.25 * spacing)
        out.push_back(last);
    return out;
}

inline double medianSpacing(const model::StrokeGroup &g)
{
    std::vector<double> d;
    for (const model::Stroke &s : g.strokes)
        for (std::size_t i = 1; i < s.data->points.size(); ++i)
            d.push_back(std::hypot(s.data->points[i].x - s.data->points[i - 1].x,
                                   s.data->points[i].y - s.data->points[i - 1].y));
    return d.empty() ? 2.0 : std::max(0.5, medianOf(d));
}

// Key B redrawn from a posed object as an animator would draw it again: each line resampled at
// kSpacingFactor × the object's median point spacing, jittered by up to 1 px, every other line
// reversed, the lines' order shuffled, and the longest line split in two. Deterministic per seed.
inline model::StrokeGroup redrawnKey(const model::StrokeGroup &posed, std::uint32_t seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> jitter(-1.0, 1.0);
    const double spacing = kSpacingFactor * medianSpacing(posed);
    std::vector<std::vector<QPointF>> lines;
    for (std::size_t s = 0; s < posed.strokes.size(); ++s)
        lines.push_back(resampledLine(model::displayedPoints(posed, s), spacing));
    // The longest line split in two.
    const auto longest =
        std::max_element(lines.begin(), lines.end(),
                         [](const auto &a, const auto &b) { return a.size() < b.size(); });
    if (longest != lines.end() && longest->size() >= 8) {
        const std::size_t half = longest->size() / 2;
        std::vector<QPointF> second(longest->begin() + std::ptrdiff_t(half), longest->end());
        longest->resize(half + 1);
        lines.push_back(std::move(second));
    }
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (i % 2 == 1)
            std::reverse(lines[i].begin(), lines[i].end());
    std::shuffle(lines.begin(), lines.end(), random);
    model::StrokeGroup b;
    b.id = 900000;
    b.name = QStringLiteral("B");
    model::Id next = 900001;
    for (const std::vector<QPointF> &line : lines) {
        if (line.size() < 2)
            continue;
        std::vector<QPointF> jittered;
        for (const QPointF &p : line) {
            const double dx = jitter(random), dy = jitter(random);
            jittered.emplace_back(p.x() + dx, p.y() + dy);
        }
        b.strokes.push_back(model::Stroke{next++, drawnLine(jittered)});
    }
    return b;
}

} // namespace finbook::testing
