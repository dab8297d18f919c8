#include "../arap_internal.h"
#include "mesh_system.h"

#include <finbook/deform/between/arap_interpolation.h>

#include <queue>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <tuple>
#include <utility>

namespace finbook::deform::between {
namespace {

constexpr double kTurn = 2.0 * std::numbers::pi;
// A link's weight against the cotangent Laplacian's (both dimensionless in 2D): it holds a
// hinge's two vertices within a small share of a pixel of their blended offset.
constexpr double kLinkWeight = 100.0;

DeformError interpolationError(DeformErrorCode code, std::string message)
{
    return DeformError{code, std::move(message)};
}

// Triangles sharing an edge with each triangle (−1 where none), row t: neighbours across the
// edges opposite corners 0, 1, 2.
Eigen::MatrixX3i dualGraph(const Eigen::MatrixX3i &F)
{
    Eigen::MatrixX3i across = Eigen::MatrixX3i::Constant(F.rows(), 3, -1);
    std::map<std::pair<int, int>, std::pair<int, int>> open; // edge → (triangle, corner)
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        for (int c = 0; c < 3; ++c) {
            const int a = F(t, (c + 1) % 3), b = F(t, (c + 2) % 3);
            const auto key = std::make_pair(std::min(a, b), std::max(a, b));
            const auto it = open.find(key);
            if (it == open.end()) {
                open.emplace(key, std::make_pair(int(t), c));
            } else {
                across(t, c) = it->second.first;
                across(it->second.first, it->second.second) = int(t);
                open.erase(it);
            }
        }
    }
    return across;
}

// How far a triangle's raw angle can be trusted, in [0, 1]: the share of its map J that is a
// turn (|similarity part| over ‖J‖, 1 for a turn and a scale, 0 for a mirror). A triangle
// turned over (det J ≤ 0), or squashed flat, by a fold in the fitted pose has no turn of its
// own: its angle is whatever its noise gives.
double reliabilityOf(const Eigen::Matrix2d &J)
{
    if (J.determinant() <= 0.0)
        return 0.0;
    const double c = J(0, 0) + J(1, 1), s = J(1, 0) - J(0, 1);
    const double norm = std::sqrt(2.0) * J.norm();
    return norm > 0.0 ? std::clamp(std::hypot(c, s) / norm, 0.0, 1.0) : 0.0;
}

double wrapped(double a)
{
    return a - kTurn * std::round(a / kTurn);
}

// Unwraps raw angles in (−π, π] over the dual graph, the most trusted triangles first (as
// quality-guided phase unwrapping does): from each part's most trusted triangle, the next
// triangle taken is always the one reached over the smallest angle step, and a triangle with
// no turn of its own (reliability below kTrusted) only after every trusted one it can reach.
// Each triangle takes the branch closest to the last trusted angle on its way, so a fold's
// turned-over triangles pass on no noise: the limb beyond a fold turns the way it turned
// next to it. Then each connected part is shifted by whole turns so that its area-weighted
// mean lies in (−π, π].
void unwrapAngles(const Eigen::MatrixX3i &F, const Eigen::VectorXd &area,
                  const Eigen::VectorXd &reliability, Eigen::VectorXd &angle)
{
    constexpr double kTrusted = 0.5;
    const Eigen::MatrixX3i across = dualGraph(F);
    const Eigen::Index m = F.rows();
    std::vector<bool> seen(std::size_t(m), false);
    // The angle each triangle passes on: its own when trusted, else what reached it.
    Eigen::VectorXd passed = angle;
    // Roots: the most trusted, largest triangles first.
    std::vector<int> order(static_cast<std::size_t>(m));
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return std::pair(reliability(a) >= kTrusted, area(a)) >
               std::pair(reliability(b) >= kTrusted, area(b));
    });
    using Step = std::tuple<double, int, int>; // cost, from, to
    std::priority_queue<Step, std::vector<Step>, std::greater<>> queue;
    for (const int root : order) {
        if (seen[std::size_t(root)])
            continue;
        std::vector<int> part = {root};
        seen[std::size_t(root)] = true;
        const auto reach = [&](int t) {
            for (int c = 0; c < 3; ++c) {
                const int u = across(t, c);
                if (u < 0 || seen[std::size_t(u)])
                    continue;
                const double step = std::abs(wrapped(angle(u) - passed(t)));
                queue.emplace(step + (reliability(u) >= kTrusted ? 0.0 : 2.0 * kTurn), t, u);
            }
        };
        reach(root);
        while (!queue.empty()) {
            const auto [cost, t, u] = queue.top();
            queue.pop();
            if (seen[std::size_t(u)])
                continue;
            seen[std::size_t(u)] = true;
            angle(u) = passed(t) + wrapped(angle(u) - passed(t));
            passed(u) = reliability(u) >= kTrusted ? angle(u) : passed(t);
            part.push_back(u);
            reach(u);
        }
        double weighted = 0.0, total = 0.0;
        for (const int t : part) {
            weighted += area(t) * angle(t);
            total += area(t);
        }
        const double mean = total > 0.0 ? weighted / total : 0.0;
        const double shift = kTurn * std::ceil((mean - std::numbers::pi) / kTurn);
        for (const int t : part)
            angle(t) -= shift;
    }
}

// Per triangle: the polar decomposition of its map V0 → V1 (angle unwrapped, stretch), its
// rest area and the gradients of its barycentric coordinates.
void decomposeTriangles(const Eigen::MatrixX2d &V0, const Eigen::MatrixX2d &V1,
                        const Eigen::MatrixX3i &F, ArapInterpolation &d)
{
    const Eigen::Index m = F.rows();
    d.angle.resize(m);
    d.stretch.resize(m, 3);
    d.area.resize(m);
    d.gradient.resize(m, 6);
    Eigen::VectorXd reliability(m);
    for (Eigen::Index t = 0; t < m; ++t) {
        Eigen::Matrix2d D0, D1;
        D0 << (V0.row(F(t, 1)) - V0.row(F(t, 0))).transpose(),
            (V0.row(F(t, 2)) - V0.row(F(t, 0))).transpose();
        D1 << (V1.row(F(t, 1)) - V1.row(F(t, 0))).transpose(),
            (V1.row(F(t, 2)) - V1.row(F(t, 0))).transpose();
        const Eigen::Matrix2d inverse = D0.inverse();
        const Eigen::Matrix2d J = D1 * inverse;
        // The rotation of the polar decomposition in 2D: the angle of J's similarity part
        // (J + cof(J)ᵀ)/2, which makes Rᵀ J symmetric.
        const double c = J(0, 0) + J(1, 1), s = J(1, 0) - J(0, 1);
        d.angle(t) = (c == 0.0 && s == 0.0) ? 0.0 : std::atan2(s, c);
        const Eigen::Matrix2d S = Eigen::Rotation2Dd(-d.angle(t)).toRotationMatrix() * J;
        d.stretch.row(t) << S(0, 0), 0.5 * (S(0, 1) + S(1, 0)), S(1, 1);
        d.area(t) = 0.5 * std::abs(D0.determinant());
        const Eigen::Vector2d g1 = inverse.row(0).transpose(), g2 = inverse.row(1).transpose();
        const Eigen::Vector2d g0 = -g1 - g2;
        d.gradient.row(t) << g0.x(), g0.y(), g1.x(), g1.y(), g2.x(), g2.y();
        reliability(t) = reliabilityOf(J);
        if (J.determinant() <= 0.0)
            ++d.flippedTriangles;
    }
    unwrapAngles(F, d.area, reliability, d.angle);
}

// Connected parts (d.component, centroids); returns the vertices the solve holds: the first
// of each part (its translation comes from the centroid afterwards) and those in no triangle.
std::vector<bool> holdOneVertexPerPart(const Eigen::MatrixX3i &F, ArapInterpolation &d)
{
    const Eigen::Index m = F.rows(), n = d.V0.rows();
    int parts = 0;
    Eigen::VectorXi labels = deform::detail::componentLabels(n, F, parts);
    const Eigen::VectorXi own = labels;
    // Parts joined by links are one part: each label takes its smallest linked label.
    std::vector<int> merged(static_cast<std::size_t>(parts));
    std::iota(merged.begin(), merged.end(), 0);
    const auto rootOf = [&merged](int a) {
        while (merged[std::size_t(a)] != a)
            a = merged[std::size_t(a)] = merged[std::size_t(merged[std::size_t(a)])];
        return a;
    };
    for (const auto &[i, j] : d.links) {
        if (labels(i) < 0 || labels(j) < 0)
            continue;
        const int a = rootOf(labels(i)), b = rootOf(labels(j));
        merged[std::size_t(std::max(a, b))] = std::min(a, b);
    }
    for (Eigen::Index v = 0; v < n; ++v)
        if (labels(v) >= 0)
            labels(v) = rootOf(labels(v));
    std::vector<int> triangles(std::size_t(n), 0);
    for (Eigen::Index t = 0; t < m; ++t)
        for (int c = 0; c < 3; ++c)
            ++triangles[std::size_t(F(t, c))];
    d.component = Eigen::VectorXi::Constant(n, -1);
    std::vector<int> partOf(std::size_t(parts), -1);
    std::vector<bool> held(std::size_t(n), false);
    int solvedParts = 0;
    for (Eigen::Index v = 0; v < n; ++v) {
        if (triangles[std::size_t(v)] == 0) {
            held[std::size_t(v)] = true;
            continue;
        }
        int &part = partOf[std::size_t(labels(v))];
        if (part < 0) {
            part = solvedParts++;
            held[std::size_t(v)] = true; // the part's first vertex fixes its translation
        }
        d.component(v) = part;
    }
    // A part of pieces joined by links is placed by its largest piece (the body an arm turns
    // on, which the arm's turn does not move): the centroid of all of them would take the
    // chord of the arm's arc.
    std::vector<int> size(std::size_t(parts), 0), largest(std::size_t(parts), -1);
    for (Eigen::Index v = 0; v < n; ++v)
        if (triangles[std::size_t(v)] > 0)
            ++size[std::size_t(own(v))];
    for (int piece = 0; piece < parts; ++piece) {
        int &big = largest[std::size_t(rootOf(piece))];
        if (size[std::size_t(piece)] > 0 &&
            (big < 0 || size[std::size_t(piece)] > size[std::size_t(big)]))
            big = piece;
    }
    d.placed.assign(std::size_t(n), false);
    for (Eigen::Index v = 0; v < n; ++v)
        d.placed[std::size_t(v)] = d.component(v) >= 0 && largest[std::size_t(labels(v))] == own(v);
    d.centroid0 = Eigen::MatrixX2d::Zero(solvedParts, 2);
    d.centroid1 = Eigen::MatrixX2d::Zero(solvedParts, 2);
    Eigen::VectorXd count = Eigen::VectorXd::Zero(solvedParts);
    for (Eigen::Index v = 0; v < n; ++v) {
        if (!d.placed[std::size_t(v)])
            continue;
        d.centroid0.row(d.component(v)) += d.V0.row(v);
        d.centroid1.row(d.component(v)) += d.V1.row(v);
        count(d.component(v)) += 1.0;
    }
    for (int p = 0; p < solvedParts; ++p) {
        d.centroid0.row(p) /= count(p);
        d.centroid1.row(p) /= count(p);
    }

    return held;
}

} // namespace

ArapInterpolationResult arapInterpolationPrecompute(const Eigen::MatrixX2d &V0,
                                                    const Eigen::MatrixX2d &V1,
                                                    const Eigen::MatrixX3i &F,
                                                    const std::vector<std::array<int, 2>> &links)
{
    if (auto error = deform::detail::validateArapInput(V0, F, Eigen::VectorXi()))
        return unexpected(*error);
    if (V1.rows() != V0.rows())
        return unexpected(interpolationError(DeformErrorCode::SizeMismatch,
                                             "the two poses have different vertex counts"));
    if (!V1.allFinite())
        return unexpected(
            interpolationError(DeformErrorCode::NonFiniteInput, "the target pose is not finite"));
    if (V1.cwiseAbs().maxCoeff() > kMaxDeformCoordinate)
        return unexpected(interpolationError(DeformErrorCode::CoordinateOutOfRange,
                                             "the target pose is out of range"));
    for (const auto &[i, j] : links)
        if (i < 0 || j < 0 || i >= V0.rows() || j >= V0.rows())
            return unexpected(
                interpolationError(DeformErrorCode::InvalidIndex, "a link joins no vertex"));
    auto d = std::make_shared<ArapInterpolation>();
    d->V0 = V0;
    d->V1 = V1;
    d->F = F;
    d->links = links;
    decomposeTriangles(V0, V1, F, *d);
    const std::vector<bool> held = holdOneVertexPerPart(F, *d);
    const Eigen::Index m = F.rows(), n = V0.rows();
    auto system = std::make_shared<detail::MeshSystem>(int(n), F, held, links);
    for (std::size_t l = 0; l < links.size(); ++l)
        system->addLink(int(l), kLinkWeight);
    for (Eigen::Index t = 0; t < m; ++t)
        for (int a = 0; a < 3; ++a)
            for (int b = a; b < 3; ++b)
                system->addEntry(int(t), a, b,
                                 d->area(t) *
                                     (d->gradient(t, 2 * a) * d->gradient(t, 2 * b) +
                                      d->gradient(t, 2 * a + 1) * d->gradient(t, 2 * b + 1)));
    if (!system->factorize())
        return unexpected(
            interpolationError(DeformErrorCode::FactorizationFailed,
                               "the interpolation's Laplacian could not be factored"));
    d->system = std::move(system);
    return std::shared_ptr<const ArapInterpolation>(std::move(d));
}

Expected<Eigen::MatrixX2d, DeformError> arapInterpolate(const ArapInterpolation &data, double t)
{
    if (!std::isfinite(t))
        return unexpected(interpolationError(DeformErrorCode::NonFiniteInput, "t is not finite"));
    const detail::MeshSystem &system = *data.system;
    const Eigen::Index n = data.V0.rows();
    // Right-hand side Σ_t area·A(t)·∇φ_a per unknown, x and y interleaved; held vertices sit
    // at the origin, so they add nothing.
    std::vector<double> rhs(std::size_t(system.size()) * 2, 0.0);
    for (Eigen::Index f = 0; f < data.F.rows(); ++f) {
        const Eigen::Matrix2d R = Eigen::Rotation2Dd(t * data.angle(f)).toRotationMatrix();
        Eigen::Matrix2d S;
        S << data.stretch(f, 0), data.stretch(f, 1), data.stretch(f, 1), data.stretch(f, 2);
        const Eigen::Matrix2d A =
            data.area(f) * R * ((1.0 - t) * Eigen::Matrix2d::Identity() + t * S);
        for (int c = 0; c < 3; ++c) {
            const int u = system.unknown(data.F(f, c));
            if (u < 0)
                continue;
            const Eigen::Vector2d g(data.gradient(f, 2 * c), data.gradient(f, 2 * c + 1));
            const Eigen::Vector2d contribution = A * g;
            rhs[std::size_t(u) * 2] += contribution.x();
            rhs[std::size_t(u) * 2 + 1] += contribution.y();
        }
    }
    for (const auto &[i, j] : data.links) {
        const Eigen::RowVector2d offset =
            (1.0 - t) * (data.V0.row(i) - data.V0.row(j)) + t * (data.V1.row(i) - data.V1.row(j));
        for (const auto &[v, sign] : {std::pair(i, 1.0), std::pair(j, -1.0)}) {
            const int u = system.unknown(v);
            if (u < 0 || data.component(v) < 0)
                continue;
            rhs[std::size_t(u) * 2] += sign * kLinkWeight * offset.x();
            rhs[std::size_t(u) * 2 + 1] += sign * kLinkWeight * offset.y();
        }
    }
    system.solveInPlace(rhs.data(), 2);
    Eigen::MatrixX2d U(n, 2);
    Eigen::MatrixX2d sum = Eigen::MatrixX2d::Zero(data.centroid0.rows(), 2);
    Eigen::VectorXd count = Eigen::VectorXd::Zero(data.centroid0.rows());
    for (Eigen::Index v = 0; v < n; ++v) {
        const int u = system.unknown(int(v));
        if (data.component(v) < 0) {
            U.row(v) = (1.0 - t) * data.V0.row(v) + t * data.V1.row(v);
            continue;
        }
        U.row(v) = u >= 0 ? Eigen::RowVector2d(rhs[std::size_t(u) * 2], rhs[std::size_t(u) * 2 + 1])
                          : Eigen::RowVector2d::Zero();
        if (!data.placed[std::size_t(v)])
            continue;
        sum.row(data.component(v)) += U.row(v);
        count(data.component(v)) += 1.0;
    }
    for (Eigen::Index v = 0; v < n; ++v) {
        const int p = data.component(v);
        if (p >= 0)
            U.row(v) += (1.0 - t) * data.centroid0.row(p) + t * data.centroid1.row(p) -
                        sum.row(p) / count(p);
    }
    if (!U.allFinite())
        return unexpected(interpolationError(DeformErrorCode::SolveFailed,
                                             "the interpolation produced non-finite positions"));
    return U;
}

} // namespace finbook::deform::between
