// finbook-bench inbetween: why in-betweens are re-solved poses, and what they cost.
//  - arm: a two-key 90° arm swing with pins; the arm's length along the deformed strokes in the
//    keys, in the middle in-between re-solved (targets along arcs, and along straight lines),
//    and in the naive point-by-point blend of the keys' deformed strokes;
//  - arm skeleton: the same swing with the skeleton Build Skeleton makes for the arm (the
//    shoulder bone turned 90°), per skinning mode: the same lengths, and the time for 24
//    in-betweens through the synchronous path (shared setup) and the app's path;
//  - arm cage: a cage around the arm bent 60° at the elbow: how far the forearm has turned half
//    way, how far corners that stay put in both keys drift, and the time for 24 in-betweens;
//  - generate: 24 in-betweens of a ~2,000-vertex pinned object through the app's path
//    (InsertInbetweensCommand pushed, the DeformController posing each new frame with the
//    keys' shared factorization), and through the synchronous path (solveInbetweenPoses).
#include "../model/inbetween_support.h"
#include "bench.h"

#include <finbook/model/deform_controller.h>
#include <finbook/model/inbetween/inbetween_commands.h>
#include <finbook/model/inbetween/inbetween_solve.h>
#include <finbook/model/rig/rig_commands.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <chrono>
#include <cmath>
#include <cstdio>

using namespace finbook::model;
using namespace finbook::inbetween_test;

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

int benchArm()
{
    auto [a, b] = armKeys();
    std::vector<Frame> keys{a, b};
    DeformSetupCache cache;
    if (!solveInbetweenPoses(keys, {}, &cache))
        return 1;
    auto arc = planInbetweens(keys[0], keys[1], {0.5}, TargetPath::Arc);
    auto line = planInbetweens(keys[0], keys[1], {0.5}, TargetPath::Straight);
    if (!solveInbetweenPoses(arc.frames, {}, &cache) ||
        !solveInbetweenPoses(line.frames, {}, &cache))
        return 1;
    const DeformedStrokes &poseA = *keys[0].groups[0].deformed;
    const DeformedStrokes &poseB = *keys[1].groups[0].deformed;
    const double keyA = strokeLength(poseA), keyB = strokeLength(poseB);
    const double keyMean = (keyA + keyB) / 2;
    const double resolved = strokeLength(*arc.frames[0].groups[0].deformed);
    const double straight = strokeLength(*line.frames[0].groups[0].deformed);
    const double naive = strokeLength(blendPoints(poseA, poseB, 0.5));
    std::printf("{\"bench\":\"inbetween\",\"case\":\"arm_swing_90\",\"key_length_px\":[%.2f,%.2f],"
                "\"middle_resolved_arc_px\":%.2f,\"middle_resolved_arc_change_pct\":%.2f,"
                "\"middle_resolved_straight_px\":%.2f,\"middle_resolved_straight_change_pct\":%.2f,"
                "\"middle_naive_blend_px\":%.2f,\"middle_naive_blend_change_pct\":%.2f}\n",
                keyA, keyB, resolved, 100 * (resolved / keyMean - 1), straight,
                100 * (straight / keyMean - 1), naive, 100 * (naive / keyMean - 1));
    return 0;
}

bool waitFor(const std::function<bool()> &done, int timeoutMs);

// Every object posed by its own deformer (not the cage's stand-in shown while waiting).
bool allPosed(const Document &doc, const DeformController &controller)
{
    return std::all_of(doc.frames().begin(), doc.frames().end(), [&](const Frame &f) {
        return f.groups[0].deformed && !controller.isWaiting(f.groups[0].id);
    });
}

struct InbetweenTimes {
    double syncMs = 0;           // 24 in-betweens planned and solved with the keys' setup
    double appMs = 0;            // InsertInbetweensCommand pushed until every frame is posed
    long long vertices = 0;      // of the mesh the deformer moves
    double keysPrecomputeMs = 0; // the controller's setup for the keys
};

// 24 evenly spaced in-betweens of two unsolved keys, both ways.
bool timeInbetweens(const Frame &a, const Frame &b, InbetweenTimes &out)
{
    std::vector<Frame> keys{a, b};
    DeformSetupCache cache;
    if (!solveInbetweenPoses(keys, {}, &cache))
        return false;
    auto plan = planInbetweens(keys[0], keys[1], inbetweenTimes(24, {}));
    const auto t0 = Clock::now();
    const auto solved = solveInbetweenPoses(plan.frames, {}, &cache);
    out.syncMs = msSince(t0);
    if (!solved || *solved != 24)
        return false;

    Document doc;
    doc.reset({a, b}, {}, 1000);
    DeformController controller(&doc);
    const auto t1 = Clock::now();
    controller.prepare(a.groups[0].id);
    controller.prepare(b.groups[0].id);
    if (!waitFor([&] { return allPosed(doc, controller); }, 60000))
        return false;
    out.keysPrecomputeMs = msSince(t1);
    out.vertices = controller.setup(a.groups[0].id)->meshVertices().rows();
    const auto t2 = Clock::now();
    doc.undoStack()->push(new InsertInbetweensCommand(&doc, a.id, b.id, 24, {}));
    if (!waitFor([&] { return allPosed(doc, controller); }, 60000))
        return false;
    out.appMs = msSince(t2);
    return doc.frameCount() == 26;
}

int benchSkeletonArm(SkinningMode mode)
{
    const SkeletonRig rest = builtArmSkeleton();
    if (rest.empty()) {
        std::fprintf(stderr, "inbetween: no skeleton for the arm\n");
        return 1;
    }
    auto [a, b] = skeletonArmKeys(rest, mode);
    std::vector<Frame> keys{a, b};
    DeformSetupCache cache;
    if (!solveInbetweenPoses(keys, {}, &cache))
        return 1;
    auto plan = planInbetweens(keys[0], keys[1], {0.5}, TargetPath::Arc);
    if (!solveInbetweenPoses(plan.frames, {}, &cache))
        return 1;
    const DeformedStrokes &poseA = *keys[0].groups[0].deformed;
    const DeformedStrokes &poseB = *keys[1].groups[0].deformed;
    const double keyA = strokeLength(poseA), keyB = strokeLength(poseB);
    const double keyMean = (keyA + keyB) / 2;
    const double resolved = strokeLength(*plan.frames[0].groups[0].deformed);
    const double naive = strokeLength(blendPoints(poseA, poseB, 0.5));
    InbetweenTimes times;
    if (!timeInbetweens(a, b, times))
        return 1;
    std::printf("{\"bench\":\"inbetween\",\"case\":\"arm_swing_90_skeleton\",\"skinning\":\"%s\","
                "\"joints\":%d,\"vertices\":%lld,\"key_length_px\":[%.2f,%.2f],"
                "\"middle_resolved_px\":%.2f,\"middle_resolved_change_pct\":%.2f,"
                "\"middle_naive_blend_px\":%.2f,\"middle_naive_blend_change_pct\":%.2f,"
                "\"keys_precompute_ms\":%.1f,\"sync_24_inbetweens_ms\":%.2f,"
                "\"app_path_24_inbetweens_ms\":%.2f}\n",
                mode == SkinningMode::Rigid ? "rigid" : "linear_blend", rest.jointCount(),
                times.vertices, keyA, keyB, resolved, 100 * (resolved / keyMean - 1), naive,
                100 * (naive / keyMean - 1), times.keysPrecomputeMs, times.syncMs, times.appMs);
    return 0;
}

int benchCageArm()
{
    const double bend = M_PI / 3;
    auto [a, b] = cageArmKeys(bend);
    std::vector<Frame> keys{a, b};
    DeformSetupCache cache;
    if (!solveInbetweenPoses(keys, {}, &cache))
        return 1;
    auto plan = planInbetweens(keys[0], keys[1], {0.5}, TargetPath::Arc);
    if (!solveInbetweenPoses(plan.frames, {}, &cache))
        return 1;
    const QPointF elbow = (kShoulder + kHand) / 2;
    const auto tipAngle = [&](const DeformedStrokes &pose) {
        const StrokePoint tip = pose.strokes[1].back();
        return std::atan2(double(tip.y) - elbow.y(), double(tip.x) - elbow.x()) * 180 / M_PI;
    };
    const double turnB =
        tipAngle(*keys[1].groups[0].deformed) - tipAngle(*keys[0].groups[0].deformed);
    const double turnMiddle =
        tipAngle(*plan.frames[0].groups[0].deformed) - tipAngle(*keys[0].groups[0].deformed);
    double drift = 0;
    const auto &rest = a.groups[0].rig.cage.rest;
    for (std::size_t i = 0; i < rest.size(); ++i)
        if (rest[i] == b.groups[0].rig.cage.posed[i]) {
            const QPointF d = plan.frames[0].groups[0].rig.cage.posed[i] - rest[i];
            drift = std::max(drift, std::hypot(d.x(), d.y()));
        }
    const DeformedStrokes &poseA = *keys[0].groups[0].deformed;
    const DeformedStrokes &poseB = *keys[1].groups[0].deformed;
    const double keyA = strokeLength(poseA), keyB = strokeLength(poseB);
    const double keyMean = (keyA + keyB) / 2;
    const double resolved = strokeLength(*plan.frames[0].groups[0].deformed);
    const double naive = strokeLength(blendPoints(poseA, poseB, 0.5));
    InbetweenTimes times;
    if (!timeInbetweens(a, b, times))
        return 1;
    std::printf("{\"bench\":\"inbetween\",\"case\":\"arm_bend_60_cage\",\"corners\":%zu,"
                "\"key_length_px\":[%.2f,%.2f],\"middle_resolved_change_pct\":%.2f,"
                "\"middle_naive_blend_change_pct\":%.2f,"
                "\"vertices\":%lld,\"key_tip_turn_deg\":%.2f,\"middle_tip_turn_deg\":%.2f,"
                "\"middle_still_corner_drift_px\":%.3f,\"keys_precompute_ms\":%.1f,"
                "\"sync_24_inbetweens_ms\":%.2f,\"app_path_24_inbetweens_ms\":%.2f}\n",
                rest.size(), keyA, keyB, 100 * (resolved / keyMean - 1),
                100 * (naive / keyMean - 1), times.vertices, turnB, turnMiddle, drift,
                times.keysPrecomputeMs, times.syncMs, times.appMs);
    return 0;
}

// 25 wavy strokes of 200 points crossing a 700×420 area (bench_pose's object), 4 corner pins.
StrokeGroup bigObject(Document &doc)
{
    StrokeGroup g;
    g.id = doc.allocateId();
    g.name = QStringLiteral("Object");
    for (int s = 0; s < 25; ++s) {
        auto data = std::make_shared<StrokeData>();
        data->width = 4.0f;
        const bool across = s % 2 == 0;
        for (int i = 0; i < 200; ++i) {
            const float t = float(i) / 199.0f;
            const float wave = 12.0f * std::sin(t * 12.0f + float(s));
            data->points.push_back(across ? StrokePoint{300 + 700 * t, 150 + 17.0f * s + wave, 1}
                                          : StrokePoint{300 + 28.0f * s + wave, 150 + 420 * t, 1});
        }
        g.strokes.push_back({doc.allocateId(), std::move(data)});
    }
    for (const QPointF p :
         {QPointF(300, 150), QPointF(1000, 150), QPointF(300, 570), QPointF(1000, 570)})
        g.rig.pins.push_back({doc.allocateId(), p, p});
    return g;
}

bool waitFor(const std::function<bool()> &done, int timeoutMs)
{
    QElapsedTimer timer;
    timer.start();
    while (!done() && timer.elapsed() < timeoutMs)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    return done();
}

int benchGenerate()
{
    Document doc;
    Frame first;
    first.id = doc.allocateId();
    first.groups.push_back(bigObject(doc));
    Frame second = first;
    second.id = doc.allocateId();
    second.groups[0].id = doc.allocateId();
    for (Stroke &s : second.groups[0].strokes)
        s.id = doc.allocateId();
    for (Pin &p : second.groups[0].rig.pins) {
        p.id = doc.allocateId(); // the second key: turned 40° about the first pin, one corner out
        const QPointF d = p.rest - QPointF(300, 150);
        const double c = std::cos(0.7), s = std::sin(0.7);
        p.target = QPointF(300, 150) + QPointF(c * d.x() - s * d.y(), s * d.x() + c * d.y());
    }
    second.groups[0].rig.pins[3].target += QPointF(60, 30);
    doc.reset({first, second}, {}, doc.nextId());
    DeformController controller(&doc);
    const Id keyA = doc.frameAt(0).groups[0].id, keyB = doc.frameAt(1).groups[0].id;
    const auto t0 = Clock::now();
    controller.prepare(keyA);
    controller.prepare(keyB);
    if (!waitFor([&] { return controller.setup(keyA) && controller.setup(keyB); }, 60000)) {
        std::fprintf(stderr, "inbetween: the keys' precompute did not finish\n");
        return 1;
    }
    const double keysMs = msSince(t0);
    const long long vertices = controller.setup(keyA)->meshVertices().rows();

    const auto t1 = Clock::now();
    auto *command = new InsertInbetweensCommand(&doc, doc.frameAt(0).id, doc.frameAt(1).id, 24,
                                                {{SpacingKind::EaseInOut, 0}, TargetPath::Arc});
    doc.undoStack()->push(command);
    const auto posed = [&] {
        return std::all_of(doc.frames().begin(), doc.frames().end(),
                           [](const Frame &f) { return f.groups[0].deformed != nullptr; });
    };
    const bool syncPosed = posed(); // all solved inside push: the factorization was shared
    const double appMs = msSince(t1);
    if (!waitFor(posed, 60000))
        return 1;

    // The synchronous path: plan, then solve with setups built here (once) or handed in.
    auto plan = planInbetweens(doc.frameAt(0), doc.frameAt(25),
                               inbetweenTimes(24, {SpacingKind::EaseInOut, 0}));
    auto planWarm = plan;
    const auto t2 = Clock::now();
    const auto cold = solveInbetweenPoses(plan.frames);
    const double coldMs = msSince(t2);
    DeformSetupCache cache{std::shared_ptr<const DeformSetup>(std::shared_ptr<const DeformSetup>{},
                                                              controller.setup(keyA))};
    const auto t3 = Clock::now();
    const auto warm = solveInbetweenPoses(planWarm.frames, {}, &cache);
    const double warmMs = msSince(t3);
    if (!cold || !warm)
        return 1;
    std::printf("{\"bench\":\"inbetween\",\"case\":\"generate_24\",\"vertices\":%lld,"
                "\"keys_precompute_ms\":%.1f,\"app_path_insert_and_pose_ms\":%.2f,"
                "\"posed_within_push\":%s,\"sync_build_once_and_solve_ms\":%.2f,"
                "\"sync_shared_setup_solve_ms\":%.2f,\"frames\":%d}\n",
                vertices, keysMs, appMs, syncPosed ? "true" : "false", coldMs, warmMs,
                doc.frameCount());
    return 0;
}

int benchInbetween(const QStringList &)
{
    if (const int rc = benchArm())
        return rc;
    for (SkinningMode mode : {SkinningMode::Rigid, SkinningMode::LinearBlend})
        if (const int rc = benchSkeletonArm(mode))
            return rc;
    if (const int rc = benchCageArm())
        return rc;
    return benchGenerate();
}

} // namespace

FINBOOK_BENCH("inbetween",
              "inbetween — arm-swing lengths (pins, skeleton, cage); 24 in-betweens of a 2k-vertex "
              "object",
              benchInbetween);
