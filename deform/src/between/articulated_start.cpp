// The articulated coarse step of rigidFit (rigid_fit.h): A's parts turned joint by joint, root
// to tips, each by the angle that lays its samples best on B.
#include "rigid_fit_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace finbook::deform::between::detail {

namespace {

// ± this about the base joint: an elbow or a knee folds about this far.
// ± this many degrees about the base joint: a part with everything below it is turned less
// far (it drags its limbs, still unturned, along); a bone by its own samples as far as an elbow
// or a knee folds.
constexpr double kSubtreeSearch = 90.0;
constexpr double kBodyFirstSearch = 120.0;
constexpr double kCoarseStep = 5.0 * std::numbers::pi / 180.0;
constexpr double kFineStep = 1.0 * std::numbers::pi / 180.0;
constexpr double kCapShare = 0.05;   // of B's diagonal: a sample's distance counts at most this
constexpr int kMaxPartSamples = 250; // evenly taken from a part's samples
constexpr int kMinPartSamples = 6;   // fewer: the part is not turned on its own
constexpr int kBodyIterations = 15;  // rigid ICP steps placing the body
// B's points within this share of B's diagonal of a sample off a hinged piece are not the
// piece's to lie on (turnHingedPieces).
constexpr double kTakenShare = 0.025;

double segmentDistance2(const Eigen::Vector2d &p, const Eigen::Vector2d &a,
                        const Eigen::Vector2d &b)
{
    const Eigen::Vector2d d = b - a;
    const double length2 = d.squaredNorm();
    const double s = length2 > 0.0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
    return (p - (a + s * d)).squaredNorm();
}

// At most kMaxPartSamples of a part's samples, evenly.
void thinned(std::vector<int> &part)
{
    if (int(part.size()) <= kMaxPartSamples)
        return;
    std::vector<int> taken;
    for (int i = 0; i < kMaxPartSamples; ++i)
        taken.push_back(part[std::size_t(i) * part.size() / kMaxPartSamples]);
    part.swap(taken);
}

// Rigid ICP of some of A's samples alone: `points` (k×2) with their unit normals, placed by
// `start`, each paired with the nearest agreeing B point within `cap`, until the placement
// moves less than 1e-3 of B's diagonal (at most kBodyIterations steps, and none with fewer
// than kMinPartSamples pairs). Returns the placement.
Similarity rigidIcpOf(const Eigen::MatrixX2d &points, const Eigen::MatrixX2d &normals,
                      Similarity start, const RigidFitTarget &target,
                      const RigidFitOptions &options, double cap)
{
    Similarity current = start;
    for (int iteration = 0; iteration < kBodyIterations; ++iteration) {
        Eigen::MatrixX2d to(points.rows(), 2);
        Eigen::VectorXd w = Eigen::VectorXd::Zero(points.rows());
        for (Eigen::Index i = 0; i < points.rows(); ++i) {
            const Eigen::Vector2d x =
                current.linear * points.row(i).transpose() + current.translation;
            Eigen::Vector2d n = current.linear * normals.row(i).transpose();
            n = n.norm() > 0.0 ? Eigen::Vector2d(n.normalized()) : Eigen::Vector2d::Zero();
            double d = 0.0;
            const int row = target.grid.nearest(x, n, options.normalAgreement, d, cap);
            to.row(i) = row >= 0 ? Eigen::RowVector2d(target.P.row(row)) : points.row(i);
            w(i) = row >= 0 && d <= cap ? 1.0 : 0.0;
        }
        if (w.sum() < kMinPartSamples)
            break;
        const Similarity next = procrustes(points, to, w, false);
        const double moved = (next.linear - current.linear).norm() * target.diagonal +
                             (next.translation - current.translation).norm();
        current = next;
        if (moved < 1e-3 * target.diagonal)
            break;
    }
    return current;
}

bool skeletonUsable(const FitSkeleton &skeleton)
{
    if (skeleton.parent.size() != skeleton.joints.size())
        return false;
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j) {
        const int p = skeleton.parent[j];
        if (!skeleton.joints[j].allFinite() || p < -1 || p >= int(j))
            return false;
    }
    return true;
}

// The turn of x by angle about a pivot, then the part's placement.
struct Placement {
    Eigen::Matrix2d linear = Eigen::Matrix2d::Identity();
    Eigen::Vector2d translation = Eigen::Vector2d::Zero();
    Eigen::Vector2d apply(const Eigen::Vector2d &x) const { return linear * x + translation; }
    // This placement after a turn by `angle` about `pivot` (rest coordinates).
    Placement turned(double angle, const Eigen::Vector2d &pivot) const
    {
        const Eigen::Matrix2d R = Eigen::Rotation2Dd(angle).toRotationMatrix();
        Placement out;
        out.linear = linear * R;
        out.translation = linear * (pivot - R * pivot) + translation;
        return out;
    }
};

} // namespace

Eigen::MatrixX2d articulatedStart(const RigidFitSource &source, const RigidFitTarget &target,
                                  const Similarity &global, const FitSkeleton &skeleton,
                                  const RigidFitOptions &options, ArticulatedStart style)
{
    const Eigen::MatrixX2d placed = global.apply(source.V);
    if (!skeletonUsable(skeleton) || target.grid.empty())
        return placed;
    const int joints = int(skeleton.joints.size());
    std::vector<int> bones; // a bone per joint with a parent (ends at that joint)
    for (int j = 0; j < joints; ++j)
        if (skeleton.parent[std::size_t(j)] >= 0 &&
            (skeleton.joints[std::size_t(j)] -
             skeleton.joints[std::size_t(skeleton.parent[std::size_t(j)])])
                    .squaredNorm() > 0.0)
            bones.push_back(j);
    if (bones.empty())
        return placed;
    const auto nearestBone = [&](const Eigen::Vector2d &p) {
        int best = bones.front();
        double bestD = std::numeric_limits<double>::infinity();
        for (int j : bones) {
            const double d =
                segmentDistance2(p, skeleton.joints[std::size_t(skeleton.parent[std::size_t(j)])],
                                 skeleton.joints[std::size_t(j)]);
            if (d < bestD) {
                bestD = d;
                best = j;
            }
        }
        return best;
    };
    // below[j][k]: joint k is j or under it.
    const auto isBelow = [&](int k, int j) {
        for (; k >= 0; k = skeleton.parent[std::size_t(k)])
            if (k == j)
                return true;
        return false;
    };
    const int k = source.sampleCount();
    std::vector<int> sampleBone(static_cast<std::size_t>(k));
    for (int s = 0; s < k; ++s)
        sampleBone[std::size_t(s)] = nearestBone(source.rest.row(s).transpose());

    std::vector<Placement> placement(static_cast<std::size_t>(joints));
    Placement root;
    root.linear = global.linear;
    root.translation = global.translation;
    const double cap = kCapShare * std::max(target.diagonal, 1e-9);
    // The body anchors the rest: the bone with the most samples of its own is placed by a
    // rigid ICP of those samples alone (the whole-drawing alignment is a compromise between
    // the body and every limb B shows turned), and the whole drawing moves with it before
    // the parts turn.
    {
        std::vector<int> count(static_cast<std::size_t>(joints), 0);
        for (int b : sampleBone)
            ++count[std::size_t(b)];
        const int body = int(std::max_element(count.begin(), count.end()) - count.begin());
        std::vector<int> own;
        for (int s = 0; s < k; ++s)
            if (sampleBone[std::size_t(s)] == body)
                own.push_back(s);
        if (int(own.size()) >= kMinPartSamples && style == ArticulatedStart::BodyFirst) {
            Eigen::MatrixX2d rest(Eigen::Index(own.size()), 2), normals(rest.rows(), 2);
            for (std::size_t i = 0; i < own.size(); ++i) {
                rest.row(Eigen::Index(i)) = source.rest.row(own[i]);
                normals.row(Eigen::Index(i)) = source.N.row(own[i]);
            }
            Similarity current = rigidIcpOf(rest, normals, global, target, options, cap);
            if (options.allowScale) // keep the whole-drawing scale; the body sets the turn
                current.linear *= std::sqrt(std::abs(global.linear.determinant()));
            root.linear = current.linear;
            root.translation = current.translation;
        }
    }
    for (int j = 0; j < joints; ++j) {
        const int p = skeleton.parent[std::size_t(j)];
        if (p < 0) {
            placement[std::size_t(j)] = root;
            continue;
        }
        const Placement &base = placement[std::size_t(p)];
        placement[std::size_t(j)] = base;
        // The bone's own samples decide its turn (everything below follows it, unturned as
        // yet, and would drag the angle towards a compromise); a bone with too few of its own
        // is decided with everything below it.
        std::vector<int> part;
        for (int s = 0; s < k; ++s)
            if (sampleBone[std::size_t(s)] == j)
                part.push_back(s);
        if (int(part.size()) < kMinPartSamples || style == ArticulatedStart::Subtrees) {
            part.clear();
            for (int s = 0; s < k; ++s)
                if (isBelow(sampleBone[std::size_t(s)], j))
                    part.push_back(s);
        }
        if (int(part.size()) < kMinPartSamples)
            continue;
        thinned(part);
        const Eigen::Vector2d pivot = skeleton.joints[std::size_t(p)];
        const auto cost = [&](double angle) {
            const Placement t = base.turned(angle, pivot);
            double sum = 0.0;
            for (int s : part) {
                const Eigen::Vector2d x = t.apply(source.rest.row(s).transpose());
                Eigen::Vector2d n = t.linear * source.N.row(s).transpose();
                const double length = n.norm();
                n = length > 0.0 ? Eigen::Vector2d(n / length) : Eigen::Vector2d::Zero();
                double d = 0.0;
                const int row = target.grid.nearest(x, n, options.normalAgreement, d, cap);
                sum += row < 0 ? cap : std::min(d, cap);
            }
            return sum;
        };
        double best = 0.0, bestCost = cost(0.0);
        const auto consider = [&](double angle) {
            const double c = cost(angle);
            // Ties to the smaller turn: a part B shows unturned stays so.
            if (c < bestCost - 1e-9 || (c <= bestCost + 1e-9 && std::abs(angle) < std::abs(best))) {
                best = angle;
                bestCost = c;
            }
        };
        const double search =
            (style == ArticulatedStart::BodyFirst ? kBodyFirstSearch : kSubtreeSearch) *
            std::numbers::pi / 180.0;
        for (double a = -search; a <= search + 1e-12; a += kCoarseStep)
            consider(a);
        const double around = best;
        for (double a = around - kCoarseStep; a <= around + kCoarseStep + 1e-12; a += kFineStep)
            consider(a);
        placement[std::size_t(j)] = base.turned(best, pivot);
    }
    Eigen::MatrixX2d U(source.V.rows(), 2);
    for (Eigen::Index v = 0; v < source.V.rows(); ++v) {
        const Eigen::Vector2d x = source.V.row(v).transpose();
        U.row(v) = placement[std::size_t(nearestBone(x))].apply(x).transpose();
    }
    return U;
}

Eigen::MatrixX2d turnHingedPieces(const RigidFitSource &source, const RigidFitTarget &target,
                                  Eigen::MatrixX2d U, const RigidFitOptions &options)
{
    if (target.grid.empty())
        return U;
    const double cap = kCapShare * std::max(target.diagonal, 1e-9);
    // First the drawing placed by what is not on a piece: a start aligned on all of A is a
    // compromise between the body and an arm B shows raised, and a hinge it leaves 30 px off
    // the shoulder turns the arm onto the wrong lines.
    {
        std::vector<bool> onPiece(std::size_t(source.sampleCount()), false);
        for (const std::vector<int> &own : source.hingedSamples)
            for (const int s : own)
                onPiece[std::size_t(s)] = true;
        std::vector<int> off;
        for (int s = 0; s < source.sampleCount(); ++s)
            if (!onPiece[std::size_t(s)])
                off.push_back(s);
        if (int(off.size()) >= kMinPartSamples) {
            const Eigen::Matrix2d turn =
                procrustes(source.V, U, Eigen::VectorXd::Ones(U.rows()), false).linear;
            const Eigen::MatrixX2d X = samplePositions(source, U);
            Eigen::MatrixX2d points(Eigen::Index(off.size()), 2), normals(points.rows(), 2);
            for (std::size_t i = 0; i < off.size(); ++i) {
                points.row(Eigen::Index(i)) = X.row(off[i]);
                normals.row(Eigen::Index(i)) =
                    (turn * source.N.row(off[i]).transpose()).transpose();
            }
            U = rigidIcpOf(points, normals, Similarity{}, target, options, cap).apply(U);
        }
    }
    for (std::size_t h = 0; h < source.hinges.size(); ++h) {
        const auto &[under, piece] = source.hinges[h];
        const std::vector<int> &vertices = source.hingedVertices[h];
        std::vector<int> own = source.hingedSamples[h];
        if (int(own.size()) < kMinPartSamples || vertices.empty())
            continue;
        thinned(own);
        // What the rest of A lies on already is not the piece's: B's points nearer than
        // kTakenShare of B's diagonal to a sample of A off the piece (an arm searched over the
        // body would otherwise lie on the body's lines as well as on its own).
        std::vector<bool> mine(std::size_t(source.sampleCount()), false);
        for (const int s : source.hingedSamples[h])
            mine[std::size_t(s)] = true;
        const Eigen::MatrixX2d X = samplePositions(source, U);
        std::vector<int> others;
        for (int s = 0; s < source.sampleCount(); ++s)
            if (!mine[std::size_t(s)])
                others.push_back(s);
        Eigen::MatrixX2d elsewhere(Eigen::Index(others.size()), 2);
        for (std::size_t i = 0; i < others.size(); ++i)
            elsewhere.row(Eigen::Index(i)) = X.row(others[i]);
        const PointGrid elsewhereGrid(elsewhere, Eigen::MatrixX2d());
        std::vector<Eigen::Index> left;
        for (Eigen::Index b = 0; b < target.P.rows(); ++b) {
            double d = std::numeric_limits<double>::infinity();
            if (elsewhereGrid.empty() ||
                elsewhereGrid.nearest(target.P.row(b).transpose(), Eigen::Vector2d::Zero(), 0.0, d,
                                      kTakenShare * target.diagonal) < 0)
                left.push_back(b);
        }
        if (left.empty())
            continue;
        Eigen::MatrixX2d leftP(Eigen::Index(left.size()), 2), leftN(leftP.rows(), 2);
        for (std::size_t i = 0; i < left.size(); ++i) {
            leftP.row(Eigen::Index(i)) = target.P.row(left[i]);
            leftN.row(Eigen::Index(i)) = target.N.row(left[i]);
        }
        const PointGrid free(leftP, leftN);
        // The turn it has now (from rest, over its vertices).
        Eigen::MatrixX2d rest(Eigen::Index(vertices.size()), 2), now(rest.rows(), 2);
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            rest.row(Eigen::Index(i)) = source.V.row(vertices[i]);
            now.row(Eigen::Index(i)) = U.row(vertices[i]);
        }
        const Eigen::Matrix2d turn =
            procrustes(rest, now, Eigen::VectorXd::Ones(rest.rows()), false).linear;
        std::vector<Eigen::Vector2d> normal;
        for (const int s : own) {
            const Eigen::Vector2d n = turn * source.N.row(s).transpose();
            normal.push_back(n.norm() > 0.0 ? Eigen::Vector2d(n.normalized())
                                            : Eigen::Vector2d::Zero());
        }
        // The best turn about a pivot, the piece first moved by `shift`; its cost.
        struct Turn {
            Eigen::Vector2d shift, pivot;
            double angle = 0.0, cost = std::numeric_limits<double>::infinity();
        };
        const auto search = [&](const Eigen::Vector2d &shift, const Eigen::Vector2d &pivot) {
            std::vector<Eigen::Vector2d> at;
            for (const int s : own) {
                Eigen::Vector2d x = shift;
                for (int c = 0; c < 3; ++c)
                    x += source.B(s, c) * U.row(source.F(source.I(s), c)).transpose();
                at.push_back(x - pivot);
            }
            const auto cost = [&](double angle) {
                const Eigen::Matrix2d R = Eigen::Rotation2Dd(angle).toRotationMatrix();
                double sum = 0.0;
                for (std::size_t i = 0; i < at.size(); ++i) {
                    double d = 0.0;
                    const int row = free.nearest(pivot + R * at[i], R * normal[i],
                                                 options.normalAgreement, d, cap);
                    sum += row < 0 ? cap : std::min(d, cap);
                }
                return sum;
            };
            Turn best{shift, pivot, 0.0, cost(0.0)};
            const auto consider = [&](double angle) {
                const double c = cost(angle);
                if (c < best.cost - 1e-9 ||
                    (c <= best.cost + 1e-9 && std::abs(angle) < std::abs(best.angle))) {
                    best.angle = angle;
                    best.cost = c;
                }
            };
            for (double a = -std::numbers::pi; a < std::numbers::pi - 1e-12; a += kCoarseStep)
                consider(a);
            const double around = best.angle;
            for (double a = around - kCoarseStep; a <= around + kCoarseStep + 1e-12; a += kFineStep)
                consider(a);
            return best;
        };
        // About its own hinge vertex where it is now, or moved onto the other piece's (a start
        // that turned it with a bone of the whole drawing's skeleton may have left it off).
        const Turn kept = search(Eigen::Vector2d::Zero(), U.row(piece).transpose());
        const Turn onto =
            search((U.row(under) - U.row(piece)).transpose(), U.row(under).transpose());
        const Turn &best = onto.cost < kept.cost ? onto : kept;
        const Eigen::Matrix2d R = Eigen::Rotation2Dd(best.angle).toRotationMatrix();
        for (const int v : vertices)
            U.row(v) =
                (best.pivot + R * (U.row(v).transpose() + best.shift - best.pivot)).transpose();
    }
    return U;
}

} // namespace finbook::deform::between::detail
