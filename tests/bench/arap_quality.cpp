#include "arap_quality.h"

#include "bench.h"

#include <finbook/deform/arap.h>

#include <QFile>
#include <QTextStream>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

namespace finbook::bench {
namespace {

using namespace finbook::deform;
using Clock = std::chrono::steady_clock;

constexpr double kRigidEnergy = 1e-9; // of the energy scale: the bend needs no deformation
// A drag as the app sees it: the bend reached in this many mouse events (about half a second
// at 60 Hz), each warm-started from the pose of the one before (the first from the rest
// pose, the stored pose with the pins where they were put); and a fast one in a few events.
constexpr int kDragEvents = 30;
constexpr int kFastDragEvents = 3;

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

using test::bendPins;
using Bend = test::BendPins;

// Oriented area of U over the rest area, minus 1, in %.
double areaChangePercent(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                         const Eigen::MatrixX2d &U)
{
    const auto doubleArea = [](const Eigen::MatrixX2d &P, const Eigen::RowVector3i &t) {
        const Eigen::RowVector2d e1 = P.row(t(1)) - P.row(t(0)), e2 = P.row(t(2)) - P.row(t(0));
        return e1.x() * e2.y() - e1.y() * e2.x();
    };
    double rest = 0.0, deformed = 0.0;
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        const double a = doubleArea(V, F.row(t));
        rest += std::abs(a);
        deformed += (a > 0 ? 1.0 : -1.0) * doubleArea(U, F.row(t));
    }
    return 100.0 * (deformed / rest - 1.0);
}

struct Solved {
    Eigen::MatrixX2d U;
    ArapSolveReport report;
    double ms = 0.0;
    double cpuMs = 0.0; // the same run's thread CPU time (the fastest)
};

std::optional<Solved> solveMedian(const ArapPrecompute &d, const Eigen::MatrixX2d &bc,
                                  ArapStage stage, int repeats)
{
    Solved s;
    std::vector<double> times, cpu;
    for (int k = 0; k < repeats; ++k) {
        const double cpuStart = threadCpuMs();
        const auto start = Clock::now();
        auto result = arapSolve(d, bc, s.U, stage);
        times.push_back(msSince(start));
        cpu.push_back(threadCpuMs() - cpuStart);
        if (!result)
            return std::nullopt;
        s.report = *result;
    }
    // The fastest run: on a shared 2-core machine the median mostly measures the neighbours.
    s.ms = *std::min_element(times.begin(), times.end());
    s.cpuMs = *std::min_element(cpu.begin(), cpu.end());
    return s;
}

// The bend reached in `events` drag events from rest, each event started from the previous
// event's pose (arapSolveFrom). ms is the median event (each event the fastest of `repeats`
// drags), maxMs the slowest event; cpuMs and maxCpuMs the same in thread CPU time; U and report
// are the last event's.
std::optional<Solved> dragInEvents(const ArapPrecompute &d, const Eigen::MatrixX2d &V,
                                   double degrees, int events, int repeats, double *maxMs,
                                   double *maxCpuMs)
{
    std::vector<double> times(std::size_t(events), INFINITY), cpu = times;
    Solved s;
    for (int r = 0; r < repeats; ++r) {
        s.U = V;
        for (int e = 1; e <= events; ++e) {
            const Eigen::MatrixX2d bc = bendPins(V, degrees * e / events).bc;
            const Eigen::MatrixX2d start = s.U;
            const double cpuStart = threadCpuMs();
            const auto begin = Clock::now();
            auto result = arapSolveFrom(d, bc, start, s.U);
            const double ms = msSince(begin);
            const double cpuMs = threadCpuMs() - cpuStart;
            if (!result)
                return std::nullopt;
            times[std::size_t(e - 1)] = std::min(times[std::size_t(e - 1)], ms);
            cpu[std::size_t(e - 1)] = std::min(cpu[std::size_t(e - 1)], cpuMs);
            s.report = *result;
        }
    }
    *maxMs = *std::max_element(times.begin(), times.end());
    *maxCpuMs = *std::max_element(cpu.begin(), cpu.end());
    s.ms = bench::median(times);
    s.cpuMs = bench::median(cpu);
    return s;
}

std::shared_ptr<const ArapPrecompute> prepare(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                              const Eigen::VectorXi &b, const ArapOptions &o,
                                              double *ms = nullptr)
{
    const auto start = Clock::now();
    auto data = arapPrecompute(V, F, b, o);
    if (ms)
        *ms = msSince(start);
    return data ? *data : nullptr;
}

std::vector<bool> flippedTriangles(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                   const Eigen::MatrixX2d &U)
{
    std::vector<bool> flipped(std::size_t(F.rows()), false);
    for (const int t : arapFlippedTriangleRows(V, F, U))
        flipped[std::size_t(t)] = true;
    return flipped;
}

// Flips counted fold by fold: the triangles flipped in the pose or in the reference, joined
// where they share a vertex, make the folds, and each fold counts the pose's flips over the
// reference's in it (all of them where the reference has none). An unconverged pose often turns
// over a neighbour of a reference fold's triangle instead, which _flips_beyond_reference counts
// and this does not, unless the fold has more triangles; a fold the pins do not force counts
// in both.
int flipsOverFolds(Eigen::Index vertices, const Eigen::MatrixX3i &F,
                   const std::vector<bool> &flipped, const std::vector<bool> &referenceFlipped)
{
    std::vector<int> parent(flipped.size());
    for (std::size_t t = 0; t < parent.size(); ++t)
        parent[t] = int(t);
    const auto find = [&](int t) {
        while (parent[std::size_t(t)] != t)
            t = parent[std::size_t(t)] = parent[std::size_t(parent[std::size_t(t)])];
        return t;
    };
    std::vector<int> firstAt(std::size_t(vertices), -1);
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        if (!flipped[std::size_t(t)] && !referenceFlipped[std::size_t(t)])
            continue;
        for (int k = 0; k < 3; ++k) {
            int &first = firstAt[std::size_t(F(t, k))];
            if (first < 0)
                first = int(t);
            else
                parent[std::size_t(find(int(t)))] = find(first);
        }
    }
    std::vector<int> over(flipped.size(), 0); // per fold root: pose flips minus reference's
    for (std::size_t t = 0; t < flipped.size(); ++t)
        over[std::size_t(find(int(t)))] += (flipped[t] ? 1 : 0) - (referenceFlipped[t] ? 1 : 0);
    int total = 0;
    for (const int excess : over)
        total += std::max(0, excess);
    return total;
}

// V, F, the pinned vertices, their targets and the reference pose as plain text (one file per
// bend, named by vertex count), for checking the reference against another ARAP solver.
void dump(const QString &directory, const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
          const Bend &bend, const Eigen::MatrixX2d &U)
{
    QFile file(directory + QStringLiteral("/bend_%1_%2.txt").arg(V.rows()).arg(F.rows()));
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
        return;
    QTextStream out(&file);
    out.setRealNumberPrecision(17);
    out << V.rows() << ' ' << F.rows() << ' ' << bend.b.size() << '\n';
    for (Eigen::Index v = 0; v < V.rows(); ++v)
        out << V(v, 0) << ' ' << V(v, 1) << ' ' << U(v, 0) << ' ' << U(v, 1) << '\n';
    for (Eigen::Index t = 0; t < F.rows(); ++t)
        out << F(t, 0) << ' ' << F(t, 1) << ' ' << F(t, 2) << '\n';
    for (Eigen::Index k = 0; k < bend.b.size(); ++k)
        out << bend.b(k) << ' ' << bend.bc(k, 0) << ' ' << bend.bc(k, 1) << '\n';
}

} // namespace

QJsonObject measureBend(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F, double degrees,
                        const QString &dumpDirectory)
{
    QJsonObject row{{QStringLiteral("vertices"), qint64(V.rows())},
                    {QStringLiteral("triangles"), qint64(F.rows())},
                    {QStringLiteral("bend_deg"), degrees}};
    const Bend bend = bendPins(V, degrees);
    row.insert(QStringLiteral("pins"), qint64(bend.b.size()));
    ArapOptions referenceOptions;
    referenceOptions.finalTolerance = 1e-10;
    referenceOptions.finalEnergyTolerance = 0.0;
    referenceOptions.finalPassCap = 20000;
    referenceOptions.fixFlips = false;
    ArapOptions twoStep;
    twoStep.method = ArapMethod::TwoStep;
    double precomputeMs = 0.0;
    const auto reference = prepare(V, F, bend.b, referenceOptions);
    const auto paper = prepare(V, F, bend.b, twoStep);
    const auto refined = prepare(V, F, bend.b, ArapOptions{}, &precomputeMs);
    if (!reference || !paper || !refined) {
        row.insert(QStringLiteral("error"), QStringLiteral("precompute failed"));
        return row;
    }
    const bool large = V.rows() > 10000;
    const int repeats = large ? 5 : 21;
    const auto converged = solveMedian(*reference, bend.bc, ArapStage::Final, 1);
    const auto exact = solveMedian(*paper, bend.bc, ArapStage::Drag, repeats);
    const auto drag = solveMedian(*refined, bend.bc, ArapStage::Drag, repeats);
    const auto stored = solveMedian(*refined, bend.bc, ArapStage::Final, V.rows() > 10000 ? 3 : 7);
    double warmMaxMs = 0.0, fastMaxMs = 0.0, warmMaxCpuMs = 0.0, fastMaxCpuMs = 0.0;
    const auto warm =
        dragInEvents(*refined, V, degrees, kDragEvents, large ? 2 : 5, &warmMaxMs, &warmMaxCpuMs);
    const auto fast = dragInEvents(*refined, V, degrees, kFastDragEvents, large ? 3 : 11,
                                   &fastMaxMs, &fastMaxCpuMs);
    if (!converged || !exact || !drag || !stored || !warm || !fast) {
        row.insert(QStringLiteral("error"), QStringLiteral("solve failed"));
        return row;
    }
    if (!dumpDirectory.isEmpty())
        dump(dumpDirectory, V, F, bend, converged->U);
    // Everything is measured in the standard (cotangent) ARAP energy, which the refined method
    // minimises; the reference is its converged pose without flip repair.
    // Energy scale: the energy of collapsing every triangle to a point (Σ area·‖I‖² = 2·area).
    // When parts move rigidly (pinned ends in separate components) the reference energy is
    // round-off, and ratios to it say nothing: they are left out (null), the excess stays.
    const double scale = arapCotangentEnergy(V, F, Eigen::MatrixX2d::Zero(V.rows(), 2));
    const double referenceEnergy = arapCotangentEnergy(V, F, converged->U);
    const bool rigid = referenceEnergy <= kRigidEnergy * scale;
    const std::vector<bool> referenceFlipped = flippedTriangles(V, F, converged->U);
    // The vertices of the reference's folds: a flipped triangle touching one lies in a fold the
    // pins force, shifted by a triangle or so (an unconverged pose folds the neighbour first);
    // one that touches none is a fold where the converged pose has none.
    std::vector<bool> referenceFoldVertex(std::size_t(V.rows()), false);
    for (Eigen::Index t = 0; t < F.rows(); ++t)
        if (referenceFlipped[std::size_t(t)])
            for (int k = 0; k < 3; ++k)
                referenceFoldVertex[std::size_t(F(t, k))] = true;
    row.insert(QStringLiteral("reference_energy_rel"), referenceEnergy / scale);
    const auto columns = [&](const char *name, const Solved &s) {
        const QString prefix = QString::fromLatin1(name);
        const double energy = arapCotangentEnergy(V, F, s.U);
        row.insert(prefix + QStringLiteral("_energy_ratio"),
                   rigid ? QJsonValue() : QJsonValue(energy / referenceEnergy));
        row.insert(prefix + QStringLiteral("_energy_excess_rel"),
                   (energy - referenceEnergy) / scale);
        row.insert(prefix + QStringLiteral("_area_pct"), areaChangePercent(V, F, s.U));
        const std::vector<bool> flipped = flippedTriangles(V, F, s.U);
        int count = 0, beyond = 0, apart = 0;
        for (std::size_t t = 0; t < flipped.size(); ++t) {
            count += flipped[t] ? 1 : 0;
            beyond += flipped[t] && !referenceFlipped[t] ? 1 : 0;
            const auto row3 = F.row(Eigen::Index(t));
            const bool touchesFold = referenceFoldVertex[std::size_t(row3(0))] ||
                                     referenceFoldVertex[std::size_t(row3(1))] ||
                                     referenceFoldVertex[std::size_t(row3(2))];
            apart += flipped[t] && !touchesFold ? 1 : 0;
        }
        row.insert(prefix + QStringLiteral("_flips"), count);
        row.insert(prefix + QStringLiteral("_flips_over_reference_folds"),
                   flipsOverFolds(V.rows(), F, flipped, referenceFlipped));
        row.insert(prefix + QStringLiteral("_flips_beyond_reference"), beyond);
        row.insert(prefix + QStringLiteral("_flips_apart_from_reference"), apart);
        row.insert(prefix + QStringLiteral("_ms"), s.ms);
        row.insert(prefix + QStringLiteral("_cpu_ms"), s.cpuMs);
        row.insert(prefix + QStringLiteral("_passes"), s.report.passes);
    };
    row.insert(QStringLiteral("reference_passes"), converged->report.passes);
    row.insert(QStringLiteral("reference_converged"), converged->report.converged);
    row.insert(QStringLiteral("reference_area_pct"), areaChangePercent(V, F, converged->U));
    row.insert(QStringLiteral("reference_flips"), arapFlippedTriangles(V, F, converged->U));
    row.insert(QStringLiteral("negative_weight_edges"), refined->negativeWeightEdges);
    columns("two_step", *exact);
    columns("drag", *drag);
    columns("stored", *stored);
    columns("warm", *warm);
    columns("fast", *fast);
    row.insert(QStringLiteral("warm_event_max_ms"), warmMaxMs);
    row.insert(QStringLiteral("fast_event_max_ms"), fastMaxMs);
    row.insert(QStringLiteral("warm_event_max_cpu_ms"), warmMaxCpuMs);
    row.insert(QStringLiteral("fast_event_max_cpu_ms"), fastMaxCpuMs);
    // Drag time over the two steps' (the budget of large meshes is 3× their modelled time).
    row.insert(QStringLiteral("drag_over_two_step"), drag->ms / exact->ms);
    row.insert(QStringLiteral("drag_repaired"), drag->report.repairedTriangles);
    row.insert(QStringLiteral("stored_repaired"), stored->report.repairedTriangles);
    row.insert(QStringLiteral("stored_converged"), stored->report.converged);
    row.insert(QStringLiteral("stored_last_pass_energy_change"), stored->report.lastEnergyChange);
    row.insert(QStringLiteral("precompute_ms"), precomputeMs);
    return row;
}

QJsonObject summariseBends(const QList<QJsonObject> &rows)
{
    QList<QJsonObject> measured;
    for (const QJsonObject &row : rows)
        if (!row.contains(QStringLiteral("error")))
            measured.append(row);
    QJsonObject summary{{QStringLiteral("bench"), QStringLiteral("arap_quality_summary")},
                        {QStringLiteral("drawings"), qint64(measured.size())},
                        {QStringLiteral("failed"), qint64(rows.size() - measured.size())}};
    const auto values = [&](const QString &column) {
        std::vector<double> out;
        for (const QJsonObject &row : measured)
            if (row.value(column).isDouble())
                out.push_back(row.value(column).toDouble());
        return out;
    };
    const auto sum = [&](const QString &column) {
        double total = 0.0;
        for (const double v : values(column))
            total += v;
        return qint64(total);
    };
    const auto medianAndMax = [&](const QString &column) {
        std::vector<double> v = values(column);
        if (v.empty())
            return;
        summary.insert(column + QStringLiteral("_max"), *std::max_element(v.begin(), v.end()));
        summary.insert(column + QStringLiteral("_median"), bench::median(std::move(v)));
    };
    for (const char *mode : {"drag", "fast", "warm", "stored"}) {
        const QString prefix = QString::fromLatin1(mode);
        const QString ratio = prefix + QStringLiteral("_energy_ratio");
        medianAndMax(ratio);
        const QJsonObject *worst = nullptr;
        for (const QJsonObject &row : measured)
            if (row.value(ratio).isDouble() &&
                (!worst || row.value(ratio).toDouble() > worst->value(ratio).toDouble()))
                worst = &row;
        if (worst)
            summary.insert(ratio + QStringLiteral("_max_file"),
                           worst->value(QStringLiteral("file")));
        for (const char *flips : {"_flips", "_flips_beyond_reference",
                                  "_flips_over_reference_folds", "_flips_apart_from_reference"})
            summary.insert(prefix + QString::fromLatin1(flips),
                           sum(prefix + QString::fromLatin1(flips)));
        std::vector<double> cpu = values(prefix + QStringLiteral("_cpu_ms"));
        if (!cpu.empty())
            summary.insert(prefix + QStringLiteral("_cpu_ms_median"),
                           bench::median(std::move(cpu)));
    }
    medianAndMax(QStringLiteral("stored_passes"));
    medianAndMax(QStringLiteral("stored_ms"));
    medianAndMax(QStringLiteral("warm_event_max_cpu_ms"));
    qint64 converged = 0;
    for (const QJsonObject &row : measured)
        converged += row.value(QStringLiteral("stored_converged")).toBool() ? 1 : 0;
    summary.insert(QStringLiteral("stored_converged"), converged);
    summary.insert(QStringLiteral("reference_flips"), sum(QStringLiteral("reference_flips")));
    summary.insert(QStringLiteral("negative_weight_edges"),
                   sum(QStringLiteral("negative_weight_edges")));
    return summary;
}

} // namespace finbook::bench
