// Tone regions traced as contours, smoothed and clipped (shade/tone_region.h).
#include "../clipper_bridge.h"
#include "ring_clip.h"

#include <finbook/geometry/shade/tone_region.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace finbook::geometry {

namespace {
// Taubin's pair: a smoothing step, then a slightly larger inflating one.
constexpr double kLambda = 0.5;
constexpr double kMu = -0.53;
// Outline runs of a ring that is clipped are thinned to this (px).
constexpr double kOutlineTolerance = 0.25;

struct ToneRing {
    std::vector<Eigen::Vector2d> points;
    std::vector<char> movable; // a contour vertex inside the mesh
};

void smoothRing(ToneRing &ring, int steps)
{
    const std::size_t n = ring.points.size();
    if (n < 3 || steps <= 0)
        return;
    thread_local std::vector<Eigen::Vector2d> next;
    next.resize(n);
    for (int step = 0; step < 2 * steps; ++step) {
        const double w = step % 2 == 0 ? kLambda : kMu;
        // Neighbours walked along rather than found by index mod n (a division per vertex).
        std::size_t before = n - 1;
        for (std::size_t i = 0, after = 1; i < n;
             before = i++, after = after + 1 < n ? after + 1 : 0) {
            const Eigen::Vector2d &p = ring.points[i];
            if (!ring.movable[i]) {
                next[i] = p;
                continue;
            }
            next[i] = p + w * (0.5 * (ring.points[before] + ring.points[after]) - p);
        }
        ring.points.swap(next);
    }
}

// Thins the runs along the mesh's outline (the fixed vertices) to `tolerance` (Douglas–Peucker;
// a run's ends stay), pushed out by as much first: Clipper's cost grows with the vertices it is
// given, and where the tone meets the outline the fill's own outline (the clip) and the ink decide
// what shows.
void thinOutlineRuns(ToneRing &ring, double tolerance)
{
    const std::size_t n = ring.points.size();
    std::size_t start = 0;
    while (start < n && !ring.movable[start])
        ++start;
    if (start == n)
        return; // no contour vertex: the ring is all outline; keep it
    // Pushed out by the tolerance first (to the right of the way round: the set lies on the
    // left), so the thinned run still holds the outline: the clip, not the thinning, cuts it.
    const auto wrap = [n](std::size_t i) { return i < n ? i : i - n; }; // i < 2n
    thread_local std::vector<Eigen::Vector2d> pushed;
    pushed = ring.points;
    for (std::size_t k = 0; k < n; ++k) {
        if (ring.movable[k])
            continue;
        const Eigen::Vector2d d = ring.points[wrap(k + 1)] - ring.points[wrap(k + n - 1)];
        const double length = d.norm();
        if (length > 1e-12)
            pushed[k] += tolerance / length * Eigen::Vector2d(d.y(), -d.x());
    }
    ring.points.swap(pushed);
    thread_local std::vector<char> keep;
    keep.assign(n, 1);
    const auto thin = [&](auto &&self, std::size_t a, std::size_t b) -> void {
        // Run a → b (indices mod n, b after a), both kept.
        const Eigen::Vector2d &p = ring.points[wrap(a)], &q = ring.points[wrap(b)];
        const Eigen::Vector2d d = q - p;
        const double length = d.norm();
        double worst = -1.0;
        std::size_t at = a;
        for (std::size_t i = a + 1; i < b; ++i) {
            const Eigen::Vector2d r = ring.points[wrap(i)] - p;
            const double off =
                length > 1e-12 ? std::abs(d.x() * r.y() - d.y() * r.x()) / length : r.norm();
            if (off > worst) {
                worst = off;
                at = i;
            }
        }
        if (worst <= tolerance) {
            for (std::size_t i = a + 1; i < b; ++i)
                keep[wrap(i)] = 0;
            return;
        }
        self(self, a, at);
        self(self, at, b);
    };
    // Walk once round from a contour vertex; a run is the fixed vertices between two movable
    // ones (the run's ends, where the contour meets the outline, are fixed and kept).
    std::size_t i = start;
    for (std::size_t step = 0; step < n;) {
        std::size_t j = i + 1;
        while (j < start + n && !ring.movable[wrap(j)])
            ++j;
        // i and j are contour vertices (or j wrapped to start); the run is i + 1 … j − 1.
        if (j - i > 3)
            thin(thin, i + 1, j - 1);
        step += j - i;
        i = j;
    }
    std::size_t w = 0;
    for (std::size_t k = 0; k < n; ++k)
        if (keep[k]) {
            ring.points[w] = ring.points[k];
            ring.movable[w] = ring.movable[k];
            ++w;
        }
    ring.points.resize(w);
    ring.movable.resize(w);
}

Pieces toPieces(const ToneRing *rings, std::size_t count)
{
    Pieces out;
    for (std::size_t r = 0; r < count; ++r) {
        out.points.insert(out.points.end(), rings[r].points.begin(), rings[r].points.end());
        out.starts.push_back(int(out.points.size()));
    }
    return out;
}

Pieces clipRings(const ToneRing *rings, std::size_t count,
                 const std::vector<Eigen::MatrixX2d> &clip)
{
    // The clip's finite points (Clipper is given the same), for the test and the frame.
    thread_local std::vector<std::vector<Eigen::Vector2d>> window;
    std::size_t windows = 0;
    for (const Eigen::MatrixX2d &ring : clip) {
        if (windows == window.size())
            window.emplace_back();
        std::vector<Eigen::Vector2d> &w = window[windows];
        w.clear();
        for (Eigen::Index i = 0; i < ring.rows(); ++i)
            if (ring.row(i).allFinite())
                w.emplace_back(ring(i, 0), ring(i, 1));
        if (w.size() >= 3)
            ++windows;
    }
    window.resize(windows);
    if (windows == 1) { // a fill without holes: cut directly where the outlines cross cleanly
        thread_local std::vector<const std::vector<Eigen::Vector2d> *> subjectRings;
        subjectRings.resize(count);
        for (std::size_t r = 0; r < count; ++r)
            subjectRings[r] = &rings[r].points;
        Pieces out;
        if (shade_detail::clipToRing(subjectRings.data(), count, window.front(), out))
            return out;
    }
    Eigen::RowVector2d lo(std::numeric_limits<double>::infinity(),
                          std::numeric_limits<double>::infinity());
    for (std::size_t r = 0; r < count; ++r)
        for (const Eigen::Vector2d &p : rings[r].points)
            lo = lo.cwiseMin(p.transpose());
    for (const auto &ring : window)
        for (const Eigen::Vector2d &p : ring)
            lo = lo.cwiseMin(p.transpose());
    const detail::ClipperFrame frame = detail::frameFor(lo);
    // Kept per thread with their capacity: re-shading clips a few rings per fill and frame.
    thread_local ClipperLib::Paths subject, paths, solution;
    const auto fill = [&frame](ClipperLib::Path &path, const std::vector<Eigen::Vector2d> &ring) {
        path.clear();
        for (const Eigen::Vector2d &p : ring) {
            const ClipperLib::IntPoint q(frame.units(p.x() - frame.origin.x()),
                                         frame.units(p.y() - frame.origin.y()));
            if (path.empty() || !(path.back() == q))
                path.push_back(q);
        }
    };
    subject.resize(count);
    for (std::size_t r = 0; r < count; ++r)
        fill(subject[r], rings[r].points);
    paths.resize(window.size());
    for (std::size_t r = 0; r < window.size(); ++r)
        fill(paths[r], window[r]);
    try {
        ClipperLib::Clipper clipper;
        clipper.AddPaths(subject, ClipperLib::ptSubject, true);
        clipper.AddPaths(paths, ClipperLib::ptClip, true);
        clipper.Execute(ClipperLib::ctIntersection, solution, ClipperLib::pftNonZero,
                        ClipperLib::pftNonZero);
    } catch (const std::exception &) {
        return {}; // nothing rather than a tone past its fill
    }
    Pieces out;
    for (const ClipperLib::Path &path : solution) {
        if (path.size() < 3)
            continue;
        for (const ClipperLib::IntPoint &q : path)
            out.points.emplace_back(frame.pixels(double(q.X)) + frame.origin.x(),
                                    frame.pixels(double(q.Y)) + frame.origin.y());
        out.starts.push_back(int(out.points.size()));
    }
    return out;
}
} // namespace

MeshEdges meshEdges(const Eigen::MatrixX3i &F)
{
    MeshEdges out;
    const Eigen::Index m = F.rows();
    out.edge.resize(m, 3);
    out.neighbour.setConstant(m, 3, -1);
    // Half-edges sorted by their undirected key: the two sides of an edge end up adjacent.
    std::vector<std::pair<std::uint64_t, int>> halves;
    halves.reserve(std::size_t(3 * m));
    for (Eigen::Index f = 0; f < m; ++f)
        for (int k = 0; k < 3; ++k) {
            const auto a = std::uint32_t(F(f, k)), b = std::uint32_t(F(f, (k + 1) % 3));
            const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
            halves.emplace_back(key, int(3 * f + k));
        }
    std::sort(halves.begin(), halves.end());
    int count = 0;
    for (std::size_t i = 0; i < halves.size();) {
        std::size_t j = i + 1;
        while (j < halves.size() && halves[j].first == halves[i].first)
            ++j;
        for (std::size_t h = i; h < j; ++h)
            out.edge(halves[h].second / 3, halves[h].second % 3) = count;
        if (j - i == 2) { // a manifold interior edge; more sides than two count as outline
            const int p = halves[i].second, q = halves[i + 1].second;
            out.neighbour(p / 3, p % 3) = q / 3;
            out.neighbour(q / 3, q % 3) = p / 3;
        }
        ++count;
        i = j;
    }
    out.edgeCount = count;
    return out;
}

Pieces toneRegion(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F, const MeshEdges &edges,
                  const Eigen::VectorXd &value, double threshold,
                  const std::vector<Eigen::MatrixX2d> &clip, const ToneOptions &options)
{
    const Eigen::Index n = V.rows(), m = F.rows();
    if (edges.edge.rows() != m || edges.neighbour.rows() != m || value.size() < n)
        return {};
    // Scratch kept per thread: re-shading calls this a few times per fill and frame.
    thread_local std::vector<char> state, valid, crossed, inside, used;
    thread_local std::vector<Eigen::Vector2d> crossing;
    thread_local std::vector<std::pair<int, int>> segments; // boundary segments (from, to)
    thread_local std::vector<int> first, out, fill;
    // Per vertex once (not per corner): 0 not finite, 1 below the threshold, 2 at or above.
    state.resize(std::size_t(n));
    for (Eigen::Index v = 0; v < n; ++v)
        state[std::size_t(v)] =
            std::isfinite(V(v, 0)) && std::isfinite(V(v, 1)) && std::isfinite(value(v))
                ? (value(v) >= threshold ? 2 : 1)
                : 0;
    valid.assign(std::size_t(m), 0);
    for (Eigen::Index f = 0; f < m; ++f) {
        bool ok = true;
        for (int k = 0; k < 3 && ok; ++k) {
            const int v = F(f, k);
            ok = v >= 0 && v < n && state[std::size_t(v)] != 0;
        }
        valid[std::size_t(f)] = ok ? 1 : 0;
    }
    // Points: vertex v is v, the crossing on edge e is n + e.
    const int edgeCount = edges.edgeCount;
    crossing.resize(std::size_t(edgeCount));
    crossed.assign(std::size_t(edgeCount), 0);
    inside.assign(std::size_t(edgeCount), 0);
    segments.clear();
    int items[6], label[6];
    for (Eigen::Index f = 0; f < m; ++f) {
        if (!valid[std::size_t(f)])
            continue;
        bool in[3];
        int above = 0;
        for (int k = 0; k < 3; ++k) {
            in[k] = state[std::size_t(F(f, k))] == 2;
            above += in[k] ? 1 : 0;
        }
        if (above == 0)
            continue;
        int count = 0;
        for (int k = 0; k < 3; ++k) {
            const int next = (k + 1) % 3;
            if (in[k]) {
                items[count] = F(f, k);
                label[count++] = k; // along edge k
            }
            if (in[k] != in[next]) {
                const int e = edges.edge(f, k);
                if (!crossed[std::size_t(e)]) {
                    // The same point from both sides: interpolate from the lower vertex.
                    const int a = std::min(F(f, k), F(f, next)), b = std::max(F(f, k), F(f, next));
                    const double t = (threshold - value(a)) / (value(b) - value(a));
                    crossing[std::size_t(e)] =
                        (V.row(a) + std::clamp(t, 0.0, 1.0) * (V.row(b) - V.row(a))).transpose();
                    crossed[std::size_t(e)] = 1;
                    const int across = edges.neighbour(f, k);
                    inside[std::size_t(e)] = across >= 0 && valid[std::size_t(across)] ? 1 : 0;
                }
                items[count] = int(n) + e;
                label[count++] = in[next] ? k : -1; // entering: along edge k; leaving: contour
            }
        }
        for (int i = 0; i < count; ++i) {
            const int along = label[i];
            const int across = along >= 0 ? edges.neighbour(f, along) : -1;
            if (along < 0 || across < 0 || !valid[std::size_t(across)])
                segments.emplace_back(items[i], items[(i + 1) % count]);
        }
    }
    if (segments.empty())
        return {};
    // Chain the segments into rings: each point's outgoing segments, in compressed rows.
    const std::size_t points = std::size_t(n) + std::size_t(edgeCount);
    first.assign(points + 1, 0);
    out.resize(segments.size());
    for (const auto &s : segments)
        ++first[std::size_t(s.first) + 1];
    for (std::size_t p = 0; p < points; ++p)
        first[p + 1] += first[p];
    {
        fill.assign(first.begin(), first.end() - 1);
        for (std::size_t s = 0; s < segments.size(); ++s)
            out[std::size_t(fill[std::size_t(segments[s].first)]++)] = int(s);
    }
    used.assign(segments.size(), 0);
    const auto position = [&](int id) -> Eigen::Vector2d {
        return id < n ? Eigen::Vector2d(V(id, 0), V(id, 1)) : crossing[std::size_t(id - n)];
    };
    // Rings reused with their capacity; `count` of them are this call's.
    thread_local std::vector<ToneRing> rings;
    std::size_t count = 0;
    for (std::size_t s0 = 0; s0 < segments.size(); ++s0) {
        if (used[s0])
            continue;
        if (count == rings.size())
            rings.emplace_back();
        ToneRing &ring = rings[count];
        ring.points.clear();
        ring.movable.clear();
        std::size_t s = s0;
        while (true) {
            used[s] = 1;
            const int from = segments[s].first;
            ring.points.push_back(position(from));
            ring.movable.push_back(from >= n && inside[std::size_t(from - n)] ? 1 : 0);
            const int to = segments[s].second;
            std::size_t nextSegment = segments.size();
            for (int o = first[std::size_t(to)]; o < first[std::size_t(to) + 1]; ++o)
                if (!used[std::size_t(out[std::size_t(o)])]) {
                    nextSegment = std::size_t(out[std::size_t(o)]);
                    break;
                }
            if (nextSegment == segments.size())
                break;
            s = nextSegment;
        }
        if (ring.points.size() >= 3) {
            smoothRing(ring, options.smoothingSteps);
            ++count;
        }
    }
    if (clip.empty())
        return toPieces(rings.data(), count);
    for (std::size_t r = 0; r < count; ++r)
        thinOutlineRuns(rings[r], kOutlineTolerance);
    return clipRings(rings.data(), count, clip);
}

double ringsArea(const Pieces &rings)
{
    double area = 0.0;
    for (int k = 0; k < rings.count(); ++k) {
        const int begin = rings.starts[std::size_t(k)], end = rings.starts[std::size_t(k) + 1];
        for (int i = begin; i < end; ++i) {
            const Eigen::Vector2d &a = rings.points[std::size_t(i)];
            const Eigen::Vector2d &b = rings.points[std::size_t(i + 1 < end ? i + 1 : begin)];
            area += 0.5 * (a.x() * b.y() - b.x() * a.y());
        }
    }
    return area;
}

} // namespace finbook::geometry
