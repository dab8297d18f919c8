// The fit's precomputed inputs (A's mesh and samples, B's points), pins, and the residual
// report every fit ends with.
#include "../arap_internal.h"
#include "rigid_fit_internal.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace finbook::deform::between {

using detail::Complex;

RigidFitSourceResult rigidFitPrecompute(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                        const geometry::Embedding &samples,
                                        const Eigen::MatrixX2d &N,
                                        const std::vector<std::array<int, 2>> &hinges)
{
    if (auto error = deform::detail::validateArapInput(V, F, Eigen::VectorXi()))
        return unexpected(*error);
    const Eigen::Index k = samples.I.size();
    if (k == 0)
        return unexpected(DeformError{DeformErrorCode::EmptyMesh, "drawing A has no points"});
    if (samples.B.rows() != k || N.rows() != k)
        return unexpected(DeformError{DeformErrorCode::SizeMismatch,
                                      "samples, weights and normals differ in count"});
    for (Eigen::Index s = 0; s < k; ++s) {
        if (samples.I(s) < 0 || samples.I(s) >= F.rows())
            return unexpected(DeformError{DeformErrorCode::InvalidIndex,
                                          "sample " + std::to_string(s) + " has no triangle",
                                          {int(s)}});
    }
    for (const auto &[a, b] : hinges)
        if (a < 0 || b < 0 || a >= V.rows() || b >= V.rows())
            return unexpected(
                DeformError{DeformErrorCode::InvalidIndex, "a hinge joins no vertex of A"});
    if (!samples.B.allFinite() || !N.allFinite())
        return unexpected(DeformError{DeformErrorCode::NonFiniteInput,
                                      "a sample's weights or normal are not finite"});

    auto source = std::make_shared<RigidFitSource>(
        RigidFitSource{V,
                       F,
                       samples.I,
                       samples.B,
                       Eigen::MatrixX2d(k, 2),
                       Eigen::MatrixX2d(),
                       {},
                       {},
                       0.0,
                       0.0,
                       0.0,
                       1.0,
                       detail::MeshSystem(int(V.rows()), F, {}, hinges),
                       hinges,
                       {},
                       {}});
    for (Eigen::Index s = 0; s < k; ++s) {
        const double len = N.row(s).norm();
        source->N.row(s) =
            len > 0.0 ? Eigen::RowVector2d(N.row(s) / len) : Eigen::RowVector2d::Zero();
    }
    source->rest = detail::samplePositions(*source, V);
    source->edgeWeight.resize(F.rows(), 3);
    source->corner.resize(F.rows(), 3);
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        Complex z[3];
        for (int c = 0; c < 3; ++c)
            z[c] = source->corner(t, c) = Complex(V(F(t, c), 0), V(F(t, c), 1));
        double w[3];
        deform::detail::edgeWeights(z, true, w);
        source->area += 0.5 * std::abs(std::imag(std::conj(z[1] - z[0]) * (z[2] - z[0])));
        for (int c = 0; c < 3; ++c) {
            source->edgeWeight(t, c) = w[c];
            source->restSquaredNorm += w[c] * std::norm(z[(c + 2) % 3] - z[(c + 1) % 3]);
        }
    }
    source->sampleDiagonal =
        (source->rest.colwise().maxCoeff() - source->rest.colwise().minCoeff()).norm();
    // Samples all on one spot: the mesh's size stands in for D.
    const double D = source->sampleDiagonal > 0.0
                         ? source->sampleDiagonal
                         : (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm();
    source->stiffnessUnit = D * D * double(V.rows()) / source->area;
    if (!hinges.empty()) {
        int parts = 0;
        const Eigen::VectorXi label = deform::detail::componentLabels(V.rows(), F, parts);
        for (const auto &[under, piece] : hinges) {
            std::vector<int> vertices, own;
            for (Eigen::Index v = 0; v < V.rows(); ++v)
                if (label(v) == label(piece))
                    vertices.push_back(int(v));
            for (Eigen::Index s = 0; s < k; ++s)
                if (label(F(samples.I(s), 0)) == label(piece))
                    own.push_back(int(s));
            source->hingedVertices.push_back(std::move(vertices));
            source->hingedSamples.push_back(std::move(own));
        }
    }
    return std::shared_ptr<const RigidFitSource>(std::move(source));
}

std::shared_ptr<const RigidFitTarget> rigidFitTarget(const Eigen::MatrixX2d &P,
                                                     const Eigen::MatrixX2d &N)
{
    auto target = std::make_shared<RigidFitTarget>();
    std::vector<Eigen::Index> keep;
    for (Eigen::Index i = 0; i < P.rows(); ++i)
        if (P.row(i).allFinite())
            keep.push_back(i);
    target->P.resize(Eigen::Index(keep.size()), 2);
    target->N = Eigen::MatrixX2d::Zero(Eigen::Index(keep.size()), 2);
    for (std::size_t j = 0; j < keep.size(); ++j) {
        target->P.row(Eigen::Index(j)) = P.row(keep[j]);
        if (keep[j] < N.rows() && N.row(keep[j]).allFinite() && N.row(keep[j]).norm() > 0.0)
            target->N.row(Eigen::Index(j)) = N.row(keep[j]).normalized();
    }
    target->grid = detail::PointGrid(target->P, target->N);
    if (!keep.empty())
        target->diagonal = (target->P.colwise().maxCoeff() - target->P.colwise().minCoeff()).norm();
    return target;
}

FitPins pinsAtSamples(const geometry::Embedding &samples, const Eigen::VectorXi &rows,
                      const Eigen::MatrixX2d &targets)
{
    FitPins pins;
    pins.where.I = Eigen::VectorXi::Constant(rows.size(), -1);
    pins.where.B = Eigen::MatrixX3d::Zero(rows.size(), 3);
    for (Eigen::Index p = 0; p < rows.size(); ++p) {
        if (rows(p) >= 0 && rows(p) < samples.I.size()) {
            pins.where.I(p) = samples.I(rows(p));
            pins.where.B.row(p) = samples.B.row(rows(p));
        }
    }
    pins.targets = targets;
    return pins;
}

FitPins pinsAtVertices(const Eigen::MatrixX3i &F, const Eigen::VectorXi &vertices,
                       const Eigen::MatrixX2d &targets)
{
    FitPins pins;
    pins.where.I = Eigen::VectorXi::Constant(vertices.size(), -1);
    pins.where.B = Eigen::MatrixX3d::Zero(vertices.size(), 3);
    for (Eigen::Index p = 0; p < vertices.size(); ++p) {
        for (Eigen::Index t = 0; t < F.rows() && pins.where.I(p) < 0; ++t) {
            for (int c = 0; c < 3; ++c) {
                if (F(t, c) == vertices(p)) {
                    pins.where.I(p) = int(t);
                    pins.where.B(p, c) = 1.0;
                }
            }
        }
    }
    pins.targets = targets;
    return pins;
}

namespace detail {

Eigen::MatrixX2d samplePositions(const RigidFitSource &source, const Eigen::MatrixX2d &U)
{
    Eigen::MatrixX2d X(source.sampleCount(), 2);
    for (int s = 0; s < source.sampleCount(); ++s) {
        const int t = source.I(s);
        X.row(s) = source.B(s, 0) * U.row(source.F(t, 0)) + source.B(s, 1) * U.row(source.F(t, 1)) +
                   source.B(s, 2) * U.row(source.F(t, 2));
    }
    return X;
}

Eigen::MatrixX2d pinPositions(const RigidFitSource &source, const FitPins &pins,
                              const Eigen::MatrixX2d &U)
{
    Eigen::MatrixX2d X(pins.where.I.size(), 2);
    for (Eigen::Index p = 0; p < pins.where.I.size(); ++p) {
        const int t = pins.where.I(p);
        X.row(p) = pins.where.B(p, 0) * U.row(source.F(t, 0)) +
                   pins.where.B(p, 1) * U.row(source.F(t, 1)) +
                   pins.where.B(p, 2) * U.row(source.F(t, 2));
    }
    return X;
}

bool pinsValid(const RigidFitSource &source, const FitPins &pins)
{
    const Eigen::Index p = pins.where.I.size();
    if (pins.where.B.rows() != p || pins.targets.rows() != p)
        return false;
    for (Eigen::Index i = 0; i < p; ++i) {
        if (pins.where.I(i) < 0 || pins.where.I(i) >= source.F.rows() ||
            !pins.where.B.row(i).allFinite() || !pins.targets.row(i).allFinite() ||
            std::abs(pins.where.B.row(i).sum() - 1.0) > 1e-6 ||
            pins.targets.row(i).cwiseAbs().maxCoeff() > kMaxDeformCoordinate)
            return false;
    }
    return true;
}

double percentileOf(std::vector<double> values, double p)
{
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    const double rank = p * double(values.size() - 1);
    const auto lo = std::size_t(rank);
    const std::size_t hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (rank - double(lo)) * (values[hi] - values[lo]);
}

double distortion(const RigidFitSource &source, const Eigen::MatrixX2d &U, double scale)
{
    double sum = 0.0;
    for (Eigen::Index t = 0; t < source.F.rows(); ++t) {
        Eigen::Matrix2d D0, D1;
        for (int c = 0; c < 2; ++c) {
            const Complex e = source.corner(t, c + 1) - source.corner(t, 0);
            D0.col(c) << e.real(), e.imag();
            D1.col(c) = (U.row(source.F(t, c + 1)) - U.row(source.F(t, 0))).transpose();
        }
        const Eigen::Matrix2d J = D1 * D0.inverse();
        const double angle = std::atan2(J(1, 0) - J(0, 1), J(0, 0) + J(1, 1));
        const Eigen::Matrix2d R = scale * Eigen::Rotation2Dd(angle).toRotationMatrix();
        sum += 0.5 * std::abs(D0.determinant()) * (J - R).squaredNorm();
    }
    return source.area > 0.0 ? std::sqrt(sum / (2.0 * source.area)) : 0.0;
}

void reportResidual(const RigidFitSource &source, const RigidFitTarget &target,
                    const RigidFitOptions &options, RigidFitResult &r)
{
    const int k = source.sampleCount();
    const double diagonal = std::max(target.diagonal, 1e-12);
    r.targetDiagonal = target.diagonal;
    r.partUncovered = false;
    r.samples = samplePositions(source, r.U);
    r.residual.resize(k);
    for (int s = 0; s < k; ++s) {
        double d = 0.0;
        // The rotation of the sample's triangle is not kept here; the nearest point whatever
        // its normal is what a viewer sees as the gap.
        target.grid.nearest(r.samples.row(s).transpose(), Eigen::Vector2d::Zero(), 0.0, d);
        r.residual(s) = std::isfinite(d) ? d : diagonal;
    }
    std::vector<double> all(r.residual.data(), r.residual.data() + k);
    r.medianResidual = percentileOf(all, 0.5);
    r.p95Residual = percentileOf(all, 0.95);
    r.relativeMedian = r.medianResidual / diagonal;
    r.relativeP95 = r.p95Residual / diagonal;
    const PointGrid fitted(r.samples, Eigen::MatrixX2d());
    std::vector<double> coverage(static_cast<std::size_t>(target.P.rows()));
    for (Eigen::Index i = 0; i < target.P.rows(); ++i) {
        double d = 0.0;
        fitted.nearest(target.P.row(i).transpose(), Eigen::Vector2d::Zero(), 0.0, d);
        coverage[std::size_t(i)] = std::isfinite(d) ? d : diagonal;
    }
    const double far = options.failMedian * diagonal;
    r.uncoveredRegion.setEmpty();
    int uncovered = 0;
    for (Eigen::Index i = 0; i < target.P.rows(); ++i)
        if (coverage[std::size_t(i)] > far) {
            ++uncovered;
            r.uncoveredRegion.extend(Eigen::Vector2d(target.P.row(i).transpose()));
        }
    r.uncoveredShare = target.P.rows() > 0 ? double(uncovered) / double(target.P.rows()) : 0.0;
    r.coverageMedian = percentileOf(coverage, 0.5);

    std::vector<int> order(static_cast<std::size_t>(k));
    std::iota(order.begin(), order.end(), 0);
    const auto worst = std::size_t(std::max(1, k / 20));
    std::partial_sort(
        order.begin(), order.begin() + std::ptrdiff_t(worst), order.end(), [&](int a, int b) {
            return r.residual(a) > r.residual(b) || (r.residual(a) == r.residual(b) && a < b);
        });
    r.worstSamples.assign(order.begin(), order.begin() + std::ptrdiff_t(worst));
    r.worstRegion.setEmpty();
    for (const int s : r.worstSamples)
        r.worstRegion.extend(Eigen::Vector2d(source.rest.row(s).transpose()));

    r.distortion = distortion(source, r.U, options.allowScale ? r.scale : 1.0);
    const double limit = options.failMedian * diagonal;
    if (r.status == FitStatus::Fitted && r.distortion > options.failDistortion) {
        r.status = FitStatus::ResidualTooLarge;
        r.message = "A would have to be stretched by " +
                    std::to_string(int(std::lround(100.0 * r.distortion))) +
                    " % on average to fit B: the drawings do not show the same thing";
    }
    if (r.status == FitStatus::Fitted && (r.medianResidual > limit || r.coverageMedian > limit)) {
        r.status = FitStatus::ResidualTooLarge;
        const Eigen::Vector2d lo = r.worstRegion.min(), hi = r.worstRegion.max();
        r.message = "A does not fit B: half of A's points stay more than " +
                    std::to_string(int(std::lround(100.0 * r.relativeMedian))) +
                    " % of B's size away (B covered to " +
                    std::to_string(int(std::lround(100.0 * r.coverageMedian / diagonal))) +
                    " %); worst between (" + std::to_string(int(lo.x())) + ", " +
                    std::to_string(int(lo.y())) + ") and (" + std::to_string(int(hi.x())) + ", " +
                    std::to_string(int(hi.y())) + ") of A";
    }
    if (r.status == FitStatus::Fitted && (r.uncoveredShare > options.failUncovered ||
                                          (r.uncoveredShare > options.failUncoveredStrained &&
                                           r.distortion > options.strainedDistortion))) {
        r.status = FitStatus::ResidualTooLarge;
        r.partUncovered = true;
        const Eigen::Vector2d lo = r.uncoveredRegion.min(), hi = r.uncoveredRegion.max();
        r.message = std::to_string(int(std::lround(100.0 * r.uncoveredShare))) +
                    " % of B's points have nothing of A near them, between (" +
                    std::to_string(int(lo.x())) + ", " + std::to_string(int(lo.y())) + ") and (" +
                    std::to_string(int(hi.x())) + ", " + std::to_string(int(hi.y())) +
                    ") of B: a part of B that A's could not reach";
    }
}

} // namespace detail
} // namespace finbook::deform::between
