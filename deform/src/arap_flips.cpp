// Flip detection and repair. ARAP does not prevent inversion, and an unconverged pose (the
// paper's two steps, a drag pose) folds triangles that the ARAP optimum keeps upright,
// typically a few next to a pin under compression. The repair relaxes the ARAP energy
// locally around them: Gauss–Seidel over the free vertices of a small region, each vertex
// moved to its energy minimum given its neighbours with the rotations of its triangles
// refitted first (in the precompute's weights: the cotangent ARAP energy for Refined). Each update
// lowers (never raises) the energy, so the repair can only bring the pose closer to the optimum; a
// fold that survives it is taken as forced by the pins.
#include "arap_solver.h"

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

} // namespace

int countFlips(const ArapPrecompute &d, const Eigen::VectorXcd &W)
{
    int count = 0;
    for (Eigen::Index t = 0; t < d.triangles.rows(); ++t)
        count += flipped(d, W, t) ? 1 : 0;
    return count;
}

void repairFlips(const ArapPrecompute &d, Workspace &w, ArapSolveReport &report)
{
    // Flips the refinement's extra passes already removed count as repaired too.
    const int found = countFlips(d, w.positions);
    const int before = std::max(found, report.repairedTriangles);
    report.flippedTriangles = found;
    report.repairedTriangles = before - found;
    if (found == 0 || d.freeCount == 0)
        return;
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
    report.flippedTriangles = countFlips(d, w.positions);
    report.repairedTriangles = std::max(0, before - report.flippedTriangles);
}

} // namespace finbook::deform::detail
