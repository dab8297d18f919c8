#include <finbook/geometry/erase/polyline_erase.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace finbook::geometry {

namespace {

using Vec = Eigen::Vector2d;

struct Interval {
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
    bool empty() const { return !(lo <= hi); }
    void hull(const Interval &o)
    {
        if (o.empty())
            return;
        lo = std::min(lo, o.lo);
        hi = std::max(hi, o.hi);
    }
};

constexpr double kInf = std::numeric_limits<double>::infinity();

// Parameters t where |a + t d - c| <= r.
Interval discInterval(const Vec &a, const Vec &d, const Vec &c, double r)
{
    const Vec ac = a - c;
    const double qa = d.squaredNorm(), qb = 2 * d.dot(ac), qc = ac.squaredNorm() - r * r;
    if (qa == 0)
        return qc <= 0 ? Interval{-kInf, kInf} : Interval{};
    const double disc = qb * qb - 4 * qa * qc;
    if (disc < 0)
        return {};
    const double s = std::sqrt(disc);
    return {(-qb - s) / (2 * qa), (-qb + s) / (2 * qa)};
}

// Narrows `t` to where f0 + t f1 lies in [lo, hi].
void clipSlab(Interval &t, double f0, double f1, double lo, double hi)
{
    if (f1 == 0) {
        if (f0 < lo || f0 > hi)
            t = {};
        return;
    }
    double t0 = (lo - f0) / f1, t1 = (hi - f0) / f1;
    if (t0 > t1)
        std::swap(t0, t1);
    t.lo = std::max(t.lo, t0);
    t.hi = std::min(t.hi, t1);
}

// Parameters t of the line a + t d inside the capsule of radius r around segment c–e. The
// capsule is convex, so the hull of its three pieces' intervals is exact.
Interval capsuleInterval(const Vec &a, const Vec &d, const Vec &c, const Vec &e, double r)
{
    Interval t = discInterval(a, d, c, r);
    const Vec ce = e - c;
    const double len = ce.norm();
    if (len == 0)
        return t;
    t.hull(discInterval(a, d, e, r));
    const Vec u = ce / len, n(-u.y(), u.x());
    const Vec ac = a - c;
    Interval slab{-kInf, kInf};
    clipSlab(slab, ac.dot(u), d.dot(u), 0, len);
    clipSlab(slab, ac.dot(n), d.dot(n), -r, r);
    t.hull(slab);
    return t;
}

struct Box {
    double x0 = kInf, y0 = kInf, x1 = -kInf, y1 = -kInf;
    void add(const Vec &p)
    {
        x0 = std::min(x0, p.x());
        y0 = std::min(y0, p.y());
        x1 = std::max(x1, p.x());
        y1 = std::max(y1, p.y());
    }
    bool meets(const Box &o, double pad) const
    {
        return x0 - pad <= o.x1 && o.x0 <= x1 + pad && y0 - pad <= o.y1 && o.y0 <= y1 + pad;
    }
};

bool finiteRow(const Eigen::MatrixX2d &m, Eigen::Index i)
{
    return std::isfinite(m(i, 0)) && std::isfinite(m(i, 1));
}

PolylinePlace placeAt(double u, Eigen::Index segments)
{
    if (segments == 0)
        return {0, 0.0};
    const Eigen::Index s = std::clamp(Eigen::Index(std::floor(u)), Eigen::Index(0), segments - 1);
    return {s, std::clamp(u - double(s), 0.0, 1.0)};
}

} // namespace

EraseResult erasePolyline(const Eigen::MatrixX2d &P, const Eigen::VectorXd &reach,
                          const Eigen::MatrixX2d &E, double radius)
{
    EraseResult result;
    const Eigen::Index n = P.rows(), m = E.rows();
    const Eigen::Index segments = std::max<Eigen::Index>(n - 1, 0);
    if (n == 0)
        return result;
    const auto keepAll = [&] {
        result.kept.push_back({{0, 0.0}, placeAt(double(segments), segments)});
        return result;
    };
    if (m == 0 || !std::isfinite(radius) || radius < 0)
        return keepAll();
    // The rub's capsules (a dab is a capsule of length 0) and their boxes.
    std::vector<Eigen::Index> rub;
    Box rubBox;
    for (Eigen::Index j = 0; j < m; ++j)
        if (finiteRow(E, j)) {
            rub.push_back(j);
            rubBox.add(E.row(j).transpose());
        }
    if (rub.empty())
        return keepAll();
    double maxReach = 0;
    for (Eigen::Index k = 0; k < reach.size(); ++k)
        if (std::isfinite(reach(k)))
            maxReach = std::max(maxReach, reach(k));
    const auto reachAt = [&](Eigen::Index k) {
        return k < reach.size() && std::isfinite(reach(k)) && reach(k) > 0 ? reach(k) : 0.0;
    };

    std::vector<Interval> covered; // in u = segment + t, sorted by lo
    std::vector<Interval> inSegment;
    for (Eigen::Index s = 0; s < std::max<Eigen::Index>(segments, 1); ++s) {
        const Eigen::Index i1 = segments == 0 ? 0 : s + 1;
        if (!finiteRow(P, s) || !finiteRow(P, i1))
            continue;
        const Vec a = P.row(s).transpose(), b = P.row(i1).transpose();
        Box segBox;
        segBox.add(a);
        segBox.add(b);
        if (!segBox.meets(rubBox, radius + maxReach))
            continue;
        const double r = radius + (reachAt(s) + reachAt(i1)) / 2;
        const Vec d = b - a;
        inSegment.clear();
        const std::size_t capsules = rub.size() > 1 ? rub.size() - 1 : 1;
        for (std::size_t k = 0; k < capsules; ++k) {
            const Vec c = E.row(rub[k]).transpose();
            const Vec e = rub.size() > 1 ? Vec(E.row(rub[k + 1]).transpose()) : c;
            Box capBox;
            capBox.add(c);
            capBox.add(e);
            if (!capBox.meets(segBox, r))
                continue;
            Interval t = capsuleInterval(a, d, c, e, r);
            t.lo = std::max(t.lo, 0.0);
            t.hi = std::min(t.hi, segments == 0 ? 0.0 : 1.0);
            // A graze (a single parameter) cuts nothing, except on a one-point polyline.
            if (!t.empty() && (segments == 0 || t.hi - t.lo > 1e-9))
                inSegment.push_back({double(s) + t.lo, double(s) + t.hi});
        }
        std::sort(inSegment.begin(), inSegment.end(),
                  [](const Interval &x, const Interval &y) { return x.lo < y.lo; });
        covered.insert(covered.end(), inSegment.begin(), inSegment.end());
    }
    if (covered.empty())
        return keepAll();
    result.touched = true;
    // Merge, then keep what lies between.
    double from = 0.0;
    const double end = double(segments);
    constexpr double kEps = 1e-12;
    std::size_t i = 0;
    while (i < covered.size()) {
        double lo = covered[i].lo, hi = covered[i].hi;
        for (++i; i < covered.size() && covered[i].lo <= hi + kEps; ++i)
            hi = std::max(hi, covered[i].hi);
        if (lo > from + kEps)
            result.kept.push_back({placeAt(from, segments), placeAt(lo, segments)});
        from = std::max(from, hi);
    }
    if (end > from + kEps)
        result.kept.push_back({placeAt(from, segments), placeAt(end, segments)});
    return result;
}

} // namespace finbook::geometry
