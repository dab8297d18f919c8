// Coarse alignment (moments, pins), pairing of nearest agreeing points, and rigid ICP.
#include "rigid_fit_internal.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace finbook::deform::between::detail {
namespace {

// Below this fraction of the target's diagonal, two chamfer distances are a tie.
constexpr double kChamferTie = 1e-6;
// Pairs are never dropped for being closer than this fraction of the target's diagonal (a
// near-perfect fit has a median pair distance of ~0, and 3 × 0 would drop everything).
constexpr double kRejectFloor = 0.05;
// The turns' sweep (turnSwept): this many turns round a full one, rigid ICP of this many of
// A's samples for at most this many steps from each, placements that turn A more than this
// (rad) left out (keys are drawn upright: a drawing turned upside down lay closer on an
// octopus's tentacles than the right one, and spun through its in-betweens), and a margin by
// which the best must lie closer than the start's (symmetric chamfer).
constexpr int kSweepSteps = 12;
constexpr Eigen::Index kSweepSamples = 200;
constexpr int kSweepIterations = 15;
constexpr double kSweepMostTurn = 0.5 * std::numbers::pi;
constexpr double kSweepMargin = 0.1;

struct Moments {
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
    Eigen::Matrix2d axes = Eigen::Matrix2d::Identity(); // columns: principal axes, det +1
    double spread = 0.0;                                // trace of the covariance
};

Moments momentsOf(const Eigen::MatrixX2d &P)
{
    Moments m;
    if (P.rows() == 0)
        return m;
    m.centroid = P.colwise().mean().transpose();
    const Eigen::MatrixX2d centred = P.rowwise() - m.centroid.transpose();
    const Eigen::Matrix2d covariance = centred.transpose() * centred / double(P.rows());
    m.spread = covariance.trace();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(covariance);
    if (eigen.info() == Eigen::Success && eigen.eigenvectors().allFinite() && m.spread > 0.0) {
        m.axes = eigen.eigenvectors();
        if (m.axes.determinant() < 0.0)
            m.axes.col(1) *= -1.0;
    }
    return m;
}

Eigen::Matrix2d rotation(double angle)
{
    return Eigen::Rotation2Dd(angle).toRotationMatrix();
}

double angleOf(const Eigen::Matrix2d &linear)
{
    return std::atan2(linear(1, 0) - linear(0, 1), linear(0, 0) + linear(1, 1));
}

// Pins' rest positions and targets with ≥ 2 distinct rest points: the transform through them.
bool distinctPins(const Eigen::MatrixX2d &rest, double diagonal)
{
    for (Eigen::Index p = 1; p < rest.rows(); ++p)
        if ((rest.row(p) - rest.row(0)).norm() > 1e-6 * std::max(diagonal, 1e-12))
            return true;
    return false;
}

} // namespace

Similarity procrustes(const Eigen::MatrixX2d &X, const Eigen::MatrixX2d &Y,
                      const Eigen::VectorXd &w, bool allowScale)
{
    Similarity s;
    const double total = w.sum();
    if (X.rows() == 0 || !(total > 0.0))
        return s;
    const Eigen::Vector2d cx = (X.transpose() * w) / total, cy = (Y.transpose() * w) / total;
    double dot = 0.0, cross = 0.0, norm = 0.0;
    for (Eigen::Index i = 0; i < X.rows(); ++i) {
        const Eigen::Vector2d a = X.row(i).transpose() - cx, b = Y.row(i).transpose() - cy;
        dot += w(i) * a.dot(b);
        cross += w(i) * (a.x() * b.y() - a.y() * b.x());
        norm += w(i) * a.squaredNorm();
    }
    const double magnitude = std::hypot(dot, cross);
    s.linear = magnitude > 0.0 ? rotation(std::atan2(cross, dot)) : Eigen::Matrix2d::Identity();
    if (allowScale && norm > 0.0 && magnitude > 0.0)
        s.linear *= magnitude / norm;
    s.translation = cy - s.linear * cx;
    return s;
}

double symmetricChamfer(const Eigen::MatrixX2d &A, const RigidFitTarget &target)
{
    if (A.rows() == 0 || target.P.rows() == 0)
        return 0.0;
    double ab = 0.0, ba = 0.0, d = 0.0;
    for (Eigen::Index i = 0; i < A.rows(); ++i) {
        target.grid.nearest(A.row(i).transpose(), Eigen::Vector2d::Zero(), 0.0, d);
        ab += d;
    }
    const PointGrid grid(A, Eigen::MatrixX2d());
    for (Eigen::Index i = 0; i < target.P.rows(); ++i) {
        grid.nearest(target.P.row(i).transpose(), Eigen::Vector2d::Zero(), 0.0, d);
        ba += d;
    }
    return ab / double(A.rows()) + ba / double(target.P.rows());
}

Similarity coarseAlignment(const RigidFitSource &source, const RigidFitTarget &target,
                           const FitPins &pins, const RigidFitOptions &options, double &chamfer,
                           Similarity *unturned)
{
    const Moments a = momentsOf(source.rest), b = momentsOf(target.P);
    const double scale = options.allowScale && a.spread > 0.0 && b.spread > 0.0
                             ? std::sqrt(b.spread / a.spread)
                             : 1.0;
    const Eigen::MatrixX2d pinRest = pinPositions(source, pins, source.V);
    if (pins.targets.rows() >= 2 && distinctPins(pinRest, source.sampleDiagonal)) {
        const Similarity s = procrustes(pinRest, pins.targets,
                                        Eigen::VectorXd::Ones(pinRest.rows()), options.allowScale);
        chamfer = symmetricChamfer(s.apply(source.rest), target);
        if (unturned)
            *unturned = s;
        return s;
    }
    // The un-rotated placement and the two proper rotations among the axes' four sign
    // choices (the other two are reflections, which no rotation field of A can undo), in order
    // of how far they turn: a tie goes to the smaller turn.
    const Eigen::Matrix2d turn = b.axes * a.axes.transpose();
    std::vector<Eigen::Matrix2d> candidates = {Eigen::Matrix2d::Identity(), turn, -turn};
    std::stable_sort(candidates.begin(), candidates.end(), [](const auto &x, const auto &y) {
        return std::abs(angleOf(x)) < std::abs(angleOf(y));
    });
    Similarity best;
    chamfer = std::numeric_limits<double>::infinity();
    const double tie = kChamferTie * std::max(target.diagonal, 1e-12);
    for (const Eigen::Matrix2d &R : candidates) {
        Similarity s;
        s.linear = scale * R;
        s.translation = pins.targets.rows() >= 1
                            ? Eigen::Vector2d(pins.targets.row(0).transpose() -
                                              s.linear * pinRest.row(0).transpose())
                            : Eigen::Vector2d(b.centroid - s.linear * a.centroid);
        if (unturned && std::abs(angleOf(R)) < 1e-12)
            *unturned = s;
        const double c = symmetricChamfer(s.apply(source.rest), target);
        if (c < chamfer - tie) {
            chamfer = c;
            best = s;
        }
    }
    return best;
}

Pairs findPairs(const RigidFitSource &source, const RigidFitTarget &target,
                const Eigen::MatrixX2d &X, const Eigen::MatrixX2d &M,
                const RigidFitOptions &options)
{
    Pairs pairs;
    std::vector<double> distance;
    const double floor = kRejectFloor * std::max(target.diagonal, source.sampleDiagonal);
    // Appends the pairs [from, end) that pass the median test, weights 1/count × share.
    const auto keep = [&](std::size_t from, double share) {
        std::vector<double> d(distance.begin() + std::ptrdiff_t(from), distance.end());
        const double limit = std::max(options.rejectFactor * percentileOf(d, 0.5), floor);
        std::size_t out = from;
        for (std::size_t i = from; i < distance.size(); ++i) {
            if (distance[i] <= limit) {
                pairs.sample[out] = pairs.sample[i];
                pairs.target[out] = pairs.target[i];
                distance[out++] = distance[i];
            }
        }
        pairs.sample.resize(out);
        pairs.target.resize(out);
        distance.resize(out);
        const double w = out > from ? share / double(out - from) : 0.0;
        pairs.weight.resize(out, w);
    };
    const double share = options.symmetric ? 0.5 : 1.0;
    for (Eigen::Index s = 0; s < X.rows(); ++s) {
        double d = 0.0;
        const int j = target.grid.nearest(X.row(s).transpose(), M.row(s).transpose(),
                                          options.normalAgreement, d);
        if (j >= 0) {
            pairs.sample.push_back(int(s));
            pairs.target.push_back(target.P.row(j).transpose());
            distance.push_back(d);
        }
    }
    keep(0, share);
    pairs.abCount = int(pairs.sample.size());
    if (options.symmetric) {
        const PointGrid grid(X, M);
        const std::size_t from = pairs.sample.size();
        for (Eigen::Index i = 0; i < target.P.rows(); ++i) {
            double d = 0.0;
            const int s = grid.nearest(target.P.row(i).transpose(), target.N.row(i).transpose(),
                                       options.normalAgreement, d);
            if (s >= 0) {
                pairs.sample.push_back(s);
                pairs.target.push_back(target.P.row(i).transpose());
                distance.push_back(d);
            }
        }
        keep(from, share);
    }
    return pairs;
}

std::optional<Similarity> turnSwept(const RigidFitSource &source, const RigidFitTarget &target,
                                    const RigidFitOptions &options, const Similarity &start,
                                    const Similarity &fromStart)
{
    const Eigen::Index n = source.rest.rows();
    if (n == 0 || target.P.rows() == 0)
        return std::nullopt;
    // The sweep's ICP runs on a few of A's samples, evenly taken.
    const Eigen::Index m = std::min<Eigen::Index>(n, kSweepSamples);
    Eigen::MatrixX2d points(m, 2), normals(m, 2);
    for (Eigen::Index i = 0; i < m; ++i) {
        points.row(i) = source.rest.row(i * n / m);
        normals.row(i) = source.N.row(i * n / m);
    }
    const auto icp = [&](Similarity s) {
        for (int iteration = 0; iteration < kSweepIterations; ++iteration) {
            const Eigen::MatrixX2d X = s.apply(points);
            const Eigen::Matrix2d turn = rotation(angleOf(s.linear));
            Eigen::MatrixX2d to = X;
            Eigen::VectorXd w = Eigen::VectorXd::Zero(m);
            for (Eigen::Index i = 0; i < m; ++i) {
                double d = 0.0;
                const int j =
                    target.grid.nearest(X.row(i).transpose(), turn * normals.row(i).transpose(),
                                        options.normalAgreement, d);
                if (j >= 0) {
                    to.row(i) = target.P.row(j);
                    w(i) = 1.0;
                }
            }
            const Similarity next = procrustes(points, to, w, options.allowScale);
            const double moved = (next.apply(points) - X).rowwise().norm().maxCoeff();
            s = next;
            if (moved <= 1e-3 * std::max(target.diagonal, 1e-12))
                break;
        }
        return s;
    };
    const Eigen::Vector2d a = source.rest.colwise().mean().transpose(),
                          b = target.P.colwise().mean().transpose();
    double bestChamfer = symmetricChamfer(icp(fromStart).apply(points), target);
    const double startChamfer = bestChamfer;
    std::optional<Similarity> bestStart;
    for (int k = 1; k < kSweepSteps; ++k) {
        Similarity s;
        s.linear = rotation(2.0 * std::numbers::pi * k / kSweepSteps) * start.linear;
        s.translation = b - s.linear * a;
        const Similarity placed = icp(s);
        if (std::abs(angleOf(placed.linear)) > kSweepMostTurn)
            continue;
        const double c = symmetricChamfer(placed.apply(points), target);
        if (c < bestChamfer && c < (1.0 - kSweepMargin) * startChamfer) {
            bestStart = s;
            bestChamfer = c;
        }
    }
    if (!bestStart)
        return std::nullopt;
    const FitPins none;
    const Similarity placed = rigidIcp(source, target, none, options, *bestStart);
    if (std::abs(angleOf(placed.linear)) > kSweepMostTurn ||
        symmetricChamfer(placed.apply(source.rest), target) >=
            (1.0 - kSweepMargin) * symmetricChamfer(fromStart.apply(source.rest), target))
        return std::nullopt;
    return placed;
}

Similarity rigidIcp(const RigidFitSource &source, const RigidFitTarget &target, const FitPins &pins,
                    const RigidFitOptions &options, Similarity start)
{
    Similarity current = start;
    const Eigen::MatrixX2d pinRest = pinPositions(source, pins, source.V);
    for (int iteration = 0; iteration < options.rigidIterations; ++iteration) {
        const Eigen::MatrixX2d X = current.apply(source.rest);
        const Eigen::Matrix2d turn = rotation(angleOf(current.linear));
        const Eigen::MatrixX2d M = source.N * turn.transpose();
        const Pairs pairs = findPairs(source, target, X, M, options);
        const auto count = Eigen::Index(pairs.sample.size());
        if (count == 0)
            break;
        const Eigen::Index p = pins.targets.rows();
        Eigen::MatrixX2d from(count + p, 2), to(count + p, 2);
        Eigen::VectorXd w(count + p);
        for (Eigen::Index i = 0; i < count; ++i) {
            from.row(i) = source.rest.row(pairs.sample[std::size_t(i)]);
            to.row(i) = pairs.target[std::size_t(i)].transpose();
            w(i) = pairs.weight[std::size_t(i)];
        }
        const double pinWeight = options.pinWeight / std::max(1, pairs.abCount);
        for (Eigen::Index i = 0; i < p; ++i) {
            from.row(count + i) = pinRest.row(i);
            to.row(count + i) = pins.targets.row(i);
            w(count + i) = pinWeight;
        }
        const Similarity next = procrustes(from, to, w, options.allowScale);
        const double moved = (next.apply(source.rest) - X).rowwise().norm().maxCoeff();
        current = next;
        if (moved <= options.tolerance * std::max(target.diagonal, 1e-12))
            break;
    }
    return current;
}

} // namespace finbook::deform::between::detail
