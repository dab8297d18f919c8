// finbook-bench skin FILE...: skinning-weight cost per real drawing or shape (meshed at about
// --vertices vertices, skeleton = the medial tree of tests/deform/skin_test_support.h with
// about 20 bones), with --compare the same boundary conditions under the alternatives of
// the notes. finbook-bench bones: per-drag cost of posing 10k stroke points with 20 bones, by
// linear blend skinning and by the rigid (ARAP) mode. One JSON object per line.
#include "../deform/skin_test_support.h"
#include "bench.h"
#include "skin_alternatives.h"

#include <finbook/deform/skeleton/inverse_kinematics.h>
#include <finbook/deform/skeleton/linear_blend_skinning.h>
#include <finbook/deform/skeleton/rigid_skinning.h>
#include <finbook/deform/skeleton/skeleton.h>
#include <finbook/deform/skeleton/skinning_weights.h>
#include <finbook/geometry/embedding.h>
#include <finbook/geometry/object_mesh.h>

#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <optional>

namespace {

using finbook::bench::threadCpuMs;

using namespace finbook::deform;
using finbook::bench::median;
using finbook::bench::percentile;
using Clock = std::chrono::steady_clock;

constexpr int kRuns = 7;

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Median wall time, and in `cpuMs` the median CPU time of this thread: the machine is shared,
// and CPU time shows what the code costs when other processes take the cores.
template <class Fn> double medianMs(int runs, Fn &&fn, double *cpuMs = nullptr)
{
    std::vector<double> cpu;
    if (cpuMs) {
        std::vector<double> wall;
        for (int k = 0; k < runs; ++k) {
            const double c = threadCpuMs();
            const auto start = Clock::now();
            fn();
            wall.push_back(msSince(start));
            cpu.push_back(threadCpuMs() - c);
        }
        *cpuMs = median(cpu);
        return median(wall);
    }
    std::vector<double> samples;
    for (int k = 0; k < runs; ++k) {
        const auto start = Clock::now();
        fn();
        samples.push_back(msSince(start));
    }
    return median(samples);
}

int optionInt(const QStringList &args, const QString &name, int fallback)
{
    const auto at = args.indexOf(name);
    return at >= 0 && at + 1 < args.size() ? args[at + 1].toInt() : fallback;
}

QStringList filesOf(const QStringList &args)
{
    QStringList files;
    for (qsizetype i = 0; i < args.size(); ++i) {
        if (args[i].startsWith(QStringLiteral("--"))) {
            i += args[i] == QStringLiteral("--compare") ? 0 : 1;
            continue;
        }
        files << args[i];
    }
    return files;
}

void print(const QJsonObject &row)
{
    std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
    std::fflush(stdout);
}

void addComparison(QJsonObject &row, const finbook::geometry::ObjectMesh &mesh,
                   const Skeleton &skeleton, const SkinningWeights &w)
{
    using namespace finbook::bench;
    double worst = 0.0;
    row.insert(QStringLiteral("harmonic_cross_gap_mean"),
               crossGapWeight(mesh.V, mesh.F, w.owner, w.handles, w.W, worst));
    row.insert(QStringLiteral("harmonic_cross_gap_max"), worst);
    Eigen::MatrixXd W;
    row.insert(QStringLiteral("inverse_square_ms"), medianMs(kRuns, [&] {
                   W = inverseSquareWeights(handleDistances(mesh.V, skeleton, w.handles));
               }));
    row.insert(QStringLiteral("inverse_square_cross_gap_mean"),
               crossGapWeight(mesh.V, mesh.F, w.owner, w.handles, W, worst));
    row.insert(QStringLiteral("inverse_square_cross_gap_max"), worst);
    row.insert(QStringLiteral("biharmonic_ms"), medianMs(3, [&] {
                   W = biharmonicWeights(mesh.V, mesh.F, w.owner, skeleton.jointCount());
               }));
    row.insert(QStringLiteral("biharmonic_min"), W.minCoeff());
    row.insert(QStringLiteral("biharmonic_max"), W.maxCoeff());
    row.insert(QStringLiteral("biharmonic_cross_gap_mean"),
               crossGapWeight(mesh.V, mesh.F, w.owner, w.handles, W, worst));
}

QJsonObject measureFile(const QString &path, int vertices, bool compare)
{
    QJsonObject row{{QStringLiteral("bench"), QStringLiteral("skin")},
                    {QStringLiteral("file"), QFileInfo(path).fileName()}};
    finbook::geometry::MeshOptions options;
    options.targetVertices = vertices;
    const auto mesh = finbook::test::meshDataFile(path, options);
    if (!mesh) {
        row.insert(QStringLiteral("error"), QStringLiteral("unreadable or not meshable"));
        return row;
    }
    const auto tree = finbook::test::medialTreeSkeleton(mesh->V, mesh->F);
    const auto skeleton = makeSkeleton(tree.joints, tree.parent);
    if (!skeleton) {
        row.insert(QStringLiteral("error"), QString::fromStdString(skeleton.error().message));
        return row;
    }
    std::shared_ptr<const SkinningWeights> w;
    double weightsCpuMs = 0.0;
    const double weightsMs = medianMs(
        kRuns,
        [&] {
            auto result = computeSkinningWeights(mesh->V, mesh->F, *skeleton);
            w = result ? *result : nullptr;
        },
        &weightsCpuMs);
    if (!w) {
        row.insert(QStringLiteral("error"), QStringLiteral("weights failed"));
        return row;
    }
    const double rigidMs = medianMs(3, [&] { (void)rigidSkinPrecompute(mesh->V, mesh->F, *w); });
    row.insert(QStringLiteral("vertices"), qint64(mesh->V.rows()));
    row.insert(QStringLiteral("bones"), qint64(w->handles.size()));
    row.insert(QStringLiteral("free_vertices"), qint64((w->owner.array() < 0).count()));
    row.insert(QStringLiteral("weights_ms"), weightsMs);
    row.insert(QStringLiteral("weights_cpu_ms"), weightsCpuMs);
    row.insert(QStringLiteral("rigid_precompute_ms"), rigidMs);
    row.insert(QStringLiteral("residual"), w->relativeResidual);
    row.insert(QStringLiteral("min_weight"), w->W.minCoeff());
    row.insert(QStringLiteral("max_row_sum_error"),
               (w->W.rowwise().sum().array() - 1.0).abs().maxCoeff());
    if (compare)
        addComparison(row, *mesh, *skeleton, *w);
    return row;
}

int benchSkin(const QStringList &args)
{
    const QStringList files = filesOf(args);
    if (files.isEmpty()) {
        std::fprintf(stderr, "usage: finbook-bench skin [--vertices N] [--compare] FILE...\n");
        return 2;
    }
    const int vertices = optionInt(args, QStringLiteral("--vertices"), 5000);
    const bool compare = args.contains(QStringLiteral("--compare"));
    std::vector<double> times, cpuTimes, sizes;
    int failures = 0;
    for (const QString &path : files) {
        const QJsonObject row = measureFile(path, vertices, compare);
        if (row.contains(QStringLiteral("error")))
            ++failures;
        else {
            times.push_back(row.value(QStringLiteral("weights_ms")).toDouble());
            cpuTimes.push_back(row.value(QStringLiteral("weights_cpu_ms")).toDouble());
            sizes.push_back(row.value(QStringLiteral("vertices")).toDouble());
        }
        print(row);
    }
    print({{QStringLiteral("bench"), QStringLiteral("skin_summary")},
           {QStringLiteral("files"), qint64(times.size())},
           {QStringLiteral("target_vertices"), vertices},
           {QStringLiteral("median_vertices"), median(sizes)},
           {QStringLiteral("median_weights_ms"), median(times)},
           {QStringLiteral("median_weights_cpu_ms"), median(cpuTimes)},
           {QStringLiteral("max_weights_cpu_ms"), percentile(cpuTimes, 1.0)},
           {QStringLiteral("max_weights_ms"), percentile(times, 1.0)}});
    return failures == 0 ? 0 : 1;
}

// A five-armed starfish (arms to 240 px) with a root in the middle and four bones per arm.
struct Scene {
    finbook::geometry::ObjectMesh mesh;
    Skeleton skeleton;
    int dragged = 0; // the joint an IK drag moves
};

std::optional<Scene> starfish(int vertices)
{
    const int n = 500;
    Eigen::MatrixX2d outline(n, 2);
    for (int i = 0; i < n; ++i) {
        const double t = 2.0 * M_PI * i / n, r = 140.0 + 100.0 * std::cos(5.0 * t);
        outline.row(i) << 300.0 + r * std::cos(t), 300.0 + r * std::sin(t);
    }
    finbook::geometry::MeshOptions options;
    options.targetVertices = vertices;
    auto mesh =
        finbook::geometry::buildObjectMesh(finbook::geometry::Region{{outline, {}}}, options);
    if (!mesh)
        return std::nullopt;
    Eigen::MatrixX2d joints(21, 2);
    Eigen::VectorXi parent(21);
    joints.row(0) << 300.0, 300.0;
    parent(0) = -1;
    const double radii[4] = {50.0, 100.0, 150.0, 210.0};
    for (int arm = 0; arm < 5; ++arm) {
        const double a = 2.0 * M_PI * arm / 5;
        for (int k = 0; k < 4; ++k) {
            const int j = 1 + 4 * arm + k;
            joints.row(j) << 300.0 + radii[k] * std::cos(a), 300.0 + radii[k] * std::sin(a);
            parent(j) = k == 0 ? 0 : j - 1;
        }
    }
    return Scene{std::move(*mesh), *makeSkeleton(joints, parent), 4};
}

std::optional<Scene> fromFile(const QString &path, int vertices)
{
    finbook::geometry::MeshOptions options;
    options.targetVertices = vertices;
    auto mesh = finbook::test::meshDataFile(path, options);
    if (!mesh)
        return std::nullopt;
    const auto tree = finbook::test::medialTreeSkeleton(mesh->V, mesh->F);
    auto skeleton = makeSkeleton(tree.joints, tree.parent);
    if (!skeleton)
        return std::nullopt;
    const int tip = int(skeleton->jointCount()) - 1; // the end of the last branch
    return Scene{std::move(*mesh), std::move(*skeleton), tip};
}

struct DragTimes {
    std::vector<double> ik, lbsPoints, lbsMesh, rigid;
};

// 200 drag events: the dragged joint circles 60 px around its rest position, each event
// solved from the rest pose (as the app does from the pose at drag start).
DragTimes drag(const Scene &scene, const SkinBinding &points, const SkinBinding &vertices,
               const RigidSkinning &rig, const finbook::geometry::Embedding &embedding)
{
    DragTimes t;
    const Skeleton &s = scene.skeleton;
    const SkeletonPose start = restPose(s);
    PosedSkeleton posed;
    Eigen::MatrixX2d out, U, strokes;
    for (int event = 0; event < 200; ++event) {
        const double a = 0.05 * event;
        const Eigen::Vector2d target = s.joints.row(scene.dragged).transpose() +
                                       60.0 * Eigen::Vector2d(std::cos(a) - 1.0, std::sin(a));
        auto begin = Clock::now();
        const auto ik = solveIk(s, start, scene.dragged, target);
        forwardKinematics(s, ik->pose, posed);
        t.ik.push_back(msSince(begin));
        begin = Clock::now();
        skin(points, posed, out);
        t.lbsPoints.push_back(t.ik.back() + msSince(begin));
        begin = Clock::now();
        skin(vertices, posed, U);
        strokes = finbook::geometry::applyEmbedding(embedding, U, scene.mesh.F);
        t.lbsMesh.push_back(t.ik.back() + msSince(begin));
        begin = Clock::now();
        (void)rigidSkinSolve(rig, posed, U);
        strokes = finbook::geometry::applyEmbedding(embedding, U, scene.mesh.F);
        t.rigid.push_back(t.ik.back() + msSince(begin));
    }
    return t;
}

// Area change (%), mean edge-length change (%) and flipped triangles of a deformed mesh.
struct Distortion {
    double area = 0.0, edges = 0.0;
    int flipped = 0;
};

Distortion distortion(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                      const Eigen::MatrixX2d &U)
{
    const auto signedArea = [&F](const Eigen::MatrixX2d &P, Eigen::Index t) {
        const Eigen::RowVector2d a = P.row(F(t, 1)) - P.row(F(t, 0));
        const Eigen::RowVector2d b = P.row(F(t, 2)) - P.row(F(t, 0));
        return 0.5 * (a.x() * b.y() - a.y() * b.x());
    };
    Distortion d;
    double rest = 0.0, posed = 0.0;
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        const double r = signedArea(V, t), p = signedArea(U, t);
        rest += r;
        posed += p;
        d.flipped += r * p <= 0.0 ? 1 : 0;
        for (int k = 0; k < 3; ++k) {
            const int i = F(t, k), j = F(t, (k + 1) % 3);
            d.edges += std::abs((U.row(j) - U.row(i)).norm() / (V.row(j) - V.row(i)).norm() - 1.0);
        }
    }
    d.area = 100.0 * std::abs(posed / rest - 1.0);
    d.edges *= 100.0 / double(3 * F.rows());
    return d;
}

// Every bone bent by `angle` (a curled character): how LBS and the rigid mode distort it.
void addCurlDistortion(QJsonObject &row, const Scene &scene, const SkinBinding &vertices,
                       const RigidSkinning &rig, double angle)
{
    SkeletonPose pose = restPose(scene.skeleton);
    for (Eigen::Index j = 0; j < pose.angles.size(); ++j)
        pose.angles(j) = scene.skeleton.isRoot(j) ? 0.0 : angle;
    const auto posed = *forwardKinematics(scene.skeleton, pose);
    Eigen::MatrixX2d U;
    skin(vertices, posed, U);
    const Distortion lbs = distortion(scene.mesh.V, scene.mesh.F, U);
    (void)rigidSkinSolve(rig, posed, U);
    const Distortion rigid = distortion(scene.mesh.V, scene.mesh.F, U);
    row.insert(QStringLiteral("curl_rad"), angle);
    row.insert(QStringLiteral("lbs_area_change_pct"), lbs.area);
    row.insert(QStringLiteral("rigid_area_change_pct"), rigid.area);
    row.insert(QStringLiteral("lbs_edge_change_pct"), lbs.edges);
    row.insert(QStringLiteral("rigid_edge_change_pct"), rigid.edges);
    row.insert(QStringLiteral("lbs_flipped"), lbs.flipped);
    row.insert(QStringLiteral("rigid_flipped"), rigid.flipped);
}

int runBones(const QString &label, const std::optional<Scene> &scene)
{
    if (!scene) {
        print({{QStringLiteral("bench"), QStringLiteral("bones")},
               {QStringLiteral("scene"), label},
               {QStringLiteral("error"), QStringLiteral("no mesh or skeleton")}});
        return 1;
    }
    const auto &mesh = scene->mesh;
    std::shared_ptr<const SkinningWeights> w;
    const double weightsMs =
        medianMs(3, [&] { w = *computeSkinningWeights(mesh.V, mesh.F, scene->skeleton); });
    std::shared_ptr<const RigidSkinning> rig;
    const double rigidMs = medianMs(3, [&] { rig = *rigidSkinPrecompute(mesh.V, mesh.F, *w); });
    Eigen::MatrixX2d strokePoints;
    const auto embedding = finbook::test::randomEmbedding(mesh.V, mesh.F, 10000, strokePoints);
    const SkinBinding points = *bindPoints(*w, mesh.V, mesh.F, embedding, strokePoints);
    const SkinBinding vertices = bindVertices(*w, mesh.V);
    const DragTimes t = drag(*scene, points, vertices, *rig, embedding);
    QJsonObject row{{QStringLiteral("bench"), QStringLiteral("bones")},
                    {QStringLiteral("scene"), label},
                    {QStringLiteral("vertices"), qint64(mesh.V.rows())},
                    {QStringLiteral("bones"), qint64(w->handles.size())},
                    {QStringLiteral("stroke_points"), 10000},
                    {QStringLiteral("rigid_pins"), qint64(rig->pinVertices.size())},
                    {QStringLiteral("weights_ms"), weightsMs},
                    {QStringLiteral("rigid_precompute_ms"), rigidMs},
                    {QStringLiteral("ik_fk_ms"), median(t.ik)},
                    {QStringLiteral("lbs_points_ms"), median(t.lbsPoints)},
                    {QStringLiteral("lbs_points_p95_ms"), percentile(t.lbsPoints, 0.95)},
                    {QStringLiteral("lbs_mesh_ms"), median(t.lbsMesh)},
                    {QStringLiteral("lbs_mesh_p95_ms"), percentile(t.lbsMesh, 0.95)},
                    {QStringLiteral("rigid_ms"), median(t.rigid)},
                    {QStringLiteral("rigid_p95_ms"), percentile(t.rigid, 0.95)}};
    addCurlDistortion(row, *scene, vertices, *rig, 0.5);
    print(row);
    return 0;
}

int benchBones(const QStringList &args)
{
    const int vertices = optionInt(args, QStringLiteral("--vertices"), 1500);
    int failures = 0;
    const QStringList files = filesOf(args);
    if (files.isEmpty())
        failures += runBones(QStringLiteral("starfish"), starfish(vertices));
    for (const QString &path : files)
        failures += runBones(QFileInfo(path).fileName(), fromFile(path, vertices));
    return failures == 0 ? 0 : 1;
}

} // namespace

FINBOOK_BENCH("skin", "[--vertices N] [--compare] FILE... (drawings or shapes as JSON)", benchSkin);
FINBOOK_BENCH("bones", "[--vertices N] [FILE...] (default: a 20-bone starfish)", benchBones);
