#include <finbook/model/inbetween/rig_interpolation.h>
#include <finbook/model/rig/rig_commands.h>

#include <cmath>

namespace finbook::model {

namespace {

// Below this turn (radians) the motion is treated as a translation: the fixed point of an
// almost-pure translation lies far away and would only cost precision.
constexpr double kMinTurn = 1e-6;

QPointF lerp(QPointF a, QPointF b, double t)
{
    // (1 - t) a + t b, not a + t (b - a): the ends are then exact.
    return a * (1.0 - t) + b * t;
}

QPointF centroid(const std::vector<QPointF> &points)
{
    QPointF sum;
    for (const QPointF p : points)
        sum += p;
    return sum / double(points.size());
}

QPointF rotated(QPointF p, double angle)
{
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * p.x() - s * p.y(), s * p.x() + c * p.y()};
}

// The angle of the rotation that best maps `a` onto `b` about their centroids (2D Procrustes);
// atan2 keeps it in (-π, π], i.e. along the shorter arc. 0 when it is undefined.
double bestTurn(const std::vector<QPointF> &a, const std::vector<QPointF> &b)
{
    const QPointF ca = centroid(a), cb = centroid(b);
    double dot = 0.0, cross = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const QPointF p = a[i] - ca, q = b[i] - cb;
        dot += p.x() * q.x() + p.y() * q.y();
        cross += p.x() * q.y() - p.y() * q.x();
    }
    const double turn = std::atan2(cross, dot);
    return std::isfinite(turn) ? turn : 0.0;
}

std::vector<QPointF> straight(const std::vector<QPointF> &a, const std::vector<QPointF> &b,
                              double t)
{
    std::vector<QPointF> out(a.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        out[i] = lerp(a[i], b[i], t);
    return out;
}

// Targets closer than this (px) in both keys count as unmoved.
constexpr double kStill = 1e-6;

bool still(QPointF a, QPointF b)
{
    return std::abs(b.x() - a.x()) <= kStill && std::abs(b.y() - a.y()) <= kStill;
}

std::vector<QPointF> alongArc(const std::vector<QPointF> &a, const std::vector<QPointF> &b,
                              double t)
{
    // A target that stays put in both keys stays put in between. The turn is fitted to the
    // targets that move when at least two do (a cage bent at one end turns about its joint,
    // not by a compromise of the whole cage), to all of them otherwise (one pin swung about
    // pins that hold still).
    std::vector<QPointF> fitA, fitB;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!still(a[i], b[i])) {
            fitA.push_back(a[i]);
            fitB.push_back(b[i]);
        }
    if (fitA.size() < 2) {
        fitA = a;
        fitB = b;
    }
    const double turn = fitA.size() >= 2 ? bestTurn(fitA, fitB) : 0.0;
    if (std::abs(turn) < kMinTurn)
        return straight(a, b, t);
    // The rigid map p ↦ R(p − ca) + cb turns about its fixed point c, (I − R) c = cb − R ca;
    // following it part way is a turn by t·turn about c (the screw motion of SE(2)).
    const QPointF ca = centroid(fitA), cb = centroid(fitB);
    const QPointF rhs = cb - rotated(ca, turn);
    const double cr = std::cos(turn), sr = std::sin(turn);
    // I − R = [[1 − cr, sr], [−sr, 1 − cr]], determinant 2 (1 − cr) > 0 for turn ≠ 0.
    const double det = 2.0 * (1.0 - cr);
    const QPointF c(((1.0 - cr) * rhs.x() - sr * rhs.y()) / det,
                    (sr * rhs.x() + (1.0 - cr) * rhs.y()) / det);
    std::vector<QPointF> out(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (still(a[i], b[i])) {
            out[i] = a[i];
            continue;
        }
        const QPointF rigidEnd = c + rotated(a[i] - c, turn);
        const QPointF residual = b[i] - rigidEnd; // the non-rigid part, blended linearly
        out[i] = c + rotated(a[i] - c, t * turn) + residual * t;
    }
    return out;
}

std::vector<QPointF> targetsOf(const std::vector<Pin> &pins)
{
    std::vector<QPointF> out;
    out.reserve(pins.size());
    for (const Pin &p : pins)
        out.push_back(p.target);
    return out;
}

// A skeleton's pose may leave its angles out (empty = all zero, at rest); otherwise one per
// joint.
bool anglesFit(const SkeletonRig &s)
{
    return s.angles.empty() || s.angles.size() == s.joints.size();
}

double angleAt(const SkeletonRig &s, std::size_t joint)
{
    return joint < s.angles.size() ? s.angles[joint] : 0.0;
}

} // namespace

bool canInterpolateRigs(const Rig &first, const Rig &second)
{
    return !first.empty() && sameRestDefinition(first, second) &&
           first.cage.posed.size() == second.cage.posed.size() && anglesFit(first.skeleton) &&
           anglesFit(second.skeleton) && first.skeleton.mode == second.skeleton.mode;
}

std::vector<QPointF> interpolateTargets(const std::vector<QPointF> &first,
                                        const std::vector<QPointF> &second, double t,
                                        TargetPath path)
{
    if (!std::isfinite(t) || t <= 0.0 || first.size() != second.size() || first.empty())
        return first;
    if (t >= 1.0)
        return second;
    return path == TargetPath::Arc ? alongArc(first, second, t) : straight(first, second, t);
}

Rig interpolateRig(const Rig &first, const Rig &second, double t, TargetPath path)
{
    if (!canInterpolateRigs(first, second))
        return first;
    Rig out = first;
    switch (first.kind()) {
    case RigKind::Pins: {
        const auto targets =
            interpolateTargets(targetsOf(first.pins), targetsOf(second.pins), t, path);
        for (std::size_t i = 0; i < out.pins.size(); ++i)
            out.pins[i].target = targets[i];
        break;
    }
    case RigKind::Cage:
        out.cage.posed = interpolateTargets(first.cage.posed, second.cage.posed, t, path);
        break;
    case RigKind::Skeleton: {
        // Each bone angle along the shorter arc, the root's offset along a straight line;
        // the ends are the keys exactly.
        if (!std::isfinite(t) || t <= 0.0)
            break;
        if (t >= 1.0) {
            // The second key's pose; the join stays the first's (it names the first key's
            // objects, which the in-between holds).
            out.skeleton = second.skeleton;
            out.skeleton.join = first.skeleton.join;
            out.skeleton.anchor = first.skeleton.anchor;
            break;
        }
        out.skeleton.angles.resize(out.skeleton.joints.size());
        for (std::size_t j = 0; j < out.skeleton.angles.size(); ++j) {
            const double a = angleAt(first.skeleton, j), b = angleAt(second.skeleton, j);
            const double turn = std::remainder(b - a, 2.0 * M_PI);
            out.skeleton.angles[j] = a + t * turn;
        }
        out.skeleton.rootOffset = first.skeleton.rootOffset +
                                  t * (second.skeleton.rootOffset - first.skeleton.rootOffset);
        break;
    }
    case RigKind::None:
        break;
    }
    return out;
}

} // namespace finbook::model
