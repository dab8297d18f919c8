// The injective finish of the flip repair. A fold that local relaxation leaves is a local
// minimum of the ARAP energy (or one the relaxation walks back into); where the pins leave
// room, a corner of a flipped triangle can still sit where all its triangles are upright: in
// the kernel of its one-ring polygon (the intersection of one half-plane per triangle). The
// finish moves such corners to the point of that kernel nearest to them (a quadratic
// programme over the ring's half-planes, solved by enumerating its active sets); where the
// kernel is empty, to where the worst of its flipped triangles is least turned over without
// turning an upright one (a linear programme), which opens room for the neighbours. A few
// rounds over the region let neighbours untangle each other. Then it relaxes the energy with
// Gauss–Seidel steps clamped so that no upright triangle turns over (each step toward the
// vertex's relaxed position shortened to a fraction of the largest step that keeps its
// triangles' areas positive, as in Smith & Schaefer 2015): for fixed rotations the energy is
// a convex quadratic along the step, least at the full step, so a shortened step still
// lowers it. Where folds are left, a free corner of a triangle whose other two corners are
// pinned is pushed over the pinned edge (pushApexes), and what it turns over untangles in turn.
// What the corners' rings do not leave room for stays, as forced by the pins.
#include "arap_flips.h"

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <limits>

namespace finbook::deform::detail {
namespace {

constexpr int kRounds = 10;      // untangling rounds over the flipped triangles' corners
constexpr int kRings = 2;        // rings of the relaxed region around them
constexpr int kRelaxSweeps = 10; // clamped relaxation sweeps
// A clamped step stops at this fraction of the step that would collapse a triangle.
constexpr double kStepFraction = 0.9;
// Margins tried, in order: a corner is placed so that each of its triangles keeps at least
// this fraction of its rest area (scaled by how its opposite edge was stretched), i.e. its
// shape is not squeezed flat; smaller margins only where larger ones leave no room.
constexpr std::array<double, 3> kMargins{0.25, 0.05, 0.005};
// Work of one untangled vertex in vertex updates (its linear programme is the costly part).
constexpr Eigen::Index kUntangleCost = 4;
constexpr int kMaxRing = 16; // vertices with more triangles are left as they are

struct HalfPlane {
    double nx, ny, r; // n·p ≥ r
    bool holds(double x, double y) const
    {
        const double value = nx * x + ny * y;
        return value >= r - 1e-12 * (std::abs(value) + std::abs(r));
    }
};

// The point of {p : n_i·p ≥ r_i} nearest to x0, if the set is not empty: the minimum lies at
// x0, on one boundary line or at a corner of two.
bool nearestInKernel(const HalfPlane *h, int count, Complex x0, Complex &out)
{
    double best = std::numeric_limits<double>::infinity();
    const auto consider = [&](double x, double y) {
        for (int i = 0; i < count; ++i)
            if (!h[i].holds(x, y))
                return;
        const double dist = (x - x0.real()) * (x - x0.real()) + (y - x0.imag()) * (y - x0.imag());
        if (dist < best) {
            best = dist;
            out = Complex(x, y);
        }
    };
    consider(x0.real(), x0.imag());
    if (best == 0.0)
        return true;
    for (int i = 0; i < count; ++i) {
        const double nn = h[i].nx * h[i].nx + h[i].ny * h[i].ny;
        if (nn <= 0.0)
            continue;
        const double s = (h[i].r - h[i].nx * x0.real() - h[i].ny * x0.imag()) / nn;
        consider(x0.real() + s * h[i].nx, x0.imag() + s * h[i].ny);
        for (int j = i + 1; j < count; ++j) {
            const double det = h[i].nx * h[j].ny - h[i].ny * h[j].nx;
            if (std::abs(det) <= 1e-14 * nn)
                continue;
            consider((h[i].r * h[j].ny - h[i].ny * h[j].r) / det,
                     (h[i].nx * h[j].r - h[i].r * h[j].nx) / det);
        }
    }
    return best < std::numeric_limits<double>::infinity();
}

// Corner k of triangle t is v: its other corners a, b (in the triangle's order), and the
// orientation s (±1) the rest triangle has in that order. With v at p the triangle's doubled
// signed area is cross(a − p, b − p), which changes by cross(b − a, δ) when p moves by δ.
struct Opposite {
    Complex a, b;
    double s;
    int k;
};

Opposite opposite(const ArapPrecompute &d, const Eigen::VectorXcd &W, int t, int v)
{
    const int k = d.triangles(t, 0) == v ? 0 : d.triangles(t, 1) == v ? 1 : 2;
    return {W(d.triangles(t, (k + 1) % 3)), W(d.triangles(t, (k + 2) % 3)),
            d.restDoubleArea(t) > 0.0 ? 1.0 : -1.0, k};
}

double cross(Complex u, Complex v)
{
    return u.real() * v.imag() - u.imag() * v.real();
}

// Triangle c of v's ring as a function of v's move δ (from W(v): no cancellation between
// large coordinates): its doubled signed area in the rest orientation, s·cross(a − p, b − p)
// = r + n·δ, and `scale`, the rest triangle's doubled area scaled by how much the edge
// opposite v was stretched (a relative area (r + n·δ) / scale of 1 is the rest shape's
// height over that edge).
struct RingTriangle {
    double nx, ny, r, scale;
};

int ringOf(const ArapPrecompute &d, const Eigen::VectorXcd &W, int v, RingTriangle *ring)
{
    const int first = d.vertexStart(v), count = d.vertexStart(v + 1) - first;
    if (count > kMaxRing)
        return 0;
    for (int c = 0; c < count; ++c) {
        const int t = d.vertexTriangle(first + c);
        const Opposite o = opposite(d, W, t, v);
        const Complex e = o.b - o.a;
        const Complex rest = d.restCentered(t, (o.k + 2) % 3) - d.restCentered(t, (o.k + 1) % 3);
        // cross(e, δ) = (−e.y, e.x)·δ
        ring[c] = {-o.s * e.imag(), o.s * e.real(), o.s * cross(o.a - W(v), o.b - W(v)),
                   std::abs(d.restDoubleArea(t)) * squaredMagnitude(e) / squaredMagnitude(rest)};
    }
    return count;
}

// Where the kernel is empty: the position that maximises the smallest relative area of v's
// flipped triangles while its upright ones stay upright (keep at least the area they have, up
// to the smallest margin), a linear programme in p and that area t, solved at the corners of
// three of its constraints. It turns the worst triangle back as far as the ring allows,
// which opens room for its neighbours, and never turns another one over.
bool bestWorstArea(const RingTriangle *ring, int count, Complex &out)
{
    constexpr double cap = kMargins.back();
    // Rows (a, b, c, e): a·x + b·y + c·t ≥ e.
    std::array<Eigen::Vector4d, kMaxRing + 1> rows;
    int n = 0;
    double current = cap;
    for (int c = 0; c < count; ++c) {
        const RingTriangle &q = ring[c];
        const double area = q.r / q.scale;
        if (area > 0.0) {
            rows[std::size_t(n++)] << q.nx, q.ny, 0.0, (0.5 * std::min(area, cap) - area) * q.scale;
        } else {
            rows[std::size_t(n++)] << q.nx, q.ny, -q.scale, -q.r;
            current = std::min(current, area);
        }
    }
    if (current >= cap)
        return false;
    rows[std::size_t(n++)] << 0.0, 0.0, -1.0, -cap;
    const auto feasible = [&](const Eigen::Vector3d &x) {
        for (int i = 0; i < n; ++i) {
            const Eigen::Vector4d &r = rows[std::size_t(i)];
            const double value = r(0) * x(0) + r(1) * x(1) + r(2) * x(2);
            if (value < r(3) - 1e-9 * (std::abs(value) + std::abs(r(3))))
                return false;
        }
        return true;
    };
    double best = current, bestDistance = 0.0;
    bool found = false;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            for (int k = j + 1; k < n; ++k) {
                Eigen::Matrix3d A;
                Eigen::Vector3d e;
                const int pick[3] = {i, j, k};
                for (int m = 0; m < 3; ++m) {
                    A.row(m) = rows[std::size_t(pick[m])].head<3>().transpose();
                    e(m) = rows[std::size_t(pick[m])](3);
                }
                const double det = A.determinant();
                const double size = A.cwiseAbs().maxCoeff();
                if (std::abs(det) <= 1e-12 * size * size * size)
                    continue;
                const Eigen::Vector3d x = A.inverse() * e;
                if (!feasible(x))
                    continue;
                const double distance = x(0) * x(0) + x(1) * x(1); // tie-break: the nearest
                if (x(2) > best + 1e-12 ||
                    (found && x(2) >= best - 1e-12 && distance < bestDistance)) {
                    best = std::max(best, x(2));
                    bestDistance = distance;
                    out = Complex(x(0), x(1));
                    found = true;
                }
            }
    return found;
}

// Moves free vertex v into the kernel of its one-ring (the point nearest to it with the
// largest margin that fits); where the kernel is empty, to where its worst flipped triangle
// is least turned over. False when v stays.
bool untangleVertex(const ArapPrecompute &d, Eigen::VectorXcd &W, int v)
{
    RingTriangle ring[kMaxRing];
    const int count = ringOf(d, W, v, ring);
    if (count == 0)
        return false;
    for (const double margin : kMargins) {
        HalfPlane h[kMaxRing];
        for (int c = 0; c < count; ++c)
            h[c] = {ring[c].nx, ring[c].ny, margin * ring[c].scale - ring[c].r};
        Complex p;
        if (nearestInKernel(h, count, Complex(0.0, 0.0), p)) {
            W(v) += p;
            return true;
        }
    }
    Complex p;
    if (!bestWorstArea(ring, count, p))
        return false;
    W(v) += p;
    return true;
}

bool touchesFlip(const ArapPrecompute &d, const Eigen::VectorXcd &W, int v)
{
    for (int c = d.vertexStart(v); c < d.vertexStart(v + 1); ++c)
        if (flipped(d, W, d.vertexTriangle(c)))
            return true;
    return false;
}

// One Gauss–Seidel step of v toward its relaxed position, shortened so that none of its
// upright triangles turns over: each keeps (1 − kStepFraction) of its area, and at least the
// smallest margin's (repeated steps of a fixed fraction would squeeze a triangle to round-off,
// where the next step's sign is noise).
void clampedStep(const ArapPrecompute &d, Eigen::VectorXcd &W, int v)
{
    const Complex step = relaxedPosition(d, W, v) - W(v);
    double fraction = 1.0;
    for (int c = d.vertexStart(v); c < d.vertexStart(v + 1); ++c) {
        const int t = d.vertexTriangle(c);
        const Opposite o = opposite(d, W, t, v);
        const double area = o.s * cross(o.a - W(v), o.b - W(v));
        if (area <= 0.0)
            continue; // already flipped or collapsed: free to open
        const double slope = o.s * cross(o.b - o.a, step);
        if (slope >= 0.0)
            continue;
        const Complex rest = d.restCentered(t, (o.k + 2) % 3) - d.restCentered(t, (o.k + 1) % 3);
        const double floor = kMargins.back() * std::abs(d.restDoubleArea(t)) *
                             squaredMagnitude(o.b - o.a) / squaredMagnitude(rest);
        const double keep = std::max((1.0 - kStepFraction) * area, floor);
        fraction = std::min(fraction, std::max(0.0, area - keep) / -slope);
    }
    W(v) += fraction * step;
}

// The energy of the triangles around the region (each once: at its first corner in it).
double regionEnergy(const ArapPrecompute &d, const Workspace &w)
{
    double energy = 0.0;
    for (const int v : w.region)
        for (int c = d.vertexStart(v); c < d.vertexStart(v + 1); ++c) {
            const int t = d.vertexTriangle(c);
            int firstInRegion = -1;
            for (int k = 0; k < 3 && firstInRegion < 0; ++k) {
                const int u = d.triangles(t, k);
                if (u < d.freeCount && w.mark[std::size_t(u)])
                    firstInRegion = u;
            }
            if (firstInRegion != v)
                continue;
            const Complex rotation = rotationOf(d, w.positions, t);
            for (int k = 0; k < 3; ++k) {
                const int i = (k + 1) % 3, j = (k + 2) % 3;
                const Complex edge =
                    w.positions(d.triangles(t, j)) - w.positions(d.triangles(t, i));
                energy += d.edgeWeight(t, k) *
                          squaredMagnitude(
                              edge - mul(rotation, d.restCentered(t, j) - d.restCentered(t, i)));
            }
        }
    return energy;
}

// The flipped triangles around the region, ascending and once each.
void flippedAround(const ArapPrecompute &d, const Workspace &w, std::vector<int> &out)
{
    out.clear();
    for (const int v : w.region)
        for (int c = d.vertexStart(v); c < d.vertexStart(v + 1); ++c)
            if (flipped(d, w.positions, d.vertexTriangle(c)))
                out.push_back(d.vertexTriangle(c));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

// Untangling rounds over the corners of the flipped triangles, then clamped sweeps.
void untangleRegion(const ArapPrecompute &d, Workspace &w)
{
    for (int round = 0; round < kRounds; ++round) {
        bool moved = false;
        for (const int v : w.region)
            if (touchesFlip(d, w.positions, v))
                moved = untangleVertex(d, w.positions, v) || moved;
        if (!moved)
            break;
    }
    for (int sweep = 0; sweep < kRelaxSweeps; ++sweep)
        for (const int v : w.region)
            clampedStep(d, w.positions, v);
}

// The free corner of each flipped triangle with two pinned corners, put where the pinned
// edge's similarity takes its rest position (the triangle upright in its rest shape). Its
// other triangles may turn over: their corners, free to move, then untangle. False when
// there is no such triangle.
bool pushApexes(const ArapPrecompute &d, Workspace &w, const std::vector<int> &flips)
{
    bool moved = false;
    for (const int t : flips) {
        int free = -1, pinned = 0;
        for (int k = 0; k < 3; ++k) {
            if (d.triangles(t, k) >= d.freeCount)
                ++pinned;
            else
                free = k;
        }
        if (pinned != 2 || !flipped(d, w.positions, t))
            continue;
        const int a = (free + 1) % 3, b = (free + 2) % 3;
        const Complex rest = d.restCentered(t, b) - d.restCentered(t, a);
        if (!(squaredMagnitude(rest) > 0.0))
            continue;
        const Complex pa = w.positions(d.triangles(t, a));
        const Complex similarity = (w.positions(d.triangles(t, b)) - pa) / rest;
        w.positions(d.triangles(t, free)) =
            pa + similarity * (d.restCentered(t, free) - d.restCentered(t, a));
        moved = true;
    }
    return moved;
}

} // namespace

void untangleFlips(const ArapPrecompute &d, Workspace &w, double maxCost, Eigen::Index &budget)
{
    seedRegion(d, w);
    if (w.region.empty())
        return;
    const Eigen::Index corners = Eigen::Index(w.region.size());
    grow(d, w, kRings);
    std::sort(w.region.begin(), w.region.end());
    const Eigen::Index size = Eigen::Index(w.region.size());
    const Eigen::Index work = kRounds * corners * kUntangleCost + kRelaxSweeps * size;
    if (budget < work)
        return;
    budget -= work;
    std::vector<int> &before = w.untangleFlipped;
    flippedAround(d, w, before);
    const double energyBefore = regionEnergy(d, w);
    w.saved.resize(size);
    for (Eigen::Index i = 0; i < size; ++i)
        w.saved(i) = w.positions(w.region[std::size_t(i)]);
    untangleRegion(d, w);
    // Kept with fewer flips than `fewest`, none of them new (by construction; checked all
    // the same), and at most maxCost of the energy more.
    std::vector<int> &after = w.untangleLeft;
    const auto better = [&](std::size_t fewest) {
        flippedAround(d, w, after);
        return after.size() < fewest &&
               std::includes(before.begin(), before.end(), after.begin(), after.end()) &&
               regionEnergy(d, w) - energyBefore <= maxCost * w.refinedEnergy;
    };
    std::size_t fewest = before.size();
    if (better(fewest))
        fewest = after.size();
    else
        for (Eigen::Index i = 0; i < size; ++i)
            w.positions(w.region[std::size_t(i)]) = w.saved(i);
    // A free corner between a pinned edge and free neighbours that leave it no room (a cold
    // drag event's first passes leave such folds next to a pinned band) stays folded: its
    // neighbours touch no flip and are never untangled. Pushed over the pinned edge, it
    // turns them over instead, and they untangle in turn where they have room. Tried only
    // where flips are left, and kept only with fewer.
    if (fewest == 0 || budget < work)
        return;
    w.pushSaved.resize(size);
    for (Eigen::Index i = 0; i < size; ++i)
        w.pushSaved(i) = w.positions(w.region[std::size_t(i)]);
    flippedAround(d, w, after);
    if (!pushApexes(d, w, after))
        return;
    budget -= work;
    untangleRegion(d, w);
    if (better(fewest))
        return;
    for (Eigen::Index i = 0; i < size; ++i)
        w.positions(w.region[std::size_t(i)]) = w.pushSaved(i);
}

} // namespace finbook::deform::detail
