#include "lottie_shapes.h"

#include <algorithm>
#include <cmath>

namespace finbook::model {

namespace {
// A quarter circle as one cubic: its tangents are this times the radius long.
constexpr double kKappa = 0.5522847498307936;
// Runs end at turns sharper than this: beyond it a mitre overshoots the round join visibly
// (by radius × (1/cos 20° − 1) ≈ 6 % of the radius at the limit).
const double kMaxMitreTurn = 40.0 * M_PI / 180.0;
// A mitre's setback along each neighbouring segment, at most this share of the segment: two
// mitres on one segment then never cross (no swallowtail, so no hole under the non-zero rule).
constexpr double kMaxSetback = 0.45;
// Runs end after this many samples, or this length in canvas pixels: rlottie's rasterizer drops
// stretches of a long thin outline (a ground line across the page), and short runs painted as
// groups of their own keep it whole. Counting samples keeps a posed stroke's runs where they
// were; only a sparse stroke (samples far apart) is cut by length.
constexpr std::size_t kRunSamples = 32;
constexpr double kRunLength = 256.0;
// Samples closer than this (canvas pixels, in place and in radius) to the line through their
// neighbours are left out: a pen's samples are dense, and the file is smaller by as much.
constexpr double kSimplify = 0.1;

double length(QPointF v)
{
    return std::hypot(v.x(), v.y());
}
double dot(QPointF a, QPointF b)
{
    return a.x() * b.x() + a.y() * b.y();
}
QPointF leftOf(QPointF d)
{
    return {-d.y(), d.x()};
}

struct Sample {
    QPointF p;
    double r;
};

// The outline of samples [a, b] of a run whose segment directions are d[a .. b-1] (unit).
BezierPath runOutline(const std::vector<Sample> &s, const std::vector<QPointF> &d, std::size_t a,
                      std::size_t b)
{
    const QPointF dStart = a < b ? d[a] : QPointF(1, 0);
    const QPointF dEnd = a < b ? d[b - 1] : QPointF(1, 0);
    const QPointF nStart = leftOf(dStart), nEnd = leftOf(dEnd);
    std::vector<QPointF> offset(b - a + 1);
    for (std::size_t j = a; j <= b; ++j) {
        if (j == a) {
            offset[j - a] = s[j].r * nStart;
        } else if (j == b) {
            offset[j - a] = s[j].r * nEnd;
        } else { // a mitre: parallel to both segments at distance r
            const QPointF n0 = leftOf(d[j - 1]), n1 = leftOf(d[j]);
            offset[j - a] = s[j].r * (n0 + n1) / (1.0 + dot(n0, n1));
        }
    }
    BezierPath path;
    const std::size_t count = 2 * (b - a + 1) + 2;
    path.vertices.reserve(count);
    path.in.reserve(count);
    path.out.reserve(count);
    const auto add = [&](QPointF v, QPointF in, QPointF out) {
        path.vertices.push_back(v);
        path.in.push_back(in);
        path.out.push_back(out);
    };
    const double ra = s[a].r, rb = s[b].r;
    for (std::size_t j = a; j <= b; ++j) // the left side, forwards
        add(s[j].p + offset[j - a], j == a ? -kKappa * ra * dStart : QPointF(),
            j == b ? kKappa * rb * dEnd : QPointF());
    // Half a circle around the last sample.
    add(s[b].p + rb * dEnd, kKappa * rb * nEnd, -kKappa * rb * nEnd);
    for (std::size_t j = b + 1; j-- > a;) // the right side, backwards
        add(s[j].p - offset[j - a], j == b ? kKappa * rb * dEnd : QPointF(),
            j == a ? -kKappa * ra * dStart : QPointF());
    // Half a circle around the first sample, back to where the path began.
    add(s[a].p - ra * dStart, -kKappa * ra * nStart, kKappa * ra * nStart);
    return path;
}
} // namespace

namespace {
// The stroke's finite samples with the radii paintStroke paints: each segment at its end
// sample's width in quarter pixels (at least a quarter pixel), so the first sample takes the
// second's; a lone sample is a dot of its own width (at least half a pixel).
std::vector<Sample> samplesOf(const std::vector<StrokePoint> &points, float width)
{
    std::vector<Sample> s;
    s.reserve(points.size());
    if (!std::isfinite(width))
        return s;
    for (const StrokePoint &p : points) {
        if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.pressure)))
            continue;
        const double pen = double(width) * std::clamp(double(p.pressure), 0.0, 1.0);
        s.push_back({QPointF(p.x, p.y),
                     points.size() == 1
                         ? std::max(0.5, pen) / 2.0
                         : std::max(0.25, std::round(std::max(0.0, pen) * 4.0) / 4.0) / 2.0});
    }
    if (s.size() > 1)
        s[0].r = s[1].r;
    return s;
}

// The samples Douglas–Peucker keeps: every sample whose place or radius the line between the
// kept ones around it would miss by more than kSimplify.
std::vector<bool> keptSamples(const std::vector<Sample> &s)
{
    std::vector<bool> keep(s.size(), s.size() <= 2);
    if (s.size() <= 2)
        return keep;
    keep.front() = keep.back() = true;
    std::vector<std::pair<std::size_t, std::size_t>> spans{{0, s.size() - 1}};
    while (!spans.empty()) {
        const auto [a, b] = spans.back();
        spans.pop_back();
        const QPointF ab = s[b].p - s[a].p;
        const double ab2 = dot(ab, ab);
        double worst = 0.0;
        std::size_t at = a;
        for (std::size_t k = a + 1; k < b; ++k) {
            const double t = ab2 > 0 ? std::clamp(dot(s[k].p - s[a].p, ab) / ab2, 0.0, 1.0) : 0.0;
            const double off = std::max(length(s[k].p - (s[a].p + t * ab)),
                                        std::abs(s[k].r - (s[a].r + t * (s[b].r - s[a].r))));
            if (off > worst) {
                worst = off;
                at = k;
            }
        }
        if (worst > kSimplify) {
            keep[at] = true;
            spans.push_back({a, at});
            spans.push_back({at, b});
        }
    }
    return keep;
}
} // namespace

std::vector<BezierPath> strokeOutline(const std::vector<StrokePoint> &points, float width,
                                      const std::vector<StrokePoint> *rest)
{
    std::vector<Sample> s = samplesOf(points, width);
    if (s.empty())
        return {};
    // Which samples to keep is decided on the rest drawing when there is one, so every pose
    // of a stroke keeps the same samples (and its outline the same vertex layout).
    std::vector<Sample> shape;
    if (rest && rest->size() == points.size())
        shape = samplesOf(*rest, width);
    const std::vector<bool> keep = keptSamples(shape.size() == s.size() ? shape : s);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (keep[i])
            s[kept++] = s[i];
    s.resize(kept);
    const std::size_t n = s.size();
    // Segment directions; a segment of no length takes its neighbour's (none at all: a dot).
    std::vector<QPointF> d(n > 1 ? n - 1 : 0);
    std::vector<double> len(d.size());
    bool any = false;
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const QPointF v = s[i + 1].p - s[i].p;
        len[i] = length(v);
        if (len[i] > 1e-9) {
            d[i] = v / len[i];
            any = true;
        }
    }
    if (!any) { // every sample on one spot: a dot as wide as the widest
        Sample single = s.front();
        for (const Sample &x : s)
            single.r = std::max(single.r, x.r);
        return {runOutline({single}, {}, 0, 0)};
    }
    for (std::size_t i = 1; i < d.size(); ++i) // forwards, then the leading ones backwards
        if (len[i] <= 1e-9)
            d[i] = d[i - 1];
    for (std::size_t i = d.size() - 1; i-- > 0;)
        if (d[i] == QPointF())
            d[i] = d[i + 1];
    // Where the runs end: turns too sharp for a mitre.
    std::vector<bool> cut(n, false);
    for (std::size_t j = 1; j + 1 < n; ++j) {
        const double turn = std::acos(std::clamp(dot(d[j - 1], d[j]), -1.0, 1.0));
        if (turn <= 1e-12)
            continue;
        const double setback = s[j].r * std::tan(turn / 2.0);
        cut[j] = turn > kMaxMitreTurn || setback > kMaxSetback * std::min(len[j - 1], len[j]);
    }
    std::vector<BezierPath> runs;
    std::size_t start = 0;
    double runLength = 0.0;
    for (std::size_t j = 1; j < n; ++j) {
        runLength += len[j - 1];
        if (cut[j] || j == n - 1 || j - start >= kRunSamples || runLength >= kRunLength) {
            runLength = 0.0;
            runs.push_back(runOutline(s, d, start, j));
            start = j;
        }
    }
    return runs;
}

std::vector<BezierPath> areaOutline(const QPainterPath &path)
{
    std::vector<BezierPath> out;
    for (const QPolygonF &ring : path.toSubpathPolygons()) {
        BezierPath p;
        for (qsizetype i = 0; i < ring.size(); ++i) {
            if (i == ring.size() - 1 && ring[i] == ring.front())
                break;
            if (!std::isfinite(ring[i].x()) || !std::isfinite(ring[i].y()))
                continue;
            p.vertices.push_back(ring[i]);
        }
        if (p.vertices.size() < 3)
            continue;
        p.in.assign(p.vertices.size(), QPointF());
        p.out.assign(p.vertices.size(), QPointF());
        out.push_back(std::move(p));
    }
    return out;
}

} // namespace finbook::model
