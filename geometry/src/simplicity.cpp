#include <finbook/geometry/simplicity.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace finbook::geometry {
namespace {

struct Edge {
    Eigen::Vector2d a, b;
    int ring;
    Eigen::Index index; // edge i joins vertex i and i+1 (mod ring size)
    Eigen::Index ringSize;
};

double orient(const Eigen::Vector2d &a, const Eigen::Vector2d &b, const Eigen::Vector2d &c)
{
    return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

int sign(double v)
{
    return (v > 0.0) - (v < 0.0);
}

bool onSegment(const Eigen::Vector2d &a, const Eigen::Vector2d &b, const Eigen::Vector2d &p)
{
    return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
           std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}

// Closed segments intersect (touching counts).
bool segmentsIntersect(const Edge &e, const Edge &f)
{
    const int o1 = sign(orient(e.a, e.b, f.a));
    const int o2 = sign(orient(e.a, e.b, f.b));
    const int o3 = sign(orient(f.a, f.b, e.a));
    const int o4 = sign(orient(f.a, f.b, e.b));
    if (o1 != o2 && o3 != o4)
        return true;
    return (o1 == 0 && onSegment(e.a, e.b, f.a)) || (o2 == 0 && onSegment(e.a, e.b, f.b)) ||
           (o3 == 0 && onSegment(f.a, f.b, e.a)) || (o4 == 0 && onSegment(f.a, f.b, e.b));
}

// Neighbouring edges share one end point; they are fine unless they fold back onto each
// other (collinear and overlapping beyond that point).
bool neighboursOverlap(const Edge &e, const Edge &f)
{
    const Edge &first = (e.index + 1) % e.ringSize == f.index ? e : f;
    const Edge &second = &first == &e ? f : e;
    // first.b == second.a is the shared vertex.
    if (sign(orient(first.a, first.b, second.b)) != 0)
        return false;
    return (first.a - first.b).dot(second.b - second.a) > 0.0;
}

// Touching at a point where one segment ends (a pinch, or a T) is allowed; properly crossing
// or overlapping along a stretch is not.
bool touchesOnly(const Edge &e, const Edge &f)
{
    const int o1 = sign(orient(e.a, e.b, f.a));
    const int o2 = sign(orient(e.a, e.b, f.b));
    const int o3 = sign(orient(f.a, f.b, e.a));
    const int o4 = sign(orient(f.a, f.b, e.b));
    if (o1 == 0 && o2 == 0) { // collinear: a shared end point only
        const Eigen::Vector2d d = e.b - e.a;
        const double s0 = 0.0, s1 = d.squaredNorm();
        const double t0 = d.dot(f.a - e.a), t1 = d.dot(f.b - e.a);
        const double lo = std::max(s0, std::min(t0, t1)), hi = std::min(s1, std::max(t0, t1));
        return hi <= lo;
    }
    return o1 == 0 || o2 == 0 || o3 == 0 || o4 == 0;
}

bool edgesConflict(const Edge &e, const Edge &f, Touching touching)
{
    if (e.ring == f.ring && e.index == f.index)
        return false;
    if (e.ring == f.ring && e.ringSize > 2 &&
        ((e.index + 1) % e.ringSize == f.index || (f.index + 1) % f.ringSize == e.index))
        return neighboursOverlap(e, f);
    if (!segmentsIntersect(e, f))
        return false;
    return touching == Touching::Forbidden || !touchesOnly(e, f);
}

struct EdgeGrid {
    Eigen::Vector2d origin;
    double cell = 1.0;
    int nx = 1, ny = 1;
    std::vector<std::vector<int>> cells;

    explicit EdgeGrid(const std::vector<Edge> &edges)
    {
        Eigen::Vector2d lo = edges.front().a, hi = lo;
        for (const Edge &e : edges) {
            lo = lo.cwiseMin(e.a).cwiseMin(e.b);
            hi = hi.cwiseMax(e.a).cwiseMax(e.b);
        }
        const Eigen::Vector2d extent = (hi - lo).cwiseMax(1e-12);
        cell = std::max(std::sqrt(extent.x() * extent.y() / double(edges.size())),
                        std::max(extent.x(), extent.y()) / 2048.0);
        origin = lo;
        nx = std::max(1, int(std::ceil(extent.x() / cell)));
        ny = std::max(1, int(std::ceil(extent.y() / cell)));
        cells.resize(std::size_t(nx) * std::size_t(ny));
        for (std::size_t i = 0; i < edges.size(); ++i)
            forCells(edges[i], [&](std::vector<int> &bucket) { bucket.push_back(int(i)); });
    }

    template <class Fn> void forCells(const Edge &e, Fn &&fn)
    {
        const Eigen::Vector2d lo = e.a.cwiseMin(e.b) - origin;
        const Eigen::Vector2d hi = e.a.cwiseMax(e.b) - origin;
        const int x0 = std::clamp(int(lo.x() / cell), 0, nx - 1);
        const int x1 = std::clamp(int(hi.x() / cell), 0, nx - 1);
        const int y0 = std::clamp(int(lo.y() / cell), 0, ny - 1);
        const int y1 = std::clamp(int(hi.y() / cell), 0, ny - 1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                fn(cells[std::size_t(y) * std::size_t(nx) + std::size_t(x)]);
    }
};

} // namespace

bool isSimple(const std::vector<Eigen::MatrixX2d> &rings, Touching touching)
{
    std::vector<Edge> edges;
    for (std::size_t r = 0; r < rings.size(); ++r) {
        const Eigen::MatrixX2d &ring = rings[r];
        const Eigen::Index n = ring.rows();
        if (n < 3 || !ring.allFinite())
            return false;
        for (Eigen::Index i = 0; i < n; ++i) {
            Edge e{ring.row(i).transpose(), ring.row((i + 1) % n).transpose(), int(r), i, n};
            if (e.a == e.b)
                return false;
            edges.push_back(e);
        }
    }
    if (edges.empty())
        return true;
    EdgeGrid grid(edges);
    for (const std::vector<int> &bucket : grid.cells) {
        for (std::size_t i = 0; i < bucket.size(); ++i)
            for (std::size_t j = i + 1; j < bucket.size(); ++j)
                if (edgesConflict(edges[std::size_t(bucket[i])], edges[std::size_t(bucket[j])],
                                  touching))
                    return false;
    }
    return true;
}

bool isSimple(const Eigen::MatrixX2d &ring, Touching touching)
{
    return isSimple(std::vector<Eigen::MatrixX2d>{ring}, touching);
}

bool isSimple(const Region &region, Touching touching)
{
    return isSimple(regionRings(region), touching);
}

} // namespace finbook::geometry
