// ARAP-regularised non-rigid ICP: the iterations after the coarse and rigid alignment.
#include "rigid_fit_internal.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <optional>

namespace finbook::deform::between {
namespace {

using detail::Complex;

// A tiny pull of every vertex towards where it is (relative to the data term's weight per
// vertex): keeps the system positive definite where a part of A has no pair and no pin
// (a stroke group's separate lobe far from B) and changes a converged fit by nothing.
constexpr double kProximalWeight = 1e-4;

// Two starts' fits whose scores (rigidFit) differ by less than this share lie as close as
// each other.
constexpr double kTie = 0.01;

// The state of the iterations: vertex positions x+iy, a rotation per triangle, one scale.
struct FitState {
    Eigen::VectorXcd u;
    Eigen::VectorXcd rotation;
    double scale = 1.0;
};

Eigen::MatrixX2d toMatrix(const Eigen::VectorXcd &u)
{
    Eigen::MatrixX2d U(u.size(), 2);
    U.col(0) = u.real();
    U.col(1) = u.imag();
    return U;
}

// Local step: the best rotation of every triangle for the cotangent-weighted edge covariance
// (a triangle squashed flat keeps its previous rotation), then the one global scale.
void fitRotations(const RigidFitSource &source, bool allowScale, FitState &state)
{
    double covarianceSum = 0.0;
    for (Eigen::Index t = 0; t < source.F.rows(); ++t) {
        Complex covariance = 0.0;
        for (int c = 0; c < 3; ++c) {
            const int i = source.F(t, (c + 1) % 3), j = source.F(t, (c + 2) % 3);
            const Complex rest = source.corner(t, (c + 2) % 3) - source.corner(t, (c + 1) % 3);
            covariance += source.edgeWeight(t, c) * std::conj(rest) * (state.u(j) - state.u(i));
        }
        const double magnitude = std::abs(covariance);
        if (magnitude > 1e-300 && std::isfinite(magnitude))
            state.rotation(t) = covariance / magnitude;
        covarianceSum += magnitude;
    }
    if (allowScale && source.restSquaredNorm > 0.0 && covarianceSum > 0.0)
        state.scale = covarianceSum / source.restSquaredNorm;
}

class ArapIcp {
public:
    ArapIcp(const RigidFitSource &source, const RigidFitTarget &target, const FitPins &pins,
            const RigidFitOptions &options)
        : m_source(source)
        , m_target(target)
        , m_pins(pins)
        , m_options(options)
        , m_system(source.system)
    {}

    // One iteration at stiffness alpha: rotations, pairs, assemble, factor, solve. Returns the
    // largest vertex move, or −1 when the system could not be factored.
    double iterate(double alpha, FitState &state)
    {
        const RigidFitSource &s = m_source;
        const double n = double(s.vertexCount());
        fitRotations(s, m_options.allowScale, state);
        const Eigen::MatrixX2d X = detail::samplePositions(s, toMatrix(state.u));
        Eigen::MatrixX2d M(s.sampleCount(), 2);
        for (int k = 0; k < s.sampleCount(); ++k) {
            const Complex r = state.rotation(s.I(k)) * Complex(s.N(k, 0), s.N(k, 1));
            M.row(k) << r.real(), r.imag();
        }
        const detail::Pairs pairs = detail::findPairs(s, m_target, X, M, m_options);

        m_system.clear();
        Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(s.vertexCount());
        for (Eigen::Index t = 0; t < s.F.rows(); ++t) {
            for (int c = 0; c < 3; ++c) {
                const int a = (c + 1) % 3, b = (c + 2) % 3;
                const double w = alpha * s.stiffnessUnit * s.edgeWeight(t, c);
                m_system.addEntry(int(t), a, a, w);
                m_system.addEntry(int(t), b, b, w);
                m_system.addEntry(int(t), a, b, -w);
                const Complex d =
                    w * state.scale * state.rotation(t) * (s.corner(t, b) - s.corner(t, a));
                rhs(s.F(t, b)) += d;
                rhs(s.F(t, a)) -= d;
            }
        }
        const auto addPoint = [&](int t, const double beta[3], double w, const Complex &y) {
            m_system.addTriangleBlock(t, beta, w);
            for (int c = 0; c < 3; ++c)
                rhs(s.F(t, c)) += w * beta[c] * y;
        };
        for (std::size_t p = 0; p < pairs.sample.size(); ++p) {
            const int k = pairs.sample[p];
            const double beta[3] = {s.B(k, 0), s.B(k, 1), s.B(k, 2)};
            addPoint(s.I(k), beta, n * pairs.weight[p],
                     Complex(pairs.target[p].x(), pairs.target[p].y()));
        }
        const double pinWeight = n * m_options.pinWeight / std::max(1, pairs.abCount);
        for (Eigen::Index p = 0; p < m_pins.targets.rows(); ++p) {
            const double beta[3] = {m_pins.where.B(p, 0), m_pins.where.B(p, 1),
                                    m_pins.where.B(p, 2)};
            addPoint(m_pins.where.I(p), beta, pinWeight,
                     Complex(m_pins.targets(p, 0), m_pins.targets(p, 1)));
        }
        const double hingeWeight = n * m_options.hingeWeight / std::max(1, pairs.abCount);
        for (std::size_t h = 0; h < s.hinges.size(); ++h)
            m_system.addLink(int(h), hingeWeight);
        for (int v = 0; v < s.vertexCount(); ++v) {
            m_system.addDiagonal(v, kProximalWeight);
            rhs(v) += kProximalWeight * state.u(v);
        }
        if (!m_system.factorize())
            return -1.0;
        m_system.solveInPlace(rhs.data());
        if (!rhs.allFinite())
            return -1.0;
        const double moved = std::sqrt((rhs - state.u).cwiseAbs2().maxCoeff());
        state.u = rhs;
        return moved;
    }

private:
    const RigidFitSource &m_source;
    const RigidFitTarget &m_target;
    const FitPins &m_pins;
    const RigidFitOptions &m_options;
    detail::MeshSystem m_system;
};

FitState stateFrom(const Eigen::MatrixX2d &U, Eigen::Index triangles, const Complex &rotation,
                   double scale)
{
    FitState state;
    state.u.resize(U.rows());
    state.u.real() = U.col(0);
    state.u.imag() = U.col(1);
    state.rotation = Eigen::VectorXcd::Constant(triangles, rotation);
    state.scale = scale;
    return state;
}

// Runs the stages on `state`; fills U, iterations, converged and status of r.
void runStages(const RigidFitSource &source, const RigidFitTarget &target, const FitPins &pins,
               const RigidFitOptions &options, const std::vector<double> &stages,
               int iterationsPerStage, FitState &state, RigidFitResult &r)
{
    ArapIcp icp(source, target, pins, options);
    const double tolerance = options.tolerance * std::max(target.diagonal, 1e-12);
    r.status = FitStatus::Fitted;
    for (std::size_t stage = 0; stage < stages.size(); ++stage) {
        r.converged = false;
        for (int i = 0; i < iterationsPerStage; ++i) {
            FitState next = state;
            const double moved = icp.iterate(stages[stage], next);
            ++r.iterations;
            if (moved < 0.0) {
                r.status = FitStatus::SolveFailed;
                r.message = "the fit's linear system could not be solved";
                break;
            }
            state = std::move(next);
            if (moved <= tolerance) {
                r.converged = true;
                break;
            }
        }
        if (r.status != FitStatus::Fitted)
            break;
    }
    r.U = toMatrix(state.u);
    r.scale = state.scale;
}

RigidFitResult unfitted(const RigidFitSource &source, FitStatus status, std::string message)
{
    RigidFitResult r;
    r.status = status;
    r.U = source.V;
    r.samples = source.rest;
    r.residual = Eigen::VectorXd::Zero(source.sampleCount());
    r.message = std::move(message);
    return r;
}

} // namespace

RigidFitResult rigidFit(const RigidFitSource &source, const RigidFitTarget &target,
                        const FitPins &pins, const RigidFitOptions &options)
{
    return rigidFit(source, target, pins, FitSkeleton{}, options);
}

RigidFitResult rigidFit(const RigidFitSource &source, const RigidFitTarget &target,
                        const FitPins &pins, const FitSkeleton &skeleton,
                        const RigidFitOptions &options)
{
    if (target.P.rows() == 0)
        return unfitted(source, FitStatus::EmptyTarget, "drawing B has no points to fit A to");
    if (!detail::pinsValid(source, pins))
        return unfitted(source, FitStatus::InvalidPins, "a correspondence pin is not on A");
    RigidFitResult r;
    detail::Similarity unturned;
    const detail::Similarity start =
        detail::coarseAlignment(source, target, pins, options, r.coarse.chamfer, &unturned);
    r.coarse.linear = start.linear;
    r.coarse.translation = start.translation;
    // A start: a rigid placement (and, with a skeleton, A's parts turned from it) and the
    // first, stiffest stage from it; then the other stages.
    struct Run {
        FitState state;
        RigidFitResult fit;
    };
    const std::size_t firstStages = std::min<std::size_t>(1, options.stiffness.size());
    const std::vector<double> first(options.stiffness.begin(),
                                    options.stiffness.begin() + std::ptrdiff_t(firstStages));
    const std::vector<double> later(options.stiffness.begin() + std::ptrdiff_t(firstStages),
                                    options.stiffness.end());
    const auto begin = [&](const detail::Similarity &rigid,
                           std::optional<detail::ArticulatedStart> articulated) {
        const double scale = std::sqrt(std::abs(rigid.linear.determinant()));
        const Complex rotation =
            std::polar(1.0, std::atan2(rigid.linear(1, 0) - rigid.linear(0, 1),
                                       rigid.linear(0, 0) + rigid.linear(1, 1)));
        const Eigen::MatrixX2d U0 =
            articulated
                ? detail::articulatedStart(source, target, rigid, skeleton, options, *articulated)
                : rigid.apply(source.V);
        Run run{stateFrom(U0, source.F.rows(), rotation, options.allowScale ? scale : 1.0), r};
        runStages(source, target, pins, options, first, options.stageIterations, run.state,
                  run.fit);
        // Pieces hinged to others (an arm drawn over the body) are turned about their hinges
        // once the stiff stage has laid the body on B's (detail::turnHingedPieces), and the
        // stage is run again from there.
        if (!source.hinges.empty() && run.fit.status != FitStatus::SolveFailed) {
            const Eigen::MatrixX2d turned =
                detail::turnHingedPieces(source, target, toMatrix(run.state.u), options);
            run.state.u.real() = turned.col(0);
            run.state.u.imag() = turned.col(1);
            const int before = run.fit.iterations;
            runStages(source, target, pins, options, first, options.stageIterations, run.state,
                      run.fit);
            run.fit.iterations += before;
        }
        detail::reportResidual(source, target, options, run.fit);
        return run;
    };
    const auto finish = [&](Run run) {
        if (run.fit.status != FitStatus::SolveFailed && !later.empty()) {
            runStages(source, target, pins, options, later, options.stageIterations, run.state,
                      run.fit);
            detail::reportResidual(source, target, options, run.fit);
        }
        return std::move(run.fit);
    };
    const detail::Similarity rigid = detail::rigidIcp(source, target, pins, options, start);
    if (skeleton.empty())
        return finish(begin(rigid, std::nullopt));
    // With A's parts the fit has more than one start, and keeps the fit whose lines lie
    // closest to B's (both ways), the less stretched: the articulated start can turn a part
    // onto the wrong limb of B, and a whole-drawing turn that the moments chose (B's limbs
    // posed otherwise move its axes) can be worse than none.
    // The medians do not see a part of B that nothing of A reached (an arm B shows raised that
    // a start left hanging): each such point of B counts as far as the distance that makes it
    // uncovered.
    const double far = options.failMedian * std::max(target.diagonal, 1e-12);
    const auto score = [far](const RigidFitResult &f) {
        if (f.status == FitStatus::SolveFailed)
            return std::numeric_limits<double>::infinity();
        return (f.medianResidual + f.coverageMedian + f.uncoveredShare * far) *
               (1.0 + f.distortion);
    };
    using detail::ArticulatedStart;
    // The starts' first stages are run side by side (each has its own system and scratch; the
    // source and target are only read): on two cores the four (five) take about the time of two.
    // Then the two that lie closest after it are relaxed, side by side, and the better kept:
    // the stiff stage already shows which starts put A's parts on the right lines of B, and
    // the relaxed stages cost as much again as the stiff one.
    const bool turned =
        (unturned.linear - start.linear).norm() > 1e-9 * std::max(1.0, start.linear.norm());
    std::vector<std::future<Run>> others;
    others.push_back(
        std::async(std::launch::async, [&] { return begin(rigid, ArticulatedStart::Subtrees); }));
    others.push_back(
        std::async(std::launch::async, [&] { return begin(rigid, ArticulatedStart::BodyFirst); }));
    if (turned)
        others.push_back(std::async(std::launch::async, [&] {
            return begin(detail::rigidIcp(source, target, pins, options, unturned),
                         ArticulatedStart::Subtrees);
        }));
    // And from the turn a sweep finds (detail::turnSwept), when the moments' turn lies far.
    const std::optional<detail::Similarity> swept =
        pins.targets.rows() == 0 ? detail::turnSwept(source, target, options, start, rigid)
                                 : std::nullopt;
    if (swept)
        others.push_back(std::async(std::launch::async,
                                    [&] { return begin(*swept, ArticulatedStart::Subtrees); }));
    std::vector<Run> runs;
    runs.push_back(begin(rigid, std::nullopt));
    for (std::future<Run> &other : others)
        runs.push_back(other.get());
    int iterations = 0;
    for (const Run &run : runs)
        iterations += run.fit.iterations;
    // Closest first. Scores within kTie of the best are a tie, kept in the starts' order
    // (plain, subtrees, body first, unturned, swept): a symmetric shape lies as close with a part
    // turned over as without, and only the plainer start has it the right way round.
    double closest = std::numeric_limits<double>::infinity();
    for (const Run &run : runs)
        closest = std::min(closest, score(run.fit));
    const auto tied = [&](const Run &run) { return score(run.fit) <= closest * (1.0 + kTie); };
    std::stable_sort(runs.begin(), runs.end(), [&](const Run &a, const Run &b) {
        if (tied(a) || tied(b))
            return tied(a) && !tied(b);
        return score(a.fit) < score(b.fit);
    });
    constexpr std::size_t kRelaxed = 2;
    runs.resize(std::min(runs.size(), kRelaxed));
    for (const Run &run : runs)
        iterations -= run.fit.iterations; // counted again with the later stages'
    std::vector<std::future<RigidFitResult>> relaxing;
    for (std::size_t i = 1; i < runs.size(); ++i)
        relaxing.push_back(
            std::async(std::launch::async, [&, i] { return finish(std::move(runs[i])); }));
    std::vector<RigidFitResult> fits;
    fits.push_back(finish(std::move(runs[0])));
    for (std::future<RigidFitResult> &other : relaxing)
        fits.push_back(other.get());
    std::size_t best = 0; // the earlier start unless a later one is closer by more than kTie
    for (std::size_t i = 0; i < fits.size(); ++i) {
        iterations += fits[i].iterations;
        if (score(fits[i]) < score(fits[best]) * (1.0 - kTie))
            best = i;
    }
    fits[best].iterations = iterations;
    return std::move(fits[best]);
}

RigidFitResult rigidRefit(const RigidFitSource &source, const RigidFitTarget &target,
                          const FitPins &pins, const RigidFitResult &previous,
                          const RigidFitOptions &options)
{
    if (previous.U.rows() != source.V.rows() || !previous.U.allFinite() ||
        previous.status == FitStatus::EmptyTarget || previous.status == FitStatus::InvalidPins ||
        previous.status == FitStatus::SolveFailed || options.stiffness.empty())
        return rigidFit(source, target, pins, options);
    if (target.P.rows() == 0)
        return unfitted(source, FitStatus::EmptyTarget, "drawing B has no points to fit A to");
    if (!detail::pinsValid(source, pins))
        return unfitted(source, FitStatus::InvalidPins, "a correspondence pin is not on A");
    RigidFitResult r;
    r.coarse = previous.coarse;
    FitState state = stateFrom(previous.U, source.F.rows(), Complex(1.0, 0.0), previous.scale);
    fitRotations(source, options.allowScale, state);
    runStages(source, target, pins, options, {options.stiffness.back()}, options.refitIterations,
              state, r);
    detail::reportResidual(source, target, options, r);
    return r;
}

} // namespace finbook::deform::between
