#include "contour_simplify.h"

#include "local_width.h"

#include <finbook/geometry/polyline.h>
#include <finbook/geometry/simplicity.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

namespace finbook::geometry::detail {
namespace {

constexpr int kMaxSteps = 40;
constexpr double kStep = 1.25;
// The smallest local half-width the adaptive budget resolves, in starting tolerances.
constexpr double kMinScale = 4.0;
// Outline detail within this many starting tolerances of a vertex (pixel steps) does not make
// the vertex's neighbourhood thin.
constexpr double kIgnoreScale = 6.0;
// The adaptive budget starts from at most this many vertex budgets of the plain outline.
constexpr long kBaseBudgets = 2;

double distanceToSegment(const Eigen::RowVector2d &p, const Eigen::RowVector2d &a,
                         const Eigen::RowVector2d &b)
{
    const Eigen::RowVector2d ab = b - a;
    const double len2 = ab.squaredNorm();
    if (len2 == 0.0)
        return (p - a).norm();
    const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
    return (p - (a + t * ab)).norm();
}

// Ranks the open stretch first..last of `points` (indices taken modulo the ring size) with
// the same splits as douglasPeucker: a vertex's value is its own distance, capped by the
// value of the split that exposed it. With `scale`, distances are divided by the vertex's
// scale (a Douglas–Peucker whose tolerance varies along the ring).
void rankStretch(const Eigen::MatrixX2d &points, Eigen::Index first, Eigen::Index last,
                 std::vector<double> &rank, const std::vector<double> *scale = nullptr)
{
    const Eigen::Index n = points.rows();
    struct Task {
        Eigen::Index a, b;
        double bound;
    };
    std::vector<Task> stack{{first, last, kInfinity}};
    while (!stack.empty()) {
        const Task task = stack.back();
        stack.pop_back();
        double worst = -1.0;
        Eigen::Index worstAt = -1;
        for (Eigen::Index i = task.a + 1; i < task.b; ++i) {
            const double d = distanceToSegment(points.row(i % n), points.row(task.a % n),
                                               points.row(task.b % n)) /
                             (scale ? (*scale)[std::size_t(i % n)] : 1.0);
            if (d > worst) {
                worst = d;
                worstAt = i;
            }
        }
        if (worstAt < 0)
            continue;
        const double value = std::min(worst, task.bound);
        rank[std::size_t(worstAt % n)] = value;
        stack.push_back({task.a, worstAt, value});
        stack.push_back({worstAt, task.b, value});
    }
}

Eigen::MatrixX2d ringAt(const Eigen::MatrixX2d &ring, const std::vector<double> &rank,
                        double tolerance)
{
    Eigen::MatrixX2d out(ring.rows(), 2);
    Eigen::Index count = 0;
    for (Eigen::Index i = 0; i < ring.rows(); ++i) {
        if (rank[std::size_t(i)] > tolerance)
            out.row(count++) = ring.row(i);
    }
    out.conservativeResize(count, 2);
    // CGAL trips over nearly coincident vertices (CGAL#3382).
    return cleanPolyline(out, 0.02 * tolerance, true);
}

struct RankedPolygon {
    const Polygon &polygon;
    std::vector<double> outer;
    std::vector<std::vector<double>> holes;

    Polygon at(double tolerance) const
    {
        Polygon out;
        out.outer = ringAt(polygon.outer, outer, tolerance);
        for (std::size_t h = 0; h < holes.size(); ++h) {
            Eigen::MatrixX2d ring = ringAt(polygon.holes[h], holes[h], tolerance);
            // A hole squashed below the tolerance carries no shape the skeleton could follow.
            if (ring.rows() >= 3 && std::abs(signedArea(ring)) > tolerance * tolerance)
                out.holes.push_back(std::move(ring));
        }
        return out;
    }

    // The smallest tolerance that keeps at most `count` vertices (0 if all fit).
    double toleranceFor(long count) const
    {
        std::vector<double> all = outer;
        for (const std::vector<double> &h : holes)
            all.insert(all.end(), h.begin(), h.end());
        if (count >= long(all.size()))
            return 0.0;
        std::nth_element(all.begin(), all.begin() + count, all.end(), std::greater<>());
        return all[std::size_t(count)];
    }
};

bool strictlySimple(const Polygon &polygon)
{
    if (polygon.outer.rows() < 3 || !(signedArea(polygon.outer) > 0.0))
        return false;
    return isSimple(Region{polygon}, Touching::Forbidden);
}

// One ring of the adaptive outline: the vertices the uniform tolerance keeps, plus those of
// the thinned ring (indices `base` into it) whose scaled rank exceeds the fraction.
struct AdaptiveRing {
    const Eigen::MatrixX2d &ring;
    std::vector<double> plain;      // keepTolerances(ring)
    std::vector<Eigen::Index> base; // indices into ring: the thinned ring
    std::vector<double> scaled;     // per base vertex: rank in local half-widths

    AdaptiveRing(const Eigen::MatrixX2d &r, double floor)
        : ring(r)
        , plain(keepTolerances(r))
    {
        for (Eigen::Index i = 0; i < ring.rows(); ++i) {
            if (plain[std::size_t(i)] > floor)
                base.push_back(i);
        }
    }

    Eigen::MatrixX2d baseRing() const
    {
        Eigen::MatrixX2d out(Eigen::Index(base.size()), 2);
        for (std::size_t k = 0; k < base.size(); ++k)
            out.row(Eigen::Index(k)) = ring.row(base[k]);
        return out;
    }

    std::vector<char> kept(double uniform, double fraction) const
    {
        std::vector<char> keep(std::size_t(ring.rows()), 0);
        for (Eigen::Index i = 0; i < ring.rows(); ++i)
            keep[std::size_t(i)] = plain[std::size_t(i)] > uniform;
        for (std::size_t k = 0; k < base.size(); ++k)
            keep[std::size_t(base[k])] |= scaled[k] > fraction;
        return keep;
    }

    Eigen::MatrixX2d at(double uniform, double fraction, double start) const
    {
        const std::vector<char> keep = kept(uniform, fraction);
        Eigen::MatrixX2d out(ring.rows(), 2);
        Eigen::Index count = 0;
        for (Eigen::Index i = 0; i < ring.rows(); ++i) {
            if (keep[std::size_t(i)])
                out.row(count++) = ring.row(i);
        }
        out.conservativeResize(count, 2);
        return cleanPolyline(out, 0.02 * start, true);
    }
};

} // namespace

std::vector<double> keepTolerances(const Eigen::MatrixX2d &ring, const std::vector<double> *scale)
{
    const Eigen::Index n = ring.rows();
    std::vector<double> rank(std::size_t(n), 0.0);
    if (n <= 3)
        return std::vector<double>(std::size_t(n), kInfinity);
    Eigen::Index far = 1;
    for (Eigen::Index i = 1; i < n; ++i) {
        if ((ring.row(i) - ring.row(0)).squaredNorm() > (ring.row(far) - ring.row(0)).squaredNorm())
            far = i;
    }
    rank[0] = rank[std::size_t(far)] = kInfinity;
    rankStretch(ring, 0, far, rank, scale);
    rankStretch(ring, far, n, rank, scale);
    return rank;
}

double thickness(const Polygon &polygon)
{
    const Region region{polygon};
    const double perimeter = regionPerimeter(region);
    return perimeter > 0.0 ? std::abs(regionArea(region)) / perimeter : 0.0;
}

Polygon simplifyToBudget(const Polygon &polygon, double start, double cap, int target, int budget,
                         double &used)
{
    RankedPolygon ranked{polygon, keepTolerances(polygon.outer), {}};
    for (const Eigen::MatrixX2d &hole : polygon.holes)
        ranked.holes.push_back(keepTolerances(hole));
    const double forTarget = std::max(start, ranked.toleranceFor(target));
    const double chosen =
        forTarget <= cap ? forTarget : std::max(cap, std::max(start, ranked.toleranceFor(budget)));
    double tolerance = chosen;
    for (int step = 0; step < kMaxSteps; ++step, tolerance *= kStep) {
        Polygon candidate = ranked.at(tolerance);
        if (candidate.outer.rows() < 3)
            break;
        if (strictlySimple(candidate)) {
            used = tolerance;
            return candidate;
        }
    }
    // Coarser only broke it further: accept more vertices than the budget.
    for (tolerance = chosen / kStep; tolerance >= start; tolerance /= kStep) {
        Polygon candidate = ranked.at(tolerance);
        if (strictlySimple(candidate)) {
            used = tolerance;
            return candidate;
        }
    }
    return {};
}

Polygon simplifyAdaptive(const Polygon &polygon, double start, double fraction, int target,
                         int budget, double &used)
{
    const double cap = std::max(start, fraction * thickness(polygon));
    RankedPolygon plain{polygon, keepTolerances(polygon.outer), {}};
    for (const Eigen::MatrixX2d &hole : polygon.holes)
        plain.holes.push_back(keepTolerances(hole));
    // The uniform tolerance simplifyToBudget would pick: every vertex it keeps stays.
    const double forTarget = std::max(start, plain.toleranceFor(target));
    const double uniform =
        forTarget <= cap ? forTarget : std::max(cap, std::max(start, plain.toleranceFor(budget)));
    // The thinned outline the extra vertices come from: no pixel noise, a few budgets at most.
    const double floor = std::max(start, plain.toleranceFor(kBaseBudgets * long(budget)));
    if (!(floor < uniform))
        return simplifyToBudget(polygon, start, cap, target, budget, used);
    std::vector<AdaptiveRing> rings;
    rings.emplace_back(polygon.outer, floor);
    for (const Eigen::MatrixX2d &hole : polygon.holes)
        rings.emplace_back(hole, floor);
    Polygon base;
    base.outer = rings[0].baseRing();
    for (std::size_t h = 1; h < rings.size(); ++h)
        base.holes.push_back(rings[h].baseRing());
    std::vector<std::vector<double>> scale = localHalfWidths(base, kIgnoreScale * start);
    const double widest = std::max(kMinScale * start, thickness(polygon));
    for (std::size_t r = 0; r < rings.size(); ++r) {
        for (double &w : scale[r])
            w = std::clamp(w, kMinScale * start, widest);
        const Eigen::MatrixX2d ring = r == 0 ? base.outer : base.holes[r - 1];
        rings[r].scaled = keepTolerances(ring, &scale[r]);
    }
    auto at = [&](double f) {
        Polygon out;
        out.outer = rings[0].at(uniform, f, start);
        for (std::size_t h = 1; h < rings.size(); ++h) {
            Eigen::MatrixX2d ring = rings[h].at(uniform, f, start);
            if (ring.rows() >= 3 && std::abs(signedArea(ring)) > start * start)
                out.holes.push_back(std::move(ring));
        }
        return out;
    };
    // The smallest fraction ≥ `fraction` whose extra vertices fit the budget, then finer
    // (thin parts that touch once simplified want more vertices) as long as they fit.
    double f = fraction;
    for (int step = 0; step < kMaxSteps && regionVertexCount(Region{at(f)}) > budget; ++step)
        f *= kStep;
    for (int step = 0; step < kMaxSteps; ++step, f /= kStep) {
        Polygon candidate = at(f);
        if (regionVertexCount(Region{candidate}) > budget)
            break;
        if (strictlySimple(candidate)) {
            used = uniform;
            return candidate;
        }
    }
    return simplifyToBudget(polygon, start, cap, target, budget, used);
}

} // namespace finbook::geometry::detail
