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

double segmentDistance2(const Eigen::Vector2d &p, const Eigen::Vector2d &a,
                        const Eigen::Vector2d &b)
{
    const Eigen::Vector2d d = b - a;
    const double length2 = d.squaredNorm();
    const double s = length2 > 0.0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
    return (p - (a + s * d)).squaredNorm();
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
            Eigen::MatrixX2d rest(Eigen::Index(own.size()), 2);
            for (std::size_t i = 0; i < own.size(); ++i)
                rest.row(Eigen::Index(i)) = source.rest.row(own[i]);
            Similarity current = global;
            for (int iteration = 0; iteration < kBodyIterations; ++iteration) {
                Eigen::MatrixX2d from(rest.rows(), 2), to(rest.rows(), 2);
                Eigen::VectorXd w = Eigen::VectorXd::Zero(rest.rows());
                for (Eigen::Index i = 0; i < rest.rows(); ++i) {
                    const Eigen::Vector2d x =
                        current.linear * rest.row(i).transpose() + current.translation;
                    Eigen::Vector2d n =
                        current.linear * source.N.row(own[std::size_t(i)]).transpose();
                    n = n.norm() > 0.0 ? Eigen::Vector2d(n.normalized()) : Eigen::Vector2d::Zero();
                    double d = 0.0;
                    const int row = target.grid.nearest(x, n, options.normalAgreement, d, cap);
                    from.row(i) = rest.row(i);
                    to.row(i) = row >= 0 ? Eigen::RowVector2d(target.P.row(row)) : from.row(i);
                    w(i) = row >= 0 && d <= cap ? 1.0 : 0.0;
                }
                if (w.sum() < kMinPartSamples)
                    break;
                const Similarity next = procrustes(from, to, w, false);
                const double moved = (next.linear - current.linear).norm() * target.diagonal +
                                     (next.translation - current.translation).norm();
                current = next;
                if (moved < 1e-3 * target.diagonal)
                    break;
            }
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
        if (int(part.size()) > kMaxPartSamples) {
            std::vector<int> taken;
            for (int i = 0; i < kMaxPartSamples; ++i)
                taken.push_back(part[std::size_t(i) * part.size() / kMaxPartSamples]);
            part.swap(taken);
        }
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

} // namespace finbook::deform::between::detail
