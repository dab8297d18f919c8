// Tone rings cut to a one-ring fill outline without a polygon boolean (ring_clip.h).
#include "ring_clip.h"

#include <algorithm>
#include <limits>

namespace finbook::geometry::shade_detail {

namespace {
using Point = Eigen::Vector2d;
using Ring = std::vector<Point>;

// Twice the signed area (shoelace).
double twiceArea(const Ring &ring)
{
    double area = 0.0;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
        area += ring[j].x() * ring[i].y() - ring[i].x() * ring[j].y();
    return area;
}

// Winding number of the closed ring around p (Sunday's crossing rule).
int winding(const Ring &ring, const Point &p)
{
    int w = 0;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        const Point &a = ring[j], &b = ring[i];
        const double side = (b.x() - a.x()) * (p.y() - a.y()) - (p.x() - a.x()) * (b.y() - a.y());
        if (a.y() <= p.y()) {
            if (b.y() > p.y() && side > 0.0)
                ++w;
        } else if (b.y() <= p.y() && side < 0.0) {
            --w;
        }
    }
    return w;
}

double cross(const Point &o, const Point &u, const Point &v)
{
    return (u.x() - o.x()) * (v.y() - o.y()) - (u.y() - o.y()) * (v.x() - o.x());
}

struct Box {
    Point lo, hi;
    bool meets(const Box &o) const
    {
        return lo.x() <= o.hi.x() && o.lo.x() <= hi.x() && lo.y() <= o.hi.y() && o.lo.y() <= hi.y();
    }
};

struct Crossing {
    int ring = 0, edge = 0; // on the tone: ring, edge (from point `edge` to the next)
    double t = 0.0;         // along that edge
    int clipEdge = 0;
    double u = 0.0; // along the clip's edge
    Point p;
};

// Appends the piece of `ring` from the crossing `start` (on edge ea at ta) forward to the
// crossing on edge eb at tb, without that end (the next piece starts there).
void appendPiece(const Ring &ring, const Point &start, int ea, double ta, int eb, double tb,
                 Ring &into)
{
    const int n = int(ring.size());
    int steps = (eb - ea + n) % n;
    if (steps == 0 && !(eb == ea && tb > ta))
        steps = n; // round the whole ring back to the same edge
    into.push_back(start);
    for (int s = 1; s <= steps; ++s)
        into.push_back(ring[std::size_t((ea + s) % n)]);
}

// The midpoint of the piece's first stretch (inside or outside the other outline, as all
// of the piece is).
Point pieceProbe(const Ring &ring, const Point &start, int ea, double ta, int eb, double tb,
                 const Point &end)
{
    const int n = int(ring.size());
    const Point next = (eb == ea && tb > ta) ? end : ring[std::size_t((ea + 1) % n)];
    return 0.5 * (start + next);
}
} // namespace

bool clipToRing(const std::vector<Eigen::Vector2d> *const *rings, std::size_t count,
                const std::vector<Eigen::Vector2d> &clip, Pieces &out)
{
    // Scratch kept per thread (re-shading cuts a few tones per fill and frame).
    thread_local std::vector<Ring> S;
    thread_local Ring C, traced;
    thread_local std::vector<Crossing> crossings;
    thread_local std::vector<int> bySubject, byClip, sNext, cNext, sIn, cIn, sUsed, cUsed, perRing;
    // Both outlines wound positive (outer rings; the tone's holes then run the other way).
    double area = 0.0;
    S.resize(count);
    for (std::size_t r = 0; r < count; ++r) {
        S[r] = *rings[r];
        if (S[r].size() < 3)
            return false;
        area += twiceArea(S[r]);
    }
    if (area < 0.0)
        for (Ring &ring : S)
            std::reverse(ring.begin(), ring.end());
    C.clear();
    for (const Point &p : clip)
        if (C.empty() || C.back() != p)
            C.push_back(p);
    while (C.size() > 1 && C.back() == C.front())
        C.pop_back();
    if (C.size() < 3)
        return false;
    const double clipArea = twiceArea(C);
    if (clipArea == 0.0)
        return false;
    if (clipArea < 0.0)
        std::reverse(C.begin(), C.end());
    const auto insideClip = [](const Point &p) { return winding(C, p) != 0; };
    const auto insideTone = [](const Point &p) {
        int w = 0;
        for (const Ring &ring : S)
            w += winding(ring, p);
        return w != 0;
    };

    // Every crossing of a tone edge with a clip edge; touching or collinear gives up.
    crossings.clear();
    Box all{Point::Constant(std::numeric_limits<double>::infinity()),
            Point::Constant(-std::numeric_limits<double>::infinity())};
    for (const Ring &ring : S)
        for (const Point &p : ring) {
            all.lo = all.lo.cwiseMin(p);
            all.hi = all.hi.cwiseMax(p);
        }
    const int cn = int(C.size());
    for (int j = 0; j < cn; ++j) {
        const Point &a = C[std::size_t(j)], &b = C[std::size_t((j + 1) % cn)];
        const Box edge{a.cwiseMin(b), a.cwiseMax(b)};
        if (!edge.meets(all))
            continue;
        for (std::size_t r = 0; r < count; ++r) {
            const Ring &ring = S[r];
            const int n = int(ring.size());
            for (int k = 0; k < n; ++k) {
                const Point &p = ring[std::size_t(k)],
                            &q = ring[std::size_t(k + 1 < n ? k + 1 : 0)];
                if (!Box{p.cwiseMin(q), p.cwiseMax(q)}.meets(edge))
                    continue;
                const double d1 = cross(a, b, p), d2 = cross(a, b, q);
                if ((d1 > 0.0 && d2 > 0.0) || (d1 < 0.0 && d2 < 0.0))
                    continue;
                const double d3 = cross(p, q, a), d4 = cross(p, q, b);
                if ((d3 > 0.0 && d4 > 0.0) || (d3 < 0.0 && d4 < 0.0))
                    continue;
                if (d1 == 0.0 || d2 == 0.0 || d3 == 0.0 || d4 == 0.0)
                    return false; // touching, through a vertex or along an edge
                const double t = d1 / (d1 - d2);
                crossings.push_back({int(r), k, t, j, d3 / (d3 - d4), p + t * (q - p)});
            }
        }
    }

    const auto appendRing = [&out](const Ring &ring) {
        if (ring.size() < 3)
            return;
        out.points.insert(out.points.end(), ring.begin(), ring.end());
        out.starts.push_back(int(out.points.size()));
    };
    const int m = int(crossings.size());
    if (m % 2 != 0)
        return false;
    // Order along each tone ring and along the clip; each crossing's successor on both.
    bySubject.resize(std::size_t(m));
    byClip.resize(std::size_t(m));
    for (int i = 0; i < m; ++i)
        bySubject[std::size_t(i)] = byClip[std::size_t(i)] = i;
    std::sort(bySubject.begin(), bySubject.end(), [](int x, int y) {
        const Crossing &a = crossings[std::size_t(x)], &b = crossings[std::size_t(y)];
        return a.ring != b.ring ? a.ring < b.ring : a.edge != b.edge ? a.edge < b.edge : a.t < b.t;
    });
    std::sort(byClip.begin(), byClip.end(), [](int x, int y) {
        const Crossing &a = crossings[std::size_t(x)], &b = crossings[std::size_t(y)];
        return a.clipEdge != b.clipEdge ? a.clipEdge < b.clipEdge : a.u < b.u;
    });
    sNext.assign(std::size_t(m), -1);
    cNext.assign(std::size_t(m), -1);
    perRing.assign(count, 0);
    for (int i = 0; i < m;) {
        int j = i;
        while (j < m && crossings[std::size_t(bySubject[std::size_t(j)])].ring ==
                            crossings[std::size_t(bySubject[std::size_t(i)])].ring)
            ++j;
        if ((j - i) % 2 != 0)
            return false;
        for (int k = i; k < j; ++k)
            sNext[std::size_t(bySubject[std::size_t(k)])] =
                bySubject[std::size_t(k + 1 < j ? k + 1 : i)];
        perRing[std::size_t(crossings[std::size_t(bySubject[std::size_t(i)])].ring)] = j - i;
        i = j;
    }
    for (int k = 0; k < m; ++k)
        cNext[std::size_t(byClip[std::size_t(k)])] = byClip[std::size_t(k + 1 < m ? k + 1 : 0)];
    // Which pieces lie inside the other outline (they alternate along each outline).
    sIn.assign(std::size_t(m), 0);
    cIn.assign(std::size_t(m), 0);
    for (int i = 0; i < m; ++i) {
        const Crossing &a = crossings[std::size_t(i)],
                       &b = crossings[std::size_t(sNext[std::size_t(i)])];
        sIn[std::size_t(i)] =
            insideClip(pieceProbe(S[std::size_t(a.ring)], a.p, a.edge, a.t, b.edge, b.t, b.p));
        const Crossing &c = crossings[std::size_t(cNext[std::size_t(i)])];
        cIn[std::size_t(i)] = insideTone(pieceProbe(C, a.p, a.clipEdge, a.u, c.clipEdge, c.u, c.p));
    }
    for (int i = 0; i < m; ++i)
        if (sIn[std::size_t(i)] == sIn[std::size_t(sNext[std::size_t(i)])] ||
            cIn[std::size_t(i)] == cIn[std::size_t(cNext[std::size_t(i)])])
            return false;
    // Chain: a tone piece inside the clip, then the clip piece inside the tone from where it
    // ends, and so on back to the start.
    sUsed.assign(std::size_t(m), 0);
    cUsed.assign(std::size_t(m), 0);
    const std::size_t before = out.points.size(), startsBefore = out.starts.size();
    const auto fail = [&]() {
        out.points.resize(before);
        out.starts.resize(startsBefore);
        return false;
    };
    for (int i0 = 0; i0 < m; ++i0) {
        if (!sIn[std::size_t(i0)] || sUsed[std::size_t(i0)])
            continue;
        traced.clear();
        int i = i0;
        for (int guard = 0;; ++guard) {
            if (guard > m || !sIn[std::size_t(i)] || sUsed[std::size_t(i)])
                return fail();
            sUsed[std::size_t(i)] = 1;
            const Crossing &a = crossings[std::size_t(i)];
            const int j = sNext[std::size_t(i)];
            const Crossing &b = crossings[std::size_t(j)];
            appendPiece(S[std::size_t(a.ring)], a.p, a.edge, a.t, b.edge, b.t, traced);
            if (!cIn[std::size_t(j)] || cUsed[std::size_t(j)])
                return fail();
            cUsed[std::size_t(j)] = 1;
            const int k = cNext[std::size_t(j)];
            const Crossing &c = crossings[std::size_t(k)];
            appendPiece(C, b.p, b.clipEdge, b.u, c.clipEdge, c.u, traced);
            i = k;
            if (i == i0)
                break;
        }
        appendRing(traced);
    }
    for (int i = 0; i < m; ++i)
        if (sIn[std::size_t(i)] != sUsed[std::size_t(i)] ||
            cIn[std::size_t(i)] != cUsed[std::size_t(i)])
            return fail();
    // Outlines that cross nothing lie wholly inside or outside the other.
    for (std::size_t r = 0; r < count; ++r)
        if (perRing[r] == 0 && insideClip(S[r].front()))
            appendRing(S[r]);
    if (m == 0 && insideTone(C.front()))
        appendRing(C);
    return true;
}

} // namespace finbook::geometry::shade_detail
