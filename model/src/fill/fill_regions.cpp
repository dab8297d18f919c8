// Regions of an object, cached by the content of its rest strokes, and their outlines as shown.
#include <finbook/model/fill/fill_regions.h>
#include <finbook/model/render.h>
#include <finbook/model/stroke_input.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <list>

namespace finbook::model {

namespace {
QPolygonF ring(const Eigen::MatrixX2d &m)
{
    QPolygonF poly;
    poly.reserve(int(m.rows()) + 1);
    for (Eigen::Index i = 0; i < m.rows(); ++i)
        poly << QPointF(m(i, 0), m(i, 1));
    if (!poly.isEmpty())
        poly << poly.front();
    return poly;
}

std::vector<const Eigen::MatrixX2d *> rings(const geometry::Polygon &p)
{
    std::vector<const Eigen::MatrixX2d *> out{&p.outer};
    for (const Eigen::MatrixX2d &h : p.holes)
        out.push_back(&h);
    return out;
}

bool finitePoint(const StrokePoint &p)
{
    return std::isfinite(p.x) && std::isfinite(p.y);
}

// Squared distance from q to segment a-b and where along it (0..1) the nearest point is.
double segmentDistance2(QPointF q, QPointF a, QPointF b, double &t)
{
    const QPointF d = b - a;
    const double len2 = d.x() * d.x() + d.y() * d.y();
    t = len2 > 0 ? std::clamp(QPointF::dotProduct(q - a, d) / len2, 0.0, 1.0) : 0.0;
    const QPointF n = a + t * d - q;
    return n.x() * n.x() + n.y() * n.y();
}
} // namespace

ObjectRegions::ObjectRegions(geometry::Regions regions, std::vector<Id> strokeIds,
                             std::vector<int> strokeIndex)
    : m_regions(std::move(regions))
    , m_strokeIndex(std::move(strokeIndex))
{
    for (const geometry::Face &face : m_regions.faces) {
        std::vector<Id> ids;
        for (int s : face.strokes)
            if (s >= 0 && std::size_t(s) < strokeIds.size())
                ids.push_back(strokeIds[std::size_t(s)]);
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        m_faceIds.push_back(std::move(ids));
        QPainterPath path;
        path.setFillRule(Qt::WindingFill);
        for (const Eigen::MatrixX2d *r : rings(face.polygon))
            path.addPolygon(ring(*r));
        m_restPaths.push_back(std::move(path));
    }
}

int ObjectRegions::faceAt(QPointF p) const
{
    return geometry::faceAt(m_regions, p.x(), p.y());
}

namespace {
using Anchor = ObjectRegions::Anchor;

// The nearest point to q on the candidate strokes (indices into the object's strokes).
Anchor nearestAnchor(QPointF q, const std::vector<int> &candidates, const StrokeGroup &group)
{
    Anchor best;
    double bestD2 = std::numeric_limits<double>::infinity();
    for (int s : candidates) {
        if (s < 0 || std::size_t(s) >= group.strokes.size() || !group.strokes[std::size_t(s)].data)
            continue;
        const auto &pts = group.strokes[std::size_t(s)].data->points;
        for (std::size_t k = 0; k < pts.size(); ++k) {
            const std::size_t next = std::min(k + 1, pts.size() - 1);
            if (!finitePoint(pts[k]) || !finitePoint(pts[next]))
                continue;
            double t = 0;
            const double d2 = segmentDistance2(q, QPointF(pts[k].x, pts[k].y),
                                               QPointF(pts[next].x, pts[next].y), t);
            if (d2 < bestD2) {
                bestD2 = d2;
                best = Anchor{s, int(k), float(t)};
            }
        }
    }
    return best;
}

// Where an anchored point shows now; `rest` when its stroke cannot say.
QPointF placed(const Anchor &a, QPointF rest, const StrokeGroup &group)
{
    if (a.stroke < 0 || std::size_t(a.stroke) >= group.strokes.size())
        return rest;
    const auto &shown = displayedPoints(group, std::size_t(a.stroke));
    const std::size_t k = std::size_t(a.segment);
    if (k >= shown.size())
        return rest;
    const StrokePoint &p0 = shown[k], &p1 = shown[std::min(k + 1, shown.size() - 1)];
    if (!finitePoint(p0) || !finitePoint(p1))
        return rest;
    return QPointF(p0.x + a.t * (p1.x - p0.x), p0.y + a.t * (p1.y - p0.y));
}
} // namespace

namespace {
using Edge = ObjectRegions::Edge;

// An outline edge runs along a stroke when its ends and middle lie within this of the stroke:
// the regions simplify strokes by a tenth of the pen width (geometry/regions.h).
double alongTolerance(const StrokeData &data)
{
    return 0.15 * double(data.width) + 0.1;
}

QPointF restAt(const Anchor &a, const StrokeGroup &group)
{
    const auto &pts = group.strokes[std::size_t(a.stroke)].data->points;
    const StrokePoint &p0 = pts[std::size_t(a.segment)];
    const StrokePoint &p1 = pts[std::min(std::size_t(a.segment) + 1, pts.size() - 1)];
    return QPointF(p0.x + a.t * (p1.x - p0.x), p0.y + a.t * (p1.y - p0.y));
}

double position(const Anchor &a)
{
    return double(a.segment) + double(a.t);
}

// Arc length along `pts` from its start to position `pos` (segment + t).
double arcTo(const std::vector<StrokePoint> &pts, double pos)
{
    double length = 0.0;
    for (std::size_t k = 0; k + 1 < pts.size() && double(k) < pos; ++k) {
        const double seg = std::hypot(pts[k + 1].x - pts[k].x, pts[k + 1].y - pts[k].y);
        length += seg * std::min(1.0, pos - double(k));
    }
    return length;
}

bool closedStroke(const std::vector<StrokePoint> &pts)
{
    return pts.size() > 3 &&
           std::hypot(pts.front().x - pts.back().x, pts.front().y - pts.back().y) <= 0.5;
}

// The edge from rest corner a to rest corner b: along the boundary stroke that holds both
// ends and its middle (the nearest such), else a chord between corners tied to the nearest
// points of the boundary strokes.
Edge edgeBetween(QPointF a, QPointF b, const std::vector<int> &candidates, const StrokeGroup &group)
{
    Edge best;
    double bestFit = std::numeric_limits<double>::infinity();
    const QPointF mid = 0.5 * (a + b);
    for (int s : candidates) {
        if (s < 0 || std::size_t(s) >= group.strokes.size() || !group.strokes[std::size_t(s)].data)
            continue;
        const StrokeData &data = *group.strokes[std::size_t(s)].data;
        const double tolerance = alongTolerance(data);
        const Anchor from = nearestAnchor(a, {s}, group), to = nearestAnchor(b, {s}, group);
        if (from.stroke < 0 || to.stroke < 0)
            continue;
        const Anchor middle = nearestAnchor(mid, {s}, group);
        const double fit = std::max({QLineF(restAt(from, group), a).length(),
                                     QLineF(restAt(to, group), b).length(),
                                     QLineF(restAt(middle, group), mid).length()});
        if (!(fit <= tolerance) || fit >= bestFit)
            continue;
        // The way along the stroke whose length matches the edge's: on a closed stroke the
        // short way may go round its joint; a way much longer than the edge is another pass
        // of the line (a stroke that comes back near itself): then a chord.
        const double direct =
            std::abs(arcTo(data.points, position(to)) - arcTo(data.points, position(from)));
        const double total = arcTo(data.points, double(data.points.size()));
        const bool wraps = closedStroke(data.points) && total - direct < direct;
        const double walk = wraps ? total - direct : direct;
        if (walk > 1.5 * QLineF(a, b).length() + 2.0 * double(data.width) + 1.0)
            continue;
        best = Edge{from, to, s, wraps};
        bestFit = fit;
    }
    if (best.along < 0)
        best.start = nearestAnchor(a, candidates, group);
    return best;
}

// Appends the shown points of `edge`'s stroke strictly between its two ends, in the order
// the edge walks them.
void appendWalk(QPolygonF &poly, const Edge &edge, const StrokeGroup &group)
{
    const auto &shown = displayedPoints(group, std::size_t(edge.along));
    const auto n = std::ptrdiff_t(shown.size());
    const auto &rest = group.strokes[std::size_t(edge.along)].data->points;
    if (n < 2 || std::size_t(n) != rest.size())
        return;
    const double from = position(edge.start), to = position(edge.end);
    const auto add = [&](std::ptrdiff_t k) {
        if (k >= 0 && k < n && finitePoint(shown[std::size_t(k)]))
            poly << QPointF(shown[std::size_t(k)].x, shown[std::size_t(k)].y);
    };
    const auto up = [&](std::ptrdiff_t first, std::ptrdiff_t last) {
        for (std::ptrdiff_t k = first; k <= last; ++k)
            add(k);
    };
    const auto down = [&](std::ptrdiff_t first, std::ptrdiff_t last) {
        for (std::ptrdiff_t k = first; k >= last; --k)
            add(k);
    };
    const auto after = [](double p) { return std::ptrdiff_t(std::floor(p)) + 1; };
    const auto before = [](double p) { return std::ptrdiff_t(std::ceil(p)) - 1; };
    if (!edge.wraps) {
        from <= to ? up(after(from), before(to)) : down(before(from), after(to));
    } else if (from <= to) { // back through the joint (the last point repeats the first)
        down(before(from), 0);
        down(n - 2, after(to));
    } else {
        up(after(from), n - 1);
        up(1, before(to));
    }
}
} // namespace

const std::vector<std::vector<ObjectRegions::Edge>> &ObjectRegions::edges(const StrokeGroup &group,
                                                                          int face) const
{
    std::lock_guard lock(m_mutex);
    if (auto it = m_edges.find(face); it != m_edges.end())
        return it->second;
    const geometry::Face &f = m_regions.faces[std::size_t(face)];
    std::vector<int> candidates;
    for (int s : f.strokes)
        if (s >= 0 && std::size_t(s) < m_strokeIndex.size())
            candidates.push_back(m_strokeIndex[std::size_t(s)]);
    std::vector<std::vector<Edge>> out;
    for (const Eigen::MatrixX2d *r : rings(f.polygon)) {
        std::vector<Edge> ring(std::size_t(r->rows()));
        for (Eigen::Index i = 0; i < r->rows(); ++i) {
            const Eigen::Index j = (i + 1) % r->rows();
            ring[std::size_t(i)] = edgeBetween(QPointF((*r)(i, 0), (*r)(i, 1)),
                                               QPointF((*r)(j, 0), (*r)(j, 1)), candidates, group);
        }
        out.push_back(std::move(ring));
    }
    return m_edges.emplace(face, std::move(out)).first->second;
}

QPainterPath ObjectRegions::displayedPath(const StrokeGroup &group, int face) const
{
    if (face < 0 || face >= faceCount())
        return {};
    if (!group.isDeformed())
        return restPath(face);
    const auto &faceEdges = edges(group, face);
    const geometry::Face &f = m_regions.faces[std::size_t(face)];
    QPainterPath path;
    path.setFillRule(Qt::WindingFill);
    const auto rs = rings(f.polygon);
    for (std::size_t r = 0; r < rs.size() && r < faceEdges.size(); ++r) {
        QPolygonF poly;
        for (Eigen::Index i = 0; i < rs[r]->rows(); ++i) {
            const Edge &edge = faceEdges[r][std::size_t(i)];
            poly << placed(edge.start, QPointF((*rs[r])(i, 0), (*rs[r])(i, 1)), group);
            if (edge.along >= 0)
                appendWalk(poly, edge, group);
        }
        if (!poly.isEmpty()) {
            poly << poly.front();
            path.addPolygon(poly);
        }
    }
    return path;
}

std::vector<QLineF> ObjectRegions::displayedClosures(const StrokeGroup &group) const
{
    std::vector<QLineF> lines;
    const auto strokeOf = [&](int input) {
        return input >= 0 && std::size_t(input) < m_strokeIndex.size()
                   ? std::vector<int>{m_strokeIndex[std::size_t(input)]}
                   : std::vector<int>{};
    };
    for (const geometry::GapClosure &c : m_regions.closures) {
        const QPointF from(c.from.x(), c.from.y()), to(c.to.x(), c.to.y());
        if (!group.isDeformed()) {
            lines.emplace_back(from, to);
            continue;
        }
        lines.emplace_back(placed(nearestAnchor(from, strokeOf(c.fromStroke), group), from, group),
                           placed(nearestAnchor(to, strokeOf(c.toStroke), group), to, group));
    }
    return lines;
}

geometry::RegionsOptions regionsOptions(double closeGap)
{
    geometry::RegionsOptions options;
    options.closeGap = std::isfinite(closeGap) && closeGap >= 0 ? closeGap : -1.0;
    return options;
}

namespace {
struct CacheEntry {
    std::vector<StrokeDataPtr> strokes; // held, so a pointer is never reused while cached
    std::vector<Id> ids;
    double closeGap;
    ObjectRegionsPtr regions;
};
constexpr std::size_t kCacheEntries = 64;
std::mutex g_cacheMutex;
std::list<CacheEntry> g_cache; // most recently used first

bool sameKey(const CacheEntry &e, const StrokeGroup &group, double closeGap)
{
    if (e.closeGap != closeGap || e.strokes.size() != group.strokes.size())
        return false;
    for (std::size_t i = 0; i < e.strokes.size(); ++i)
        if (e.strokes[i] != group.strokes[i].data || e.ids[i] != group.strokes[i].id)
            return false;
    return true;
}

ObjectRegionsPtr compute(const StrokeGroup &group, double closeGap)
{
    std::vector<geometry::StrokeInput> inputs;
    std::vector<Id> ids;
    std::vector<int> index;
    for (std::size_t s = 0; s < group.strokes.size(); ++s) {
        const StrokeDataPtr &data = group.strokes[s].data;
        if (!data || data->points.empty() || data->color == kHiddenLineColor)
            continue;
        inputs.push_back(strokeInput(data->points, data->width));
        ids.push_back(group.strokes[s].id);
        index.push_back(int(s));
    }
    geometry::Regions regions;
    if (!inputs.empty()) {
        auto computed = geometry::computeRegions(inputs, regionsOptions(closeGap));
        if (computed)
            regions = std::move(computed.value());
    }
    return std::make_shared<const ObjectRegions>(std::move(regions), std::move(ids),
                                                 std::move(index));
}
} // namespace

ObjectRegionsPtr objectRegions(const StrokeGroup &group, double closeGap)
{
    {
        std::lock_guard lock(g_cacheMutex);
        for (auto it = g_cache.begin(); it != g_cache.end(); ++it)
            if (sameKey(*it, group, closeGap)) {
                g_cache.splice(g_cache.begin(), g_cache, it);
                return g_cache.front().regions;
            }
    }
    // Computed outside the lock: two threads may both compute one object, never wait on
    // each other's long computations.
    ObjectRegionsPtr regions = compute(group, closeGap);
    CacheEntry entry{{}, {}, closeGap, regions};
    for (const Stroke &s : group.strokes) {
        entry.strokes.push_back(s.data);
        entry.ids.push_back(s.id);
    }
    std::lock_guard lock(g_cacheMutex);
    g_cache.push_front(std::move(entry));
    if (g_cache.size() > kCacheEntries)
        g_cache.pop_back();
    return regions;
}

std::vector<Id> withLinesOfNoInk(const StrokeGroup &group, std::vector<Id> picked)
{
    const auto isPicked = [&](Id id) {
        return std::find(picked.begin(), picked.end(), id) != picked.end();
    };
    // The inked lines whose displayed line passes within their half width (and half a px, or
    // a px at least) of p.
    const auto inkedAt = [&](QPointF p) {
        std::vector<std::size_t> out;
        for (std::size_t i = 0; i < group.strokes.size(); ++i) {
            const Stroke &s = group.strokes[i];
            if (!s.data || qAlpha(s.data->color) == 0)
                continue;
            const std::vector<StrokePoint> &points = displayedPoints(group, i);
            const double reach = std::max(1.0, 0.5 * double(s.data->width) + 0.5);
            for (std::size_t k = 0; k < points.size(); ++k) {
                const QPointF a(points[k].x, points[k].y);
                const QPointF b =
                    k + 1 < points.size() ? QPointF(points[k + 1].x, points[k + 1].y) : a;
                const QPointF d = b - a;
                const double dd = QPointF::dotProduct(d, d);
                const double t =
                    dd > 0.0 ? std::clamp(QPointF::dotProduct(p - a, d) / dd, 0.0, 1.0) : 0.0;
                if (QLineF(p, a + t * d).length() <= reach) {
                    out.push_back(i);
                    break;
                }
            }
        }
        return out;
    };
    std::vector<Id> join, leave;
    for (std::size_t i = 0; i < group.strokes.size(); ++i) {
        const Stroke &s = group.strokes[i];
        if (!s.data || qAlpha(s.data->color) != 0)
            continue;
        const std::vector<StrokePoint> &points = displayedPoints(group, i);
        if (points.empty())
            continue;
        bool any = false, all = true;
        for (const StrokePoint *end : {&points.front(), &points.back()})
            for (std::size_t j : inkedAt(QPointF(end->x, end->y))) {
                any = true;
                all = all && isPicked(group.strokes[j].id);
            }
        if (!any)
            continue;
        (all ? join : leave).push_back(s.id);
    }
    std::erase_if(picked,
                  [&](Id id) { return std::find(leave.begin(), leave.end(), id) != leave.end(); });
    for (Id id : join)
        if (!isPicked(id))
            picked.push_back(id);
    return picked;
}

std::vector<std::vector<std::size_t>> linesOfParts(const StrokeGroup &group)
{
    const std::size_t n = group.strokes.size();
    std::vector<std::size_t> root(n);
    for (std::size_t i = 0; i < n; ++i)
        root[i] = i;
    const auto find = [&](std::size_t i) {
        while (root[i] != i)
            i = root[i] = root[root[i]];
        return i;
    };
    const auto hidden = [&](std::size_t i) {
        return group.strokes[i].data && group.strokes[i].data->color == kHiddenLineColor;
    };
    const auto sameEnd = [](const StrokePoint &a, const StrokePoint &b) {
        return a.x == b.x && a.y == b.y;
    };
    // A hidden part and the parts either side of it share their ends exactly (bakedStrokes
    // copies the point), so ends are matched by value.
    for (std::size_t i = 0; i < n; ++i) {
        if (!hidden(i) || group.strokes[i].data->points.empty())
            continue;
        const auto &pi = group.strokes[i].data->points;
        for (std::size_t j = 0; j < n; ++j) {
            if (j == i || !group.strokes[j].data || group.strokes[j].data->points.empty() ||
                (qAlpha(group.strokes[j].data->color) == 0 && !hidden(j)))
                continue;
            const auto &pj = group.strokes[j].data->points;
            if (sameEnd(pi.front(), pj.back()) || sameEnd(pi.back(), pj.front()))
                root[find(i)] = find(j);
        }
    }
    std::vector<std::vector<std::size_t>> lines;
    std::vector<std::ptrdiff_t> lineOf(n, -1);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t r = find(i);
        if (lineOf[r] < 0) {
            lineOf[r] = std::ptrdiff_t(lines.size());
            lines.emplace_back();
        }
        lines[std::size_t(lineOf[r])].push_back(i);
    }
    return lines;
}

} // namespace finbook::model
