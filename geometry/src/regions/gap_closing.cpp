#include "gap_closing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <utility>

namespace finbook::geometry::detail {
namespace {

// Along its own stroke, a point counts as "elsewhere" (a loop coming back) only when it is
// this many times its straight distance away along the stroke, plus a few pen widths.
constexpr double kLoopArcFactor = 2.5;
// Weight of direction in a closure's score: distance/gap + kTurnWeight·(1 − cos turn).
constexpr double kTurnWeight = 0.35;
// A closure carries a line on "head-on" when it turns at most ~35° from the way the line left
// its end (1 − cos 35°).
constexpr double kHeadOnTurn = 0.18;
// Closures only start this far from the ends they join (numerical contact slack, px).
constexpr double kContactSlack = 0.05;
// Passes of accept-and-reconnect (each may connect parts that let further closures close;
// a pass with nothing else to do accepts one pair or ring).
constexpr int kMaxPasses = 24;

// A link ending on a stroke's interior runs this far past it: the rounded point on the
// segment misses it in exact arithmetic, the overshoot crosses it (a dangling tip that no face
// keeps).
constexpr double kOvershoot = 0.01;

LabelledSegment linkTo(const Eigen::Vector2d &from, const Eigen::Vector2d &to, int label)
{
    const Eigen::Vector2d d = to - from;
    const double len = d.norm();
    return {from, len > 0.0 ? Eigen::Vector2d(to + kOvershoot / len * d) : to, label};
}

struct End {
    int stroke = -1, end = 0;
    Eigen::Vector2d point, direction;
    double arc = 0.0;
};

struct Candidate {
    int from = -1;  // free end index
    int toEnd = -1; // free end index, or -1 for a point on a stroke
    int toStroke = -1;
    Eigen::Vector2d to;
    bool exact = false; // `to` is a vertex of the drawing
    double score = 0.0;
};

class UnionFind {
public:
    explicit UnionFind(int n)
        : m_parent(std::size_t(n))
    {
        std::iota(m_parent.begin(), m_parent.end(), 0);
    }
    int find(int a)
    {
        while (m_parent[std::size_t(a)] != a)
            a = m_parent[std::size_t(a)] = m_parent[std::size_t(m_parent[std::size_t(a)])];
        return a;
    }
    void join(int a, int b) { m_parent[std::size_t(find(a))] = find(b); }

private:
    std::vector<int> m_parent;
};

double touchTolerance(const StrokeSoup &soup, int a, int b)
{
    return std::max(
        0.25, 0.5 * (soup.strokes()[std::size_t(a)].width + soup.strokes()[std::size_t(b)].width));
}

// Splits the stroke ends into free ones and touching ones; a touching end that does not
// quite reach gets a snap segment to the point it touches.
std::vector<End> findEnds(const StrokeSoup &soup, std::vector<LabelledSegment> &snaps,
                          std::vector<std::pair<int, int>> &snapStrokes)
{
    std::vector<End> free;
    const int n = int(soup.strokes().size());
    for (int s = 0; s < n; ++s) {
        if (soup.strokes()[std::size_t(s)].segmentCount == 0)
            continue;
        for (int end = 0; end < 2; ++end) {
            End e{s, end, soup.endPoint(s, end), soup.endDirection(s, end), soup.endArc(s, end)};
            const double w = soup.strokes()[std::size_t(s)].width;
            NearestPoint touch;
            for (int j = 0; j < n; ++j) {
                if (!soup.within(j, e.point, touchTolerance(soup, s, j)))
                    continue;
                const NearestPoint near =
                    soup.nearestOnStroke(j, e.point, s, e.arc, kLoopArcFactor, 2.0 * w + 0.5);
                if (near.distance >= 0.0 && near.distance <= touchTolerance(soup, s, j) &&
                    (touch.distance < 0.0 || near.distance < touch.distance))
                    touch = near;
            }
            if (touch.distance < 0.0) {
                free.push_back(e);
            } else if (touch.distance > 0.0) {
                const int label = -1 - int(snaps.size());
                snaps.push_back(touch.onVertex ? LabelledSegment{e.point, touch.point, label}
                                               : linkTo(e.point, touch.point, label));
                snapStrokes.emplace_back(s, touch.stroke);
            }
        }
    }
    return free;
}

double turnCost(const Eigen::Vector2d &direction, const Eigen::Vector2d &delta)
{
    const double d = delta.norm();
    if (!(d > 0.0) || !(direction.squaredNorm() > 0.0))
        return 1.0;
    return 1.0 - std::clamp(direction.dot(delta) / d, -1.0, 1.0);
}

std::vector<Candidate> candidates(const StrokeSoup &soup, const std::vector<End> &ends, double gap)
{
    std::vector<Candidate> out;
    for (int i = 0; i < int(ends.size()); ++i) {
        const End &e = ends[std::size_t(i)];
        const double w = soup.strokes()[std::size_t(e.stroke)].width;
        const auto add = [&](const NearestPoint &near, int toEnd) {
            if (near.distance <= 0.0 || near.distance > gap)
                return;
            double turn = turnCost(e.direction, near.point - e.point);
            if (toEnd >= 0)
                turn = 0.5 *
                       (turn + turnCost(ends[std::size_t(toEnd)].direction, e.point - near.point));
            out.push_back({i, toEnd, near.stroke, near.point, toEnd >= 0 || near.onVertex,
                           near.distance / gap + kTurnWeight * turn});
        };
        for (int j = 0; j < int(soup.strokes().size()); ++j)
            if (soup.within(j, e.point, gap))
                add(soup.nearestOnStroke(j, e.point, e.stroke, e.arc, kLoopArcFactor,
                                         2.0 * w + 0.5),
                    -1);
        add(soup.castRay(e.point, e.direction, gap, e.stroke, e.arc, 2.0 * w + 0.5), -1);
        for (int k = 0; k < int(ends.size()); ++k) {
            const End &o = ends[std::size_t(k)];
            if (k == i || (o.stroke == e.stroke && soup.strokes()[std::size_t(e.stroke)].length <
                                                       kLoopArcFactor * (o.point - e.point).norm()))
                continue;
            NearestPoint near{o.point, (o.point - e.point).norm(), o.stroke, true};
            add(near, k);
        }
    }
    std::sort(out.begin(), out.end(),
              [](const Candidate &a, const Candidate &b) { return a.score < b.score; });
    return out;
}

class Closer {
public:
    Closer(const StrokeSoup &soup, const std::vector<End> &ends, PlanarMap &map, UnionFind &parts)
        : m_soup(soup)
        , m_ends(ends)
        , m_map(map)
        , m_parts(parts)
        , m_used(ends.size(), false)
    {}

    bool usable(const Candidate &c) const
    {
        if (m_used[std::size_t(c.from)] || (c.toEnd >= 0 && m_used[std::size_t(c.toEnd)]))
            return false;
        const Eigen::Vector2d p = m_ends[std::size_t(c.from)].point;
        if (m_soup.crossesStrokes(p, c.to, kContactSlack))
            return false;
        for (const GapClosure &g : closures)
            if (segmentsCross(p, c.to, g.from, g.to, kContactSlack))
                return false;
        for (double t : {0.25, 0.5, 0.75})
            if (m_map.inBoundedFace(p + t * (c.to - p)))
                return false;
        return !runsAlongOwnInk(c);
    }

    // A closure that doubles back along the stroke it starts from (a T's bar closed onto its
    // own stem, lying on the bar) encloses nothing, but it would use up the end that a real
    // gap further on needs.
    bool runsAlongOwnInk(const Candidate &c) const
    {
        const End &e = m_ends[std::size_t(c.from)];
        if (turnCost(e.direction, c.to - e.point) <= 1.0)
            return false; // heads on, within 90° of the way the pen left: a real gap
        const double w = m_soup.strokes()[std::size_t(e.stroke)].width;
        if ((c.to - e.point).norm() < 4.0 * w + 2.0)
            return false; // a hook's tip: too short to lie along anything
        for (double t : {0.25, 0.5, 0.75}) {
            const NearestPoint near = m_soup.nearestOnStroke(
                e.stroke, e.point + t * (c.to - e.point), e.stroke, e.arc, 0.0, 2.0 * w + 0.5);
            if (!(near.distance >= 0.0 && near.distance <= 2.0 * w + 1.0))
                return false;
        }
        return true;
    }

    bool connected(const Candidate &c)
    {
        return m_parts.find(m_ends[std::size_t(c.from)].stroke) == m_parts.find(c.toStroke);
    }

    bool used(int end) const { return m_used[std::size_t(end)]; }

    void accept(const Candidate &c, bool mouth = false)
    {
        const End &e = m_ends[std::size_t(c.from)];
        m_used[std::size_t(c.from)] = true;
        if (c.toEnd >= 0)
            m_used[std::size_t(c.toEnd)] = true;
        m_map.insert(c.exact ? LabelledSegment{e.point, c.to, -1} : linkTo(e.point, c.to, -1));
        m_parts.join(e.stroke, c.toStroke);
        closures.push_back({e.point, c.to, e.stroke, c.toStroke, mouth});
        // A free end the closure now touches (the other side of the gap, when the closure
        // went to the point of its stroke rather than to the end itself) has had its gap
        // closed: left free, it would reach on to whatever line is nearest (an arm beside
        // the gap) and close nothing but a sliver.
        for (std::size_t k = 0; k < m_ends.size(); ++k) {
            const End &o = m_ends[k];
            if (!m_used[k] && (closestOnSegment(o.point, e.point, c.to) - o.point).norm() <=
                                  touchTolerance(m_soup, o.stroke, e.stroke) + kContactSlack)
                m_used[k] = true;
        }
    }

    std::vector<GapClosure> closures;

private:
    const StrokeSoup &m_soup;
    const std::vector<End> &m_ends;
    PlanarMap &m_map;
    UnionFind &m_parts;
    std::vector<bool> m_used;
};

// Two separate parts joined by two closures enclose a face between them (two halves of an
// outline drawn facing each other); one closure alone would only join them.
double segmentDistance(const Eigen::Vector2d &p, const Eigen::Vector2d &q, const Eigen::Vector2d &a,
                       const Eigen::Vector2d &b)
{
    if (segmentsCross(p, q, a, b, 0.0))
        return 0.0;
    return std::min({(closestOnSegment(p, a, b) - p).norm(), (closestOnSegment(q, a, b) - q).norm(),
                     (closestOnSegment(a, p, q) - a).norm(),
                     (closestOnSegment(b, p, q) - b).norm()});
}

// A closure from a free end to a free end that carries on both lines within kHeadOnTurn of
// the way each left its end: the two ends of one line broken apart.
bool bridgesHeadOn(const Candidate &c, const std::vector<End> &ends)
{
    if (c.toEnd < 0)
        return false;
    const End &from = ends[std::size_t(c.from)], &to = ends[std::size_t(c.toEnd)];
    return turnCost(from.direction, to.point - from.point) <= kHeadOnTurn &&
           turnCost(to.direction, from.point - to.point) <= kHeadOnTurn;
}

bool acceptPairs(Closer &closer, const std::vector<Candidate> &deferred, UnionFind &parts,
                 const std::vector<End> &ends, double gap)
{
    std::map<std::pair<int, int>, std::vector<const Candidate *>> byParts;
    for (const Candidate &c : deferred) {
        int a = parts.find(ends[std::size_t(c.from)].stroke), b = parts.find(c.toStroke);
        if (a != b)
            byParts[{std::min(a, b), std::max(a, b)}].push_back(&c);
    }
    for (auto &[key, list] : byParts) {
        for (std::size_t i = 0; i < list.size(); ++i) {
            if (!closer.usable(*list[i]))
                continue;
            for (std::size_t j = i + 1; j < list.size(); ++j) {
                const Candidate &a = *list[i], &b = *list[j];
                const bool sharesEnd = a.from == b.from || a.from == b.toEnd ||
                                       (a.toEnd >= 0 && (a.toEnd == b.from || a.toEnd == b.toEnd));
                // Two closures side by side across one narrow slot (two fingers) enclose
                // nothing worth a face: the pair must be further apart than a gap. Not so for
                // two lines each broken head-on (a rub of the eraser across an arm): their
                // ends face each other, and a finger's never do.
                if (sharesEnd || !closer.usable(b) ||
                    (!(bridgesHeadOn(a, ends) && bridgesHeadOn(b, ends)) &&
                     segmentDistance(ends[std::size_t(a.from)].point, a.to,
                                     ends[std::size_t(b.from)].point, b.to) <= gap))
                    continue;
                closer.accept(a);
                closer.accept(b);
                return true;
            }
        }
    }
    return false;
}

// Closures between parts grown into a forest over the parts, each free end used once
// (acceptRing, linksAcross), and the path of closures between two parts in it.
class LinkForest {
public:
    LinkForest(int strokeCount, std::size_t endCount)
        : m_forest(strokeCount)
        , m_endTaken(endCount, false)
    {}

    bool joined(int a, int b) { return m_forest.find(a) == m_forest.find(b); }
    bool endsFree(const Candidate &c) const
    {
        return !m_endTaken[std::size_t(c.from)] &&
               (c.toEnd < 0 || !m_endTaken[std::size_t(c.toEnd)]);
    }
    void takeEnd(int end) { m_endTaken[std::size_t(end)] = true; }

    // Joins parts a and b (c's ends' parts) by c.
    void add(const Candidate &c, int a, int b)
    {
        m_forest.join(a, b);
        m_links[a].emplace_back(b, &c);
        m_links[b].emplace_back(a, &c);
        takeEnd(c.from);
        if (c.toEnd >= 0)
            takeEnd(c.toEnd);
    }

    // The closures from part `from` to part `to`, which the forest joins.
    std::vector<const Candidate *> path(int from, int to)
    {
        std::map<int, std::pair<int, const Candidate *>> cameFrom{{from, {from, nullptr}}};
        std::vector<int> queue{from};
        for (std::size_t q = 0; q < queue.size() && !cameFrom.count(to); ++q)
            for (const auto &[next, c] : m_links[queue[q]])
                if (cameFrom.emplace(next, std::make_pair(queue[q], c)).second)
                    queue.push_back(next);
        std::vector<const Candidate *> out;
        for (int at = to; at != from; at = cameFrom.at(at).first)
            out.push_back(cameFrom.at(at).second);
        return out;
    }

private:
    UnionFind m_forest;
    std::vector<bool> m_endTaken;
    std::map<int, std::vector<std::pair<int, const Candidate *>>> m_links;
};

// A ring of parts, each joined to the next by one short closure (an outline drawn in several
// strokes that all stop short of each other): no closure closes anything alone and no two join
// the same two parts. The best usable closures between parts grow a forest over the parts,
// each free end used once; the first closure that would join two parts already joined in it
// closes a ring of three or more parts, and the ring's closures are accepted together.
bool acceptRing(Closer &closer, const std::vector<Candidate> &deferred, UnionFind &parts,
                const std::vector<End> &ends, int strokeCount)
{
    LinkForest forest(strokeCount, ends.size());
    const auto crossesEachOther = [&](const std::vector<const Candidate *> &ring) {
        for (std::size_t i = 0; i < ring.size(); ++i)
            for (std::size_t j = i + 1; j < ring.size(); ++j)
                if (segmentsCross(ends[std::size_t(ring[i]->from)].point, ring[i]->to,
                                  ends[std::size_t(ring[j]->from)].point, ring[j]->to,
                                  kContactSlack))
                    return true;
        return false;
    };
    for (const Candidate &c : deferred) {
        const int a = parts.find(ends[std::size_t(c.from)].stroke), b = parts.find(c.toStroke);
        if (a == b || !forest.endsFree(c) || !closer.usable(c))
            continue;
        if (!forest.joined(a, b)) {
            forest.add(c, a, b);
            continue;
        }
        std::vector<const Candidate *> ring = forest.path(a, b);
        if (ring.size() < 2) // two parts: acceptPairs' rule (and its slot test) decides
            continue;
        ring.push_back(&c);
        if (crossesEachOther(ring))
            continue;
        for (const Candidate *link : ring)
            closer.accept(*link);
        return true;
    }
    return false;
}

// Mouths (regions.h): the facing angle, the face's shape against the mouth's width.
constexpr double kMouthLeansAway = -0.35;   // cos of ~110°: an end may lean this far away,
constexpr double kMouthOneLineLeans = -0.8; // ~145° when both are one line's (a flared wrist)
constexpr double kMouthTwoLines = -0.1;     // as above for the sides of two strokes: ~95°,
constexpr double kMouthOutline = 0.6;       // unless this share of the ink is around the face
constexpr double kMouthHeadOn = 1.0;        // the two cosines summing above this: a gap, head on
constexpr double kMouthDepth = 0.4;         // the face's area ≥ this · d²
constexpr double kMouthShare = 0.3;         // chord and links ≤ this share of the face's outline
constexpr double kMouthWidth = 2.0;         // d ≤ this · the widest inscribed circle's diameter
constexpr double kMouthBorder = 0.5;        // the face borders closed faces along < this · d,
constexpr double kMouthSpeck = 0.1;         // counting those of at least this · d² only
constexpr double kMouthBeyond = 0.6;        // nothing drawn this · d beyond the chord
constexpr double kMouthLinkGap = 2.0;       // a gap joining a mouth's sides: ≤ this · closeGap
constexpr int kMouthTrials = 24;            // faces tried per drawing at most (each copies the map)
constexpr int kInscribedGrid = 32;          // samples per side for the widest inscribed circle

// The radius of (about) the widest circle inside the polygon: the largest distance to its
// outline over a grid of points inside it.
double widestInscribedRadius(const Polygon &polygon)
{
    std::vector<const Eigen::MatrixX2d *> rings{&polygon.outer};
    for (const Eigen::MatrixX2d &hole : polygon.holes)
        rings.push_back(&hole);
    const Eigen::Vector2d lo = polygon.outer.colwise().minCoeff().transpose();
    const Eigen::Vector2d hi = polygon.outer.colwise().maxCoeff().transpose();
    const Region region{polygon};
    double best = 0.0;
    for (int i = 0; i < kInscribedGrid; ++i)
        for (int j = 0; j < kInscribedGrid; ++j) {
            const Eigen::Vector2d p(lo.x() + (hi.x() - lo.x()) * (i + 0.5) / kInscribedGrid,
                                    lo.y() + (hi.y() - lo.y()) * (j + 0.5) / kInscribedGrid);
            if (!regionContains(region, p.x(), p.y()))
                continue;
            double nearest = std::numeric_limits<double>::max();
            for (const Eigen::MatrixX2d *ring : rings)
                for (Eigen::Index k = 0, n = ring->rows(); k < n && nearest > best; ++k)
                    nearest =
                        std::min(nearest, (closestOnSegment(p, ring->row(k).transpose(),
                                                            ring->row((k + 1) % n).transpose()) -
                                           p)
                                              .norm());
            best = std::max(best, nearest);
        }
    return best;
}

struct Mouth {
    int from = -1, to = -1; // free end indices
    double width = 0.0;
    double leansAway = 0.0; // the smaller cosine of the ends' ways against the chord
    Eigen::Vector2d inward; // unit normal of the chord, towards the shape it opens
};

// Pairs of free ends left that lie side by side, facing each other across the chord or
// running beside each other, narrower first.
std::vector<Mouth> mouthCandidates(const StrokeSoup &soup, const std::vector<End> &ends,
                                   const Closer &closer)
{
    std::vector<Mouth> out;
    for (int i = 0; i < int(ends.size()); ++i)
        for (int k = i + 1; k < int(ends.size()); ++k) {
            if (closer.used(i) || closer.used(k))
                continue;
            const End &a = ends[std::size_t(i)], &b = ends[std::size_t(k)];
            const Eigen::Vector2d chord = b.point - a.point;
            const double d = chord.norm();
            if (!(d > 0.0))
                continue;
            const Eigen::Vector2d u = chord / d;
            // The way each line leaves at the mouth's scale, not its last wobble.
            const auto leaving = [&](const End &e) {
                const double length = soup.strokes()[std::size_t(e.stroke)].length;
                return soup.endDirectionOver(e.stroke, e.end, std::min(0.5 * d, 0.3 * length));
            };
            const Eigen::Vector2d ta = leaving(a), tb = leaving(b);
            const double ca = ta.dot(u), cb = -tb.dot(u);
            const double lean = a.stroke == b.stroke ? kMouthOneLineLeans : kMouthLeansAway;
            if (ca < lean || cb < lean || ca + cb > kMouthHeadOn)
                continue;
            const Eigen::Vector2d n(-u.y(), u.x());
            const double side = (ta + tb).dot(n);
            if (std::abs(side) < 1e-6 || ta.dot(n) * tb.dot(n) < -0.25)
                continue; // they leave on opposite sides of the chord: an S, not a mouth
            out.push_back({i, k, d, std::min(ca, cb), side > 0.0 ? Eigen::Vector2d(-n) : n});
        }
    std::sort(out.begin(), out.end(),
              [](const Mouth &a, const Mouth &b) { return a.width < b.width; });
    return out;
}

// The gap closures (best first) that would join the mouth's two parts when nothing joins
// them yet (an outline drawn in pieces that stop short of each other and also open at a
// wrist; with the mouth's evidence of a shape, a gap up to kMouthLinkGap times the gap
// distance): a path through the forest the usable closures grow over the parts, none of them
// using the mouth's ends or crossing its chord. Empty when the parts stay apart.
std::vector<const Candidate *> linksAcross(const Candidate &mouth,
                                           const std::vector<Candidate> &all, const Closer &closer,
                                           UnionFind &parts, const std::vector<End> &ends,
                                           int strokeCount)
{
    const int from = parts.find(ends[std::size_t(mouth.from)].stroke);
    const int to = parts.find(mouth.toStroke);
    LinkForest forest(strokeCount, ends.size());
    forest.takeEnd(mouth.from);
    forest.takeEnd(mouth.toEnd);
    const Eigen::Vector2d p = ends[std::size_t(mouth.from)].point;
    for (const Candidate &c : all) {
        const int a = parts.find(ends[std::size_t(c.from)].stroke), b = parts.find(c.toStroke);
        if (a == b || forest.joined(a, b) || !forest.endsFree(c) || !closer.usable(c) ||
            segmentsCross(ends[std::size_t(c.from)].point, c.to, p, mouth.to, kContactSlack))
            continue;
        forest.add(c, a, b);
        if (forest.joined(from, to))
            return forest.path(from, to);
    }
    return {};
}

// Whether the mouth's own outline goes on beyond the chord, within kMouthBeyond of the
// mouth's width (a circle with a gap, whose chord across it would cut it in two, has its
// other side within half the chord): a mouth opens onto nothing of its own (another part
// may lie there: the body a wing is drawn against).
bool inkBeyond(const StrokeSoup &soup, UnionFind &chains, int chain, const Eigen::Vector2d &a,
               const Eigen::Vector2d &b, const Eigen::Vector2d &outward)
{
    const double d = (b - a).norm();
    for (const SoupSegment &segment : soup.segments()) {
        if (chains.find(segment.stroke) != chain)
            continue;
        for (double t : {0.25, 0.5, 0.75}) {
            const Eigen::Vector2d from = a + t * (b - a);
            if (segmentsCross(from, from + kMouthBeyond * d * outward, segment.a, segment.b, 0.0))
                return true;
        }
    }
    return false;
}

// Strokes chained end to end: an end within `reach` of another stroke's end. An outline
// drawn in several strokes is one chain; a leg drawn as a line from a body's side is not
// chained to the body (its end meets the body's line, not an end).
UnionFind endChains(const StrokeSoup &soup, double reach)
{
    const int n = int(soup.strokes().size());
    UnionFind chains(n);
    for (int s = 0; s < n; ++s)
        for (int j = s + 1; j < n; ++j) {
            if (soup.strokes()[std::size_t(s)].segmentCount == 0 ||
                soup.strokes()[std::size_t(j)].segmentCount == 0)
                continue;
            for (int e = 0; e < 2; ++e)
                for (int f = 0; f < 2; ++f)
                    if ((soup.endPoint(s, e) - soup.endPoint(j, f)).norm() <= reach)
                        chains.join(s, j);
        }
    return chains;
}

// Closes the mouths that open a shape (regions.h), with the gap closures that join their
// two sides when the drawing does not.
void closeMouths(const StrokeSoup &soup, const std::vector<End> &ends, Closer &closer,
                 UnionFind &parts, const PlanarMap &map, double closeGap)
{
    const std::vector<Mouth> mouths = mouthCandidates(soup, ends, closer);
    if (mouths.empty())
        return;
    UnionFind chains = endChains(soup, closeGap);
    std::optional<std::vector<Candidate>> links; // the gaps that may join a mouth's sides
    double inked = 0.0;
    for (const SoupStroke &stroke : soup.strokes())
        inked += stroke.length;
    int trials = 0;
    for (const Mouth &m : mouths) {
        if (trials >= kMouthTrials)
            break;
        const End &a = ends[std::size_t(m.from)], &b = ends[std::size_t(m.to)];
        const Candidate c{m.from, m.to, b.stroke, b.point, true, 0.0};
        if (!closer.usable(c) ||
            inkBeyond(soup, chains, chains.find(a.stroke), a.point, b.point, -m.inward) ||
            inkBeyond(soup, chains, chains.find(b.stroke), a.point, b.point, -m.inward))
            continue;
        std::vector<const Candidate *> across;
        if (!closer.connected(c)) {
            if (!links)
                links = candidates(soup, ends, kMouthLinkGap * closeGap);
            across = linksAcross(c, *links, closer, parts, ends, int(soup.strokes().size()));
            if (across.empty())
                continue;
        }
        ++trials;
        std::vector<LabelledSegment> segments{{a.point, b.point, -1}};
        double closed = m.width; // the face's outline along closures, not lines
        for (const Candidate *link : across) {
            const Eigen::Vector2d from = ends[std::size_t(link->from)].point;
            closed += (link->to - from).norm();
            segments.push_back(link->exact ? LabelledSegment{from, link->to, -1}
                                           : linkTo(from, link->to, -1));
        }
        const Eigen::Vector2d probe = 0.5 * (a.point + b.point) + 0.01 * m.width * m.inward;
        const auto trial = map.trialFace(segments, probe, kMouthSpeck * m.width * m.width);
        // The face's lines are the mouth's own outline: every stroke around it chained end
        // to end with the mouth's sides or the links' (not two lines hung from a body).
        std::vector<int> own{chains.find(a.stroke), chains.find(b.stroke)};
        for (const Candidate *link : across)
            own.insert(own.end(), {chains.find(ends[std::size_t(link->from)].stroke),
                                   chains.find(link->toStroke)});
        const bool ownOutline =
            trial && std::all_of(trial->face.labels.begin(), trial->face.labels.end(), [&](int l) {
                return std::find(own.begin(), own.end(), chains.find(l)) != own.end();
            });
        // Two lines drawn apart that spread from where they meet (legs, antennae, whiskers
        // hung from a body) are no mouth, unless the face is the drawing's outline (a
        // trunk's two sides under the crown). One line turned back on itself (a fish's
        // tail, a leg drawn as a V) may spread, and two parallel lines (a tail) may.
        double around = 0.0;
        if (trial)
            for (int l : trial->face.labels)
                around += soup.strokes()[std::size_t(l)].length;
        const bool spreadsApart =
            a.stroke != b.stroke && m.leansAway < kMouthTwoLines && around < kMouthOutline * inked;
        if (!trial || !ownOutline || spreadsApart ||
            trial->face.area < kMouthDepth * m.width * m.width ||
            closed > kMouthShare * trial->face.perimeter ||
            trial->sharedWithBounded >= kMouthBorder * m.width ||
            m.width > kMouthWidth * 2.0 * widestInscribedRadius(trial->face.polygon))
            continue;
        for (const Candidate *link : across)
            closer.accept(*link);
        closer.accept(c, true);
    }
}

} // namespace

GapClosingResult closeGaps(const StrokeSoup &soup, double closeGap, bool mouths, PlanarMap &map)
{
    std::vector<LabelledSegment> segments, snaps;
    std::vector<std::pair<int, int>> snapStrokes;
    const std::vector<End> ends = findEnds(soup, snaps, snapStrokes);
    for (const SoupSegment &s : soup.segments())
        segments.push_back({s.a, s.b, s.stroke});
    segments.insert(segments.end(), snaps.begin(), snaps.end());
    map.insertAll(segments);

    const int strokeCount = int(soup.strokes().size());
    UnionFind parts(strokeCount);
    const auto node = [&](int label) {
        return label >= 0 ? label : snapStrokes[std::size_t(-1 - label)].first;
    };
    map.forEachContact([&](int a, int b) { parts.join(node(a), node(b)); });
    for (const auto &[a, b] : snapStrokes)
        parts.join(a, b);

    GapClosingResult result;
    result.freeEnds = int(ends.size());
    if (!(closeGap > 0.0) || ends.empty())
        return result;
    Closer closer(soup, ends, map, parts);
    const std::vector<Candidate> all = candidates(soup, ends, closeGap);
    // An end that a better closure would carry on head-on into another part (a line the
    // eraser broke) waits for the pairs and rings before a closure within its own part (across
    // an arm's cut end) may take it; when they find nothing, the next pass lets it.
    bool headOnFirst = true;
    for (int pass = 0; pass < kMaxPasses; ++pass) {
        std::vector<Candidate> deferred;
        std::vector<bool> waiting(ends.size(), false);
        bool changed = false;
        for (const Candidate &c : all) {
            if (!closer.usable(c))
                continue;
            if (!closer.connected(c)) {
                deferred.push_back(c);
                if (headOnFirst && bridgesHeadOn(c, ends))
                    waiting[std::size_t(c.from)] = waiting[std::size_t(c.toEnd)] = true;
            } else if (!waiting[std::size_t(c.from)] &&
                       (c.toEnd < 0 || !waiting[std::size_t(c.toEnd)])) {
                closer.accept(c);
                changed = true;
            }
        }
        if (changed || acceptPairs(closer, deferred, parts, ends, closeGap) ||
            acceptRing(closer, deferred, parts, ends, strokeCount))
            headOnFirst = true;
        else if (std::exchange(headOnFirst, false) == false)
            break;
    }
    if (mouths)
        closeMouths(soup, ends, closer, parts, map, closeGap);
    result.closures = std::move(closer.closures);
    return result;
}

} // namespace finbook::geometry::detail
