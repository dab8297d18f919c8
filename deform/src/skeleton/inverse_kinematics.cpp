// Drag-driven posing: FK bone turns and IK chains (one bone, two-bone closed form, FABRIK).
#include "skeleton_internal.h"

#include <finbook/deform/skeleton/inverse_kinematics.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace finbook::deform {
namespace {

using detail::makeError;
using Points = std::vector<Eigen::Vector2d>;

// Below this a direction (px) is treated as undefined and the previous one is kept: it
// decides only where the target sits on the pivot itself.
constexpr double kTinyLength = 1e-12;

// FABRIK target steps: a quarter of the shortest bone, a few passes each, at most this many
// steps (a drag across a whole canvas with 5 px bones stays under a millisecond).
constexpr double kFabrikStep = 0.25;
constexpr int kPassesPerStep = 4;
constexpr int kMaxFabrikSteps = 2000;
// Gauss–Newton polish: damping relative to the chain's length, at most this turn per step.
constexpr double kPolishDamping = 1e-3;
constexpr double kMaxPolishTurn = 0.2;
constexpr int kPolishSteps = 16;

double perpDot(const Eigen::Vector2d &a, const Eigen::Vector2d &b)
{
    return a.x() * b.y() - a.y() * b.x();
}

// Signed angle turning a onto b, 0 when either is ~zero.
double turn(const Eigen::Vector2d &a, const Eigen::Vector2d &b)
{
    if (a.norm() <= kTinyLength || b.norm() <= kTinyLength)
        return 0.0;
    return std::atan2(perpDot(a, b), a.dot(b));
}

Eigen::Vector2d direction(const Eigen::Vector2d &v, const Eigen::Vector2d &fallback)
{
    const double length = v.norm();
    return length > kTinyLength ? Eigen::Vector2d(v / length) : fallback;
}

Eigen::Vector2d rotated(const Eigen::Vector2d &v, double angle)
{
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

std::optional<DeformError> checkPoint(const Eigen::Vector2d &p, const char *what)
{
    if (!p.allFinite())
        return makeError(DeformErrorCode::NonFiniteInput, std::string(what) + " is not finite");
    if (p.cwiseAbs().maxCoeff() > kMaxDeformCoordinate)
        return makeError(DeformErrorCode::CoordinateOutOfRange, std::string(what) + " is too far");
    return std::nullopt;
}

// Two bones from P[0] (fixed): the law of cosines with the distance clamped to what the bones
// can span, so an unreachable target straightens (or folds) the chain towards it.
void solveTwoBones(Points &P, const Eigen::Vector2d &target)
{
    const double a = (P[1] - P[0]).norm(), b = (P[2] - P[1]).norm();
    const Eigen::Vector2d toward = direction(target - P[0], direction(P[2] - P[0], {1.0, 0.0}));
    const double d = std::clamp((target - P[0]).norm(), std::abs(a - b), a + b);
    double bend = 0.0;
    if (a > kTinyLength && d > kTinyLength) {
        const double cosine = (a * a + d * d - b * b) / (2.0 * a * d);
        bend = std::acos(std::clamp(cosine, -1.0, 1.0));
    }
    // Keep the side the middle joint bends to; a straight chain bends like a positive turn.
    const double side = perpDot(P[1] - P[0], P[2] - P[1]) < 0.0 ? -1.0 : 1.0;
    P[1] = P[0] + a * rotated(toward, -side * bend);
    P[2] = P[1] + b * direction(P[0] + d * toward - P[1], toward);
}

// FABRIK passes (Aristidou & Lasenby 2011) with P[0] fixed, towards one target, until the end
// is within `tolerance` or `passes` ran out.
void fabrikPasses(Points &P, const std::vector<double> &length,
                  const std::vector<Eigen::Vector2d> &fallback, const Eigen::Vector2d &target,
                  int passes, double tolerance)
{
    const std::size_t m = P.size() - 1;
    const Eigen::Vector2d base = P[0];
    for (int pass = 0; pass < passes; ++pass) {
        if ((P[m] - target).norm() <= tolerance)
            break;
        P[m] = target;
        for (std::size_t i = m; i-- > 0;)
            P[i] = P[i + 1] + length[i] * direction(P[i] - P[i + 1], -fallback[i]);
        P[0] = base;
        for (std::size_t i = 0; i < m; ++i)
            P[i + 1] = P[i] + length[i] * direction(P[i + 1] - P[i], fallback[i]);
    }
}

// FABRIK converges slowly where the solution is nearly straight. A few damped Gauss–Newton
// steps on the bones' directions close that last gap. They aim at the target pulled into the
// chain's reach, so an unreachable target (where FABRIK already stretched the chain) is met as
// it is and the steps never push a straight chain back and forth.
void polishChain(Points &P, const std::vector<double> &length, const Eigen::Vector2d &target,
                 double tolerance)
{
    const std::size_t m = length.size();
    double reach = 0.0;
    std::vector<double> angle(m);
    for (std::size_t i = 0; i < m; ++i) {
        reach += length[i];
        angle[i] = std::atan2(P[i + 1].y() - P[i].y(), P[i + 1].x() - P[i].x());
    }
    const Eigen::Vector2d offset = target - P[0];
    const double distance = offset.norm();
    const Eigen::Vector2d aim =
        distance > reach ? Eigen::Vector2d(P[0] + offset * (reach / distance)) : target;
    const double damping = kPolishDamping * reach;
    for (int step = 0; step < kPolishSteps; ++step) {
        Eigen::Vector2d end = P[0];
        for (std::size_t i = 0; i < m; ++i)
            end += length[i] * Eigen::Vector2d(std::cos(angle[i]), std::sin(angle[i]));
        const Eigen::Vector2d residual = aim - end;
        if (residual.norm() <= tolerance)
            break;
        Eigen::Matrix2d A = damping * damping * Eigen::Matrix2d::Identity();
        for (std::size_t i = 0; i < m; ++i) {
            const Eigen::Vector2d column =
                length[i] * Eigen::Vector2d(-std::sin(angle[i]), std::cos(angle[i]));
            A += column * column.transpose();
        }
        // A is SPD (damping > 0 unless every bone has zero length, excluded by the caller).
        const double det = A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0);
        const Eigen::Vector2d y((A(1, 1) * residual.x() - A(0, 1) * residual.y()) / det,
                                (A(0, 0) * residual.y() - A(1, 0) * residual.x()) / det);
        double largest = 0.0;
        std::vector<double> change(m);
        for (std::size_t i = 0; i < m; ++i) {
            change[i] = length[i] * (-std::sin(angle[i]) * y.x() + std::cos(angle[i]) * y.y());
            largest = std::max(largest, std::abs(change[i]));
        }
        const double scale = largest > kMaxPolishTurn ? kMaxPolishTurn / largest : 1.0;
        for (std::size_t i = 0; i < m; ++i)
            angle[i] += scale * change[i];
    }
    for (std::size_t i = 0; i < m; ++i)
        P[i + 1] = P[i] + length[i] * Eigen::Vector2d(std::cos(angle[i]), std::sin(angle[i]));
}

// Chains of three or more bones. Plain FABRIK jumps when the target crosses one of the starting
// joints (a backward pass flips that bone). Walking the target from the end's start position to the
// cursor in steps well below a bone length, warm-starting each step, keeps every pass local, so the
// result follows the cursor continuously and reachable targets are met to the tolerance.
void solveFabrik(Points &P, const Eigen::Vector2d &target, const IkOptions &options)
{
    const std::size_t m = P.size() - 1;
    std::vector<double> length(m);
    std::vector<Eigen::Vector2d> fallback(m);
    double shortest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < m; ++i) {
        length[i] = (P[i + 1] - P[i]).norm();
        fallback[i] = direction(P[i + 1] - P[i], {1.0, 0.0});
        if (length[i] > kTinyLength)
            shortest = std::min(shortest, length[i]);
    }
    if (!std::isfinite(shortest))
        return; // every bone has zero length: nothing can turn
    // Steps of a fixed length from the start, not a fixed number of them: a new step appears
    // exactly at the target, where it changes nothing, so the result stays continuous in the
    // target's distance too.
    const Eigen::Vector2d start = P[m];
    const double distance = (target - start).norm();
    const double step = std::max(kFabrikStep * shortest, distance / kMaxFabrikSteps);
    for (int k = 1; k * step < distance; ++k)
        fabrikPasses(P, length, fallback, start + (k * step / distance) * (target - start),
                     kPassesPerStep, options.tolerance);
    fabrikPasses(P, length, fallback, target, options.iterations, options.tolerance);
    polishChain(P, length, target, options.tolerance);
}

// Joint angles that turn the chain's bones onto the solved positions Q (top first).
void applyChain(const Eigen::VectorXi &chain, const Points &before, const Points &Q,
                SkeletonPose &pose)
{
    double above = 0.0; // total turn already given to the bones above
    for (std::size_t i = 0; i + 1 < Q.size(); ++i) {
        const int bone = chain(chain.size() - 1 - Eigen::Index(i));
        const double total = turn(before[i + 1] - before[i], Q[i + 1] - Q[i]);
        const double own = std::remainder(total - above, 2.0 * M_PI);
        if ((before[i + 1] - before[i]).norm() > kTinyLength) {
            pose.angles(bone) = std::remainder(pose.angles(bone) + own, 2.0 * M_PI);
            above += own;
        }
    }
}

Expected<IkResult, DeformError> translateRoots(const PosedSkeleton &posed, IkResult result,
                                               int joint, const Eigen::Vector2d &target,
                                               const std::vector<bool> &locked)
{
    for (const bool l : locked) {
        if (l)
            return result;
    }
    result.pose.rootOffset += target - posed.joints.row(joint).transpose();
    if (auto error = checkPoint(result.pose.rootOffset, "the root offset"))
        return unexpected(*error);
    return result;
}

} // namespace

Eigen::VectorXi ikChain(const Skeleton &skeleton, int joint, const std::vector<bool> &locked,
                        int maxChainBones, const std::vector<bool> &limbBase)
{
    const Eigen::Index count = skeleton.jointCount();
    if (joint < 0 || joint >= count || (!locked.empty() && Eigen::Index(locked.size()) != count) ||
        (!limbBase.empty() && Eigen::Index(limbBase.size()) != count))
        return Eigen::VectorXi();
    // lockedBelow[j]: joint j or one of its descendants is locked (children after parents in
    // `order`, so a reverse sweep sees every child before its parent).
    std::vector<bool> lockedBelow(static_cast<std::size_t>(count), false);
    if (!locked.empty()) {
        for (Eigen::Index k = count; k-- > 0;) {
            const int j = skeleton.order(k);
            if (locked[static_cast<std::size_t>(j)])
                lockedBelow[static_cast<std::size_t>(j)] = true;
            if (lockedBelow[static_cast<std::size_t>(j)] && skeleton.parent(j) >= 0)
                lockedBelow[static_cast<std::size_t>(skeleton.parent(j))] = true;
        }
    }
    const int longest =
        maxChainBones > 0 ? std::min(maxChainBones, kMaxIkChainBones) : kMaxIkChainBones;
    // A branch point (a joint with two or more children: the chest, the hips) ends the limb: a
    // bone that starts there turns only when the chain has no two bones of its own, so a
    // dragged hand turns the arm at its shoulder, not a bone from the body's centre.
    std::vector<int> children(static_cast<std::size_t>(count), 0);
    for (Eigen::Index j = 0; j < count; ++j)
        if (!skeleton.isRoot(j))
            ++children[static_cast<std::size_t>(skeleton.parent(j))];
    std::vector<int> chain;
    for (int j = joint; j >= 0 && !skeleton.isRoot(j) && !lockedBelow[static_cast<std::size_t>(j)];
         j = skeleton.parent(j)) {
        if (static_cast<int>(chain.size()) >= longest)
            break;
        // A limb base's bone runs into the body: it turns only when the base itself is dragged.
        if (!chain.empty() && !limbBase.empty() && limbBase[static_cast<std::size_t>(j)])
            break;
        const bool fromBranch = children[static_cast<std::size_t>(skeleton.parent(j))] >= 2;
        if (fromBranch && chain.size() >= 2)
            break;
        chain.push_back(j);
        if (fromBranch)
            break;
    }
    return Eigen::Map<const Eigen::VectorXi>(chain.data(), Eigen::Index(chain.size()));
}

Expected<IkResult, DeformError> solveIk(const Skeleton &skeleton, const SkeletonPose &start,
                                        int joint, const Eigen::Vector2d &target,
                                        const std::vector<bool> &locked, const IkOptions &options)
{
    if (joint < 0 || joint >= skeleton.jointCount())
        return unexpected(makeError(DeformErrorCode::InvalidIndex,
                                    "joint " + std::to_string(joint) + " does not exist"));
    if (!locked.empty() && Eigen::Index(locked.size()) != skeleton.jointCount())
        return unexpected(makeError(DeformErrorCode::SizeMismatch,
                                    "the locks do not match the skeleton's joints"));
    if (!options.limbBase.empty() && Eigen::Index(options.limbBase.size()) != skeleton.jointCount())
        return unexpected(makeError(DeformErrorCode::SizeMismatch,
                                    "the limb bases do not match the skeleton's joints"));
    if (auto error = checkPoint(target, "the target"))
        return unexpected(*error);
    auto posed = forwardKinematics(skeleton, start);
    if (!posed)
        return unexpected(posed.error());
    IkResult result{start, {}, 0.0};
    if (!locked.empty() && locked[static_cast<std::size_t>(joint)]) {
        result.distance = (posed->joints.row(joint).transpose() - target).norm();
        return result;
    }
    if (skeleton.isRoot(joint))
        return translateRoots(*posed, std::move(result), joint, target, locked);
    result.chain = ikChain(skeleton, joint, locked, options.maxChainBones, options.limbBase);
    const Eigen::Index m = result.chain.size();
    if (m > 0) {
        // Chain positions from its fixed pivot down to the dragged joint.
        Points before(static_cast<std::size_t>(m + 1));
        before[0] = posed->joints.row(skeleton.parent(result.chain(m - 1))).transpose();
        for (Eigen::Index i = 0; i < m; ++i)
            before[std::size_t(i + 1)] = posed->joints.row(result.chain(m - 1 - i)).transpose();
        Points solved = before;
        if (m == 1)
            solved[1] = solved[0] + (before[1] - before[0]).norm() *
                                        direction(target - solved[0],
                                                  direction(before[1] - before[0], {1.0, 0.0}));
        else if (m == 2)
            solveTwoBones(solved, target);
        else
            solveFabrik(solved, target, options);
        applyChain(result.chain, before, solved, result.pose);
    }
    auto after = forwardKinematics(skeleton, result.pose);
    if (!after)
        return unexpected(after.error());
    result.distance = (after->joints.row(joint).transpose() - target).norm();
    return result;
}

Expected<SkeletonPose, DeformError> rotateBone(const Skeleton &skeleton, const SkeletonPose &start,
                                               int bone, const Eigen::Vector2d &grabbed,
                                               const Eigen::Vector2d &cursor)
{
    if (bone < 0 || bone >= skeleton.jointCount())
        return unexpected(makeError(DeformErrorCode::InvalidIndex,
                                    "bone " + std::to_string(bone) + " does not exist"));
    for (const Eigen::Vector2d *p : {&grabbed, &cursor}) {
        if (auto error = checkPoint(*p, "the drag position"))
            return unexpected(*error);
    }
    auto posed = forwardKinematics(skeleton, start);
    if (!posed)
        return unexpected(posed.error());
    const int pivotJoint = skeleton.isRoot(bone) ? bone : skeleton.parent(bone);
    const Eigen::Vector2d pivot = posed->joints.row(pivotJoint).transpose();
    SkeletonPose pose = start;
    // Stored in (−π, π]: the same pose, and angles cannot creep up over many drags.
    pose.angles(bone) =
        std::remainder(pose.angles(bone) + turn(grabbed - pivot, cursor - pivot), 2.0 * M_PI);
    return pose;
}

} // namespace finbook::deform
