// Flip detection and repair. ARAP does not prevent inversion, and an unconverged pose (the
// paper's two steps, a drag pose) folds triangles that the ARAP optimum keeps upright,
// typically a few next to a pin under compression. The repair relaxes the ARAP energy
// locally around them: Gauss–Seidel over the free vertices of a small region, each vertex
// moved to its energy minimum given its neighbours with the rotations of its triangles
// refitted first (in the precompute's weights: the cotangent ARAP energy for Refined). Each update
// lowers (never raises) the energy. A fold that survives is a local minimum: the region around
// it restarts from a smoothed shape once and relaxes again (restartRegion), which may leave a
// little more energy there and is kept only with fewer flips. What survives that too gets an
// injective finish (untangleFlips, arap_untangle.cpp): its corners moved to where their
// triangles are upright where their rings leave room, then relaxed without turning any
// triangle over; kept only with fewer flips and little more energy. What survives that is
// taken as forced by the pins.
#include "arap_flips.h"

#include <algorithm>
#include <limits>

namespace finbook::deform::detail {
namespace {

// Sweeps per region and region growths: a region of 2 rings around the flips is usually
// clean after a few sweeps; a fold spread over more triangles gets wider regions.
constexpr int kSweeps = 12;
constexpr int kStall = 3;
// Work bound per solve, in vertex updates (each refits the vertex's ~6 triangles, about
// 0.1 µs): at least kMinUpdates (0.2 ms), else a sixteenth of the free vertices, about a
// tenth of a pass. Many flips forced by point pins on a fine mesh made the repair cost
// several passes per drag event.
constexpr Eigen::Index kMinUpdates = 2048;
constexpr Eigen::Index kUpdatesPerFree = 16;
constexpr int kGrowths = 3;
constexpr int kRingsPerGrowth = 2;
// The restart of a fold that relaxation leaves (restartRegion): smoothing sweeps, the rings
// around the flips it covers, and relaxation sweeps after it (all of them: stopping when the
// flips were gone left the drag of tst_arap_drag's 2:1 bar at 1.09× the converged energy). On the
// drawings below 2 smoothing sweeps opened fewer folds than 5; 3 or 4 rings and 10 sweeps did
// no better than 2 and 5.
constexpr int kSmoothSweeps = 5;
constexpr int kRestartRings = 2;
constexpr int kRestartSweeps = 30;
// The injective finish (untangleFlips) is kept only if it adds at most this share of the
// energy (refine's): opening a fold that the converged pose has too can cost visible rigidity
// (on the 20k-vertex drawings of `finbook-bench arap --quality` one cost 2.3 % of a stored
// pose's energy, where the converged pose has that fold). A drag pose is replaced by the stored
// one, and a fold flickering in and out of a drag shows more than a percent of energy does.
constexpr double kFinishCostFinal = 0.005;
constexpr double kFinishCostDrag = 0.02;

} // namespace

double signedDoubleArea(const ArapPrecompute &d, const Eigen::VectorXcd &W, Eigen::Index t)
{
    const Complex a = W(d.triangles(t, 0)), e1 = W(d.triangles(t, 1)) - a,
                  e2 = W(d.triangles(t, 2)) - a;
    return e1.real() * e2.imag() - e1.imag() * e2.real();
}

// Strictly opposite orientation: a triangle collapsed to a segment or a point (pins dragged
// onto one spot) is degenerate, not inside out, and no relaxation can open it.
bool flipped(const ArapPrecompute &d, const Eigen::VectorXcd &W, Eigen::Index t)
{
    return signedDoubleArea(d, W, t) * d.restDoubleArea(t) < 0.0;
}

// Best rotation of triangle t at W (unit complex number; identity when collapsed).
Complex rotationOf(const ArapPrecompute &d, const Eigen::VectorXcd &W, Eigen::Index t)
{
    Complex r[3], p[3];
    for (int k = 0; k < 3; ++k) {
        r[k] = d.restWeighted(t, k);
        p[k] = W(d.triangles(t, k)) - W(d.triangles(t, 0));
    }
    return bestRotation(r, p, d.collapseThreshold(t));
}

// The energy minimum of free vertex v with everything else fixed: the weighted mean over its
// triangles' two edges at v of "neighbour + rotated rest edge". The weights sum to the
// vertex's diagonal entry of the per-triangle forms, which is positive even where a single
// cotangent weight is negative (½(cot α + cot β) = sin(α + β) / (2 sin α sin β) per triangle).
Complex relaxedPosition(const ArapPrecompute &d, const Eigen::VectorXcd &W, int v)
{
    Complex sum;
    double total = 0.0;
    for (int c = d.vertexStart(v); c < d.vertexStart(v + 1); ++c) {
        const int t = d.vertexTriangle(c);
        const Complex rotation = rotationOf(d, W, t);
        const int k = d.triangles(t, 0) == v ? 0 : d.triangles(t, 1) == v ? 1 : 2;
        for (int j = 1; j < 3; ++j) {
            const int other = (k + j) % 3;
            const double weight = d.edgeWeight(t, 3 - k - other);
            sum += weight * (W(d.triangles(t, other)) +
                             mul(rotation, d.restCentered(t, k) - d.restCentered(t, other)));
            total += weight;
        }
    }
    return total > 0.0 ? sum / total : W(v);
}

// Adds the free vertices of the triangles around the region's vertices, `rings` times.
void grow(const ArapPrecompute &d, Workspace &w, int rings)
{
    for (int ring = 0; ring < rings; ++ring) {
        const std::size_t before = w.region.size();
        for (std::size_t i = 0; i < before; ++i) {
            const int v = w.region[i];
            for (int c = d.vertexStart(v); c < d.vertexStart(v + 1); ++c) {
                for (int k = 0; k < 3; ++k) {
                    const int u = d.triangles(d.vertexTriangle(c), k);
                    if (u < d.freeCount && !w.mark[u]) {
                        w.mark[u] = 1;
                        w.region.push_back(u);
                    }
                }
            }
        }
    }
}

// Flipped triangles around the region's vertices (a triangle counts once per region corner:
// a measure of progress, not a count).
int regionFlips(const ArapPrecompute &d, const Workspace &w)
{
    int count = 0;
    for (const int v : w.region)
        for (int c = d.vertexStart(v); c < d.vertexStart(v + 1); ++c)
            count += flipped(d, w.positions, d.vertexTriangle(c)) ? 1 : 0;
    return count;
}

// The region: the free corners of the flipped triangles (w.mark set for them).
void seedRegion(const ArapPrecompute &d, Workspace &w)
{
    w.mark.assign(std::size_t(d.freeCount), 0);
    w.region.clear();
    for (Eigen::Index t = 0; t < d.triangles.rows(); ++t) {
        if (!flipped(d, w.positions, t))
            continue;
        for (int k = 0; k < 3; ++k) {
            const int v = d.triangles(t, k);
            if (v < d.freeCount && !w.mark[v]) {
                w.mark[v] = 1;
                w.region.push_back(v);
            }
        }
    }
}

namespace {

// Gauss–Seidel sweeps over the region until it holds no flip, or kStall sweeps in a row
// bring no new low (a fold the region cannot undo), or kSweeps, or `budget` vertex updates
// are spent. Returns the flips left.
int relaxRegion(const ArapPrecompute &d, Workspace &w, Eigen::Index &budget)
{
    std::sort(w.region.begin(), w.region.end()); // a fixed sweep order: deterministic
    int fewest = regionFlips(d, w), stalled = 0;
    for (int sweep = 0; sweep < kSweeps && fewest > 0 && stalled < kStall &&
                        budget >= Eigen::Index(w.region.size());
         ++sweep) {
        budget -= Eigen::Index(w.region.size());
        for (const int v : w.region)
            w.positions(v) = relaxedPosition(d, w.positions, v);
        const int flips = regionFlips(d, w);
        stalled = flips < fewest ? 0 : stalled + 1;
        fewest = std::min(fewest, flips);
    }
    return regionFlips(d, w);
}

// A fold that local relaxation cannot open is a local minimum of the energy, and a drag that
// compresses the triangles next to a pinned band often walks into one the converged pose does
// not have (on the 20k-vertex drawings of `finbook-bench arap --quality`, 13 triangles over 7
// drawings after the bend's 30-event drag, each squeezed to 3–20 % of its area in the
// converged pose and turned over by 0.3–7 % in the drag's). The restart takes the region
// around the flips (kRestartRings) to its vertices' neighbour means, kSmoothSweeps times
// (uniform smoothing opens small folds), relaxes it again from there and keeps it only where
// that leaves fewer flips: 7 of the 13 opened (the rest appear in the last events of the drag
// and go with the next event's passes, or sit among the converged pose's own forced folds).
void restartRegion(const ArapPrecompute &d, Workspace &w, Eigen::Index &budget)
{
    seedRegion(d, w);
    if (w.region.empty())
        return;
    grow(d, w, kRestartRings);
    std::sort(w.region.begin(), w.region.end());
    const Eigen::Index size = Eigen::Index(w.region.size());
    if (budget < (kSmoothSweeps + kRestartSweeps) * size) // room to relax what it smoothed
        return;
    budget -= kSmoothSweeps * size;
    const int before = regionFlips(d, w);
    w.saved.resize(Eigen::Index(w.region.size()));
    for (std::size_t i = 0; i < w.region.size(); ++i)
        w.saved(Eigen::Index(i)) = w.positions(w.region[i]);
    for (int sweep = 0; sweep < kSmoothSweeps; ++sweep) {
        for (const int v : w.region) {
            Complex sum;
            int count = 0;
            for (int c = d.vertexStart(v); c < d.vertexStart(v + 1); ++c) {
                const int t = d.vertexTriangle(c);
                for (int k = 0; k < 3; ++k) {
                    const int u = d.triangles(t, k);
                    if (u != v) {
                        sum += w.positions(u);
                        ++count;
                    }
                }
            }
            if (count > 0)
                w.positions(v) = sum / double(count);
        }
    }
    // All the sweeps, not only until the flips are gone: the smoothed region is far from
    // its relaxed shape.
    const int sweeps = int(std::min<Eigen::Index>(kRestartSweeps, budget / size));
    budget -= sweeps * size;
    for (int sweep = 0; sweep < sweeps; ++sweep)
        for (const int v : w.region)
            w.positions(v) = relaxedPosition(d, w.positions, v);
    const int after = regionFlips(d, w);
    if (after < before)
        return;
    for (std::size_t i = 0; i < w.region.size(); ++i)
        w.positions(w.region[i]) = w.saved(Eigen::Index(i));
}

} // namespace

int countFlips(const ArapPrecompute &d, const Eigen::VectorXcd &W)
{
    int count = 0;
    for (Eigen::Index t = 0; t < d.triangles.rows(); ++t)
        count += flipped(d, W, t) ? 1 : 0;
    return count;
}

void repairFlips(const ArapPrecompute &d, Workspace &w, ArapSolveReport &report, bool final)
{
    // Flips the refinement's extra passes already removed count as repaired too.
    const int found = countFlips(d, w.positions);
    const int before = std::max(found, report.repairedTriangles);
    report.flippedTriangles = found;
    report.repairedTriangles = before - found;
    if (found == 0 || d.freeCount == 0)
        return;
    seedRegion(d, w);
    // A wider region only when the last one made progress: a fold forced by the pins stays
    // whatever the region, and must not cost three rounds per drag event.
    int left = std::numeric_limits<int>::max();
    Eigen::Index budget = std::max(kMinUpdates, d.freeCount / kUpdatesPerFree);
    for (int growth = 0; growth < kGrowths && !w.region.empty(); ++growth) {
        grow(d, w, kRingsPerGrowth);
        const int now = relaxRegion(d, w, budget);
        if (now == 0 || now >= left)
            break;
        left = now;
    }
    restartRegion(d, w, budget);
    // The injective finish has a budget of its own: the relaxation may have spent the first.
    if (countFlips(d, w.positions) > 0) {
        Eigen::Index finishBudget = std::max(kMinUpdates, d.freeCount / kUpdatesPerFree);
        untangleFlips(d, w, final ? kFinishCostFinal : kFinishCostDrag, finishBudget);
    }
    report.flippedTriangles = countFlips(d, w.positions);
    report.repairedTriangles = std::max(0, before - report.flippedTriangles);
}

} // namespace finbook::deform::detail
