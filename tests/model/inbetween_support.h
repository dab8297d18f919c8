// A two-key arm swing for the in-between test and benchmark: an arm drawn as two strokes
// (upper arm, forearm), pinned at the shoulder and the hand; the second key swings the hand
// pin 90° about the shoulder.
#pragma once

#include <finbook/model/types.h>

#include <cmath>
#include <memory>

namespace finbook::inbetween_test {

using namespace finbook::model;

inline const QPointF kShoulder(300, 300);
inline const QPointF kHand(500, 300);

inline StrokeDataPtr line(QPointF from, QPointF to, int points)
{
    auto data = std::make_shared<StrokeData>();
    data->width = 16.0f;
    for (int i = 0; i < points; ++i) {
        const QPointF p = from + (to - from) * (double(i) / (points - 1));
        data->points.push_back({float(p.x()), float(p.y()), 1.0f});
    }
    return data;
}

// Key frames: ids from `firstId` on (frame, object, 2 strokes, 2 pins per key).
inline std::pair<Frame, Frame> armKeys(Id firstId = 1)
{
    Id next = firstId;
    const QPointF elbow = (kShoulder + kHand) / 2;
    Frame a;
    a.id = next++;
    StrokeGroup arm;
    arm.id = next++;
    arm.name = QStringLiteral("Arm");
    arm.strokes.push_back({next++, line(kShoulder, elbow, 51)});
    arm.strokes.push_back({next++, line(elbow, kHand, 51)});
    arm.rig.pins = {{next++, kShoulder, kShoulder}, {next++, kHand, kHand}};
    a.groups.push_back(arm);
    Frame b = a;
    b.id = next++;
    b.groups[0].id = next++;
    for (Stroke &s : b.groups[0].strokes)
        s.id = next++;
    for (Pin &p : b.groups[0].rig.pins)
        p.id = next++;
    const QPointF d = kHand - kShoulder; // swung 90° about the shoulder
    b.groups[0].rig.pins[1].target = kShoulder + QPointF(-d.y(), d.x());
    return {a, b};
}

// Length of an object's drawing measured along its (deformed) strokes.
inline double strokeLength(const DeformedStrokes &pose)
{
    double length = 0.0;
    for (const auto &stroke : pose.strokes)
        for (std::size_t i = 1; i < stroke.size(); ++i)
            length += std::hypot(double(stroke[i].x - stroke[i - 1].x),
                                 double(stroke[i].y - stroke[i - 1].y));
    return length;
}

// The naive in-between: every deformed point blended between the keys.
inline DeformedStrokes blendPoints(const DeformedStrokes &a, const DeformedStrokes &b, double t)
{
    DeformedStrokes out = a;
    for (std::size_t s = 0; s < out.strokes.size() && s < b.strokes.size(); ++s)
        for (std::size_t i = 0; i < out.strokes[s].size() && i < b.strokes[s].size(); ++i) {
            out.strokes[s][i].x = float((1 - t) * a.strokes[s][i].x + t * b.strokes[s][i].x);
            out.strokes[s][i].y = float((1 - t) * a.strokes[s][i].y + t * b.strokes[s][i].y);
        }
    return out;
}

} // namespace finbook::inbetween_test
