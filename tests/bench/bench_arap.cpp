// finbook-bench arap: precompute and per-drag-event cost of the ARAP deformer on square grid
// meshes (with --bar: 4:1 bars, the bent bars' shape), each with 4 pins and with about 6 % of
// the vertices pinned (pins column; precompute_min_ms the fastest of several precomputes,
// precompute_cpu_min_ms the least CPU time of the calling thread, which a busy machine
// disturbs less; the precompute's helper thread runs beside it), against the floor of one step-2
// back-substitution, plus pin-to-strokes latency and the refined method's drag event (update_ms is
// the paper's two steps, drag_ms the refined drag stage, drag_over_update their ratio; factor_isa
// the instruction set of the factorization; *_min_ms the fastest event, less disturbed by a busy
// machine); then the pose quality of a 4:1 bar bent 60° (see arap_quality.h; there
// drag_over_two_step is the same ratio for that pose). With --quality FILE... the same quality
// columns for real drawings, each meshed as the app meshes it and bent 45° (with --density D
// at that mesh density: 3.65 for about 20k vertices). --dump DIR writes each bend and its
// reference pose as text, to check the reference against another ARAP solver.
#include "../deform/grid_mesh.h"
#include "arap_quality.h"
#include "bench.h"

#include <finbook/deform/arap.h>

#include <QFileInfo>
#include <QJsonDocument>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <random>

namespace {

using finbook::bench::threadCpuMs;

using finbook::deform::ArapPrecompute;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

template <class Fn> double medianMs(int repeats, Fn &&fn)
{
    std::vector<double> samples;
    for (int k = 0; k < repeats; ++k) {
        const auto start = Clock::now();
        fn();
        samples.push_back(msSince(start));
    }
    return finbook::bench::median(samples);
}

// Stroke points embedded barycentrically: a face and three weights per point, as the
// geometry layer's embedding provides them in the app.
struct Embedding {
    Eigen::VectorXi face;
    Eigen::MatrixX3d weights;
};

Embedding randomEmbedding(Eigen::Index faces, int points)
{
    std::mt19937 random(7);
    std::uniform_int_distribution<int> pick(0, int(faces) - 1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Embedding e{Eigen::VectorXi(points), Eigen::MatrixX3d(points, 3)};
    for (int p = 0; p < points; ++p) {
        double a = unit(random), b = unit(random);
        if (a + b > 1.0) {
            a = 1.0 - a;
            b = 1.0 - b;
        }
        e.face(p) = pick(random);
        e.weights.row(p) << 1.0 - a - b, a, b;
    }
    return e;
}

void mapPoints(const Embedding &e, const Eigen::MatrixX3i &F, const Eigen::MatrixX2d &U,
               Eigen::MatrixX2d &out)
{
    out.resize(e.face.size(), 2);
    for (Eigen::Index p = 0; p < e.face.size(); ++p) {
        const auto f = F.row(e.face(p));
        out.row(p) = e.weights(p, 0) * U.row(f(0)) + e.weights(p, 1) * U.row(f(1)) +
                     e.weights(p, 2) * U.row(f(2));
    }
}

// One drag event: the first `moving` pins move along a circle, the other pins stay.
Eigen::MatrixX2d dragTargets(const Eigen::MatrixX2d &rest, int event, double radius,
                             Eigen::Index moving = 1)
{
    Eigen::MatrixX2d bc = rest;
    const double angle = 0.05 * event;
    bc.topRows(moving).rowwise() +=
        radius * Eigen::RowVector2d(std::cos(angle) - 1.0, std::sin(angle));
    return bc;
}

// The pinned sets of `finbook-bench arap`: 4 single vertices (a quarter in from each corner),
// or about 6 % of the vertices (every vertex within 3 % of the width of the right edge, then of
// the left; the right ones move).
struct PinSet {
    Eigen::VectorXi b;
    Eigen::Index moving = 1;
};

PinSet pinSet(const finbook::test::GridMesh &g, bool sixPercent)
{
    PinSet p;
    const int c = g.columns, r = g.rows;
    if (!sixPercent) {
        p.b.resize(4);
        p.b << g.vertex(c / 4, r / 4), g.vertex(3 * c / 4, r / 4), g.vertex(c / 4, 3 * r / 4),
            g.vertex(3 * c / 4, 3 * r / 4);
        return p;
    }
    const double low = g.V.col(0).minCoeff(), high = g.V.col(0).maxCoeff();
    std::vector<int> right, left;
    for (Eigen::Index v = 0; v < g.V.rows(); ++v) {
        if (g.V(v, 0) >= high - 0.03 * (high - low))
            right.push_back(int(v));
        else if (g.V(v, 0) <= low + 0.03 * (high - low))
            left.push_back(int(v));
    }
    p.b.resize(Eigen::Index(right.size() + left.size()));
    Eigen::Index k = 0;
    for (const auto *side : {&right, &left})
        for (const int v : *side)
            p.b(k++) = v;
    p.moving = Eigen::Index(right.size());
    return p;
}

struct Floors {
    double realPairMs, complexMs, kernelMs;
};

// The lower bound of an update: one back-substitution for x and y with the same step-2 factor,
// measured three ways. floor_ms is Eigen's sparse triangular solves (as SimplicialLLT::solve) on an
// n×2 real right-hand side (two passes over L); the stricter ones pack x + iy into one complex
// right-hand side (one pass), through Eigen's solve and through the kernel arapSolve itself uses.
Floors measureFloor(const ArapPrecompute &d, int repeats)
{
    const Eigen::VectorXcd complexRhs = Eigen::VectorXcd::Random(d.freeCount);
    const Eigen::MatrixX2d realRhs = Eigen::MatrixX2d::Random(d.freeCount, 2);
    Eigen::VectorXcd x(d.freeCount);
    Eigen::MatrixX2d y(d.freeCount, 2);
    Floors f{};
    f.kernelMs = medianMs(repeats, [&] {
        x = complexRhs;
        finbook::deform::arapStepTwoBacksubstitute(d, x);
    });
    // What SimplicialLLT::solve does with the same L: Eigen's sparse triangular solves.
    const auto &L = d.stepTwoLower;
    f.complexMs = medianMs(repeats, [&] {
        x = complexRhs;
        L.triangularView<Eigen::Lower>().solveInPlace(x);
        L.transpose().triangularView<Eigen::Upper>().solveInPlace(x);
    });
    f.realPairMs = medianMs(repeats, [&] {
        y = realRhs;
        L.triangularView<Eigen::Lower>().solveInPlace(y);
        L.transpose().triangularView<Eigen::Upper>().solveInPlace(y);
    });
    return f;
}

// A 4:1 bar of about `vertices` vertices (the shape runBar bends).
finbook::test::GridMesh barMesh(int vertices)
{
    const int rows = std::max(2, int(std::lround((std::sqrt(1.0 + 16.0 * vertices) - 5.0) / 8.0)));
    return finbook::test::gridMesh(4 * rows, rows, 400.0, 100.0, 0.1);
}

int runSize(int vertices, bool sixPercent, bool bar)
{
    const auto g =
        bar ? barMesh(vertices) : finbook::test::gridMeshWithVertices(vertices, 1000.0, 0.1);
    const PinSet pins = pinSet(g, sixPercent);
    const Eigen::VectorXi &b = pins.b;
    const int repeats = vertices > 50000 ? 5 : 9;
    std::shared_ptr<const ArapPrecompute> data;
    std::vector<double> precomputes, precomputeCpu;
    for (int k = 0; k < repeats; ++k) {
        const double cpuStart = threadCpuMs();
        const auto start = Clock::now();
        data = *finbook::deform::arapPrecompute(g.V, g.F, b);
        precomputes.push_back(msSince(start));
        precomputeCpu.push_back(threadCpuMs() - cpuStart);
    }
    const double precomputeMs = finbook::bench::median(precomputes);
    const Eigen::MatrixX2d rest = finbook::test::rowsOf(g.V, b);
    Eigen::MatrixX2d U, points;
    std::vector<double> updates, endToEnd;
    const Embedding embedding = randomEmbedding(g.F.rows(), 5000);
    for (int event = 0; event < 200; ++event) {
        const Eigen::MatrixX2d bc = dragTargets(rest, event, 150.0, pins.moving);
        auto start = Clock::now();
        if (!finbook::deform::arapSolve(*data, bc, U))
            return 1;
        updates.push_back(msSince(start));
        mapPoints(embedding, g.F, U, points);
        endToEnd.push_back(msSince(start));
    }
    // The same drag with the refined method's drag stage (data.dragPasses passes).
    std::vector<double> drags;
    for (int event = 0; event < (vertices > 50000 ? 20 : 100); ++event) {
        const Eigen::MatrixX2d bc = dragTargets(rest, event, 150.0, pins.moving);
        const auto start = Clock::now();
        if (!finbook::deform::arapSolve(*data, bc, U, finbook::deform::ArapStage::Drag))
            return 1;
        drags.push_back(msSince(start));
    }
    const Floors floor = measureFloor(*data, vertices > 50000 ? 30 : 200);
    const double update = finbook::bench::median(updates);
    std::fprintf(stderr, "nnzL=%ld (%.1f/row)\n", long(data->stepTwoLower.nonZeros()),
                 double(data->stepTwoLower.nonZeros()) / double(data->freeCount));
    std::printf("{\"bench\":\"arap\",\"mesh\":\"%s\",\"vertices\":%lld,\"triangles\":%lld,"
                "\"pins\":%lld,\"precompute_ms\":%.3f,\"precompute_min_ms\":%.3f,"
                "\"precompute_cpu_min_ms\":%.3f,\"update_ms\":%.4f,\"floor_ms\":"
                "%.4f,\"ratio\":%.2f,"
                "\"floor_complex_ms\":%.4f,\"floor_kernel_ms\":%.4f,\"ratio_vs_kernel\":%.2f,"
                "\"stroke_points\":5000,\"end_to_end_ms\":%.4f,\"drag_passes\":%d,"
                "\"drag_ms\":%.4f,\"drag_min_ms\":%.4f,\"update_min_ms\":%.4f,"
                "\"drag_over_update\":%.2f,\"factor_isa\":\"%s\"}\n",
                bar ? "bar 4:1" : "square", (long long)g.V.rows(), (long long)g.F.rows(),
                (long long)b.size(), precomputeMs,
                *std::min_element(precomputes.begin(), precomputes.end()),
                *std::min_element(precomputeCpu.begin(), precomputeCpu.end()), update,
                floor.realPairMs, update / floor.realPairMs, floor.complexMs, floor.kernelMs,
                update / floor.kernelMs, finbook::bench::median(endToEnd), data->dragPasses,
                finbook::bench::median(drags), *std::min_element(drags.begin(), drags.end()),
                *std::min_element(updates.begin(), updates.end()),
                finbook::bench::median(drags) / update,
                finbook::deform::supernodalInstructionSet());
    std::fflush(stdout);
    return 0;
}

void printRow(QJsonObject row)
{
    if (!row.contains(QStringLiteral("bench")))
        row.insert(QStringLiteral("bench"), QStringLiteral("arap_quality"));
    std::printf("%s\n", QJsonDocument(row).toJson(QJsonDocument::Compact).constData());
    std::fflush(stdout);
}

// A 4:1 bar of about `vertices` vertices, bent 60°.
void runBar(int vertices, const QString &dumpDirectory)
{
    const auto g = barMesh(vertices);
    QJsonObject row = finbook::bench::measureBend(g.V, g.F, 60.0, dumpDirectory);
    row.insert(QStringLiteral("mesh"), QStringLiteral("bar 4:1"));
    printRow(row);
}

int runQuality(QStringList files)
{
    double density = 1.0;
    if (const int at = int(files.indexOf(QStringLiteral("--density")));
        at >= 0 && at + 1 < files.size()) {
        density = std::clamp(files[at + 1].toDouble(), 0.01, 100.0);
        files.remove(at, 2);
    }
    QString dumpDirectory;
    if (const int at = int(files.indexOf(QStringLiteral("--dump")));
        at >= 0 && at + 1 < files.size()) {
        dumpDirectory = files[at + 1];
        files.remove(at, 2);
    }
    QList<QJsonObject> rows;
    for (const QString &path : files) {
        QString error;
        const auto mesh = finbook::test::meshDrawing(path, error, density);
        QJsonObject row =
            mesh ? finbook::bench::measureBend(mesh->first, mesh->second, 45.0, dumpDirectory)
                 : QJsonObject{{QStringLiteral("error"), error}};
        row.insert(QStringLiteral("file"), QFileInfo(path).fileName());
        printRow(row);
        rows.append(row);
    }
    const QJsonObject summary = finbook::bench::summariseBends(rows);
    if (rows.size() > 1)
        printRow(summary);
    return summary.value(QStringLiteral("failed")).toInt() == 0 ? 0 : 1;
}

int benchArap(const QStringList &args)
{
    if (const int at = int(args.indexOf(QStringLiteral("--quality"))); at >= 0)
        return runQuality(args.mid(at + 1));
    QList<int> sizes{2000, 20000, 100000}, bars{2000, 20000};
    for (const auto &[flag, list] : {std::pair{QStringLiteral("--sizes"), &sizes},
                                     std::pair{QStringLiteral("--bars"), &bars}}) {
        const int at = int(args.indexOf(flag));
        if (at >= 0 && at + 1 < args.size()) {
            list->clear();
            for (const QString &s : args[at + 1].split(QLatin1Char(','), Qt::SkipEmptyParts))
                list->append(s.toInt());
        }
    }
    const bool bar = args.contains(QStringLiteral("--bar"));
    for (const int n : sizes) {
        for (const bool sixPercent : {false, true}) {
            if (n < 9 || runSize(n, sixPercent, bar) != 0) {
                std::fprintf(stderr, "arap: size %d failed\n", n);
                return 1;
            }
        }
    }
    const int dump = int(args.indexOf(QStringLiteral("--dump")));
    const QString dumpDirectory = dump >= 0 && dump + 1 < args.size() ? args[dump + 1] : QString();
    for (const int n : bars)
        runBar(std::max(9, n), dumpDirectory);
    return 0;
}

} // namespace

FINBOOK_BENCH("arap",
              "[--sizes 2000,20000,100000] [--bar] [--bars 2000,20000] [--dump DIR] | --quality "
              "[--density D] [--dump DIR] FILE...",
              benchArap);
