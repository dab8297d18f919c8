// finbook-bench between-core: figures for the Between Drawings core (issue 50) on synthetic
// shapes, one JSON object per line; never gates on time.
//
// For each shape: meshed at ~2k vertices (geometry's quality triangulation of the outline);
// key B = the outline bent by 40° at a joint (blended over the limb's width), redrawn (resampled
// at 1.37× the spacing, cut into 8 strokes, half of them reversed, their order shuffled,
// jittered by up to 1 px). Prints the correspondence error of A's samples against the known
// bend (median and p95, % of the diagonal), the fit's time, the re-solve time per pin change,
// and the interpolation's precompute time and time per t.
#include "../deform/between_fixtures.h"
#include "bench.h"

#include <finbook/deform/between/arap_interpolation.h>
#include <finbook/deform/between/rigid_fit.h>
#include <finbook/geometry/embedding.h>
#include <finbook/geometry/object_mesh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using namespace finbook;
using namespace finbook::deform::between;

namespace {
using finbook::bench::percentile;

double nowMs()
{
    return std::chrono::duration<double, std::milli>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

struct Shape {
    std::string name;
    Eigen::MatrixX2d outline; // closed ring, counter-clockwise (y up)
    Eigen::Vector2d joint;    // the bend's centre; points right of it turn
    double width = 0.0;       // the limb's width: the bend is blended over it
};

// The bend: points right of joint.x − width/2 turn about the joint, by 40° at joint.x + width/2
// and beyond (smoothstep between): an ARAP-ish pose of the limb.
Eigen::Vector2d bend(const Shape &shape, const Eigen::Vector2d &p)
{
    const double x = std::clamp((p.x() - shape.joint.x()) / shape.width + 0.5, 0.0, 1.0);
    const double degrees = 40.0 * x * x * (3.0 - 2.0 * x);
    return shape.joint + test::rotationBy(degrees) * (p - shape.joint);
}

// Points every `spacing` along the closed ring (or open polyline), in order.
Eigen::MatrixX2d resample(const Eigen::MatrixX2d &ring, double spacing, bool closed)
{
    std::vector<Eigen::Vector2d> out;
    const Eigen::Index n = ring.rows(), segments = closed ? n : n - 1;
    double carry = 0.0;
    for (Eigen::Index i = 0; i < segments; ++i) {
        const Eigen::Vector2d a = ring.row(i).transpose(), b = ring.row((i + 1) % n).transpose();
        const double length = (b - a).norm();
        double at = carry;
        for (; at < length; at += spacing)
            out.push_back(a + (b - a) * (at / length));
        carry = at - length;
    }
    Eigen::MatrixX2d P(Eigen::Index(out.size()), 2);
    for (std::size_t i = 0; i < out.size(); ++i)
        P.row(Eigen::Index(i)) = out[i].transpose();
    return P;
}

// Unit normals of a polyline's points from their neighbours two steps away.
Eigen::MatrixX2d normalsOf(const Eigen::MatrixX2d &P, bool closed)
{
    const Eigen::Index n = P.rows();
    Eigen::MatrixX2d N(n, 2);
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Index a = closed ? (i + n - 2) % n : std::max<Eigen::Index>(0, i - 2);
        const Eigen::Index b = closed ? (i + 2) % n : std::min(n - 1, i + 2);
        const Eigen::Vector2d d = P.row(b) - P.row(a);
        N.row(i) = Eigen::RowVector2d(-d.y(), d.x()).normalized();
    }
    return N;
}

std::vector<Shape> shapes()
{
    std::vector<Shape> all;
    Eigen::MatrixX2d bar(4, 2);
    bar << 0, 0, 400, 0, 400, 60, 0, 60;
    all.push_back({"bar", bar, {200.0, 30.0}, 60.0});
    Eigen::MatrixX2d figure(6, 2);
    figure << 0, 0, 120, 0, 120, 140, 400, 140, 400, 200, 0, 200;
    all.push_back({"torso-arm", figure, {260.0, 170.0}, 60.0});
    std::vector<Eigen::Vector2d> tail;
    const double a0 = std::asin(14.0 / 80.0);
    for (int i = 0; i <= 60; ++i) {
        const double a = a0 + (2.0 * std::numbers::pi - 2.0 * a0) * i / 60.0;
        tail.emplace_back(100.0 + 80.0 * std::cos(a), 100.0 + 80.0 * std::sin(a));
    }
    tail.emplace_back(450.0, 86.0);
    tail.emplace_back(450.0, 114.0);
    Eigen::MatrixX2d ring(Eigen::Index(tail.size()), 2);
    for (std::size_t i = 0; i < tail.size(); ++i)
        ring.row(Eigen::Index(i)) = tail[i].transpose();
    all.push_back({"blob-tail", ring, {300.0, 100.0}, 28.0});
    return all;
}

void runShape(const Shape &shape, double spacing)
{
    geometry::MeshOptions meshOptions;
    meshOptions.targetVertices = 2000;
    meshOptions.maxVertices = 4000;
    const auto mesh = geometry::meshRegion({geometry::Polygon{shape.outline, {}}}, meshOptions);
    if (!mesh) {
        std::printf("{\"shape\":\"%s\",\"error\":\"meshing failed\"}\n", shape.name.c_str());
        return;
    }
    const Eigen::MatrixX2d aPoints = resample(shape.outline, spacing, true);
    const Eigen::MatrixX2d aNormals = normalsOf(aPoints, true);
    const geometry::Embedding samples = geometry::embed(mesh->V, mesh->F, aPoints);
    const double t0 = nowMs();
    const auto source = rigidFitPrecompute(mesh->V, mesh->F, samples, aNormals);
    const double precomputeMs = nowMs() - t0;
    if (!source) {
        std::printf("{\"shape\":\"%s\",\"error\":\"%s\"}\n", shape.name.c_str(),
                    source.error().message.c_str());
        return;
    }

    // Key B: the bent outline, redrawn.
    const Eigen::MatrixX2d dense = resample(shape.outline, 1.0, true);
    Eigen::MatrixX2d bent(dense.rows(), 2);
    for (Eigen::Index i = 0; i < dense.rows(); ++i)
        bent.row(i) = bend(shape, dense.row(i).transpose()).transpose();
    const Eigen::MatrixX2d redrawn = resample(bent, 1.37 * spacing, true);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> jitter(-1.0, 1.0);
    const int strokes = 8;
    std::vector<int> order(strokes);
    for (int s = 0; s < strokes; ++s)
        order[std::size_t(s)] = s;
    std::shuffle(order.begin(), order.end(), random);
    test::StrokePoints b;
    for (const int s : order) {
        const Eigen::Index from = redrawn.rows() * s / strokes,
                           to = redrawn.rows() * (s + 1) / strokes;
        Eigen::MatrixX2d stroke = redrawn.middleRows(from, to - from);
        if (s % 2 == 1)
            stroke = stroke.colwise().reverse().eval();
        for (Eigen::Index i = 0; i < stroke.rows(); ++i)
            stroke.row(i) += Eigen::RowVector2d(jitter(random), jitter(random));
        const Eigen::MatrixX2d normals = normalsOf(stroke, false);
        for (Eigen::Index i = 0; i < stroke.rows(); ++i)
            b.add(stroke.row(i).transpose(), normals.row(i).transpose());
    }
    const auto target = rigidFitTarget(b.P, b.N);

    std::vector<double> fitMs;
    RigidFitResult fit;
    for (int run = 0; run < 3; ++run) {
        const double start = nowMs();
        fit = rigidFit(**source, *target);
        fitMs.push_back(nowMs() - start);
    }
    Eigen::MatrixX2d truth(aPoints.rows(), 2);
    for (Eigen::Index i = 0; i < aPoints.rows(); ++i)
        truth.row(i) = bend(shape, aPoints.row(i).transpose()).transpose();
    const double diagonal = (truth.colwise().maxCoeff() - truth.colwise().minCoeff()).norm();
    std::vector<double> error(std::size_t(aPoints.rows()));
    for (Eigen::Index i = 0; i < aPoints.rows(); ++i)
        error[std::size_t(i)] = 100.0 * (fit.samples.row(i) - truth.row(i)).norm() / diagonal;

    // Pin changes: a pin on the sample farthest right (the limb's tip) at its true place,
    // then dragged 2 px at a time.
    Eigen::Index tip = 0;
    for (Eigen::Index i = 0; i < aPoints.rows(); ++i)
        if (aPoints(i, 0) > aPoints(tip, 0))
            tip = i;
    std::vector<double> pinMs;
    RigidFitResult pinned = fit;
    for (int move = 0; move < 6; ++move) {
        const Eigen::RowVector2d goal = truth.row(tip) + Eigen::RowVector2d(0.0, 2.0 * move);
        const FitPins pins =
            pinsAtSamples(samples, (Eigen::VectorXi(1) << int(tip)).finished(), goal);
        const double start = nowMs();
        pinned = rigidRefit(**source, *target, pins, pinned);
        pinMs.push_back(nowMs() - start);
    }

    double start = nowMs();
    const auto interpolation = arapInterpolationPrecompute(mesh->V, fit.U, mesh->F);
    const double interpolationPrecomputeMs = nowMs() - start;
    std::vector<double> perT;
    bool finite = true;
    for (int k = 0; k <= 8 && interpolation; ++k) {
        start = nowMs();
        const auto U = arapInterpolate(**interpolation, k / 8.0);
        perT.push_back(nowMs() - start);
        finite = finite && U && U->allFinite();
    }

    std::printf("{\"bench\":\"between-core\",\"shape\":\"%s\",\"spacingPx\":%.1f,"
                "\"vertices\":%d,\"triangles\":%d,"
                "\"samplesA\":%d,\"pointsB\":%d,\"status\":%d,\"converged\":%s,\"iterations\":%d,"
                "\"errorMedianPct\":%.3f,\"errorP95Pct\":%.3f,\"residualMedianPx\":%.3f,"
                "\"residualP95Px\":%.3f,\"distortion\":%.4f,\"precomputeMs\":%.2f,"
                "\"fitMs\":%.1f,\"pinChangeMs\":%.1f,\"pinChangeMaxMs\":%.1f,"
                "\"interpolationPrecomputeMs\":%.2f,\"interpolationPerTMs\":%.3f,"
                "\"interpolationFinite\":%s}\n",
                shape.name.c_str(), spacing, int(mesh->V.rows()), int(mesh->F.rows()),
                int(aPoints.rows()), int(b.P.rows()), int(fit.status),
                fit.converged ? "true" : "false", fit.iterations, percentile(error, 0.5),
                percentile(error, 0.95), fit.medianResidual, fit.p95Residual, fit.distortion,
                precomputeMs, percentile(fitMs, 0.5), percentile(pinMs, 0.5),
                *std::max_element(pinMs.begin(), pinMs.end()), interpolationPrecomputeMs,
                percentile(perT, 0.5), finite ? "true" : "false");
    std::fflush(stdout);
}

int benchBetweenCore(const QStringList &)
{
    // A's stroke points every 4 px and every 2 px (B's at 1.37× that).
    for (const double spacing : {4.0, 2.0})
        for (const Shape &shape : shapes())
            runShape(shape, spacing);
    return 0;
}

} // namespace

FINBOOK_BENCH("between-core", "  (Between Drawings: fit and interpolation on synthetic shapes)",
              benchBetweenCore);
