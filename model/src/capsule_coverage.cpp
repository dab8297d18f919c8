#include "capsule_coverage.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace finbook::model {

namespace {
struct Prepared {
    double ax, ay, bx, by, r;
    double ux, uy, length; // unit direction a→b (0 when a = b)
    double top, bottom;
    // Between these heights a row meets neither end disk: the crossing is the centre line's
    // x there ± halfWidth (empty range when the segment is not that tall).
    double middleTop, middleBottom, slope, halfWidth;
};

// x - ax within [lo, hi] / k, intersected into [from, to]; false when nothing is left.
bool cutLinear(double k, double lo, double hi, double &from, double &to)
{
    if (k == 0.0)
        return lo <= 0.0 && 0.0 <= hi;
    double a = lo / k, b = hi / k;
    if (a > b)
        std::swap(a, b);
    from = std::max(from, a);
    to = std::min(to, b);
    return from <= to;
}

// Where the horizontal line at height y crosses the capsule, widened into [lo, hi]. The
// capsule is the union of its two end disks and the rectangle between them, and it is convex,
// so its crossing is the hull of theirs.
void rowSpan(const Prepared &c, double y, double &lo, double &hi)
{
    if (c.middleTop < y && y < c.middleBottom) {
        const double x = c.ax + (y - c.ay) * c.slope;
        lo = std::min(lo, x - c.halfWidth);
        hi = std::max(hi, x + c.halfWidth);
        return;
    }
    const double r2 = c.r * c.r;
    for (const auto &[x, cy] : {std::pair{c.ax, c.ay}, std::pair{c.bx, c.by}}) {
        const double dy = y - cy;
        if (dy * dy <= r2) {
            const double h = std::sqrt(r2 - dy * dy);
            lo = std::min(lo, x - h);
            hi = std::max(hi, x + h);
        }
    }
    if (c.length <= 0.0)
        return;
    // Along the segment (x - ax)·ux + (y - ay)·uy in [0, length]; across it
    // -(x - ax)·uy + (y - ay)·ux in [-r, r].
    const double dy = y - c.ay;
    double from = -std::numeric_limits<double>::infinity();
    double to = std::numeric_limits<double>::infinity();
    if (cutLinear(c.ux, -dy * c.uy, c.length - dy * c.uy, from, to) &&
        cutLinear(-c.uy, -c.r - dy * c.ux, c.r - dy * c.ux, from, to)) {
        lo = std::min(lo, c.ax + from);
        hi = std::max(hi, c.ax + to);
    }
}

bool prepare(const Capsule &in, int width, int height, Prepared &out)
{
    const double r = in.radius;
    if (!std::isfinite(in.ax) || !std::isfinite(in.ay) || !std::isfinite(in.bx) ||
        !std::isfinite(in.by) || !std::isfinite(r) || !(r > 0.0))
        return false;
    out = {in.ax, in.ay, in.bx, in.by, r, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    out.top = std::min(in.ay, in.by) - r;
    out.bottom = std::max(in.ay, in.by) + r;
    if (out.bottom < 0.0 || out.top > height || std::max(in.ax, in.bx) + r < 0.0 ||
        std::min(in.ax, in.bx) - r > width)
        return false;
    const double dx = in.bx - in.ax, dy = in.by - in.ay;
    const double length = std::hypot(dx, dy);
    if (length > 0.0 && std::isfinite(length)) {
        out.ux = dx / length;
        out.uy = dy / length;
        out.length = length;
    }
    // Rows strictly between the end disks cross the rectangle only, both its long sides.
    if (std::abs(dy) > 2 * r && std::isfinite(dx / dy)) {
        out.middleTop = std::min(in.ay, in.by) + r;
        out.middleBottom = std::max(in.ay, in.by) - r;
        out.slope = dx / dy;
        out.halfWidth = r / std::abs(out.uy);
    }
    return true;
}

// One row of samples, covered interval by interval: each sample points at the next one not yet
// covered (union-find with path halving), so covering costs what is newly covered and the row
// knows at once when nothing is left to cover.
class SampleRow {
public:
    explicit SampleRow(int samples)
        : m_next(std::size_t(samples) + 1)
    {}
    void reset()
    {
        std::iota(m_next.begin(), m_next.end(), 0);
        m_uncovered = int(m_next.size()) - 1;
    }
    bool full() const { return m_uncovered == 0; }
    // Covers samples first..last; `covered(k)` hears of each sample newly covered.
    template <class Covered> void cover(int first, int last, Covered covered)
    {
        for (int k = find(first); k <= last; k = find(k)) {
            covered(k);
            m_next[std::size_t(k)] = k + 1;
            --m_uncovered;
        }
    }

private:
    int find(int k)
    {
        while (m_next[std::size_t(k)] != k) {
            const int skip = m_next[std::size_t(m_next[std::size_t(k)])];
            m_next[std::size_t(k)] = skip;
            k = skip;
        }
        return k;
    }
    std::vector<int> m_next; // the last entry is a sentinel, never covered
    int m_uncovered = 0;
};
} // namespace

CoverageWork capsuleCoverage(std::span<const Capsule> capsules, int width, int height,
                             std::vector<std::uint8_t> &alpha)
{
    constexpr int S = kCoverageSamples;
    CoverageWork work;
    width = std::max(0, width);
    height = std::max(0, height);
    alpha.assign(std::size_t(width) * std::size_t(height), 0);
    std::vector<Prepared> prepared;
    prepared.reserve(capsules.size());
    for (const Capsule &c : capsules)
        if (Prepared p; prepare(c, width, height, p))
            prepared.push_back(p);
    if (prepared.empty() || width == 0)
        return work;
    std::sort(prepared.begin(), prepared.end(),
              [](const Prepared &a, const Prepared &b) { return a.top < b.top; });

    const int samplesWide = S * width;
    SampleRow samples(samplesWide);
    std::vector<std::uint16_t> counts(static_cast<std::size_t>(width));
    std::vector<const Prepared *> active;
    std::size_t next = 0;
    for (int row = 0; row < height; ++row) {
        std::fill(counts.begin(), counts.end(), 0);
        // Capsules ending above this row leave; those ending inside it give empty spans below.
        std::erase_if(active, [row](const Prepared *c) { return c->bottom < row; });
        bool touched = false;
        for (int sub = 0; sub < S; ++sub) {
            const double y = row + (sub + 0.5) / S;
            while (next < prepared.size() && prepared[next].top <= y)
                active.push_back(&prepared[next++]);
            if (active.empty())
                continue;
            touched = true;
            samples.reset();
            work.samples += samplesWide;
            for (const Prepared *c : active) {
                double lo = std::numeric_limits<double>::infinity(), hi = -lo;
                rowSpan(*c, y, lo, hi);
                ++work.spans;
                if (!(lo <= hi))
                    continue;
                // Samples at (k + 0.5) / S inside [lo, hi]; clamped before converting.
                const double first = std::ceil(std::max(lo * S - 0.5, -1.0));
                const double last = std::floor(std::min(hi * S - 0.5, double(samplesWide)));
                const double k0 = std::max(0.0, first), k1 = std::min(samplesWide - 1.0, last);
                if (k0 <= k1)
                    samples.cover(int(k0), int(k1),
                                  [&counts](int k) { ++counts[std::size_t(k / S)]; });
                if (samples.full()) // the rest of the capsules cannot add anything here
                    break;
            }
        }
        if (!touched)
            continue;
        std::uint8_t *out = alpha.data() + std::size_t(row) * std::size_t(width);
        for (int x = 0; x < width; ++x)
            out[x] = std::uint8_t((counts[std::size_t(x)] * 255 + S * S / 2) / (S * S));
    }
    return work;
}

} // namespace finbook::model
