// traceAlphaOutline: marching squares over the alpha at pixel centres, crossings joined into
// rings by the edge they lie on, holes given to the smallest outer ring around them.
#include <finbook/geometry/picture/alpha_outline.h>
#include <finbook/geometry/polyline.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace finbook::geometry {

namespace {

// Samples are addressed in a frame padded by one transparent sample on every side: sample
// (X, Y) is pixel (X − 1, Y − 1). A crossing is named by the sample edge it lies on:
// 2·(Y·(W+2) + X) for the edge from (X, Y) to (X+1, Y), the same + 1 for (X, Y) to (X, Y+1).
struct AlphaGrid {
    const std::uint8_t *alpha;
    int width;
    int height;
    long rowStride;
    int pixelStride;

    int at(long X, long Y) const
    {
        const long x = X - 1, y = Y - 1;
        if (x < 0 || y < 0 || x >= width || y >= height)
            return 0;
        return alpha[y * rowStride + x * pixelStride];
    }
    std::int64_t paddedWidth() const { return std::int64_t(width) + 2; }
    std::int64_t horizontal(long X, long Y) const { return 2 * (Y * paddedWidth() + X); }
    std::int64_t vertical(long X, long Y) const { return 2 * (Y * paddedWidth() + X) + 1; }
};

using Segment = std::pair<std::int64_t, std::int64_t>; // from crossing, to crossing

// One padded row of samples (transparent at both ends).
void loadRow(const AlphaGrid &g, long Y, std::vector<std::uint8_t> &row)
{
    std::fill(row.begin(), row.end(), std::uint8_t(0));
    const long y = Y - 1;
    if (y < 0 || y >= g.height)
        return;
    const std::uint8_t *src = g.alpha + y * g.rowStride;
    for (int x = 0; x < g.width; ++x)
        row[std::size_t(x) + 1] = src[std::size_t(x) * std::size_t(g.pixelStride)];
}

// The segments of the cell whose top-left sample is (X, Y). The cell's border is walked
// a → b → c → d (clockwise on the y-down screen); a segment runs from a crossing where the
// walk enters the inside to one where it leaves, so the inside is always on the same side.
void cellSegments(const AlphaGrid &g, long X, long Y, const int v[4], double iso,
                  std::vector<Segment> &out)
{
    const bool in[4] = {v[0] > iso, v[1] > iso, v[2] > iso, v[3] > iso};
    const std::int64_t edge[4] = {g.horizontal(X, Y), g.vertical(X + 1, Y), g.horizontal(X, Y + 1),
                                  g.vertical(X, Y)};
    std::int64_t enter[2], leave[2];
    int entered = 0, left = 0;
    for (int k = 0; k < 4; ++k) {
        const bool from = in[k], to = in[(k + 1) % 4];
        if (!from && to)
            enter[entered++] = edge[k];
        else if (from && !to)
            leave[left++] = edge[k];
    }
    if (entered == 1) {
        out.emplace_back(enter[0], leave[0]);
        return;
    }
    if (entered != 2)
        return;
    // A saddle: a and c on one side, b and d on the other. Its centre decides whether the two
    // inside corners join across the cell (each enter goes to the leave before it on the walk)
    // or stay apart (each enter goes to the next leave). The walk meets, with a inside:
    // leave[0] enter[0] leave[1] enter[1]; with a outside: enter[0] leave[0] enter[1] leave[1].
    const bool centreIn = double(v[0] + v[1] + v[2] + v[3]) / 4.0 > iso;
    if (in[0] == centreIn) {
        out.emplace_back(enter[0], leave[0]);
        out.emplace_back(enter[1], leave[1]);
    } else {
        out.emplace_back(enter[0], leave[1]);
        out.emplace_back(enter[1], leave[0]);
    }
}

// Where the crossing `id` lies, in picture pixels.
Eigen::RowVector2d crossingPoint(const AlphaGrid &g, std::int64_t id, double iso)
{
    const bool vertical = id & 1;
    const std::int64_t cell = id / 2;
    const long X = long(cell % g.paddedWidth()), Y = long(cell / g.paddedWidth());
    const int a = g.at(X, Y);
    const int b = vertical ? g.at(X, Y + 1) : g.at(X + 1, Y);
    const double t = (double(a) - iso) / double(a - b); // a and b lie on either side of iso
    const double x = double(X) - 0.5, y = double(Y) - 0.5;
    return vertical ? Eigen::RowVector2d(x, y + t) : Eigen::RowVector2d(x + t, y);
}

// Every segment of the picture; false when there are more than `limit`.
bool collectSegments(const AlphaGrid &g, double iso, long limit, std::vector<Segment> &segments)
{
    std::vector<std::uint8_t> top(std::size_t(g.width) + 2), bottom(top.size());
    loadRow(g, 0, bottom);
    for (long Y = 0; Y <= g.height; ++Y) {
        std::swap(top, bottom);
        loadRow(g, Y + 1, bottom);
        for (long X = 0; X <= g.width; ++X) {
            const int v[4] = {top[std::size_t(X)], top[std::size_t(X) + 1],
                              bottom[std::size_t(X) + 1], bottom[std::size_t(X)]};
            const bool a = v[0] > iso;
            if (a == (v[1] > iso) && a == (v[2] > iso) && a == (v[3] > iso))
                continue;
            cellSegments(g, X, Y, v, iso, segments);
        }
        if (long(segments.size()) > limit)
            return false;
    }
    return true;
}

// Joins the segments into rings of crossing points, each walked with the inside on one side.
std::vector<Eigen::MatrixX2d> joinRings(const AlphaGrid &g, std::vector<Segment> &segments,
                                        double iso)
{
    std::sort(segments.begin(), segments.end());
    std::vector<char> used(segments.size(), 0);
    std::vector<Eigen::MatrixX2d> rings;
    std::vector<std::int64_t> ids;
    for (std::size_t start = 0; start < segments.size(); ++start) {
        if (used[start])
            continue;
        ids.clear();
        std::size_t at = start;
        bool closed = false;
        while (!used[at]) {
            used[at] = 1;
            ids.push_back(segments[at].first);
            const std::int64_t next = segments[at].second;
            const auto it =
                std::lower_bound(segments.begin(), segments.end(), Segment{next, INT64_MIN});
            if (it == segments.end() || it->first != next)
                break; // cannot happen: every crossing is entered once and left once
            at = std::size_t(it - segments.begin());
            closed = at == start;
        }
        if (!closed || ids.size() < 3)
            continue;
        Eigen::MatrixX2d ring(Eigen::Index(ids.size()), 2);
        // Reversed: the walk keeps the inside on the screen's left, which gives outer rings a
        // negative shoelace area; region.h wants them positive.
        for (std::size_t i = 0; i < ids.size(); ++i)
            ring.row(Eigen::Index(ids.size() - 1 - i)) = crossingPoint(g, ids[i], iso);
        rings.push_back(std::move(ring));
    }
    return rings;
}

struct Box {
    double x0, y0, x1, y1;
    bool contains(const Eigen::RowVector2d &p) const
    {
        return p.x() >= x0 && p.x() <= x1 && p.y() >= y0 && p.y() <= y1;
    }
};

Box boxOf(const Eigen::MatrixX2d &ring)
{
    return {ring.col(0).minCoeff(), ring.col(1).minCoeff(), ring.col(0).maxCoeff(),
            ring.col(1).maxCoeff()};
}

bool ringContains(const Eigen::MatrixX2d &ring, const Eigen::RowVector2d &p)
{
    bool inside = false;
    const Eigen::Index n = ring.rows();
    for (Eigen::Index i = 0, j = n - 1; i < n; j = i++) {
        const double yi = ring(i, 1), yj = ring(j, 1);
        if ((yi > p.y()) != (yj > p.y()) &&
            p.x() < (ring(j, 0) - ring(i, 0)) * (p.y() - yi) / (yj - yi) + ring(i, 0))
            inside = !inside;
    }
    return inside;
}

// The simplified ring, or an empty matrix when simplification leaves no area of the right sign.
Eigen::MatrixX2d simplifyRing(const Eigen::MatrixX2d &ring, double tolerance, bool outer)
{
    Eigen::MatrixX2d out = tolerance > 0.0 ? douglasPeucker(ring, tolerance, true) : ring;
    const double area = signedArea(out);
    if (out.rows() < 3 || (outer ? area <= 0.0 : area >= 0.0))
        return {};
    return out;
}

// Rings → polygons: each hole goes to the smallest outer ring around it (rings do not cross
// before simplification, so one of its points decides), then every ring is simplified.
Region assemble(std::vector<Eigen::MatrixX2d> rings, const AlphaOutlineOptions &options)
{
    std::vector<std::size_t> outers, holes;
    std::vector<double> areas(rings.size());
    for (std::size_t i = 0; i < rings.size(); ++i) {
        areas[i] = signedArea(rings[i]);
        if (std::abs(areas[i]) < options.minArea)
            continue;
        (areas[i] > 0.0 ? outers : holes).push_back(i);
    }
    std::vector<Box> boxes(rings.size());
    for (std::size_t i : outers)
        boxes[i] = boxOf(rings[i]);
    std::vector<std::vector<std::size_t>> holesOf(rings.size());
    for (std::size_t h : holes) {
        const Eigen::RowVector2d p = rings[h].row(0);
        std::size_t best = rings.size();
        for (std::size_t o : outers) {
            if (boxes[o].contains(p) && (best == rings.size() || areas[o] < areas[best]) &&
                ringContains(rings[o], p))
                best = o;
        }
        if (best < rings.size())
            holesOf[best].push_back(h);
    }
    Region region;
    for (std::size_t o : outers) {
        Polygon polygon;
        polygon.outer = simplifyRing(rings[o], options.simplify, true);
        if (polygon.outer.rows() == 0)
            continue;
        for (std::size_t h : holesOf[o]) {
            Eigen::MatrixX2d hole = simplifyRing(rings[h], options.simplify, false);
            if (hole.rows() > 0)
                polygon.holes.push_back(std::move(hole));
        }
        region.push_back(std::move(polygon));
    }
    return region;
}

GeometryError invalid(const char *what)
{
    return {GeometryErrorCode::InvalidOptions, what};
}

} // namespace

Expected<Region, GeometryError> traceAlphaOutline(const std::uint8_t *alpha, int width, int height,
                                                  long rowStride, int pixelStride,
                                                  const AlphaOutlineOptions &options)
{
    if (width < 0 || height < 0 || width > kMaxAlphaSide || height > kMaxAlphaSide)
        return unexpected(invalid("The picture's size is out of range."));
    if (width == 0 || height == 0)
        return Region{};
    if (!alpha || pixelStride < 1 || rowStride < long(width - 1) * pixelStride + 1)
        return unexpected(invalid("The picture's pixels are not laid out as described."));
    if (options.threshold < 1 || options.threshold > 255 || !(options.simplify >= 0.0) ||
        !std::isfinite(options.simplify) || !(options.minArea >= 0.0) ||
        !std::isfinite(options.minArea) || options.maxOutlinePoints < 0)
        return unexpected(invalid("The outline's threshold, tolerance or limits are invalid."));
    const AlphaGrid grid{alpha, width, height, rowStride, pixelStride};
    // Alpha is an integer: ≥ threshold is > threshold − ½, and threshold − ½ lies strictly
    // between an inside and an outside value, so every crossing falls inside its edge.
    const double iso = double(options.threshold) - 0.5;
    std::vector<Segment> segments;
    if (!collectSegments(grid, iso, options.maxOutlinePoints, segments))
        return unexpected(GeometryError{GeometryErrorCode::TooManyPoints,
                                        "The picture's outline is too intricate to trace (is it "
                                        "noise?). Try a higher alpha threshold."});
    return assemble(joinRings(grid, segments, iso), options);
}

} // namespace finbook::geometry
