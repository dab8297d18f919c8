// A two-key arm swing for the in-between test and benchmark: an arm drawn as two strokes
// (upper arm, forearm), pinned at the shoulder and the hand; the second key swings the hand
// pin 90° about the shoulder. The same arm with a skeleton (the shoulder bone turned 90°) and
// with a cage (the forearm's corners bent about the elbow).
#pragma once

#include "stroke_support.h"

#include <finbook/model/skeleton/skeleton_commands.h>
#include <finbook/model/types.h>

#include <cmath>
#include <memory>

namespace finbook::inbetween_test {

using namespace finbook::model;

inline const QPointF kShoulder(300, 300);
inline const QPointF kHand(500, 300);

inline StrokeDataPtr line(QPointF from, QPointF to, int points)
{
    return testing::lineStroke(from, to, points, 16.0f);
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

inline QPointF turnedAbout(QPointF p, QPointF pivot, double angle)
{
    // R(angle) turns +x towards +y, i.e. clockwise on the y-down canvas, as the skeleton does.
    const double c = std::cos(angle), s = std::sin(angle);
    const QPointF v = p - pivot;
    return pivot + QPointF(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

// A skeleton laid along the arm by hand: shoulder (the root), elbow, hand.
inline SkeletonRig armSkeleton()
{
    SkeletonRig s;
    s.joints = {kShoulder, (kShoulder + kHand) / 2, kHand};
    s.parent = {-1, 0, 1};
    s.radius = {8, 8, 8};
    s.root = 0;
    return s.atRest();
}

// The skeleton the app builds for the arm (Build Skeleton), rooted at the shoulder. Empty
// when the drawing cannot be skeletonised.
inline SkeletonRig builtArmSkeleton()
{
    auto built = buildSkeletonRig(armKeys().first.groups[0], {}, kShoulder);
    return built ? *built : SkeletonRig{};
}

// The arm keys with `rest` (a skeleton at rest) instead of pins, skinned in `mode`: the first
// key at rest, in the second every bone leaving the root (the shoulder bone) turned by `turn`.
inline std::pair<Frame, Frame> skeletonArmKeys(const SkeletonRig &rest, SkinningMode mode,
                                               double turn = M_PI / 2, Id firstId = 1)
{
    auto [a, b] = armKeys(firstId);
    for (Frame *f : {&a, &b}) {
        Rig &rig = f->groups[0].rig;
        rig = Rig{};
        rig.skeleton = rest.atRest();
        rig.skeleton.mode = mode;
    }
    SkeletonRig &posed = b.groups[0].rig.skeleton;
    for (std::size_t j = 0; j < posed.joints.size(); ++j)
        if (posed.parent[j] >= 0 && posed.parent[j] == posed.root)
            posed.angles[j] = turn;
    return {a, b};
}

// A cage around the arm with corners at the shoulder, the elbow and the hand end.
inline std::vector<QPointF> armCage()
{
    return {{280, 270}, {400, 270}, {520, 270}, {520, 330}, {400, 330}, {280, 330}};
}

// The arm keys with armCage() instead of pins: the first key at rest, in the second the
// corners at the hand end turned by `bend` about the elbow (the forearm bent).
inline std::pair<Frame, Frame> cageArmKeys(double bend = M_PI / 3, Id firstId = 1)
{
    auto [a, b] = armKeys(firstId);
    for (Frame *f : {&a, &b}) {
        Rig &rig = f->groups[0].rig;
        rig = Rig{};
        rig.cage.rest = armCage();
        rig.cage.posed = rig.cage.rest;
    }
    const QPointF elbow = (kShoulder + kHand) / 2;
    for (QPointF &c : b.groups[0].rig.cage.posed)
        if (c.x() > elbow.x() + 1)
            c = turnedAbout(c, elbow, bend);
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
