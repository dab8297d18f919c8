#include "medial_ball.h"

#include "outline_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace finbook::geometry::inflate_detail {
namespace {

// Slack on an edge's parameter (0 at its start, 1 at its end) for a contact on its end.
constexpr double kParameterSlack = 1e-9;
// Beyond this angle (cos of 2°) between the smoothed direction and the exact ray through the
// vertex, the ball along the exact ray is grown too (see medialBall).
constexpr double kExactCos = 0.99939;

struct Foot {
    Eigen::RowVector2d point;     // b
    Eigen::RowVector2d direction; // from b toward p (or the outline's normal when p is on it)
    double distance = 0.0;
    Eigen::Index edge = -1;       // the edge whose inside holds b, −1 at a corner
    Eigen::Index nearestEdge = 0; // the edge b was found on, at parameter lambda
    double lambda = 0.0;
};

// Nearest outline point of an interior vertex, and the direction from it to the vertex. A
// vertex (numerically) on the outline takes the edge's or the corner's normal.
Foot nearestFoot(const MeshOutline &outline, const OutlineGrid &grid, const Eigen::RowVector2d &p,
                 double tolerance)
{
    double best = std::numeric_limits<double>::infinity();
    Eigen::Index bestEdge = 0;
    double bestParameter = 0.0;
    const auto visit = [&](Eigen::Index i) {
        const Eigen::RowVector2d a = outline.a.row(i), e = outline.e.row(i);
        const double lambda = std::clamp((p - a).dot(e) * outline.invLength2(i), 0.0, 1.0);
        const double distance2 = (p - a - lambda * e).squaredNorm();
        if (distance2 < best || (distance2 == best && i < bestEdge)) {
            best = distance2;
            bestEdge = i;
            bestParameter = lambda;
        }
    };
    grid.visitNear(p, visit, [&] { return std::sqrt(best); });
    Foot foot;
    foot.point = outline.a.row(bestEdge) + bestParameter * outline.e.row(bestEdge);
    foot.distance = std::sqrt(best);
    foot.nearestEdge = bestEdge;
    foot.lambda = bestParameter;
    const bool inside = bestParameter > 0.0 && bestParameter < 1.0;
    if (inside)
        foot.edge = bestEdge;
    if (foot.distance > tolerance) {
        foot.direction = (p - foot.point) / foot.distance;
    } else if (inside) {
        foot.direction = outline.inward.row(bestEdge);
        foot.distance = 0.0;
    } else {
        foot.direction = outline.normal.row(outline.ends(bestEdge, bestParameter > 0.5 ? 1 : 0));
        foot.distance = 0.0;
    }
    return foot;
}

// The direction the ball grows in: the outline's smoothed normal, interpolated along the edge
// (like a Phong normal), so it turns continuously along the outline; at a corner, whatever
// side of it the point lies on, the corner's own normal.
Eigen::RowVector2d growthDirection(const MeshOutline &outline, const Foot &foot)
{
    const Eigen::Index i = foot.nearestEdge;
    const Eigen::RowVector2d n = (1.0 - foot.lambda) * outline.normal.row(outline.ends(i, 0)) +
                                 foot.lambda * outline.normal.row(outline.ends(i, 1));
    const double length = n.norm();
    return length > 1e-12 ? Eigen::RowVector2d(n / length) : foot.direction;
}

// A disc growing from b along n that meets edge i's line already at b (b lies on that line):
// is it blocked there, i.e. does the edge run from b into the half-plane n points to? That is
// a convex corner (or b inside the edge); at a reflex corner the edge falls away behind b.
bool blockedAtStart(const MeshOutline &outline, Eigen::Index i, const Eigen::RowVector2d &b,
                    const Eigen::RowVector2d &n)
{
    const Eigen::RowVector2d e = outline.e.row(i);
    const double lambda = (b - outline.a.row(i)).dot(e) * outline.invLength2(i);
    if (lambda > kParameterSlack && lambda < 1.0 - kParameterSlack)
        return true;
    if (std::abs(lambda) <= kParameterSlack)
        return n.dot(e) > 0.0;
    if (std::abs(lambda - 1.0) <= kParameterSlack)
        return n.dot(e) < 0.0;
    return false;
}

// Smallest t ≥ 0 at which the disc of radius t centred at b + t·n touches the outline:
// tangent to an edge's inner side within the edge, or through an outline vertex. The edge
// that b lies inside never stops the disc.
//
// A contact stops the disc only if it is at least the contact angle away from b: an edge
// whose normal turns that far from the disc's growth direction n, a vertex seen from
// the centre at that angle from b. A polygon has a medial-axis branch at every convex vertex,
// however slight its turn: on a 128-gon the largest disc touching a chord near a vertex has a
// radius of a few percent of the circle's, and the height would ripple with the sampling.
// Ignoring the near contacts reads the outline as the smooth curve it samples (in the spirit
// of the λ-medial axis), while sharp corners and real opposite sides still stop the ball.
// Without any such contact the nearest one of all is taken.
double firstContact(const MeshOutline &outline, const OutlineGrid &grid, const Foot &foot,
                    const Eigen::RowVector2d &n, double tolerance, const ContactRule &rule)
{
    const Eigen::RowVector2d b = foot.point;
    constexpr double kNone = std::numeric_limits<double>::infinity();
    double radius = kNone, anyRadius = kNone;
    bool blocked = false;
    const double tolerance2 = tolerance * tolerance;
    const double minChord2 = rule.minChord * rule.minChord;
    // cosAngle: of the angle at the centre between b and the contact; chord2: their distance².
    const auto stops = [&](double cosAngle, double chord2) {
        return cosAngle <= kOppositeCos || (cosAngle <= rule.minCos && chord2 >= minChord2);
    };
    const auto throughVertex = [&](int k) {
        // |b + t·n − q|² = t²  ⇔  t = |q − b|² / (2 n·(q − b)).
        const Eigen::RowVector2d w = outline.points.row(k) - b;
        const double along = n.dot(w);
        if (along <= 0.0)
            return; // behind the disc's growth: never on it
        const double w2 = w.squaredNorm();
        if (w2 <= tolerance2)
            return;
        const double t = w2 / (2.0 * along);
        if (t >= radius)
            return;
        anyRadius = std::min(anyRadius, t);
        // |q − b|² = 2t²(1 − cos) for two points on a circle of radius t.
        if (stops(1.0 - w2 / (2.0 * t * t), w2))
            radius = t;
    };
    const auto visit = [&](Eigen::Index i) {
        if (blocked)
            return;
        // Every outline vertex starts one edge, and that edge is filed in the vertex's cell.
        throughVertex(outline.ends(i, 0));
        if (i == foot.edge || outline.invLength2(i) == 0.0)
            return;
        const Eigen::RowVector2d u = outline.inward.row(i);
        // Signed distance of the centre to the edge's line, u·(b − a) + t·(u·n), equals t.
        const double offset = u.dot(b - outline.a.row(i));
        if (offset < -tolerance)
            return; // b lies outside the edge's line: t would be negative
        // Seen from the centre, b lies along −n and a tangent contact along −u.
        const double cosAngle = u.dot(n);
        const double closing = 1.0 - cosAngle;
        if (closing <= 1e-12 || offset >= radius * closing)
            return; // parallel to the disc's growth, or no nearer than the contact found
        if (std::abs(offset) <= tolerance) {
            if (blockedAtStart(outline, i, b, n)) {
                blocked = stops(cosAngle, 0.0);
                anyRadius = 0.0;
            }
            return;
        }
        const double t = offset / closing;
        const Eigen::RowVector2d contact = b + t * (n - u);
        const double lambda =
            (contact - outline.a.row(i)).dot(outline.e.row(i)) * outline.invLength2(i);
        if (lambda < -kParameterSlack || lambda > 1.0 + kParameterSlack)
            return;
        if (stops(cosAngle, t * t * (n - u).squaredNorm()))
            radius = t;
        anyRadius = std::min(anyRadius, t);
    };
    // Any point of a disc through b lies within its diameter of b.
    grid.visitNear(b, visit, [&] { return blocked ? -1.0 : 2.0 * radius; });
    if (blocked)
        return 0.0;
    return radius < kNone ? radius : anyRadius;
}

} // namespace

MedialBall medialBall(const MeshOutline &outline, const OutlineGrid &grid,
                      const Eigen::RowVector2d &p, int slot, double tolerance,
                      const ContactRule &rule)
{
    if (slot >= 0) {
        MedialBall ball;
        ball.direction = outline.normal.row(slot);
        ball.centre = p;
        return ball; // on the outline the height is 0 and the normal −n, whatever the radius
    }
    const Foot foot = nearestFoot(outline, grid, p, tolerance);
    const auto grow = [&](const Eigen::RowVector2d &n, bool throughP) {
        MedialBall ball;
        ball.direction = n;
        ball.depth = foot.distance;
        const double radius = firstContact(outline, grid, foot, n, tolerance, rule);
        ball.radius = std::isfinite(radius) ? radius : foot.distance;
        if (throughP) // p lies on the ray and the disc of radius d around it is empty
            ball.radius = std::max(ball.radius, foot.distance);
        ball.centre = foot.point + ball.radius * n;
        ball.height =
            std::sqrt(std::max(0.0, ball.radius * ball.radius - (p - ball.centre).squaredNorm()));
        return ball;
    };
    // The smoothed direction misses p where the outline bends sharply (a reflex corner's
    // wedge, a notch between fingers): its ball, stopped by the wall it leans toward, may not
    // reach p. The ball along the exact ray from b through p always does; of the two the
    // higher one wins, as in a union of balls.
    MedialBall ball = grow(growthDirection(outline, foot), false);
    if (foot.distance > tolerance && ball.direction.dot(foot.direction) < kExactCos) {
        MedialBall exact = grow(foot.direction, true);
        if (exact.height > ball.height)
            ball = exact;
    }
    return ball;
}

} // namespace finbook::geometry::inflate_detail
